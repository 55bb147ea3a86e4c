// End-to-end tests of topology along the iso level in headless Chromium: `criticalPoints()` against the
// closed form for two spheres, the panel's plot whose cursor sets the iso level, the merge tree whose
// join brings the two blobs together in the picture, the markers over the figure and the HUD's field
// line with what the mesh misses.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useServerAndBrowser, openClosedAfterEach, settledTriangles, screenshot } from './helpers.js';

useServerAndBrowser();

const open = openClosedAfterEach();

// Two spheres of radius 0.25 at x = ±0.4: one saddle, at the origin, f = 2 r² / a² = 0.78125.
const BALLS = '-0.4,0,0,0.25;0.4,0,0,0.25';
const SADDLE = 2 * 0.25 ** 2 / 0.4 ** 2;

const meshBlobs = (page) => page.$eval('metaballs-view', (e) => e.topology()).then((shape) => shape.components);

test('criticalPoints() finds the saddle between two spheres where the closed form puts it', async () => {
  const { page, errors } = await open(`?balls=${BALLS}&res=32&paused=1`);
  await settledTriangles(page);
  const result = await page.$eval('metaballs-view', (e) => e.criticalPoints());
  assert.equal(result.points.length, 1, JSON.stringify(result.points));
  const [saddle] = result.points;
  assert.ok(Math.abs(saddle.value - SADDLE) < 1e-5 * SADDLE, `${saddle.value} against ${SADDLE}`);
  assert.equal(saddle.role, 'join');
  assert.ok(Math.hypot(...saddle.position) < 1e-6);
  assert.equal(result.complete, true);
  assert.deepEqual(result.tree.at(-1).spheres, [0, 1]);
  // The iso level (1) is above the saddle: two blobs, in the field and in the mesh.
  assert.equal(result.counts.blobs, 2);
  assert.equal(await meshBlobs(page), 2);
  assert.deepEqual(errors, []);
});

test('the plot\'s cursor sets the iso level, and a join of the merge tree brings the two blobs together', async () => {
  const { page, errors } = await open(`?balls=${BALLS}&res=32&paused=1&controls=all&hud=on&critical=1`);
  await settledTriangles(page);
  // The panel's "Along the iso level" opens the box (the `levels` setting, which the link then carries).
  await page.click('text=Teaching');
  await page.check('#levels');
  assert.equal(await page.$eval('metaballs-view', (e) => e.levels), true);
  // Drawn once the area and volume along the level are in (the plot is drawn again then).
  await page.waitForSelector('div.levels svg.levels-plot path[stroke="#5ec962"]', { timeout: 60000 });
  assert.equal(await page.isVisible('#levels-box'), true);
  const status = await page.textContent('div.levels p[role=status]');
  assert.match(status, /1 critical point \(all found, with proof/);
  assert.match(status, /2 blobs, 0 cavities, genus 0/);
  // A drag on the plot's left part sets a lower iso level.
  const box = await page.locator('div.levels svg.levels-plot').boundingBox();
  await page.mouse.move(box.x + box.width * 0.2, box.y + box.height * 0.5);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width * 0.15, box.y + box.height * 0.5);
  await page.mouse.up();
  const dragged = await page.$eval('metaballs-view', (e) => Number(e.iso));
  assert.ok(dragged < 1 && dragged > 0, `iso after the drag: ${dragged}`);
  await page.$eval('metaballs-view', (e) => { e.iso = 1; });
  await settledTriangles(page);
  const apart = await screenshot(page, 'levels-apart');
  // The tree's one join sets the iso level just below the saddle: one blob, in the field and the mesh.
  await page.click('div.levels svg.merge-tree g.join');
  const iso = await page.$eval('metaballs-view', (e) => Number(e.iso));
  assert.ok(iso < SADDLE && iso > SADDLE * 0.9, `iso after the join: ${iso}`);
  await settledTriangles(page);
  assert.equal(await meshBlobs(page), 1);
  const joined = await page.$eval('metaballs-view', (e) => e.criticalPoints());
  assert.equal(joined.counts.blobs, 1);
  await page.waitForFunction(() => /1 blob, 0 cavities/.test(document.querySelector('metaballs-view').shadowRoot
    .querySelector('div.levels p[role=status]')?.textContent ?? ''), null, { timeout: 20000 });
  // The picture changed where the blobs met: the gap between them is filled.
  const together = await screenshot(page, 'levels-joined');
  assert.notDeepEqual(apart, together);
  // The marker of the saddle sits over the figure's middle, with its value.
  const mark = await page.waitForFunction(() => {
    const span = document.querySelector('metaballs-view').shadowRoot.querySelector('#critical-marks span');
    return span && !span.hidden && span.textContent;
  }, null, { timeout: 20000 });
  assert.match(await mark.jsonValue(), /◆ 0\.781/);
  // The box's × closes it.
  await page.click('#levels-box button.close');
  assert.equal(await page.$eval('metaballs-view', (e) => e.levels), false);
  assert.equal(await page.isVisible('#levels-box'), false);
  // The HUD gives the field's count.
  await page.waitForFunction(() => /^1 surface · genus 0/.test(document.querySelector('metaballs-view').shadowRoot
    .getElementById('hud-field-text').textContent), null, { timeout: 20000 });
  assert.deepEqual(errors, []);
});

test('where the neck is thinner than a cell, the HUD says where the field joins the spheres and how thin', async () => {
  // Just below the saddle at 16³, with the spheres' axis between grid lines (the grid's points nearest
  // the saddle are off the neck): the field has one blob, the mesh two.
  const balls = '-0.4,0.0625,0.0625,0.25;0.4,0.0625,0.0625,0.25';
  const { page, errors } = await open(`?balls=${balls}&res=16&paused=1&hud=on&critical=1&iso=${(SADDLE * 0.995).toFixed(5)}`);
  await settledTriangles(page);
  assert.equal(await meshBlobs(page), 2);
  const warning = await page.waitForFunction(() => {
    const text = document.querySelector('metaballs-view').shadowRoot.getElementById('hud-field-warning').textContent;
    return text && text;
  }, null, { timeout: 30000 });
  assert.match(await warning.jsonValue(), /The field joins spheres 0 and 1 here, f = 0\.7812 at the saddle; the neck is 0\.\d cells wide at 16³/);
  assert.deepEqual(errors, []);
});
