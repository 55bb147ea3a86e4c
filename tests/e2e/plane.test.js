// The 2D figure, <metaballs-2d>, in headless Chromium: the lecture's figure (on a page of its own) draws its samples, cases,
// saddles and contour with WebGPU, with WebGL2 only and with neither; each setting changes the picture;
// a bad value gets a notice and keeps the figure; the SVG export parses and holds the contour drawn;
// dragging a circle moves it. Its contouring is held to d3-contour in squares.test.js.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { useServerAndBrowser, openClosedAfterEach, differingFraction, pixelStats } from './helpers.js';

useServerAndBrowser();
const open = openClosedAfterEach();

// The lecture's two 2D figures on a page of their own (the lecture itself is printed and checked in
// course.test.js).
const PAGE = 'tests/e2e/fixtures/plane.html';
const NO_WEBGPU = () => { delete Navigator.prototype.gpu; };
const NO_WEBGPU_OR_WEBGL = () => {
  delete Navigator.prototype.gpu;
  const getContext = HTMLCanvasElement.prototype.getContext;
  HTMLCanvasElement.prototype.getContext = function (kind, ...rest) {
    return kind === 'webgl2' || kind === 'webgl' ? null : getContext.call(this, kind, ...rest);
  };
};

const figure = (page) => page.locator('#squares metaballs-2d');
const shot = (page) => figure(page).screenshot();
const contours = (page) => page.$eval('#squares metaballs-2d', (e) => e.contours());
const set = (page, name, value) => page.$eval('#squares metaballs-2d', (e, [n, v]) => e.setAttribute(n, v), [name, value]);
// A frame drawn after a change (the figure draws on the next animation frame).
const drawn = (page) => page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));

async function lecture(options) {
  const opened = await open(PAGE, options);
  await opened.page.locator('#squares').scrollIntoViewIfNeeded();
  await opened.page.waitForFunction(() => document.querySelector('#squares metaballs-2d')?.frameMs > 0);
  return opened;
}

test('the lecture\'s 2D figure draws its samples, saddles and contour with WebGPU, with WebGL2 only and with neither', async () => {
  // Each browser: what it takes away, and what is left (WebGPU, WebGL2).
  for (const [initScript, left] of [[undefined, [true, true]], [NO_WEBGPU, [false, true]], [NO_WEBGPU_OR_WEBGL, [false, false]]]) {
    const { page, errors } = await lecture({ initScript });
    const has = await page.evaluate(() => ['gpu' in navigator, document.createElement('canvas').getContext('webgl2') !== null]);
    assert.deepEqual(has, left);
    const result = await contours(page);
    // The decider joins the three circles through two saddle squares: one contour.
    assert.equal(result.rings.length, 1);
    assert.deepEqual(result.saddles.map((s) => [s.square, s.case, s.joined]), [[[4, 4], 10, true], [[7, 5], 5, true]]);
    const stats = await pixelStats(page, await shot(page));
    // The white contour, and the orange of the inside samples.
    assert.ok(stats.highlight / stats.pixels > 0.003 && stats.surface > 0.003, `the contour and samples show: ${JSON.stringify(stats)}`);
    const label = await page.$eval('#squares metaballs-2d', (e) => e.shadowRoot.querySelector('canvas').getAttribute('aria-label'));
    assert.match(label, /two saddle squares the decider joins/);
    assert.deepEqual(errors, []);
  }
});

test('each setting changes the picture; the saddle rule changes the contour; a bad value gets a notice', async () => {
  const { page, errors } = await lecture();
  let before = await shot(page);
  for (const [name, value] of [['saddle', 'table'], ['iso', '0.9'], ['resolution', '20'], ['interpolation', 'midpoint'],
    ['iso-levels', '0.5'], ['show', 'grid,contour'], ['kernel', 'wyvill'], ['kernel', 'blinn'], ['blobbiness', '6'],
    ['kernel', 'inverse_square'], ['theme', 'light']]) {
    await set(page, name, value);
    await drawn(page);
    const after = await shot(page);
    assert.ok(await differingFraction(page, before, after) > 0.001, `${name}=${value} changes the picture`);
    before = after;
  }
  // The fixed table cuts the saddles apart: three contours on the lecture's grid where the decider
  // drew one.
  for (const [name, value] of [['iso', '1.2'], ['resolution', '12'], ['interpolation', 'linear']]) await set(page, name, value);
  await drawn(page);
  assert.equal((await contours(page)).rings.length, 3);
  await set(page, 'saddle', 'center');
  await drawn(page);
  const center = await contours(page);
  assert.ok(center.saddles.every((s) => Math.abs(s.value - 1.2) > 0 && s.joined === s.value > 1.2));
  // Bad values: a notice saying what is accepted, and the figure keeps its setting.
  for (const [name, value, said] of [['iso', 'abc', /^iso="abc": iso level must be a number from 0.05 to 20, got "abc"/],
    ['iso', '0x10', /^iso="0x10": iso level must be a number from 0.05 to 20, got "0x10"/],
    ['saddle', 'middle', /^saddle="middle": saddle must be one of table, center, decider, got "middle"/],
    ['circles', '0,0', /^circles="0,0": circles: "0,0" is not x,y,r/],
    ['circles', '0,0,0x1', /^circles="0,0,0x1": circles: "0x1" is not a number/],
    ['show', 'grid,sparkles', /^show="grid,sparkles": show must be all, none, or a comma list of grid, values/]]) {
    await set(page, name, value);
    await drawn(page);
    const notice = await page.$eval('#squares metaballs-2d', (e) => e.shadowRoot.getElementById('notice').textContent);
    assert.match(notice, said);
    assert.match(notice, /; keeping /);
  }
  assert.equal((await contours(page)).iso, 1.2);
  assert.deepEqual(errors, []);
});

test('the SVG export parses and holds the contour drawn; dragging a circle moves it', async () => {
  const { page, errors } = await lecture();
  const svg = await page.$eval('#squares metaballs-2d', (e) => e.toSVG(480));
  const parsed = await page.evaluate((text) => {
    const doc = new DOMParser().parseFromString(text, 'image/svg+xml');
    const contour = doc.querySelector('path.contour');
    return {
      error: doc.querySelector('parsererror')?.textContent ?? null,
      subpaths: contour ? contour.getAttribute('d').split('M').length - 1 : 0,
      title: doc.querySelector('title')?.textContent,
      texts: doc.querySelectorAll('text').length,
      saddles: doc.querySelectorAll('rect.saddle').length,
    };
  }, svg);
  assert.equal(parsed.error, null);
  assert.equal(parsed.subpaths, (await contours(page)).rings.length);
  assert.match(parsed.title, /Three circles/);
  assert.equal(parsed.saddles, 2);
  assert.ok(parsed.texts > 13 * 13, `every sample's value is printed: ${parsed.texts} labels`);
  // Drag the first circle by its centre.
  const [circle] = await page.$eval('#squares metaballs-2d', (e) => e.circleList.map((c) => ({ ...c })));
  const box = await figure(page).boundingBox();
  const at = (x, y) => [box.x + box.width * (0.03 + 0.94 * (x + 1) / 2), box.y + box.height * (0.03 + 0.94 * (1 - y) / 2)];
  await page.mouse.move(...at(circle.x, circle.y));
  await page.mouse.down();
  await page.mouse.move(...at(circle.x - 0.3, circle.y - 0.2), { steps: 5 });
  await page.mouse.up();
  const [moved] = await page.$eval('#squares metaballs-2d', (e) => e.circleList);
  assert.ok(Math.abs(moved.x - (circle.x - 0.3)) < 0.05 && Math.abs(moved.y - (circle.y - 0.2)) < 0.05, JSON.stringify(moved));
  assert.deepEqual(errors, []);
});

test('the stepper walks the march: the lit row is each square\'s case, and the last step draws the whole contour', async () => {
  const { page, errors } = await open(PAGE);
  const march = page.locator('#march metaballs-2d');
  await march.scrollIntoViewIfNeeded();
  await page.waitForFunction(() => document.querySelector('#march metaballs-2d')?.frameMs > 0);
  const state = () => page.$eval('#march metaballs-2d', (e) => ({
    step: e.stepIndex,
    lit: [...e.shadowRoot.querySelectorAll('.cases tr.current')].map((r) => Number(r.dataset.case)),
    said: e.shadowRoot.querySelector('.where').textContent,
  }));
  const { cases, rings } = await page.$eval('#march metaballs-2d', (e) => e.contours());
  // march="0,2" opens it at square (0, 2) of the 8 × 8 grid.
  assert.equal((await state()).step, 16);
  for (let k = 0; k < 64; k += 1) {
    await page.$eval('#march metaballs-2d', (e, step) => e.stepTo(step), k);
    await drawn(page);
    const now = await state();
    assert.deepEqual(now.lit, [cases[k]], `step ${k}`);
    assert.match(now.said, new RegExp(`square \\(${k % 8}, ${Math.floor(k / 8)}\\).*case ${cases[k]} =`));
  }
  // The buttons: back, forward, next crossed.
  const click = (what) => page.locator('#march metaballs-2d').locator(`button[data-do="${what}"]`).click();
  await page.$eval('#march metaballs-2d', (e) => e.stepTo(0));
  await click('forward');
  await click('forward');
  await click('back');
  await drawn(page);
  assert.equal((await state()).step, 1);
  await click('next');
  await drawn(page);
  const firstCrossed = cases.findIndex((c, k) => k > 1 && c !== 0 && c !== 15);
  assert.equal((await state()).step, firstCrossed);
  // Played, it advances by itself.
  await click('play');
  await page.waitForFunction((from) => document.querySelector('#march metaballs-2d').stepIndex > from + 1, firstCrossed);
  await click('play');
  // The end: the whole contour, segment for segment.
  await page.$eval('#march metaballs-2d', (e) => e.stepTo(64));
  await drawn(page);
  assert.match((await state()).said, /the march is done/);
  const segments = await page.$eval('#march metaballs-2d', (e) => {
    const doc = new DOMParser().parseFromString(e.toSVG(400), 'image/svg+xml');
    return doc.querySelector('path.contour').getAttribute('d').split('M').length - 1;
  });
  assert.equal(segments, rings.reduce((sum, ring) => sum + ring.length, 0));
  // A square outside the grid: a notice, and the stepper stays.
  await page.$eval('#march metaballs-2d', (e) => e.setAttribute('march', '9,9'));
  await drawn(page);
  assert.match(await page.$eval('#march metaballs-2d', (e) => e.shadowRoot.getElementById('notice').textContent),
    /march: "9,9" is not a square i,j of the 8 × 8 grid/);
  assert.equal((await state()).step, 64);
  // Whatever the order of the attributes: a square of the finer grid given first opens there once the
  // grid is given; `march` given empty opens at the first square; `off` closes it; the square it holds,
  // asked for again after the step-through played on, is shown again.
  const steps = await page.evaluate(() => {
    const figure = (attributes) => {
      const e = document.createElement('metaballs-2d');
      for (const [name, value] of attributes) e.setAttribute(name, value);
      document.body.append(e);
      const step = e.stepIndex;
      e.remove();
      return step;
    };
    const e = document.querySelector('#march metaballs-2d');
    e.setAttribute('march', '1,1');
    e.stepTo(30);
    const moved = e.stepIndex;
    e.setAttribute('march', '1,1');
    return [figure([['march', '20,3'], ['resolution', '24']]), figure([['march', '']]), figure([['march', 'off']]), moved, e.stepIndex];
  });
  assert.deepEqual(steps, [3 * 24 + 20, 0, null, 30, 9]);
  assert.deepEqual(errors, []);
});

test('a 2D figure following a 3D figure\'s slice plane draws the same samples', async () => {
  const { page, errors } = await open(PAGE);
  await page.addScriptTag({ type: 'module', url: '../../../www/metaballs-view.js' });
  await page.waitForFunction(() => customElements.get('metaballs-view'));
  await page.evaluate(() => {
    const view = document.createElement('metaballs-view');
    Object.assign(view, { id: 'solid' });
    for (const [k, v] of Object.entries({ spheres: '4', seed: '4', resolution: '20', slice: 'z:0.1', paused: '', style: 'width: 320px' })) view.setAttribute(k, v);
    const plane = document.createElement('metaballs-2d');
    plane.setAttribute('slice-of', 'solid');
    plane.style.width = '320px';
    document.querySelector('main').prepend(view, plane);
  });
  await page.waitForFunction(() => document.getElementById('solid').framesDrawn > 0, null, { timeout: 60_000 });
  const { cells, values } = await page.$eval('metaballs-2d[slice-of]', (e) => e.samples());
  assert.equal(cells, 20);
  // The plane z = 0.1 on 20 cells: index round(1.1 / 2 · 20) = 11. The 3D figure's inspector reads the
  // corner values of cell (i, j, 11): its lower four lie on the plane.
  let compared = 0;
  for (const [i, j] of [[5, 5], [9, 10], [10, 9], [12, 7], [3, 15]]) {
    const report = await page.$eval('#solid', (e, [x, y]) => e.inspectCell(x, y, 11), [i, j]);
    const plane = [values[j * 21 + i], values[j * 21 + i + 1], values[(j + 1) * 21 + i + 1], values[(j + 1) * 21 + i]];
    for (let c = 0; c < 4; c += 1) {
      assert.ok(Math.abs(report.corners[c] - plane[c]) <= 1e-5 * Math.max(1, Math.abs(plane[c])), `cell (${i}, ${j}) corner ${c}: ${report.corners[c]} vs ${plane[c]}`);
      compared += 1;
    }
  }
  assert.equal(compared, 20);
  // It follows a change of the 3D figure's plane.
  await page.$eval('#solid', (e) => e.setAttribute('slice', 'x:-0.2'));
  await page.waitForFunction(() => document.querySelector('metaballs-2d[slice-of]').samples().values[10 * 21 + 10] !== null);
  const moved = await page.$eval('metaballs-2d[slice-of]', (e) => e.samples().values);
  assert.notDeepEqual(moved, values);
  // And the 3D figure's kernel: once the 3D figure takes Wyvill's soft objects, the 2D figure samples
  // them as the cell inspector reads them (x = -0.2: plane index 8; point (j, k) of the x slice lies
  // along y and z, the inspector's cell (8, j, k), corner 0).
  const points = [[9, 10], [10, 9], [12, 7]];
  const corners = () => page.$eval('#solid', (e, at) => at.map(([y, z]) => e.inspectCell(8, y, z).corners[0]), points);
  const before = await corners();
  await page.$eval('#solid', (e) => e.setAttribute('kernel', 'wyvill'));
  await page.waitForFunction((at) => {
    const view = document.getElementById('solid');
    const values = document.querySelector('metaballs-2d[slice-of]').samples().values;
    return view.kernel === 'wyvill' && at.every(([y, z]) => {
      const [c, v] = [view.inspectCell(8, y, z).corners[0], values[z * 21 + y]];
      return Math.abs(c - v) <= 1e-5 * Math.max(1, Math.abs(v));
    });
  }, points, { timeout: 30_000 });
  const after = await corners();
  assert.ok(after.every((c, k) => Math.abs(c - before[k]) > 1e-3), `the kernel changed the field: ${before} → ${after}`);
  assert.deepEqual(errors, []);
});

test('the 2D page: each panel control changes the picture and goes into the link; a link restores it; double-clicks add and remove circles', async () => {
  const { page, errors } = await open('squares.html?circles=0.58,0.18,0.29;0.08,-0.37,0.25;-0.5,-0.14,0.22&iso=1.2&resolution=12&paused=true');
  const el = page.locator('metaballs-2d');
  await page.waitForFunction(() => document.querySelector('metaballs-2d')?.frameMs > 0);
  await el.locator('summary').click();
  const picture = () => el.locator('canvas').screenshot();
  const link = () => new URL(page.url()).searchParams;
  const settle = async () => { await drawn(page); await page.waitForTimeout(250); };
  let before = await picture();
  const changes = [
    // The decider joins the circles through two saddle squares (the lecture's first 2D figure).
    ['saddle', (c) => c.locator('#control-saddle').selectOption('decider'), 'decider'],
    ['iso', (c) => c.locator('#control-iso').fill('1.6'), '1.6'],
    ['resolution', (c) => c.locator('#control-resolution').fill('20'), '20'],
    ['interpolation', (c) => c.locator('#control-interpolation').selectOption('midpoint'), 'midpoint'],
    ['iso-levels', async (c) => { await c.locator('#control-levels').fill('0.8,2.4'); await c.locator('#control-levels').press('Enter'); }, '0.8,2.4'],
    ['show', (c) => c.locator('input[data-show="values"]').uncheck(), null],
    ['theme', (c) => c.locator('#control-theme').selectOption('light'), 'light'],
  ];
  for (const [name, act, value] of changes) {
    await act(el);
    await settle();
    const after = await picture();
    assert.ok(await differingFraction(page, before, after) > 0.002, `${name} changes the picture`);
    if (value !== null) assert.equal(link().get(name), value, `${name} goes into the link`);
    else assert.ok(!link().get(name).split(',').includes('values'), `${name} goes into the link: ${link().get(name)}`);
    before = after;
  }
  // The link gives the same figure back.
  const url = page.url();
  const again = await open(url);
  await again.page.waitForFunction(() => document.querySelector('metaballs-2d')?.frameMs > 0);
  await again.page.waitForTimeout(250);
  const pixels = (p) => p.$eval('metaballs-2d', (e) => e.shadowRoot.querySelector('canvas').toDataURL());
  // The same picture (to within the canvas's antialiasing of a picture drawn once against one drawn over).
  const png = async (p) => Buffer.from((await pixels(p)).split(',')[1], 'base64');
  const differing = await differingFraction(page, await png(page), await png(again.page));
  assert.ok(differing < 0.002, `the link restores the picture: ${(differing * 100).toFixed(3)} % of the pixels differ`);
  // Double-click on empty space adds a circle; on a circle, removes it.
  const box = await el.locator('canvas').boundingBox();
  const at = (x, y) => [box.x + (x + 1) / 2 * box.width, box.y + (1 - y) / 2 * box.height];
  await page.mouse.dblclick(...at(0.6, 0.7));
  await settle();
  assert.equal((await page.$eval('metaballs-2d', (e) => e.circleList.length)), 4);
  const added = link().get('circles').split(';')[3].split(',').map(Number);
  assert.ok(Math.abs(added[0] - 0.6) < 0.01 && Math.abs(added[1] - 0.7) < 0.01 && added[2] === 0.2, `added ${added}`);
  await page.mouse.dblclick(...at(0.08, -0.37));
  await settle();
  assert.deepEqual(await page.$eval('metaballs-2d', (e) => e.circleList.map((c) => [c.x, c.y])), [[0.58, 0.18], [-0.5, -0.14], added.slice(0, 2)]);
  // The step-through opens from the panel.
  await el.locator('button[data-action="step-through"]').click();
  await settle();
  assert.equal(link().get('march'), '0');
  assert.equal(await page.$eval('metaballs-2d', (e) => e.stepIndex), 0);
  // Steps taken in the figure go into the link (as the square i,j).
  await el.locator('button[data-do="forward"]').click();
  await settle();
  assert.equal(link().get('march'), '1,0');
  // A bad value typed in the panel gets the notice and stays out of the figure and the link.
  await el.locator('#control-levels').fill('0.8,abc');
  await el.locator('#control-levels').press('Enter');
  await settle();
  assert.match(await page.$eval('metaballs-2d', (e) => e.shadowRoot.getElementById('notice').textContent),
    /^iso-levels="0.8,abc": iso level must be a number from 0.05 to 20, got "abc"; keeping "0.8,2.4"/);
  assert.equal(link().get('iso-levels'), '0.8,2.4');
  // A panel built again hears each click once: the step-through closes and stays closed. (`levels` is
  // the older name of the levels' control.)
  await page.$eval('metaballs-2d', (e) => e.setAttribute('controls', 'step-through,levels'));
  await el.locator('summary').click();
  await el.locator('button[data-action="step-through"]').click();
  await settle();
  assert.equal(await page.$eval('metaballs-2d', (e) => e.stepIndex), null);
  assert.deepEqual(errors, []);
  assert.deepEqual(again.errors, []);
});

test('2D scene files: saved and loaded back the same figure; a bad file changes nothing and says what is wrong', async () => {
  const { page, errors } = await open('squares.html?circles=0.58,0.18,0.29;0.08,-0.37,-0.25;-0.5,-0.14,0.22&iso=1.2&resolution=12&saddle=decider&levels=0.8,2&paused=true');
  const el = page.locator('metaballs-2d');
  await page.waitForFunction(() => document.querySelector('metaballs-2d')?.frameMs > 0);
  const pixels = () => page.$eval('metaballs-2d', (e) => e.shadowRoot.querySelector('canvas').toDataURL());
  // The same picture, to within the canvas's antialiasing (a picture drawn once against one drawn over).
  const png = (url) => Buffer.from(url.split(',')[1], 'base64');
  const same = async (a, b) => await differingFraction(page, png(a), png(b)) < 0.002;
  const saved = await page.$eval('metaballs-2d', (e) => e.saveScene());
  const doc = JSON.parse(saved);
  assert.equal(doc.format, 'metaballs-2d-scene');
  assert.deepEqual(doc.circles[1], { center: [0.08, -0.37], radius: 0.25, charge: -1 });
  assert.equal(doc.settings.saddle, 'decider');
  // The link's `levels` is the older name of `iso-levels`.
  assert.deepEqual(doc.settings['iso-levels'], [0.8, 2]);
  const before = await pixels();
  // Saved from the panel: the download is the same document.
  await el.locator('summary').click();
  const [download] = await Promise.all([page.waitForEvent('download'), el.locator('button[data-action="save-scene"]').click()]);
  assert.equal(download.suggestedFilename(), 'metaballs-2d-scene.json');
  // Changed, then loaded back from the panel's file chooser.
  await page.$eval('metaballs-2d', (e) => { e.setAttribute('iso', '0.7'); e.setAttribute('circles', '0,0,0.4'); e.setAttribute('saddle', 'table'); });
  await drawn(page);
  assert.notEqual(await pixels(), before);
  const [chooser] = await Promise.all([page.waitForEvent('filechooser'), el.locator('button[data-action="load-scene"]').click()]);
  await chooser.setFiles({ name: 'scene.json', mimeType: 'application/json', buffer: Buffer.from(saved) });
  await page.waitForFunction(() => document.querySelector('metaballs-2d').getAttribute('saddle') === 'decider');
  await drawn(page);
  assert.ok(await same(await pixels(), before), 'the scene file gives the same picture back');
  // Bad documents: each refused with what is wrong, the figure unchanged.
  for (const [bad, said] of [
    ['{"format": "metaballs-2d-scene", "version": 1, "circles": [{"center": [3, 0], "radius": 0.2}]}', /circles\[0\]\.center \(3, 0\) is outside the box/],
    ['{"format": "metaballs-2d-scene", "version": 1, "circles": [{"center": [0, 0], "radius": 0.2}], "settings": {"iso": 99}}', /settings\.iso: iso level must be between 0\.05 and 20, got 99/],
    ['{"format": "metaballs-2d-scene", "version": 2, "circles": []}', /version 2/],
    ['not json', /not JSON/],
  ]) {
    const message = await page.$eval('metaballs-2d', (e, text) => { try { e.loadScene(text); return 'loaded'; } catch (error) { return error.message; } }, bad);
    assert.match(message, said);
  }
  await drawn(page);
  assert.ok(await same(await pixels(), before), 'the bad documents changed the picture');
  assert.deepEqual(errors, []);
});

test('printed, the 2D figure is vector art: its values are text in the PDF, its controls and step-through left out', async () => {
  const { page, errors } = await open('squares.html?circles=0.58,0.18,0.29;0.08,-0.37,0.25;-0.5,-0.14,0.22&iso=1.2&resolution=12&paused=true&march=0,3');
  await page.waitForFunction(() => document.querySelector('metaballs-2d')?.frameMs > 0);
  // Still: its picture for print is made once it has settled.
  await page.waitForFunction(() => document.querySelector('metaballs-2d').shadowRoot.querySelector('.print svg'));
  await page.emulateMedia({ media: 'print' });
  const shown = await page.$eval('metaballs-2d', (e) => ['.print', 'canvas', '.controls', '.side']
    .map((s) => getComputedStyle(e.shadowRoot.querySelector(s)).display));
  assert.deepEqual(shown, ['block', 'none', 'none', 'none']);
  const directory = mkdtempSync(path.join(os.tmpdir(), 'metaballs-2d-print-'));
  try {
    const pdf = path.join(directory, 'squares.pdf');
    writeFileSync(pdf, await page.pdf({ format: 'A4', printBackground: true }));
    const text = execFileSync('pdftotext', [pdf, '-']).toString();
    const values = await page.$eval('metaballs-2d', (e) => e.samples().values.filter((v) => v > 0.3 && v < 10).map((v) => v.toFixed(2)));
    const found = values.filter((v) => text.includes(v));
    assert.ok(found.length >= values.length * 0.9, `${found.length} of ${values.length} sample values are text in the PDF`);
    assert.ok(!text.includes('next crossed'), 'the step-through panel is not printed');
  } finally {
    rmSync(directory, { recursive: true, force: true });
  }
  assert.deepEqual(errors, []);
});
