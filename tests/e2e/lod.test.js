// End-to-end tests of level of detail in headless Chromium (SwiftShader): a LOD figure draws with the
// HUD's effective resolution and counts per level, coloured by level, on the CPU and GPU paths alike; a
// frozen selection stays while the camera moves; a 2048³ link asks first instead of freezing the
// page; slow frames make the cells larger on screen after the render scale has fallen, within
// `max-lod-pixels`, and fast ones make them small again, the HUD saying how large; and a zoomed 2048³
// figure settles at 10 frames a second or more. First, without the page, the steps that frame times
// move (www/lib/figure/ladder.js).

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useServerAndBrowser, openClosedAfterEach, settledTriangles, frameDrawn } from './helpers.js';
import { DetailBudget, Ladder, LOD_STEPS, RENDER_SCALES } from '../../www/lib/figure/ladder.js';

/** A figure's chain, as detail.js makes it: the render scale down to 0.5, then cells from 2 to 16 px. */
function chain() {
  const scale = new Ladder(RENDER_SCALES);
  const cells = new Ladder(LOD_STEPS);
  const links = [{ ladder: scale, floor: 0.5 }, { ladder: cells, floor: 2 / 16 }];
  return { links, now: () => [scale.value(0.5), Number((2 / cells.value(2 / 16)).toPrecision(6))] };
}

test('slow frames take the render scale down first, then the cells, never past their limits', () => {
  const budget = new DetailBudget();
  const { links, now } = chain();
  // Twice the budget: the scale alone gives up what is asked (the cost goes as the square of the scale).
  assert.equal(budget.observe(60, 30, links), true);
  assert.deepEqual(now(), [0.7, 2]);
  // The window after a change is not measured.
  assert.equal(budget.observe(3000, 30, links), false);
  assert.deepEqual(now(), [0.7, 2]);
  // A hundred times over: the scale goes to its floor and the cells give up the rest, a tenth of the
  // detail (cells of 14 px), to the first step past it.
  assert.equal(budget.observe(3000, 30, links), true);
  assert.deepEqual(now(), [0.5, 16]);
  budget.observe(3000, 30, links);
  for (let i = 0; i < 10; i++) assert.equal(budget.observe(10_000, 30, links), false, 'everything is at its limit');
  assert.deepEqual(now(), [0.5, 16]);
  // Over budget by less than 15 %, or between the thresholds: nothing moves.
  const calm = chain();
  for (const ms of [34, 20, 33, 25]) assert.equal(budget.observe(ms, 30, calm.links), false);
  assert.deepEqual(calm.now(), [1, 2]);
  // A chain whose cells may not grow (no LOD, or max-lod-pixels at lod-pixels) gives up pixels alone.
  const fixed = new Ladder(LOD_STEPS);
  budget.observe(3000, 30, [{ ladder: new Ladder(RENDER_SCALES), floor: 0.5 }, { ladder: fixed, floor: 1 }]);
  assert.equal(fixed.value(0), 1, 'the cells moved');
});

test('fast frames give the cells back first, a step per two fast windows, then the pixels', () => {
  const budget = new DetailBudget();
  const { links, now } = chain();
  for (let i = 0; i < 3; i++) budget.observe(3000, 30, links);
  assert.deepEqual(now(), [0.5, 16]);
  const seen = [now()];
  let windows = 0;
  for (; windows < 200 && now()[0] < 1; windows++) {
    // A window between the thresholds breaks a run of fast ones.
    if (windows % 7 === 6) assert.equal(budget.observe(25, 30, links), false);
    else budget.observe(5, 30, links);
    if (now().join() !== seen.at(-1).join()) seen.push(now());
  }
  assert.deepEqual(seen, [[0.5, 16], [0.5, 12], [0.5, 10], [0.5, 8], [0.5, 6], [0.5, 5], [0.5, 4], [0.5, 3],
    [0.5, 2.5], [0.5, 2], [0.6, 2], [0.7, 2], [0.85, 2], [1, 2]]);
  // Thirteen steps, each after a skipped window and two fast ones, some runs broken.
  assert.ok(windows >= 39 && windows < 60, `${windows} windows`);
});

useServerAndBrowser();

const open = openClosedAfterEach();

const levels = (page) => page.$eval('metaballs-view', (e) => e.stats.lod?.levels.map((l) => l.blocks) ?? null);

async function setAndSettle(page, name, value) {
  await page.$eval('metaballs-view', (element, [n, v]) => element.setAttribute(n, v), [name, value]);
  // Two frames of the new settings, each with its statistics (the levels among them) read back.
  await frameDrawn(page);
  await frameDrawn(page);
}

test('a LOD figure draws coloured by level and its HUD counts each level, on the CPU and the GPU', async () => {
  const { page, errors } = await open('?lod=on&res=256&lod_px=8&dist=1.5&color_by=level&hud=on&paused=1&aa=0');
  const cpuTriangles = await settledTriangles(page);
  assert.ok(cpuTriangles > 500, `${cpuTriangles} triangles`);
  assert.match(await page.textContent('#adapter'), /swiftshader · LOD-CPU meshing$/i);
  assert.equal(await page.locator('#hud-lod').isVisible(), true);
  assert.match(await page.textContent('#hud-lod-summary'), /^256³ effective · [2-9] levels$/);
  const rows = await page.locator('#hud-lod-levels li:not([hidden])').allTextContents();
  assert.ok(rows.length >= 2, rows.join(' | '));
  for (const row of rows) assert.match(row, /^\d: [\d,]+ blocks · [\d,]+ △$/);
  const perLevel = rows.map((r) => Number(r.split('·')[1].replace(/[^\d]/g, '')));
  assert.equal(perLevel.reduce((a, b) => a + b, 0), cpuTriangles, 'triangles per level add up');
  // The key names the levels.
  assert.match(await page.textContent('#panel'), /finest first/);

  await setAndSettle(page, 'mesher', 'gpu');
  await page.waitForFunction(() => /LOD-GPU meshing$/.test(
    document.querySelector('metaballs-view').shadowRoot.getElementById('adapter').textContent));
  const gpuTriangles = await settledTriangles(page);
  // The CPU's mesh again, now that the figure has drawn a while: its first meshes may hold more of the
  // surface than the view's selection keeps later.
  await setAndSettle(page, 'mesher', 'cpu');
  await page.waitForFunction(() => /LOD-CPU meshing$/.test(
    document.querySelector('metaballs-view').shadowRoot.getElementById('adapter').textContent));
  const cpuAgain = await settledTriangles(page);
  console.log(`LOD at 256³ and 8 px: the CPU's first mesh ${cpuTriangles} triangles, the GPU's ${gpuTriangles}, the CPU's again ${cpuAgain}`);
  assert.equal(gpuTriangles, cpuAgain, `the GPU and CPU LOD meshes have as many triangles (the CPU's first: ${cpuTriangles})`);
  assert.match(await page.textContent('#hud-lod-summary'), /^256³ effective/);
  assert.deepEqual(errors, []);
});

test('a frozen selection stays while the camera orbits away, and follows it again when thawed', async () => {
  const { page, errors } = await open('?lod=on&res=256&lod_px=8&dist=1.5&hud=on&paused=1&aa=0');
  await settledTriangles(page);
  await setAndSettle(page, 'lod_freeze', 'on');
  const frozen = await levels(page);
  assert.ok(frozen && frozen.filter((n) => n > 0).length >= 2, JSON.stringify(frozen));
  await setAndSettle(page, 'distance', '8');
  await setAndSettle(page, 'yaw', '140');
  assert.deepEqual(await levels(page), frozen, 'the frozen selection changed');
  await setAndSettle(page, 'lod_freeze', 'off');
  const thawed = await levels(page);
  assert.notDeepEqual(thawed, frozen, 'the selection does not follow the camera');
  assert.deepEqual(errors, []);
});

test('a link asking for 2048³ with LOD on SwiftShader asks first, and the page stays responsive', async () => {
  const { page, errors } = await open('?lod=on&res=2048');
  await page.waitForSelector('#confirm:not([hidden])', { timeout: 30_000 });
  assert.match(await page.textContent('#confirm-text'), /^2048³ with LOD × 5 spheres: about \d+(\.\d)? s per frame/);
  assert.equal(await page.$eval('metaballs-view', (e) => e.resolution), 64);
  assert.ok(await settledTriangles(page) > 0, 'the figure draws the kept settings meanwhile');
  const started = Date.now();
  await page.locator('#confirm-keep').click({ timeout: 1000 });
  assert.ok(Date.now() - started < 1000, `the click took ${Date.now() - started} ms`);
  assert.equal(await page.$eval('metaballs-view', (e) => e.resolution), 64);
  assert.deepEqual(errors, []);
});

const setBudget = (page, ms) => page.evaluate((b) => { customElements.get('metaballs-view').frameBudget = b; }, ms);

/** The render scale and the LOD cell size in effect, and what the HUD says of the cells. */
const detail = (page) => page.$eval('metaballs-view', (e) => ({
  scale: e.renderScale,
  cell: e.stats.lod?.cellPixels ?? null,
  triangles: e.stats.triangles,
  hud: e.shadowRoot.getElementById('hud-lod-cell-text').textContent,
}));

/** Waits until `test`, a condition on `d` (detail's fields), holds. */
const waitForDetail = (page, test, timeout = 60_000) => page.waitForFunction((t) => {
  const e = document.querySelector('metaballs-view');
  const d = { scale: e.renderScale, cell: e.stats.lod?.cellPixels ?? null };
  return new Function('d', `return ${t}`)(d);
}, test, { timeout, polling: 100 });

test('slow frames make LOD cells larger once the render scale is at its floor, up to max-lod-pixels, and fast ones small again', async () => {
  const { page, errors } = await open('?lod=on&res=256&dist=2&hud=on&aa=0&max_lod_px=8', { viewport: { width: 480, height: 320 } });
  await page.waitForFunction(() => document.querySelector('metaballs-view').stats?.lod?.levels.length > 0, null, { timeout: 30_000 });
  // The scale and the cells in effect every tenth of a second, to check the order they change in.
  await page.evaluate(() => {
    const e = document.querySelector('metaballs-view');
    window.seen = [];
    setInterval(() => window.seen.push([e.renderScale, e.stats.lod?.cellPixels]), 100);
  });
  const seen = () => page.evaluate(() => window.seen.splice(0));
  // Under a budget no frame misses, cells of lod-pixels (2) at full scale.
  await setBudget(page, 10_000);
  await waitForDetail(page, 'd.scale === 1 && d.cell === 2');
  await page.waitForTimeout(1200);
  const fine = await detail(page);
  assert.equal(fine.hud, '≤ 2 px (2–8)');

  await seen();
  await setBudget(page, 0.5);
  let started = Date.now();
  await waitForDetail(page, 'd.scale === 0.5 && d.cell === 8');
  await page.waitForTimeout(1200);
  const coarse = await detail(page);
  console.log(`over budget: scale 0.5 and cells of 8 px after ${Date.now() - started} ms; `
    + `${fine.triangles} triangles at 2 px and full scale, ${coarse.triangles} now; HUD "${coarse.hud}"`);
  assert.equal(coarse.hud, '≤ 8 px (2–8)');
  assert.ok(coarse.triangles * 8 < fine.triangles, `${coarse.triangles} triangles against ${fine.triangles}`);
  // Held there: the limit holds however slow the frames.
  await page.waitForTimeout(2000);
  const held = await detail(page);
  assert.deepEqual([held.scale, held.cell], [0.5, 8]);
  // The cells grew only once the scale was at its floor.
  const falling = await seen();
  assert.deepEqual(falling.filter(([scale, cell]) => cell > 2 && scale !== 0.5), [], 'cells grew before the scale was at its floor');

  // Paused, the figure draws cells of lod-pixels at full scale; playing again, it goes back to its cells.
  await page.$eval('metaballs-view', (e) => e.pause());
  await waitForDetail(page, 'd.scale === 1 && d.cell === 2', 10_000);
  await page.$eval('metaballs-view', (e) => e.play());
  await waitForDetail(page, 'd.scale === 0.5 && d.cell === 8', 10_000);

  // A lower limit holds at once.
  await page.$eval('metaballs-view', (e) => e.setAttribute('max-lod-pixels', '4'));
  await waitForDetail(page, 'd.cell === 4', 10_000);
  await page.waitForTimeout(1500);
  assert.equal((await detail(page)).cell, 4);
  assert.equal((await detail(page)).hud, '≤ 4 px (2–4)');

  await seen();
  await setBudget(page, 10_000);
  started = Date.now();
  await waitForDetail(page, 'd.scale === 1 && d.cell === 2');
  console.log(`under budget: cells of 2 px and scale 1 after ${Date.now() - started} ms`);
  // The cells were small again before the scale rose.
  const rising = await seen();
  assert.deepEqual(rising.filter(([scale, cell]) => cell > 2 && scale !== 0.5), [], 'the scale rose before the cells were small');
  assert.ok(rising.some(([scale, cell]) => scale === 0.5 && cell === 2), 'the cells were given back first');
  await setBudget(page, 0);
  assert.deepEqual(errors, []);
});

test('a 2048³ LOD figure zoomed in (fov 15) at 960×640 settles at 10 frames a second or more', async () => {
  const { page, errors } = await open('?lod=on&res=2048&fov=15');
  await page.waitForSelector('#confirm:not([hidden])', { timeout: 30_000 });
  await page.locator('#confirm-apply').click();
  await page.waitForFunction(() => document.querySelector('metaballs-view').stats?.lod?.resolution === 2048,
    null, { timeout: 60_000 });
  const started = Date.now();
  // Settled: the scale and the cells unchanged for three seconds.
  let last = '';
  let since = Date.now();
  while (Date.now() - since < 3000) {
    assert.ok(Date.now() - started < 90_000, `still changing after 90 s: ${last}`);
    await page.waitForTimeout(250);
    const now = JSON.stringify(await page.$eval('metaballs-view', (e) => [e.renderScale, e.stats.lod.cellPixels]));
    if (now !== last) [last, since] = [now, Date.now()];
  }
  const settledMs = since - started;
  const fps = await page.$eval('metaballs-view', async (e) => {
    const [frames, t0] = [e.framesDrawn, performance.now()];
    await new Promise((r) => setTimeout(r, 5000));
    return ((e.framesDrawn - frames) * 1000) / (performance.now() - t0);
  });
  const d = await detail(page);
  console.log(`2048³ LOD, fov 15, 960×640: ${fps.toFixed(1)} fps over 5 s, settled ${settledMs} ms after the first `
    + `2048³ frame's figures, at render scale ${d.scale} with cells of ${d.cell} px, ${d.triangles} triangles`);
  assert.ok(fps >= 10, `${fps.toFixed(1)} frames a second`);
  assert.deepEqual(errors, []);
});
