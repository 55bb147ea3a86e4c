// End-to-end tests of level of detail in headless Chromium (SwiftShader): a LOD figure draws with the
// HUD's effective resolution and counts per level, coloured by level, on the CPU and GPU paths alike; a
// frozen selection stays while the camera moves; and a 2048³ link asks first instead of freezing the
// page.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useServerAndBrowser, openClosedAfterEach, settledTriangles, frameDrawn } from './helpers.js';

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
  const { page, errors } = await open('?lod=on&res=256&lod_px=8&dist=2&color_by=level&hud=on&paused=1&aa=0');
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
  assert.equal(gpuTriangles, cpuTriangles, 'the GPU and CPU LOD meshes have as many triangles');
  assert.match(await page.textContent('#hud-lod-summary'), /^256³ effective/);
  assert.deepEqual(errors, []);
});

test('a frozen selection stays while the camera orbits away, and follows it again when thawed', async () => {
  const { page, errors } = await open('?lod=on&res=256&lod_px=8&dist=2&hud=on&paused=1&aa=0');
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
