// The teaching views end to end in headless Chromium (WebGPU on SwiftShader): each control changes the
// picture, keeps the triangle count, writes its link parameter, and the link restores the view; bad
// values are refused with a notice; the cell inspector picks, follows and lets go; Step advances one
// frame; the case gallery marks the inspected class.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import {
  useServerAndBrowser, open, waitForTriangles, settledTriangles, screenshot, differingFraction, setRange,
  openPanelGroups, outputDir, frameDrawn,
} from './helpers.js';

useServerAndBrowser();

const START = '?paused=1&res=16&seed=3';

// Each control: how to operate it, and the link parameter it writes.
const CONTROLS = [
  ['display', (p) => p.selectOption('#display', 'wireframe'), 'display=wireframe'],
  ['grid', (p) => p.selectOption('#grid', 'cells'), 'grid=cells'],
  ['color_by', (p) => p.selectOption('#color_by', 'quality'), 'color_by=quality'],
  // Ambiguous faces are few on smooth blobs: a small but certain change. Their crosses share pixels
  // with the cells' boxes, which SwiftShader draws in a varying order: the best of five pictures.
  ['ambiguous', (p) => p.check('#ambiguous'), 'ambiguous=1', 0.0005, 5],
  ['slice', (p) => p.selectOption('#slice-axis', 'x'), 'slice=x:0'],
  ['slice position', (p) => setRange(p, 'slice', -0.3), 'slice=x:-0.3'],
  ['interpolation', (p) => p.selectOption('#interpolation', 'midpoint'), 'interp=midpoint'],
  ['light', (p) => p.check('#light-spot'), 'light=point,spot'],
  ['spot_angle', (p) => setRange(p, 'spot_angle', 8), 'spot_angle=8'],
  ['ambient', (p) => setRange(p, 'ambient', 0.6), 'ambient=0.6'],
  ['projection', (p) => p.selectOption('#projection', 'orthographic'), 'proj=orthographic'],
  ['fov', (p) => setRange(p, 'fov', 80), 'fov=80'],
];

async function frameAfterChange(page) {
  // Two frames of the changed settings, even paused: the second is drawn once the first one's counts
  // are back (a mesh that outgrew its buffers is drawn again in grown ones).
  await frameDrawn(page);
  await frameDrawn(page);
  // The figure's own picture of its state (drawn once more, settled; without the panel over it).
  const png = Buffer.from(await page.evaluate(async () => {
    const blob = await window.metaballs.element.picture(1);
    return [...new Uint8Array(await blob.arrayBuffer())];
  }));
  writeFileSync(path.join(outputDir, 'e2e-teaching-step.png'), png);
  return png;
}

test('each teaching control changes the picture, keeps the triangles, and its link restores the view', async () => {
  const { page, errors } = await open(START);
  const triangles = await settledTriangles(page);
  await openPanelGroups(page);
  let before = await frameAfterChange(page);
  for (const [name, operate, parameter, least = 0.002, pictures = 1] of CONTROLS) {
    await operate(page);
    let after = await frameAfterChange(page);
    let changed = await differingFraction(page, before, after);
    for (let i = 1; i < pictures && changed <= least; i++) {
      after = await frameAfterChange(page);
      changed = await differingFraction(page, before, after);
    }
    assert.ok(changed > least, `${name}: only ${(changed * 100).toFixed(3)}% of pixels changed`);
    assert.equal(await settledTriangles(page), triangles, `${name}: the triangle count changed`);
    await page.waitForFunction((p) => location.search.includes(p), parameter, { timeout: 5000 }).catch(() => {});
    const search = await page.evaluate(() => location.search);
    assert.ok(search.includes(parameter), `${name}: the link ${search} lacks ${parameter}`);
    console.log(`${name}: ${(changed * 100).toFixed(1)}% of pixels changed, ${triangles} triangles, link ${parameter}`);
    before = after;
  }
  // The link reproduces the view: same settings, same picture.
  const search = await page.evaluate(() => location.search);
  const state = await page.evaluate(() => {
    const e = window.metaballs.element;
    return [e.display, e.grid, e.color_by, e.ambiguous, e.slice, e.interpolation, e.light, e.projection, e.fov];
  });
  const { page: again, errors: againErrors } = await open(search);
  await settledTriangles(again);
  await openPanelGroups(again);
  const restored = await again.evaluate(() => {
    const e = window.metaballs.element;
    return [e.display, e.grid, e.color_by, e.ambiguous, e.slice, e.interpolation, e.light, e.projection, e.fov];
  });
  assert.deepEqual(restored, state);
  assert.deepEqual(restored, ['wireframe', 'cells', 'quality', true, 'x:-0.3', 'midpoint', 'point,spot', 'orthographic', 80]);
  // Compare the figures without their panels (scrolled differently).
  for (const p of [page, again]) await p.$eval('metaballs-view', (e) => e.setAttribute('controls', 'none'));
  const original = await frameAfterChange(page);
  const reopened = await frameAfterChange(again);
  const difference = await differingFraction(page, original, reopened);
  assert.ok(difference < 0.01, `the restored view differs in ${(difference * 100).toFixed(2)}% of pixels`);
  // Blend by max is a different surface: the triangle count changes, and the link keeps it.
  await again.$eval('metaballs-view', (e) => e.setAttribute('controls', 'all'));
  await openPanelGroups(again);
  const merged = await settledTriangles(again);
  await again.selectOption('#blend', 'max');
  assert.notEqual(await waitForTriangles(again, merged), merged, 'blend by max separates the spheres');
  await again.waitForFunction(() => location.search.includes('blend=max'));
  // Another kernel is another field: from the panel (Wyvill's soft objects), as an attribute (Blinn's
  // Gaussian, then a blobbiness), each a different surface that the link keeps; the critical points
  // say they serve the inverse-square sum only rather than show another field's.
  await again.selectOption('#blend', 'sum');
  // At iso 0.5 the kernels' surfaces lie far apart (at iso 1 a lone sphere is the same for every kernel).
  await again.$eval('metaballs-view', (e) => e.setAttribute('iso', '0.5'));
  const summed = await waitForTriangles(again, merged).then(() => settledTriangles(again));
  await again.selectOption('#kernel', 'wyvill');
  const soft = await waitForTriangles(again, summed);
  await again.waitForFunction(() => location.search.includes('kernel=wyvill'));
  await again.$eval('metaballs-view', (e) => e.setAttribute('kernel', 'blinn'));
  const blobby = await waitForTriangles(again, soft);
  await again.$eval('metaballs-view', (e) => e.setAttribute('blobbiness', '6'));
  await waitForTriangles(again, blobby);
  assert.deepEqual(await again.evaluate(() => [window.metaballs.element.kernel, window.metaballs.element.blobbiness]), ['blinn', 6]);
  await again.waitForFunction(() => location.search.includes('kernel=blinn') && location.search.includes('blobbiness=6'));
  await again.$eval('metaballs-view', (e) => e.setAttribute('critical', 'true'));
  await again.waitForFunction(() => document.querySelector('metaballs-view').shadowRoot.getElementById('hud-field-text')?.textContent.includes('inverse-square'));
  console.log(`kernels at iso 0.5: ${summed} triangles summing inverse squares, ${soft} with Wyvill's, ${blobby} with Blinn's`);
  assert.deepEqual(errors, []);
  assert.deepEqual(againErrors, []);
  await page.close();
  await again.close();
});

test('bad teaching values show a notice and keep the view', async () => {
  const { page, errors } = await open(`${START}&display=sketch&slice=z:2&spot_angle=NaN&grid=cells`);
  await waitForTriangles(page);
  const notice = await page.textContent('#notice');
  for (const fragment of ['display=sketch', 'one of shaded, flat, wireframe, points, normals',
    'slice position must be between -1 and 1, got 2', 'spot_angle=NaN']) {
    assert.ok(notice.includes(fragment), `the notice lacks ${fragment}: ${notice}`);
  }
  const kept = await page.evaluate(() => {
    const e = window.metaballs.element;
    return [e.display, e.slice, e.spot_angle, e.grid];
  });
  assert.deepEqual(kept, ['shaded', 'off', 15, 'cells'], 'defaults where the link was bad, its good values kept');
  // A bad attribute set later keeps the previous value.
  await page.$eval('metaballs-view', (e) => e.setAttribute('projection', 'fisheye'));
  await page.waitForFunction(() => document.querySelector('metaballs-view').shadowRoot
    .getElementById('notice').textContent.includes('fisheye'));
  assert.equal(await page.evaluate(() => window.metaballs.element.projection), 'perspective');
  await page.$eval('metaballs-view', (e) => e.setAttribute('slice', 'y:0.5'));
  await page.$eval('metaballs-view', (e) => e.setAttribute('slice', 'y:-7'));
  assert.equal(await page.evaluate(() => window.metaballs.element.slice), 'y:0.5');
  assert.deepEqual(errors, []);
  await page.close();
});

test('clicking the surface inspects a cell; Esc and the background let go; the gallery marks its configuration', async () => {
  const { page, errors } = await open(`${START}&display=wireframe`);
  await settledTriangles(page);
  await openPanelGroups(page);
  const canvas = await page.locator('#view').boundingBox();
  // The surface is where the shaded frame is red: click the pixel of the surface nearest the centre.
  const before = await screenshot(page, 'inspector-before');
  const spot = await page.evaluate(async (b64) => {
    const bitmap = await createImageBitmap(await (await fetch(`data:image/png;base64,${b64}`)).blob());
    const off = new OffscreenCanvas(bitmap.width, bitmap.height);
    const context = off.getContext('2d');
    context.drawImage(bitmap, 0, 0);
    const { data, width, height } = context.getImageData(0, 0, bitmap.width, bitmap.height);
    let best = null;
    for (let y = 0; y < height; y += 4) {
      for (let x = 0; x < width; x += 4) {
        const i = 4 * (y * width + x);
        if (data[i] > data[i + 2] + 20 && data[i] > 80) {
          const d = Math.hypot(x - width / 2, y - height / 2);
          if (!best || d < best.d) best = { x, y, d };
        }
      }
    }
    return best && { x: best.x / width, y: best.y / height };
  }, before.toString('base64'));
  assert.ok(spot, 'the surface shows');
  await page.mouse.click(canvas.x + spot.x * canvas.width, canvas.y + spot.y * canvas.height);
  await page.waitForFunction(() => window.metaballs.element.inspected !== null);
  const report = await page.evaluate(() => window.metaballs.element.inspected);
  const iso = 1;
  const bits = report.corners.reduce((m, v, c) => m | ((v > iso ? 1 : 0) << c), 0);
  assert.equal(report.case, bits, 'the case is the corners inside');
  assert.ok(report.case !== 0 && report.case !== 255, 'a cell the surface crosses');
  assert.equal(report.bits, report.case.toString(2).padStart(8, '0'));
  assert.equal(report.triangles.length > 0, true);
  for (const edge of report.edges) assert.ok(edge.t >= 0 && edge.t <= 1, `t ${edge.t}`);
  assert.equal(await page.isVisible('#inspector'), true);
  assert.match(await page.textContent('#inspector h3'), new RegExp(`Cell \\(${report.cell.join(', ')}\\)`));
  assert.equal(await page.textContent('#inspector-case'), String(report.case));
  assert.equal(await page.textContent('#inspector-subcase'), report.subcase);
  assert.ok(report.subcase === String(report.class) || report.subcase.startsWith(`${report.class}.`), report.subcase);
  const current = await page.$eval('metaballs-view', (e) => {
    const figure = e.shadowRoot.querySelector('.gallery figure.current');
    return figure && { class: figure.dataset.class, subcase: figure.dataset.subcase };
  });
  assert.deepEqual(current, { class: String(report.class), subcase: report.subcase }, 'the gallery marks the inspected configuration');
  // MC33's 33 configurations, each once, the tunnels among them said so.
  const gallery = await page.$$eval('metaballs-view >> .gallery figure', (f) => f.map((x) => [x.dataset.subcase, x.title]));
  assert.equal(new Set(gallery.map(([name]) => name)).size, 33, JSON.stringify(gallery));
  assert.deepEqual(gallery.filter(([, title]) => title.includes('a tunnel inside')).map(([name]) => name),
    ['4.1.2', '6.1.2', '7.4.2', '10.1.2', '12.1.2', '13.5.2']);
  const highlighted = await screenshot(page, 'inspector-selected');
  assert.ok(await differingFraction(page, before, highlighted) > 0.0005, 'the selected cell is highlighted');
  // It follows the animation: play, and the corner values change while the cell stays.
  await page.evaluate(() => window.metaballs.element.play());
  await page.waitForFunction((first) => {
    const now = window.metaballs.element.inspected;
    return now && now.corners[0] !== first;
  }, report.corners[0], { timeout: 20_000 });
  assert.deepEqual((await page.evaluate(() => window.metaballs.element.inspected)).cell, report.cell);
  // Esc lets go.
  await page.focus('#view');
  await page.keyboard.press('Escape');
  await page.waitForFunction(() => window.metaballs.element.inspected === null);
  assert.equal(await page.isVisible('#inspector'), false);
  // Clicking the background (above the box, between the panel and the statistics) selects nothing.
  await page.evaluate(() => window.metaballs.element.inspectCell(8, 8, 8));
  assert.equal(await page.isVisible('#inspector'), true);
  await page.mouse.click(canvas.x + canvas.width / 2, canvas.y + 20);
  await page.waitForFunction(() => window.metaballs.element.inspected === null);
  assert.deepEqual(errors, []);
  await page.close();
});

test('Step advances one frame while paused', async () => {
  const { page, errors } = await open(START);
  await settledTriangles(page);
  const before = await frameAfterChange(page);
  for (let i = 0; i < 20; i += 1) await page.click('#step');
  const after = await frameAfterChange(page);
  assert.ok(await differingFraction(page, before, after) > 0.001, 'the spheres moved');
  assert.equal(await page.evaluate(() => window.metaballs.element.paused), true);
  // The . key does the same while the figure has focus.
  await page.focus('#view');
  for (let i = 0; i < 20; i += 1) await page.keyboard.press('.');
  const later = await frameAfterChange(page);
  assert.ok(await differingFraction(page, after, later) > 0.001, 'the . key steps too');
  assert.deepEqual(errors, []);
  await page.close();
});
