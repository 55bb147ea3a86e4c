// The notebook widget's front end under a host of its own that follows the anywidget contract (no kernel,
// the wasm beside the module, as on MyST's static pages): Python's side is played by the page, which
// sets traits through the model and reads back what the figure reports. The module is the one
// python/build.sh bundles into python/src/metaballs_widget/static/ (built here when missing or older than
// its sources).

import { before, test } from 'node:test';
import assert from 'node:assert/strict';
import { browser, baseUrl, builtBy, differingFraction, frameDrawn, useServerAndBrowser } from './helpers.js';

before(() => builtBy('python/build.sh', 'python/src/metaballs_widget/static/widget.js'));
useServerAndBrowser();

const ESM = '/python/src/metaballs_widget/static/widget.js';

async function host(props, { initScript, esm = ESM } = {}) {
  const page = await browser.newPage({ viewport: { width: 960, height: 640 } });
  if (initScript) await page.addInitScript(initScript);
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  const query = new URLSearchParams({ esm, props: JSON.stringify(props) });
  await page.goto(`${baseUrl}tests/e2e/fixtures/widget-host.html?${query}`);
  return { page, errors };
}

const triangles = (page, other = -1) => page.waitForFunction(
  (o) => window.host?.get('triangles') > 0 && window.host.get('triangles') !== o && window.host.get('triangles'),
  other, { timeout: 60_000 }).then((h) => h.jsonValue());

test('under a plain anywidget host the figure draws, follows its traits and reports back', async () => {
  const { page, errors } = await host({ spheres: 2, iso: 1, resolution: 32, paused: true, hud: 'on' });
  const figure = page.locator('metaballs-view');
  // The figure reads its attributes once its WebAssembly is there: by its first frame.
  const before = await triangles(page);
  assert.equal(await figure.evaluate((e) => [e.spheres, e.resolution, e.paused].join()), '2,32,true');
  assert.match(await page.evaluate(() => window.host.get('adapter')), /WebGPU|WebGL2/);
  assert.equal(await page.evaluate(() => window.host.get('sphere_list').length), 2);
  assert.ok(!(await figure.getAttribute('balls')), 'reporting the spheres placed them by hand');
  assert.ok(!(await figure.getAttribute('sphere-list')), 'reporting the spheres placed them by hand');
  const shot = await figure.screenshot();

  // Python sets iso: the figure takes it, draws a different surface and reports a new count.
  await page.evaluate(() => window.host.set('iso', 0.5));
  assert.equal(await figure.evaluate((e) => e.iso), 0.5);
  const after = await triangles(page, before);
  assert.notEqual(after, before);
  await frameDrawn(page);
  const changed = await differingFraction(page, shot, await figure.screenshot());
  assert.ok(changed > 0.01, `iso 1 → 0.5 changed ${(changed * 100).toFixed(2)}% of the pixels`);

  // A control moved in the figure reaches the model.
  const saves = await page.evaluate(() => window.host.saves());
  await figure.evaluate((e) => { e.iso = 0.8; });
  await page.waitForFunction(() => window.host.get('iso') === 0.8);
  assert.ok(await page.evaluate(() => window.host.saves()) > saves, 'the change was not saved to the model');

  // Spheres placed from Python.
  await page.evaluate(() => window.host.set('sphere_list', [
    { center: [-0.3, 0, 0], radius: 0.35 }, { center: [0.3, 0, 0], radius: 0.35 }, { center: [0, 0.5, 0], radius: 0.2 }]));
  await page.waitForFunction(() => document.querySelector('metaballs-view').sphereList.length === 3);
  assert.deepEqual(await figure.evaluate((e) => e.sphereList[2].center), [0, 0.5, 0]);

  // The critical points, from the module beside the widget's (its own small WebAssembly): the three
  // spheres placed from Python join at two saddles.
  const found = await figure.evaluate((e) => e.criticalPoints());
  assert.equal(found.points.filter((p) => p.role === 'join').length, 2, JSON.stringify(found.points));
  assert.equal(found.complete, true);

  // A bad value from the model: the figure keeps its value and says why.
  await page.evaluate(() => window.host.set('display', 'sketch'));
  assert.equal(await figure.evaluate((e) => e.display), 'shaded');
  assert.equal(await page.evaluate(() => window.host.get('display')), 'shaded', 'the model kept the refused value');
  // Slices are checked by the figure alone: a refused one goes back to the slice it keeps.
  await page.evaluate(() => window.host.set('slice', 'z:0.25'));
  assert.equal(await figure.evaluate((e) => e.slice), 'z:0.25');
  await page.evaluate(() => window.host.set('slice', 'y:1.5'));
  assert.equal(await figure.evaluate((e) => e.slice), 'z:0.25');
  assert.equal(await page.evaluate(() => window.host.get('slice')), 'z:0.25');

  // The cleanup lets go of the figure, its renderer and the model's listeners.
  await page.evaluate(() => window.host.cleanup());
  assert.equal(await page.evaluate(() => document.querySelectorAll('metaballs-view').length), 0);
  assert.equal(await page.evaluate(() => window.host.listeners()), 1, "only the model's own listener for questions stays");
  await page.evaluate(() => window.host.close());
  assert.equal(await page.evaluate(() => window.host.listeners()), 0);
  await page.waitForFunction(() => customElements.get('metaballs-view').liveRenderers === 0);
  assert.deepEqual(errors.filter((e) => !/display/.test(e)), []);
  await page.close();
});

test('in the widget as on a page: WebGL2 without WebGPU (its wasm beside the module), and a lost device draws again', async () => {
  // No WebGPU: the WebGL2 build, fetched from beside the module, meshing on the CPU.
  const noWebGpu = await host({ spheres: 2, resolution: 32, paused: true }, { initScript: () => { delete Navigator.prototype.gpu; } });
  assert.ok(await triangles(noWebGpu.page) > 0);
  const wasm = await noWebGpu.page.evaluate(() => performance.getEntriesByType('resource')
    .map((e) => new URL(e.name).pathname).filter((p) => p.endsWith('.wasm')));
  assert.deepEqual(wasm, ['/python/src/metaballs_widget/static/pkg-webgl/metaballs_bg.wasm']);
  assert.match(await noWebGpu.page.evaluate(() => window.host.get('adapter')), /^WebGL2/);
  assert.deepEqual(noWebGpu.errors, []);
  await noWebGpu.page.close();

  // WebGPU, then the device is lost: the figure draws again on a new one with the model's settings.
  // Its props hold a slice the figure refuses when its WebAssembly arrives: the model gets the figure's.
  const { page, errors } = await host({ spheres: 2, iso: 0.8, resolution: 32, paused: true, slice: 'y:1.5' });
  await triangles(page);
  await page.waitForFunction(() => window.host.get('slice') === 'off');
  const drawn = await page.evaluate(() => document.querySelector('metaballs-view').framesDrawn);
  await page.evaluate(() => customElements.get('metaballs-view').destroyDevice());
  await page.waitForFunction(() => customElements.get('metaballs-view').devicesCreated >= 2, null, { timeout: 30_000 });
  await page.evaluate(() => window.host.set('spheres', 3));
  await page.waitForFunction((n) => {
    const figure = document.querySelector('metaballs-view');
    return figure.framesDrawn > n && figure.stats.triangles > 0 && figure.sphereList.length === 3;
  }, drawn, { timeout: 30_000 });
  assert.equal(await page.evaluate(() => document.querySelector('metaballs-view').iso), 0.8);
  assert.deepEqual(errors.filter((e) => !/lost|destroyed|slice/i.test(e)), []);
  await page.close();
});

test('the 2D widget: its figure draws from the traits, follows them, and its panel and edits reach the model', async () => {
  const props = { circles: '0.3,0.1,0.35;-0.35,-0.2,0.3', saddle: 'decider', resolution: 12, iso: 1, controls: 'all', show: 'grid,corners,contour' };
  const { page, errors } = await host(props, { esm: '/python/src/metaballs_widget/static/widget-2d.js' });
  const figure = page.locator('metaballs-2d');
  await page.waitForFunction(() => document.querySelector('metaballs-2d')?.frameMs > 0);
  assert.deepEqual(await figure.evaluate((e) => [e.contours().cells, e.circleList.length, e.getAttribute('saddle')]), [12, 2, 'decider']);
  const shot = await figure.locator('canvas').screenshot();
  // Python sets a trait: the figure draws it.
  await page.evaluate(() => window.host.set('iso', 1.6));
  await page.waitForFunction(() => document.querySelector('metaballs-2d').contours().iso === 1.6);
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
  assert.ok(await differingFraction(page, shot, await figure.locator('canvas').screenshot()) > 0.002, 'iso 1 → 1.6 changes the picture');
  // The figure's panel and a circle added by hand reach the model.
  await figure.locator('summary').click();
  await figure.locator('#control-saddle').selectOption('center');
  await page.waitForFunction(() => window.host.get('saddle') === 'center');
  const box = await figure.locator('canvas').boundingBox();
  await page.mouse.dblclick(box.x + box.width * 0.8, box.y + box.height * 0.2);
  await page.waitForFunction(() => window.host.get('circles').split(';').length === 3);
  await page.evaluate(() => window.host.cleanup());
  assert.equal(await page.evaluate(() => document.querySelectorAll('metaballs-2d').length), 0);
  assert.equal(await page.evaluate(() => window.host.listeners()), 0);
  assert.deepEqual(errors, []);
});
