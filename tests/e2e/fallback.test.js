// End-to-end tests of the paths for browsers without WebGPU or with a slow software adapter: WebGL2
// with CPU meshing (navigator.gpu removed, or Chromium started without WebGPU), the message when
// neither API exists, several WebGL2 figures on one page, `auto` choosing the CPU mesher on SwiftShader,
// and a link that asks for frames too slow to draw without confirmation.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { chromium } from 'playwright-core';
import {
  useServerAndBrowser, openClosedAfterEach, CHROMIUM, FLAGS, differingFraction, pixelStats, settledTriangles,
  openPanelGroups, frameDrawn,
} from './helpers.js';

useServerAndBrowser();

const NO_WEBGPU = () => { delete Navigator.prototype.gpu; };
const NO_WEBGL2 = () => {
  const getContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function (kind, ...rest) {
    return kind === 'webgl2' ? null : getContext.call(this, kind, ...rest);
  };
};

const open = openClosedAfterEach();

const canvasShot = (page) => page.locator('metaballs-view').locator('#view').screenshot();

async function setAndSettle(page, name, value) {
  await page.$eval('metaballs-view', (element, [n, v]) => element.setAttribute(n, v), [name, value]);
  await frameDrawn(page);
}

test('without navigator.gpu the page draws with WebGL2 and CPU meshing, and its controls change the picture', async () => {
  const { page, errors } = await open('?paused=1&res=32', { initScript: [NO_WEBGPU] });
  const triangles = await settledTriangles(page);
  assert.ok(triangles > 500, `${triangles} triangles`);
  assert.match(await page.textContent('#adapter'), /^WebGL2 · CPU meshing$/);
  let before = await canvasShot(page);
  const { surface } = await pixelStats(page, before);
  assert.ok(surface > 0.03, `the surface covers ${(100 * surface).toFixed(1)} % of the canvas`);

  const changes = [
    ['spheres', '9'], ['iso', '0.7'], ['resolution', '40'], ['interpolation', 'midpoint'], ['blend', 'max'],
    ['color', '#3080e0'], ['shininess', '8'], ['ambient', '0.6'], ['specular', '1.8'], ['light', 'point,directional'],
    ['fov', '80'], ['yaw', '40'], ['distance', '5'], ['projection', 'orthographic'], ['seed', '9'],
  ];
  for (const [name, value] of changes) {
    await setAndSettle(page, name, value);
    const after = await canvasShot(page);
    const changed = await differingFraction(page, before, after);
    console.log(`WebGL2: ${name}=${value} changed ${(100 * changed).toFixed(2)} % of the pixels`);
    assert.ok(changed > 0.001, `${name}=${value} changed only ${(100 * changed).toFixed(3)} % of the pixels`);
    before = after;
  }
  // What needs compute shaders is shown, disabled, saying why.
  await openPanelGroups(page);
  for (const id of ['display', 'grid', 'color_by', 'mesher']) {
    assert.equal(await page.locator(`#${id}`).isDisabled(), true, `${id} should be disabled`);
    const title = await page.locator(`#${id}`).evaluate((input) => input.closest('.control').title);
    assert.match(title, /Needs WebGPU/);
  }
  assert.equal(await page.locator('#iso').isDisabled(), false);
  assert.deepEqual(errors, []);
});

test('Chromium started without WebGPU falls back to WebGL2', async () => {
  const plain = await chromium.launch({
    executablePath: CHROMIUM, args: FLAGS.filter((f) => f !== '--enable-unsafe-webgpu'), headless: true,
  });
  try {
    const { page, errors } = await open('?paused=1&res=24', { on: plain });
    assert.ok(await settledTriangles(page) > 100);
    assert.match(await page.textContent('#adapter'), /WebGL2/);
    assert.deepEqual(errors, []);
  } finally {
    await plain.close();
  }
});

test('with neither WebGPU nor WebGL2 the figure says so', async () => {
  const { page } = await open('', { initScript: [NO_WEBGPU, NO_WEBGL2] });
  await page.waitForSelector('#message:not([hidden])', { timeout: 30_000 });
  assert.match(await page.textContent('#message-title'), /Neither WebGPU nor WebGL2/);
  assert.match(await page.textContent('#message-text'), /Chrome|Firefox|Safari/);
});

test('WebGL2 figures beyond the page\'s share wait, say why, and start when one leaves', async () => {
  const { page, errors } = await open(`tests/e2e/fixtures/many.html?n=10`, { initScript: [NO_WEBGPU] });
  const census = () => page.$$eval('metaballs-view', (elements) => elements.map((e) => {
    const $ = (id) => e.shadowRoot.getElementById(id);
    return { drawing: Number($('triangles').textContent.replace(/,/g, '')) > 0, waiting: !$('message').hidden };
  }));
  await page.waitForFunction(() => [...document.querySelectorAll('metaballs-view')].filter(
    (e) => Number(e.shadowRoot?.getElementById('triangles').textContent.replace(/,/g, '')) > 0).length === 8,
  null, { timeout: 60_000 });
  let figures = await census();
  assert.equal(figures.filter((f) => f.drawing).length, 8);
  assert.equal(figures.filter((f) => f.waiting).length, 2);
  const waitingText = await page.$$eval('metaballs-view', (elements) => elements
    .map((e) => e.shadowRoot.getElementById('message'))
    .filter((m) => !m.hidden)[0].textContent);
  assert.match(waitingText, /WebGL2.*8 figures are drawing already/s);
  // Remove a drawing figure: a waiting one takes its place.
  await page.$eval('metaballs-view', (first) => first.remove());
  await page.waitForFunction(() => [...document.querySelectorAll('metaballs-view')].filter(
    (e) => !e.shadowRoot?.getElementById('message').hidden).length === 1, null, { timeout: 30_000 });
  await page.waitForFunction(() => [...document.querySelectorAll('metaballs-view')].filter(
    (e) => Number(e.shadowRoot?.getElementById('triangles').textContent.replace(/,/g, '')) > 0).length === 8,
  null, { timeout: 30_000 });
  figures = await census();
  assert.equal(figures.length, 9);
  assert.deepEqual(errors, []);
});

test('on SwiftShader auto meshes on the CPU, and mesher=gpu still draws the same surface', async () => {
  const { page, errors } = await open('?paused=1&res=32&aa=0');
  const cpuTriangles = await settledTriangles(page);
  assert.match(await page.textContent('#adapter'), /swiftshader · CPU meshing$/i);
  const cpu = await canvasShot(page);
  await setAndSettle(page, 'mesher', 'gpu');
  await page.waitForFunction(() => /GPU meshing$/.test(
    document.querySelector('metaballs-view').shadowRoot.getElementById('adapter').textContent));
  const gpuTriangles = await settledTriangles(page);
  const gpu = await canvasShot(page);
  assert.ok(Math.abs(gpuTriangles - cpuTriangles) <= 8, `gpu ${gpuTriangles}, cpu ${cpuTriangles} triangles`);
  const differing = await differingFraction(page, cpu, gpu);
  assert.ok(differing < 0.01, `${(100 * differing).toFixed(2)} % of the pixels differ between the meshers`);
  assert.match(new URL(page.url()).search, /mesher=gpu/);
  assert.deepEqual(errors, []);
});

test('a link asking for 512³ × 64 spheres on SwiftShader asks first and the page stays responsive', async () => {
  const { page, errors } = await open('?res=512&spheres=64');
  await page.waitForSelector('#confirm:not([hidden])', { timeout: 30_000 });
  assert.match(await page.textContent('#confirm-text'), /512³ × 64 spheres: about \d+(\.\d)? s per frame/);
  assert.match(await page.textContent('#confirm-keep'), /Keep 64³ × 64 spheres/);
  assert.equal(await page.$eval('metaballs-view', (e) => e.resolution), 64);
  assert.ok(await settledTriangles(page) > 0, 'the figure draws the kept settings meanwhile');
  // A click is handled at once: the page is not stuck in a frame.
  const started = Date.now();
  await page.locator('#pause').click({ timeout: 1000 });
  await page.waitForFunction(() => document.querySelector('metaballs-view').paused, null, { timeout: 1000 });
  assert.ok(Date.now() - started < 1000, `the click took ${Date.now() - started} ms`);
  // On a machine ten times slower than this one, the frames measured at the kept settings put
  // 256³ × 64 spheres well past a second, however fast this machine meshes.
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Emulation.setCPUThrottlingRate', { rate: 10 });
  await page.locator('#pause').click();
  const drawn = await page.$eval('metaballs-view', (e) => e.framesDrawn);
  await page.waitForFunction((n) => document.querySelector('metaballs-view').framesDrawn > n + 10, drawn,
    { timeout: 60_000 });
  // A slider asking for too much asks too (on a software adapter it stops at 256³); keeping leaves
  // everything as it was.
  await page.locator('#resolution').evaluate((input) => {
    input.value = '256';
    input.dispatchEvent(new Event('input', { bubbles: true }));
  });
  assert.match(await page.textContent('#confirm-text'), /^256³ × 64 spheres/);
  await page.locator('#confirm-keep').click();
  assert.equal(await page.locator('#confirm').isHidden(), true);
  assert.equal(await page.$eval('metaballs-view', (e) => e.resolution), 64);
  assert.equal(await page.$eval('metaballs-view', (e) => e.pendingChange), null);
  assert.doesNotMatch(new URL(page.url()).search, /res=512/);
  assert.deepEqual(errors, []);
});
