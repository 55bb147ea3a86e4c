// Hands on the scene end to end in headless Chromium (WebGPU on SwiftShader): dragging a sphere moves
// it until the surfaces merge, Shift-click adds one and Delete removes it, the wheel sets the radius,
// a long press on touch drags; the export buttons download a valid STL and PNGs; a saved scene file
// dropped on the figure restores it, and bad files are refused with a message, changing nothing. The
// page's picture of a saved scene matches the committed fixture that `metaballs render --scene` is
// compared with (tests/suite/scene_render.rs).

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import {
  useServerAndBrowser, browser, baseUrl, open, settledTriangles, frameDrawn, screenshot, differingFraction,
  openPanelGroups, root, outputDir,
} from './helpers.js';

useServerAndBrowser();

// Two spheres apart on the x axis, seen straight along z: dragging one along x brings them together.
const TWO = '?balls=-0.5,0,0,0.3;0.5,0,0,0.3&edit=1&paused=1&res=48&yaw=0&pitch=0&aa=0';

const centres = (page) => page.evaluate(() => window.metaballs.element.sphereList.map((s) => s.center));
const onScreen = (page, i) => page.evaluate((k) => window.metaballs.element.sphereOnScreen(k), i);
const notice = (page) => page.evaluate(() => {
  const box = window.metaballs.element.shadowRoot.getElementById('notice');
  return box.hidden ? '' : box.textContent;
});

// The figure's own picture (not a screenshot, which would include the notices over it).
async function picture(page) {
  return Buffer.from(await page.evaluate(async () => {
    const blob = await window.metaballs.element.picture(1);
    return [...new Uint8Array(await blob.arrayBuffer())];
  }));
}

async function drag(page, from, to, steps = 12) {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let k = 1; k <= steps; k++) {
    await page.mouse.move(from.x + ((to.x - from.x) * k) / steps, from.y + ((to.y - from.y) * k) / steps);
  }
  await page.mouse.up();
}

// Drops a file with `text` named `name` on the figure, as a person dragging it from their desktop, and
// waits for the figure's notice about it (loaded or refused, it names the file).
async function dropFile(page, name, text) {
  await page.evaluate(([fileName, content]) => {
    const transfer = new DataTransfer();
    transfer.items.add(new File([content], fileName, { type: 'application/json' }));
    const element = window.metaballs.element;
    for (const type of ['dragover', 'drop']) {
      element.dispatchEvent(new DragEvent(type, { dataTransfer: transfer, bubbles: true, cancelable: true }));
    }
  }, [name, text]);
  await page.waitForFunction((fileName) => {
    const box = window.metaballs.element.shadowRoot.getElementById('notice');
    return !box.hidden && box.textContent.includes(fileName);
  }, name);
}

test('dragging a sphere moves it until the surfaces merge; Shift-click adds one, Delete removes it', async () => {
  const { page, errors } = await open(TWO);
  const triangles = await settledTriangles(page);
  const before = await screenshot(page, 'edit-start');
  const [a, b] = [await onScreen(page, 0), await onScreen(page, 1)];
  // Hovering rings the sphere under the pointer.
  await page.mouse.move(b.x, b.y);
  await page.waitForFunction(() => !window.metaballs.element.shadowRoot.getElementById('hover-ring').hasAttribute('hidden'));

  await drag(page, b, { x: a.x + 1.2 * a.radius, y: a.y });
  const moved = await centres(page);
  assert.deepEqual(moved[0], [-0.5, 0, 0], 'the other sphere stays');
  assert.ok(moved[1][0] < 0.0 && moved[1][0] > -0.2, `dragged along x to ${moved[1]}`);
  assert.ok(Math.abs(moved[1][1]) < 0.02 && Math.abs(moved[1][2]) < 1e-4, `in the plane facing the camera: ${moved[1]}`);
  assert.equal(await page.evaluate(() => window.metaballs.element.selectedSphere), 1);
  const merged = await settledTriangles(page);
  assert.notEqual(merged, triangles, 'the triangle count changes as the surfaces merge');
  const after = await screenshot(page, 'edit-merged');
  const changed = await differingFraction(page, before, after);
  assert.ok(changed > 0.01, `only ${(changed * 100).toFixed(2)}% of pixels changed`);
  await page.waitForFunction(() => location.search.includes('balls=-0.5,0,0,0.3;'));
  console.log(`drag: ${triangles} → ${merged} triangles, ${(changed * 100).toFixed(1)}% of pixels changed`);

  // Shift-click on empty space adds a still sphere there, at the depth of the box's centre.
  await page.keyboard.down('Shift');
  await page.mouse.click(480, 150);
  await page.keyboard.up('Shift');
  let list = await page.evaluate(() => window.metaballs.element.sphereList);
  assert.equal(list.length, 3);
  assert.equal(await page.evaluate(() => window.metaballs.element.spheres), 3, 'the count follows');
  assert.ok(list[2].center[1] > 0.3 && Math.abs(list[2].center[2]) < 1e-4, `added at ${list[2].center}`);
  assert.deepEqual(list[2].velocity, [0, 0, 0]);
  assert.equal(await page.evaluate(() => window.metaballs.element.selectedSphere), 2);
  assert.match(await page.textContent('#sphere-box h3'), /Sphere 3 of 3/);

  // The wheel changes the selected sphere's radius; F lets it move and freezes it again.
  const radius = list[2].radius;
  await page.mouse.move(480, 150);
  await page.mouse.wheel(0, -300);
  list = await page.evaluate(() => window.metaballs.element.sphereList);
  assert.ok(list[2].radius > radius * 1.2, `radius ${radius} → ${list[2].radius}`);
  await page.keyboard.press('f');
  list = await page.evaluate(() => window.metaballs.element.sphereList);
  assert.ok(list[2].velocity.some((v) => v !== 0), 'let go, it moves');
  await page.click('#sphere-freeze');
  list = await page.evaluate(() => window.metaballs.element.sphereList);
  assert.deepEqual(list[2].velocity, [0, 0, 0], 'frozen');

  await page.focus('#view');
  await page.keyboard.press('Delete');
  list = await page.evaluate(() => window.metaballs.element.sphereList);
  assert.equal(list.length, 2);
  assert.equal(await page.isVisible('#sphere-box'), false);
  // Backspace removes too; the last sphere stays, with a notice.
  let at = await onScreen(page, 1);
  await page.mouse.click(at.x, at.y);
  await page.keyboard.press('Backspace');
  assert.equal((await centres(page)).length, 1);
  at = await onScreen(page, 0);
  await page.mouse.click(at.x, at.y);
  await page.keyboard.press('Backspace');
  assert.equal((await centres(page)).length, 1);
  assert.match(await notice(page), /a scene keeps at least one sphere/);
  // Dragging empty space still orbits the camera.
  const yaw = await page.evaluate(() => window.metaballs.element.yaw);
  await drag(page, { x: 400, y: 540 }, { x: 500, y: 540 });
  assert.notEqual(await page.evaluate(() => window.metaballs.element.yaw), yaw);
  assert.deepEqual(errors, []);
  await page.close();
});

test('on touch, a long press drags a sphere or adds one, and a tap selects', async () => {
  const context = await browser.newContext({ viewport: { width: 960, height: 640 }, hasTouch: true });
  const page = await context.newPage();
  await page.goto(`${baseUrl}${TWO}`);
  await settledTriangles(page);
  const b = await onScreen(page, 1);
  const cdp = await context.newCDPSession(page);
  const touch = (type, x, y) => cdp.send('Input.dispatchTouchEvent', {
    type, touchPoints: type === 'touchEnd' ? [] : [{ x, y, id: 1 }],
  });
  // The figure focused first, so touch drags it rather than scrolling the page.
  await page.focus('#view');
  await touch('touchStart', b.x, b.y);
  await page.waitForTimeout(700);
  for (let k = 1; k <= 8; k++) await touch('touchMove', b.x, b.y + 10 * k);
  await touch('touchEnd');
  const moved = await centres(page);
  assert.ok(moved[1][1] < -0.1, `the long-pressed sphere moved down: ${moved[1]}`);
  assert.deepEqual(moved[0], [-0.5, 0, 0]);
  // A long press on empty space adds a sphere there; a tap on a sphere selects it.
  await touch('touchStart', 480, 120);
  await page.waitForTimeout(700);
  await touch('touchEnd');
  const list = await page.evaluate(() => window.metaballs.element.sphereList);
  assert.equal(list.length, 3);
  assert.ok(list[2].center[1] > 0.3, `added under the finger: ${list[2].center}`);
  const a = await onScreen(page, 0);
  await touch('touchStart', a.x, a.y);
  await touch('touchEnd');
  // The tap is taken in the figure's next frame.
  await page.waitForFunction(() => window.metaballs.element.selectedSphere === 0, null, { timeout: 5000 }).catch(() => {});
  assert.equal(await page.evaluate(() => window.metaballs.element.selectedSphere), 0);
  await context.close();
});

test('the export buttons download a valid STL and PNGs of the view', async () => {
  const page = await browser.newPage({ viewport: { width: 960, height: 640 }, acceptDownloads: true });
  await page.goto(`${baseUrl}${TWO}`);
  const triangles = await settledTriangles(page);
  await openPanelGroups(page);
  const timings = [];
  await page.exposeFunction('recordExport', (detail) => timings.push(detail));
  await page.evaluate(() => window.metaballs.element.addEventListener('metaballs-export', (e) => window.recordExport(e.detail)));
  const [stl] = await Promise.all([page.waitForEvent('download'), page.click('#export-stl')]);
  assert.equal(stl.suggestedFilename(), 'metaballs.stl');
  const bytes = readFileSync(await stl.path());
  const count = bytes.readUInt32LE(80);
  assert.equal(bytes.length, 84 + 50 * count, 'a binary STL: 84 bytes of header and count, 50 per facet');
  assert.equal(count, triangles, 'the frame drawn');
  // Every facet's corners are in millimetres inside the 50 mm box, and its normal is a unit vector.
  for (let f = 0; f < count; f++) {
    const at = 84 + 50 * f;
    const n = [0, 1, 2].map((k) => bytes.readFloatLE(at + 4 * k));
    const length = Math.hypot(...n);
    assert.ok(length === 0 || Math.abs(length - 1) < 1e-4, `facet ${f} normal ${n}`);
    for (let k = 3; k < 12; k++) assert.ok(Math.abs(bytes.readFloatLE(at + 4 * k)) <= 25, `facet ${f}`);
  }
  const [obj] = await Promise.all([page.waitForEvent('download'), page.click('#export-obj')]);
  const text = readFileSync(await obj.path(), 'utf8');
  assert.equal(text.split('\n').filter((l) => l.startsWith('f ')).length, triangles);
  assert.ok(text.includes('\nvn '), 'OBJ with normals');
  const [ply] = await Promise.all([page.waitForEvent('download'), page.click('#export-ply')]);
  assert.ok(readFileSync(await ply.path()).subarray(0, 40).toString().startsWith('ply\nformat binary_little_endian'));
  assert.equal(timings.length, 3);
  console.log(`export in the browser: ${timings.map((t) => `${t.format} ${t.bytes} bytes in ${t.ms.toFixed(0)} ms`).join(', ')}`);

  for (const [id, scale] of [['#picture', 1], ['#picture-2x', 2]]) {
    const [png] = await Promise.all([page.waitForEvent('download'), page.click(id)]);
    const file = readFileSync(await png.path());
    assert.equal(file.subarray(1, 4).toString(), 'PNG');
    assert.deepEqual([file.readUInt32BE(16), file.readUInt32BE(20)], [960 * scale, 640 * scale], `${id} size`);
  }
  await page.close();
});

test('a saved scene dropped on the figure restores it; bad files are refused and change nothing', async () => {
  const page = await browser.newPage({ viewport: { width: 960, height: 640 }, acceptDownloads: true });
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`${baseUrl}${TWO}&iso=0.8&color=%2333aa66`);
  await settledTriangles(page);
  await openPanelGroups(page);
  const [file] = await Promise.all([page.waitForEvent('download'), page.click('#save-scene')]);
  const text = readFileSync(await file.path(), 'utf8');
  const document = JSON.parse(text);
  assert.equal(document.format, 'metaballs-scene');
  assert.equal(document.version, 1);
  assert.equal(document.spheres.length, 2);
  assert.equal(document.settings.iso, 0.8);
  assert.equal(document.settings.color, '#33aa66');
  const original = await page.evaluate(() => window.metaballs.element.sphereList);
  const saved = await picture(page);

  // Change the scene: move a sphere, another iso and colour.
  await drag(page, await onScreen(page, 1), { x: 700, y: 150 });
  await page.evaluate(() => { const e = window.metaballs.element; e.iso = 1.3; e.color = '#2244ff'; });
  await frameDrawn(page);
  const changed = await page.evaluate(() => window.metaballs.element.sphereList);
  assert.notDeepEqual(changed, original);

  // Bad files: each refused with what is wrong; the scene stays as it is.
  const bad = [
    ['not-json.json', '{ spheres: [ }', /not valid JSON/],
    ['cut.json', text.slice(0, text.length / 2), /ends early/],
    ['negative.json', text.replace(/"radius": 0.3/, '"radius": -0.3'), /spheres\[0\]\.radius: sphere radius must be between 0\.01 and 1, got -0\.3/],
    ['future.json', text.replace('"version": 1', '"version": 7'), /version 7 is not one this build reads/],
    ['huge.json', `${text.slice(0, -1)}, "padding": "${'x'.repeat(1_100_000)}"}`, /the file is 1\.1 MB; a scene file is at most 1 MB/],
  ];
  for (const [name, content, message] of bad) {
    await dropFile(page, name, content);
    const shown = await notice(page);
    assert.match(shown, message, `${name}: ${shown}`);
    assert.ok(shown.includes(name) && shown.includes('The scene is unchanged'), shown);
    assert.deepEqual(await page.evaluate(() => window.metaballs.element.sphereList), changed, `${name} changed the spheres`);
    assert.equal(await page.evaluate(() => window.metaballs.element.iso), 1.3);
  }

  // The saved file restores spheres and settings, and the same picture.
  await dropFile(page, 'saved.json', text);
  assert.match(await notice(page), /Loaded saved.json: 2 spheres/);
  assert.deepEqual(await page.evaluate(() => window.metaballs.element.sphereList), original);
  assert.equal(await page.evaluate(() => window.metaballs.element.iso), 0.8);
  assert.equal(await page.evaluate(() => window.metaballs.element.color), '#33aa66');
  await frameDrawn(page);
  const restored = await picture(page);
  const differing = await differingFraction(page, saved, restored);
  assert.ok(differing < 0.005, `${(differing * 100).toFixed(2)}% of pixels differ from the saved scene`);
  assert.deepEqual(errors, []);
  await page.close();
});

// The fixture pair tests/fixtures/page-scene.json and tests/reference/page-scene.png: a scene built and
// saved in the page, and the page's picture of it. tests/suite/scene_render.rs renders the JSON with
// `metaballs render --scene` and compares with the PNG (FLIP). Here: the page still saves that document
// and draws that picture.
test('the page saves and draws the fixture scene that the command line renders', async () => {
  const fixture = path.join(root, 'tests/fixtures/page-scene.json');
  const expected = JSON.parse(readFileSync(fixture, 'utf8'));
  const { page, errors } = await open('?controls=none&hud=off&paused=1');
  await settledTriangles(page).catch(() => {});
  await page.evaluate((t) => window.metaballs.element.loadScene(t), JSON.stringify(expected));
  await frameDrawn(page);
  const saved = JSON.parse(await page.evaluate(() => window.metaballs.element.saveScene()));
  assert.deepEqual(saved, expected, 'the page saves the scene it loaded, unchanged');
  const png = await picture(page);
  writeFileSync(path.join(outputDir, 'e2e-page-scene.png'), png);
  const reference = readFileSync(path.join(root, 'tests/reference/page-scene.png'));
  const differing = await differingFraction(page, reference, png);
  assert.ok(differing < 0.01, `${(differing * 100).toFixed(2)}% of pixels differ from tests/reference/page-scene.png`);
  assert.deepEqual(errors, []);
  await page.close();
});
