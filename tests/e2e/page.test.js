// End-to-end tests of the served page in headless Chromium with real WebGPU (SwiftShader): what a
// person sees and does. Expects pkg/ built (www/build.sh); serves the repository itself on 127.0.0.1.
// The page is one full-bleed <metaballs-view>; Playwright's selectors reach into its shadow root.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import {
  useServerAndBrowser, open, waitForTriangles, settledTriangles, frameDrawn, screenshot, pixelStats,
  differingFraction, setRange, outputDir,
} from './helpers.js';

useServerAndBrowser();

test('the page shows glossy blobs with no console errors', async () => {
  const { page, errors } = await open();
  await waitForTriangles(page);
  // The triangle count can arrive before the first frame with them is on screen (a busy machine):
  // look again, a frame later, a few times.
  let png = await screenshot(page, 'default');
  let stats = await pixelStats(page, png);
  for (let i = 0; i < 8 && stats.surface <= 0.01; i++) {
    await frameDrawn(page);
    png = await screenshot(page, 'default');
    stats = await pixelStats(page, png);
  }
  assert.ok(stats.surface > 0.01, `surface covers ${(stats.surface * 100).toFixed(2)}% of the canvas`);
  assert.ok(stats.highlight > 0, 'no specular highlight visible');
  assert.match(await page.textContent('#adapter'), /WebGPU/);
  // SwiftShader is a software adapter: the page starts without multisampling there.
  assert.equal(await page.isChecked('#antialiasing'), false);
  // The frame rate shows once a half second has had a frame drawn in it ('–' before, on a busy machine).
  await page.waitForFunction(() => /^\d+(\.\d)?$/.test(document.querySelector('metaballs-view').shadowRoot
    .getElementById('fps').textContent), null, { timeout: 15000 }).catch(() => {});
  assert.match(await page.textContent('#fps'), /^\d+(\.\d)?$/);
  assert.equal(await page.isVisible('#message'), false);
  // At its render scale, which falls below 1 while this software renderer's frames are slow.
  const [width, height, ratio, scale] = await page.$eval('metaballs-view', (e) => {
    const c = e.shadowRoot.getElementById('view');
    return [c.width, c.height, devicePixelRatio, e.renderScale];
  });
  assert.ok(scale >= 0.5 && scale <= 1, `render scale ${scale}`);
  assert.deepEqual([width, height, ratio], [Math.round(960 * scale), Math.round(640 * scale), 1],
    'the canvas fills the page in device pixels at its render scale');
  assert.deepEqual(errors, []);
  await page.close();
});

test('each control changes the picture and the triangle count', async () => {
  const { page, errors } = await open('?paused=1&seed=3');
  let triangles = await settledTriangles(page);
  let before = await screenshot(page, 'controls-start');
  for (const [id, value] of [['spheres', 12], ['iso', 0.6], ['resolution', 24]]) {
    await setRange(page, id, value);
    const now = await waitForTriangles(page, triangles);
    const after = await screenshot(page, `controls-${id}`);
    const changed = await differingFraction(page, before, after);
    assert.ok(changed > 0.002, `${id}: only ${(changed * 100).toFixed(3)}% of pixels changed`);
    assert.notEqual(now, triangles, `${id}: the triangle count did not change`);
    console.log(`${id} → ${value}: ${triangles} → ${now} triangles, ${(changed * 100).toFixed(1)}% of pixels changed`);
    triangles = await settledTriangles(page);
    // The buffers have grown to the surface: no lasting overflow warning, two frames later.
    await frameDrawn(page);
    await frameDrawn(page);
    assert.equal(await page.isVisible('#overflow'), false, `${id}: overflow warning still shown`);
    before = after;
  }
  // Keyboard: arrow keys move a focused slider.
  await page.focus('#spheres');
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => window.metaballs.element.spheres === 13);
  assert.equal(await page.textContent('#spheres-value'), '13');
  assert.deepEqual(errors, []);
  await page.close();
});

test('the URL keeps the state and restores it', async () => {
  const query = '?spheres=9&iso=0.8&res=40&seed=7&paused=1&yaw=-40&pitch=10&dist=5&speed=0.5&aa=1';
  const { page, errors } = await open(query);
  await waitForTriangles(page);
  const app = await page.evaluate(() => {
    const { element: e } = window.metaballs;
    return {
      spheres: e.spheres, iso: e.iso, res: e.resolution, seed: e.seed,
      state: { yaw: e.yaw, pitch: e.pitch, dist: e.distance, speed: e.speed, paused: e.paused },
    };
  });
  assert.equal(app.spheres, 9);
  assert.ok(Math.abs(app.iso - 0.8) < 1e-6);
  assert.equal(app.res, 40);
  assert.equal(app.seed, 7);
  assert.deepEqual([app.state.yaw, app.state.pitch, app.state.dist, app.state.speed, app.state.paused], [-40, 10, 5, 0.5, true]);
  assert.equal(await page.inputValue('#spheres'), '9');
  assert.equal(await page.textContent('#resolution-value'), '40³');
  assert.equal(await page.textContent('#pause'), 'Play');
  assert.equal(await page.isChecked('#antialiasing'), true);
  // A change is written back to the URL.
  await setRange(page, 'spheres', 11);
  await page.waitForFunction(() => new URLSearchParams(location.search).get('spheres') === '11');
  assert.equal(await page.isVisible('#notice'), false);
  assert.deepEqual(errors, []);
  await page.close();
});

test('bad values in the URL fall back to defaults with a visible notice', async () => {
  const { page, errors } = await open('?spheres=500&iso=abc&res=3&pitch=95&color=red');
  await waitForTriangles(page);
  await page.waitForSelector('#notice', { state: 'visible' });
  const notice = await page.textContent('#notice');
  for (const fragment of ['iso=abc', 'sphere count must be between 1 and 64, got 500', 'resolution (cells per axis) must be between 8', 'camera pitch', 'color=red']) {
    assert.ok(notice.includes(fragment), `notice ${JSON.stringify(notice)} should mention ${fragment}`);
  }
  const state = await page.evaluate(() => {
    const { element: e } = window.metaballs;
    return [e.spheres, e.iso, e.resolution];
  });
  assert.deepEqual(state, [5, 1, 64]);
  const stats = await pixelStats(page, await screenshot(page, 'bad-url'));
  assert.ok(stats.surface > 0.01, 'the page still draws');
  assert.deepEqual(errors, []);
  await page.close();
});

test('the camera follows drag, wheel, keys and double-click', async () => {
  const { page, errors } = await open('?paused=1');
  await waitForTriangles(page);
  const camera = () => page.evaluate(() => {
    const { yaw, pitch, distance } = window.metaballs.element;
    return { yaw, pitch, dist: distance };
  });
  const start = await camera();
  await page.mouse.move(480, 320);
  await page.mouse.down();
  await page.mouse.move(380, 280, { steps: 5 });
  await page.mouse.up();
  const dragged = await camera();
  assert.ok(Math.abs(dragged.yaw - start.yaw - 30) < 1e-6, `yaw ${start.yaw} → ${dragged.yaw}`);
  assert.ok(Math.abs(dragged.pitch - start.pitch + 12) < 1e-6, `pitch ${start.pitch} → ${dragged.pitch}`);
  await page.mouse.wheel(0, 400);
  await page.waitForFunction((d) => window.metaballs.element.distance > d, start.dist);
  await page.focus('#view');
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('+');
  const keyed = await camera();
  assert.ok(Math.abs(keyed.yaw - dragged.yaw + 5) < 1e-6);
  await page.mouse.dblclick(480, 320);
  assert.deepEqual(await camera(), start);
  assert.deepEqual(errors, []);
  await page.close();
});

test('without WebGPU, or with no adapter, the page draws with WebGL2 (neither: see fallback.test.js)', async () => {
  const cases = [
    ['no-webgpu', () => { delete Navigator.prototype.gpu; }],
    ['no-adapter', () => { GPU.prototype.requestAdapter = async () => null; }],
  ];
  for (const [name, initScript] of cases) {
    const { page, errors } = await open('', { initScript });
    assert.ok(await waitForTriangles(page) > 0, `${name}: triangles`);
    assert.equal(await page.textContent('#adapter'), 'WebGL2 · CPU meshing', name);
    assert.equal(await page.locator('#message').isHidden(), true, `${name}: no message`);
    await page.screenshot({ path: path.join(outputDir, `e2e-${name}.png`) });
    console.log(`screenshot: ${path.join(outputDir, `e2e-${name}.png`)}`);
    assert.deepEqual(errors, [], `${name}: no uncaught errors`);
    await page.close();
  }
});

test('the HUD reports frame rate, frame time and triangles at 32, 64 and 128 cells', async () => {
  let previous = 0;
  for (const res of [32, 64, 128]) {
    const { page, errors } = await open(`?res=${res}`);
    await waitForTriangles(page);
    // The HUD times the frames of each half second: wait until it has timed some.
    await page.waitForFunction(() => {
      const $ = (id) => document.querySelector('metaballs-view').shadowRoot.getElementById(id);
      return Number($('fps').textContent) > 0 && / ms$/.test($('frame-time').textContent);
    }, null, { timeout: 30_000 });
    const fps = Number(await page.textContent('#fps'));
    const frame = await page.textContent('#frame-time');
    const triangles = Number((await page.textContent('#triangles')).replace(/,/g, ''));
    console.log(`${res} cells, 5 spheres: ${fps} fps, ${frame} per frame, ${triangles} triangles`);
    assert.ok(fps > 0, `fps ${fps}`);
    assert.match(frame, /^\d+(\.\d)? ms$/);
    assert.ok(triangles > 2 * previous, `${triangles} triangles at ${res} cells after ${previous}`);
    previous = triangles;
    assert.deepEqual(errors, []);
    await page.close();
  }
});

test('the benchmark mode times both meshers and level of detail, shows a table, logs it as JSON and says what auto picks', async () => {
  const { page, errors } = await open('?bench&bench_resolutions=16,24&bench_spheres=1,5&bench_frames=2&bench_lod=128');
  const logged = new Promise((resolve) => {
    page.on('console', (m) => { if (m.text().startsWith('metaballs-bench ')) resolve(m.text()); });
  });
  const auto = new Promise((resolve) => {
    page.on('console', (m) => { if (m.text().startsWith('metaballs-bench-auto ')) resolve(m.text().split(' ')[1]); });
  });
  const records = JSON.parse((await logged).slice('metaballs-bench '.length));
  assert.equal(records.length, 10);
  for (const r of records) {
    for (const key of ['mesher', 'resolution', 'spheres', 'frame_ms', 'mesh_ms', 'triangles']) {
      assert.ok(key in r, `record lacks ${key}: ${JSON.stringify(r)}`);
    }
    assert.ok(r.triangles > 0 && r.frame_ms > 0 && r.mesh_ms > 0, JSON.stringify(r));
    // The CPU mesher's rows also time it alone, as the mesher worker runs it.
    if (!r.lod) assert.equal(r.mesher === 'cpu', r.alone_ms > 0, JSON.stringify(r));
  }
  assert.deepEqual(records.map((r) => [r.resolution, r.spheres, r.mesher]), [
    [16, 1, 'gpu'], [16, 1, 'cpu'], [16, 5, 'gpu'], [16, 5, 'cpu'],
    [24, 1, 'gpu'], [24, 1, 'cpu'], [24, 5, 'gpu'], [24, 5, 'cpu'],
    [128, 16, 'lod-gpu'], [128, 16, 'lod-cpu'],
  ]);
  for (const r of records.slice(8)) {
    assert.ok(r.lod && r.blocks_per_level.length >= 1 && r.blocks_per_level.some((n) => n > 0), JSON.stringify(r));
  }
  // Both meshers make the same kind of surface (the spheres move a few frames between the two rows).
  for (let i = 0; i < records.length; i += 2) {
    const [gpu, cpu] = [records[i].triangles, records[i + 1].triangles];
    assert.ok(Math.abs(gpu - cpu) <= 8 + 0.1 * cpu, `gpu ${gpu} against cpu ${cpu} triangles`);
  }
  // SwiftShader is a software adapter: auto meshes on the CPU.
  assert.equal(await auto, 'cpu');
  await page.waitForSelector('#bench table');
  assert.equal(await page.locator('#bench tbody tr').count(), 10);
  assert.match(await page.textContent('#bench'), /128 LOD/);
  assert.match(await page.textContent('#bench'), /mesher=auto uses the CPU mesher/);
  assert.match(new URL(page.url()).search, /bench/);
  assert.deepEqual(errors, []);
  await page.close();
});
