// A semester of use in headless Chromium (SwiftShader): the render scale falls while frames are over
// the page's budget and rises again when they are fast, down to `min-render-scale`, and a still figure
// draws at full scale; a figure long off screen lets go of its GPU memory and comes back with the same
// picture (or, when its spheres were set meanwhile, those); a lecture of 24 figures, scrolled through,
// holds only what the figures on screen need.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useServerAndBrowser, openClosedAfterEach, picture, differingFraction } from './helpers.js';

useServerAndBrowser();
const open = openClosedAfterEach();

const figure = (page) => page.$eval('metaballs-view', (e) => ({
  scale: e.renderScale,
  width: e.shadowRoot.getElementById('view').width,
  cssWidth: e.shadowRoot.getElementById('view').clientWidth,
  hud: e.shadowRoot.getElementById('hud-scale').textContent,
}));
const setBudget = (page, ms) => page.evaluate((b) => { customElements.get('metaballs-view').frameBudget = b; }, ms);
const waitForScale = (page, test, timeout = 30_000) => page.waitForFunction(
  (t) => new Function('s', `return ${t}`)(document.querySelector('metaballs-view').renderScale), String(test), { timeout });

test('a slow budget lowers the render scale to its floor, a fast one restores it, and a still figure draws at full scale', async () => {
  const { page, errors } = await open('tests/e2e/fixtures/grid.html?n=1&cols=1&res=32&hud=on');
  await page.waitForFunction(() => document.querySelector('metaballs-view').stats?.triangles > 0, null, { timeout: 30_000 });
  // Held under a fast budget first: on this machine the figure's own frames are over the real one.
  await setBudget(page, 10_000);
  await waitForScale(page, 's === 1');
  const full = await figure(page);
  assert.equal(full.width, full.cssWidth, 'a software renderer draws at pixel ratio 1');

  await setBudget(page, 0.5);
  let started = Date.now();
  await waitForScale(page, 's === 0.5');
  const low = await figure(page);
  console.log(`over budget: scale ${low.scale} after ${Date.now() - started} ms, canvas ${low.width} of ${low.cssWidth} px, HUD "${low.hud}"`);
  assert.equal(low.width, Math.round(low.cssWidth / 2));
  assert.match(low.hud, /^0\.50× · \d+×\d+$/);

  // Paused, the figure draws once at full scale; playing again, it goes back to its scale.
  await page.$eval('metaballs-view', (e) => e.pause());
  await page.waitForFunction(() => {
    const canvas = document.querySelector('metaballs-view').shadowRoot.getElementById('view');
    return canvas.width === canvas.clientWidth;
  });
  assert.equal((await figure(page)).scale, 1);
  await page.$eval('metaballs-view', (e) => e.play());
  assert.equal((await figure(page)).scale, 0.5);

  // A higher floor holds.
  await page.$eval('metaballs-view', (e) => e.setAttribute('min-render-scale', '0.7'));
  await waitForScale(page, 's === 0.7');
  await page.waitForTimeout(1500);
  assert.equal((await figure(page)).scale, 0.7);

  await setBudget(page, 10_000);
  started = Date.now();
  await waitForScale(page, 's === 1');
  console.log(`under budget: back to scale 1 after ${Date.now() - started} ms`);
  assert.equal((await figure(page)).width, full.width);
  await setBudget(page, 0);
  assert.deepEqual(errors, []);
});

test('a figure off screen for a while lets go of its GPU memory and, back on screen, draws the same picture', async () => {
  const { page, errors } = await open('tests/e2e/fixtures/five.html', { viewport: { width: 840, height: 600 } });
  await page.waitForFunction(() => document.getElementById('a').stats?.triangles > 0, null, { timeout: 30_000 });
  await page.$eval('#a', async (e) => { e.pause(); await e.nextFrame(); });
  const before = await picture(page, '#a');
  const bytes = await page.$eval('#a', (e) => e.gpuBytes);
  const renderers = await page.evaluate(() => customElements.get('metaballs-view').liveRenderers);
  assert.ok(bytes > 0);
  await page.evaluate(() => { customElements.get('metaballs-view').releaseAfter = 1000; });
  await page.$eval('#c', (e) => e.scrollIntoView());
  await page.waitForFunction(() => document.getElementById('a').gpuBytes === 0, null, { timeout: 10_000 });
  // Figure c has started meanwhile; a and b have let go of theirs.
  await page.waitForFunction(() => customElements.get('metaballs-view').liveRenderers === 1, null, { timeout: 10_000 });
  console.log(`off screen: figure a went from ${bytes} GPU bytes to 0; ${renderers} renderers became 1`);
  await page.evaluate(() => window.scrollTo(0, 0));
  const back = performance.now();
  await page.waitForFunction(() => document.getElementById('a').gpuBytes > 0 && document.getElementById('a').framesDrawn > 0,
    null, { timeout: 10_000 });
  await page.$eval('#a', (e) => e.nextFrame());
  console.log(`back on screen: figure a drew again within ${Math.round(performance.now() - back)} ms`);
  assert.equal(await page.$eval('#a', (e) => e.gpuBytes), bytes);
  const differing = await differingFraction(page, before, await picture(page, '#a'));
  assert.equal(differing, 0, `${(100 * differing).toFixed(3)} % of the picture changed`);
  assert.deepEqual(errors, []);
});

test('a lecture of 24 figures, scrolled through, holds no more GPU memory than the figures on screen', async () => {
  const { page, errors } = await open('tests/e2e/fixtures/lecture.html?n=24');
  await page.waitForFunction(() => [...document.querySelectorAll('metaballs-view')].some((e) => e.framesDrawn > 0),
    null, { timeout: 30_000 });
  await page.evaluate(() => { customElements.get('metaballs-view').releaseAfter = 1000; });
  // Each figure below the fold draws once while the page is idle, for print, and lets go again.
  await page.$$eval('metaballs-view', (all) => Promise.all(all.map((e) => e.printable())));
  const totals = () => page.evaluate(() => {
    const View = customElements.get('metaballs-view');
    return { bytes: View.gpuBytes, renderers: View.liveRenderers };
  });
  let most = { bytes: 0, renderers: 0 };
  let figureBytes = 0;
  for (let k = 0; k < 24; k++) {
    const drawn = await page.$$eval('metaballs-view', (all, i) => { all[i].scrollIntoView({ block: 'center' }); return all[i].framesDrawn; }, k);
    await page.waitForFunction(([i, n]) => document.querySelectorAll('metaballs-view')[i].framesDrawn > n, [k, drawn], { timeout: 30_000 });
    figureBytes = Math.max(figureBytes, await page.$$eval('metaballs-view', (all, i) => all[i].gpuBytes, k));
    await page.waitForTimeout(300);
    const now = await totals();
    most = { bytes: Math.max(most.bytes, now.bytes), renderers: Math.max(most.renderers, now.renderers) };
  }
  // Until the figures scrolled past have let go (a second after they left the screen).
  await page.waitForFunction(() => [...document.querySelectorAll('metaballs-view')].every((e) => {
    const box = e.getBoundingClientRect();
    return (box.bottom > 0 && box.top < innerHeight) || e.gpuBytes === 0;
  }), null, { timeout: 10_000 }).catch(() => {});
  // The figures and the page's totals are read in one task: an animating figure's mesh buffers change size.
  const { figures, end } = await page.evaluate(() => {
    const View = customElements.get('metaballs-view');
    const all = [...document.querySelectorAll('metaballs-view')].map((e, i) => {
      const box = e.getBoundingClientRect();
      return { i, bytes: e.gpuBytes, visible: box.bottom > 0 && box.top < innerHeight };
    });
    return { figures: all, end: { bytes: View.gpuBytes, renderers: View.liveRenderers } };
  });
  const visible = figures.filter((f) => f.visible);
  console.log(`24 figures scrolled through: at most ${most.renderers} renderers and ${(most.bytes / 1e6).toFixed(2)} MB at once `
    + `(one figure: ${(figureBytes / 1e6).toFixed(2)} MB); at the end ${visible.length} on screen, ${end.renderers} renderers, `
    + `${(end.bytes / 1e6).toFixed(2)} MB`);
  assert.ok(visible.length >= 1 && visible.length <= 2);
  assert.deepEqual(figures.filter((f) => !f.visible && f.bytes > 0).map((f) => f.i), [], 'figures off screen hold GPU memory');
  assert.equal(end.renderers, visible.length);
  assert.equal(end.bytes, visible.reduce((sum, f) => sum + f.bytes, 0));
  assert.ok(end.bytes <= visible.length * figureBytes);
  // While scrolling, only the figures seen within the last second keep theirs.
  assert.ok(most.renderers <= 8, `${most.renderers} renderers alive at once`);
  assert.deepEqual(errors, []);
});

test('spheres set by attribute while a figure is let go are the ones it draws when it comes back', async () => {
  const { page, errors } = await open('tests/e2e/fixtures/five.html', { viewport: { width: 840, height: 600 } });
  await page.waitForFunction(() => document.getElementById('a').stats?.triangles > 0, null, { timeout: 30_000 });
  await page.evaluate(() => { customElements.get('metaballs-view').releaseAfter = 500; });
  await page.$eval('#c', (e) => e.scrollIntoView());
  await page.waitForFunction(() => document.getElementById('a').gpuBytes === 0, null, { timeout: 10_000 });
  const balls = '-0.3,0,0,0.3,0,0,0;0.35,0.1,0,0.25,0,0,0';
  await page.$eval('#a', (e, b) => { e.pause(); e.setAttribute('balls', b); }, balls);
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.waitForFunction(() => document.getElementById('a').gpuBytes > 0, null, { timeout: 10_000 });
  await page.$eval('#a', (e) => e.nextFrame());
  const list = await page.$eval('#a', (e) => e.sphereList.map((b) => [...b.center, b.radius].map((x) => Number(x.toFixed(3)))));
  assert.deepEqual(list, [[-0.3, 0, 0, 0.3], [0.35, 0.1, 0, 0.25]]);
  assert.deepEqual(errors, []);
});
