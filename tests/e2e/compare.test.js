// End-to-end tests of the comparisons in headless Chromium (SwiftShader): the exact surface alone,
// split against the mesh with a draggable divider, and as an outline; surface nets; and two figures
// sharing spheres and camera through `sync`. Each control changes the picture, goes into the link, and
// a bad value gets the notice.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import {
  useServerAndBrowser, openClosedAfterEach, picture, settledTriangles, screenshot, differingFraction, frameDrawn, outputDir,
  openPanelGroups,
} from './helpers.js';

useServerAndBrowser();

const open = openClosedAfterEach();

const BALLS = '-0.3,0,0,0.32;0.25,0.1,0,0.3;0,-0.25,0.2,0.26';
const set = (page, name, value) => page.$eval('metaballs-view', (e, [n, v]) => e.setAttribute(n, v), [name, value]);

test('display=exact, compare=split with its divider and compare=overlay change the picture and go into the link', async () => {
  const { page, errors } = await open(`?balls=${BALLS}&res=8&paused=1&aa=0&yaw=0&pitch=0`);
  await settledTriangles(page);
  const mesh = await picture(page);
  await screenshot(page, 'compare-mesh');
  const pictures = { mesh };
  for (const [name, value] of [['display', 'exact'], ['display', 'shaded'], ['compare', 'split'], ['compare', 'overlay']]) {
    await set(page, name, value);
    await page.waitForFunction(([n, v]) => location.search.includes(`${n}=${v}`) || (n === 'display' && v === 'shaded' && !location.search.includes('display=')), [name, value]);
    await frameDrawn(page);
    pictures[`${name}-${value}`] = await picture(page);
    await screenshot(page, `compare-${name}-${value}`);
  }
  assert.ok(await differingFraction(page, mesh, pictures['display-exact']) > 0.005, 'the exact surface is not the 8³ mesh');
  assert.ok(await differingFraction(page, mesh, pictures['compare-split']) > 0.003, 'the split shows the exact half');
  assert.ok(await differingFraction(page, mesh, pictures['compare-overlay']) > 0.003, 'the overlay draws the outline');
  // On this software renderer the exact surface is drawn at a lower pixel ratio, and it says so.
  const notice = await page.textContent('#notice');
  assert.match(notice, /exact surface is drawn at 0.5× pixel ratio/);

  // The divider drags with the mouse and its place goes into the link.
  await set(page, 'compare', 'split');
  const box = await page.$eval('metaballs-view', (e) => {
    const r = e.shadowRoot.querySelector('canvas').getBoundingClientRect();
    return { x: r.x, y: r.y, width: r.width, height: r.height };
  });
  const y = box.y + box.height * 0.8;
  await page.mouse.move(box.x + box.width * 0.5, y);
  await page.mouse.down();
  for (let k = 1; k <= 8; k++) await page.mouse.move(box.x + box.width * (0.5 - 0.03 * k), y);
  await page.mouse.up();
  await page.waitForFunction(() => /divider=0\.2\d*/.test(location.search));
  const divider = await page.$eval('metaballs-view', (e) => e.divider);
  assert.ok(Math.abs(divider - 0.26) < 0.03, `divider at ${divider}`);
  const yaw = await page.$eval('metaballs-view', (e) => e.yaw);
  assert.equal(yaw, 0, 'dragging the divider does not turn the camera');
  assert.deepEqual(errors, []);
});

test('extractor=surface_nets meshes one vertex per crossed cell, shows in the picture, the HUD and the link', async () => {
  const { page, errors } = await open(`?balls=${BALLS}&res=16&paused=1&aa=0&display=wireframe&hud=on`);
  const cubes = await settledTriangles(page);
  const before = await picture(page);
  await set(page, 'extractor', 'surface_nets');
  await page.waitForFunction(() => location.search.includes('extractor=surface_nets'));
  await page.waitForFunction(() => /SURFACE-NETS/.test(window.metaballs.element.stats.adapter), null, { timeout: 20000 });
  const nets = await settledTriangles(page);
  const after = await picture(page);
  await screenshot(page, 'extractor-nets');
  assert.ok(await differingFraction(page, before, after) > 0.005, 'the wireframe changes');
  // Two triangles per crossed edge, where marching cubes has about two per vertex: comparable counts.
  assert.ok(nets > cubes * 0.7 && nets < cubes * 1.3, `${nets} against ${cubes}`);
  const shape = await page.$eval('metaballs-view', (e) => e.topology());
  assert.equal(shape.closed, true);
  assert.deepEqual(errors, []);
});

test('method=marching_tetrahedra from an attribute, split=five from the panel: each another closed surface, in the HUD and the link', async () => {
  const { page, errors } = await open(`?balls=${BALLS}&res=16&paused=1&aa=0&display=wireframe&hud=on&controls=all`);
  const cubes = await settledTriangles(page);
  const before = await picture(page);
  await set(page, 'method', 'marching_tetrahedra');
  await page.waitForFunction(() => location.search.includes('extractor=marching_tetrahedra'));
  // The WebGPU page meshes marching tetrahedra in compute shaders, even on a software adapter.
  await page.waitForFunction(() => /TETRAHEDRA/.test(window.metaballs.element.stats.adapter), null, { timeout: 20000 });
  const six = await settledTriangles(page);
  const after = await picture(page);
  await screenshot(page, 'extractor-tetrahedra-six');
  assert.ok(await differingFraction(page, before, after) > 0.005, 'the wireframe changes');
  // Each crossed cell's triangles are cut by its tetrahedra: more and thinner triangles.
  assert.ok(six > cubes * 1.5, `${six} against ${cubes}`);
  assert.equal((await page.$eval('metaballs-view', (e) => e.topology())).closed, true);
  await openPanelGroups(page);
  await page.selectOption('#split', 'five');
  await page.waitForFunction(() => location.search.includes('split=five'));
  await page.waitForFunction((n) => window.metaballs.element.stats.triangles !== n, six, { timeout: 20000 });
  const five = await settledTriangles(page);
  await screenshot(page, 'extractor-tetrahedra-five');
  assert.notEqual(five, six, 'the five-way split cuts the cells otherwise');
  const shape = await page.$eval('metaballs-view', (e) => e.topology());
  assert.equal(shape.closed, true);
  // The case table has nothing to choose here, and says so.
  await set(page, 'table', 'mc33');
  await page.waitForFunction(() => document.querySelector('metaballs-view').shadowRoot.getElementById('notice')
    .textContent === 'table=mc33: marching tetrahedra has no ambiguous case and no case table; the mesh is unchanged', null, { timeout: 10000 });
  await frameDrawn(page);
  assert.equal(await page.$eval('metaballs-view', (e) => e.stats.triangles), five);
  console.log(`marching tetrahedra at 16³: ${six} triangles cut six ways, ${five} five ways (marching cubes ${cubes})`);
  assert.deepEqual(errors, []);
});

test('bad comparison values get the notice and the figure keeps its view', async () => {
  const { page } = await open(`?balls=${BALLS}&res=16&paused=1&compare=sideways&extractor=dual&divider=2`);
  await settledTriangles(page);
  const notice = await page.textContent('#notice');
  for (const fragment of ['compare=sideways', 'one of none, split, overlay', 'extractor=dual',
    'one of marching_cubes, surface_nets, dual_contouring, marching_tetrahedra', 'divider position must be between 0.05 and 0.95, got 2']) {
    assert.ok(notice.includes(fragment), `the notice lacks ${fragment}: ${notice}`);
  }
  const kept = await page.$eval('metaballs-view', (e) => [e.compare, e.extractor, e.divider]);
  assert.deepEqual(kept, ['none', 'marching_cubes', 0.5]);
});

test('figures with one sync name share spheres and camera: turning one turns the other', async () => {
  const { page, errors } = await open('www/examples/lecture.html');
  const figures = '#methods metaballs-view';
  await page.$eval('#methods', (e) => e.scrollIntoView());
  await page.waitForFunction((sel) => [...document.querySelectorAll(sel)].every((e) => e.stats.triangles > 0), figures, { timeout: 60000 });
  const sources = await page.$$eval(figures, (es) => es.map((e) => e.stats.adapter));
  assert.match(sources[1], /SURFACE-NETS/);
  // The spheres move in the first and follow in the second.
  const centres = () => page.$$eval(figures, (es) => es.map((e) => JSON.stringify(e.sphereList.map((s) => s.center.map((c) => c.toFixed(3))))));
  const drawn = await page.$$eval(figures, (es) => es[0].framesDrawn);
  await page.waitForFunction(([sel, n]) => document.querySelector(sel).framesDrawn > n + 3, [figures, drawn]);
  await page.$$eval(figures, (es) => es[0].pause());
  // A frame of each after the pause: the second takes the first one's spheres before it draws.
  await page.$$eval(figures, async (es) => { for (const e of es) await e.nextFrame(); });
  const [lead, follow] = await centres();
  assert.equal(follow, lead, 'the second figure shows the first one\'s spheres');
  // Dragging the camera in the second turns the first.
  const box = await page.$$eval(figures, (es) => {
    const r = es[1].shadowRoot.querySelector('canvas').getBoundingClientRect();
    // On the left, above the row of tabs of a small figure (its statistics are a sheet below).
    return { x: r.x + r.width * 0.2, y: r.y + r.height * 0.4 };
  });
  const before = await page.$$eval(figures, (es) => es.map((e) => e.yaw));
  await page.mouse.move(box.x, box.y);
  await page.mouse.down();
  for (let k = 1; k <= 10; k++) await page.mouse.move(box.x + 6 * k, box.y);
  await page.mouse.up();
  const after = await page.$$eval(figures, (es) => es.map((e) => e.yaw));
  assert.notEqual(after[1], before[1], 'the dragged figure turned');
  assert.equal(after[0], after[1], 'the other figure turned with it');
  assert.deepEqual(errors, []);
});

// The lecture's trio of figures `id`, scrolled to, once each has drawn and measured its error: the page,
// its errors, the figures' selector, and a screenshot of the trio by name.
async function lectureTrio(id) {
  const { page, errors } = await open('www/examples/lecture.html');
  const figures = `#${id} metaballs-view`;
  await page.$eval(`#${id}`, (e) => e.scrollIntoView());
  await page.waitForFunction((sel) => [...document.querySelectorAll(sel)].every((e) => e.stats.triangles > 0 && e.stats.error),
    figures, { timeout: 60000 });
  const shot = (name) => page.locator(`#${id}`).screenshot({ path: path.join(outputDir, `e2e-${name}.png`) });
  return { page, errors, figures, shot };
}

test('the lecture compares marching cubes, surface nets and dual contouring on one union, with counts and errors', async () => {
  const { page, errors, figures, shot } = await lectureTrio('creases');
  await shot('lecture-creases');
  const stats = await page.$$eval(figures, (es) => es.map((e) => ({
    adapter: e.stats.adapter, triangles: e.stats.triangles, max: e.stats.error.max, rms: e.stats.error.rms,
    hud: e.shadowRoot.getElementById('hud-error-text').textContent,
  })));
  assert.match(stats[0].adapter, /CPU|GPU/);
  // The WebGPU page meshes the dual methods in compute shaders.
  assert.match(stats[1].adapter, /GPU-SURFACE-NETS/);
  assert.match(stats[2].adapter, /GPU-DUAL-CONTOURING/);
  // The dual methods make two triangles per crossed edge; all three meshes are of one size.
  for (const s of stats) assert.ok(Math.abs(s.triangles / stats[0].triangles - 1) < 0.1, JSON.stringify(stats));
  // Surface nets' vertices are averages off the surface; dual contouring's sit on it, as the HUD says.
  assert.ok(stats[2].max < stats[1].max / 2, JSON.stringify(stats));
  assert.ok(stats.every((s) => /\d/.test(s.hud)), 'each HUD gives the error');
  // The rank view colours dual contouring's vertices, and its key says what the colours are.
  await page.$$eval(figures, (es) => es[2].setAttribute('color-by', 'rank'));
  await page.waitForFunction((sel) => document.querySelectorAll(sel)[2].shadowRoot.textContent.includes('minimiser'), figures);
  await shot('lecture-creases-rank');
  // The crease's cells are edges (magenta), written by the dual pass on the GPU.
  const handles = await page.$$(figures);
  const edges = await colourShare(handles[2], 'magenta');
  // The crossings' normals (yellow) with dual contouring; surface nets have none.
  await page.$$eval(figures, (es) => es.forEach((e) => { e.setAttribute('color-by', 'none'); e.setAttribute('display', 'normals'); }));
  await page.waitForFunction((sel) => [...document.querySelectorAll(sel)].every((e) => e.display === 'normals'), figures);
  await page.$$eval(figures, (es) => Promise.all(es.map((e) => e.nextFrame())));
  await shot('lecture-creases-normals');
  const crossings = await colourShare(handles[2], 'yellow');
  const none = await colourShare(handles[1], 'yellow');
  console.log(`creases: rank view ${edges.toFixed(4)} edges; crossings ${crossings.toFixed(4)}, surface nets ${none.toFixed(4)}`);
  assert.ok(edges > 0.0005, `the rank view shows the crease's edges: ${edges}`);
  assert.ok(crossings > 0.003 && none < crossings / 20, `crossings ${crossings} against ${none}`);
  assert.deepEqual(errors, []);
});

// The share of a figure's picture in a colour: 'magenta' (a QEF of rank 2, an edge) or 'yellow' (a
// crossing's normal).
function colourShare(figure, colour) {
  return figure.evaluate(async (e, colour) => {
    const image = await createImageBitmap(await e.picture(1));
    const context = new OffscreenCanvas(image.width, image.height).getContext('2d');
    context.drawImage(image, 0, 0);
    const { data } = context.getImageData(0, 0, image.width, image.height);
    let count = 0;
    for (let i = 0; i < data.length; i += 4) {
      const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
      count += colour === 'magenta' ? r > g + 60 && b > g + 60 : r > 170 && g > 130 && b < g - 60;
    }
    return count / (data.length / 4);
  }, colour);
}

test('the lecture cuts cells into tetrahedra both ways, beside marching cubes on the same spheres', async () => {
  const { page, errors } = await open('www/examples/lecture.html');
  const figure = '#tetrahedra metaballs-view';
  await page.$eval('#tetrahedra', (e) => e.scrollIntoView());
  const settled = async (before) => {
    await page.waitForFunction(([sel, b]) => {
      const s = document.querySelector(sel).stats;
      return s.triangles > 0 && s.triangles !== b;
    }, [figure, before], { timeout: 60000 });
    return page.$eval(figure, (e) => ({ adapter: e.stats.adapter, triangles: e.stats.triangles }));
  };
  const six = await settled(0);
  assert.match(six.adapter, /TETRAHEDRA/);
  await page.locator('#tetrahedra').screenshot({ path: path.join(outputDir, 'e2e-lecture-tetrahedra-six.png') });
  await page.$eval(figure, (e) => e.setAttribute('split', 'five'));
  const five = await settled(six.triangles);
  await page.locator('#tetrahedra').screenshot({ path: path.join(outputDir, 'e2e-lecture-tetrahedra-five.png') });
  await page.$eval(figure, (e) => e.setAttribute('method', 'marching_cubes'));
  const cubes = await settled(five.triangles);
  console.log(`tetrahedra: six ${six.triangles}, five ${five.triangles}, marching cubes ${cubes.triangles} triangles`);
  // Five tetrahedra a cell cut fewer triangles than six, and both more than marching cubes.
  assert.ok(six.triangles > five.triangles && five.triangles > cubes.triangles, JSON.stringify([six, five, cubes]));
  // The counts the figure's caption gives.
  const caption = await page.textContent('#tetrahedra figcaption');
  for (const { triangles } of [six, five, cubes]) assert.ok(caption.includes(triangles.toLocaleString('en')), `${triangles}: ${caption}`);
  assert.deepEqual(errors, []);
});

test('the lecture compares the kernels on the same spheres, each measured against its own exact surface', async () => {
  const { page, errors, figures, shot } = await lectureTrio('kernels');
  await shot('lecture-kernels');
  const stats = await page.$$eval(figures, (es) => es.map((e) => ({
    kernel: e.kernel, triangles: e.stats.triangles, max: e.stats.error.max, rms: e.stats.error.rms,
  })));
  console.log(`kernels: ${JSON.stringify(stats)}`);
  assert.deepEqual(stats.map((s) => s.kernel), ['inverse_square', 'blinn', 'wyvill']);
  // Three different surfaces, each meshed as closely to its own field as marching cubes meshes any.
  assert.equal(new Set(stats.map((s) => s.triangles)).size, 3, JSON.stringify(stats));
  for (const s of stats) assert.ok(s.max < 0.5 && s.rms < 0.1, JSON.stringify(s));
  // Blinn's blobbiness, from the figure's own slider: a faster fall, fewer triangles where spheres join.
  const blinn = stats[1].triangles;
  await page.$$eval(figures, (es) => es[1].setAttribute('blobbiness', '6'));
  await page.waitForFunction(([sel, before]) => document.querySelectorAll(sel)[1].stats.triangles !== before,
    [figures, blinn], { timeout: 60000 });
  assert.deepEqual(errors, []);
});
