// The page's thread stays free while figures animate: four figures of 128³ cells × 16 spheres mesh in
// the page's mesher worker (SwiftShader meshes on the CPU) and the page's thread is not blocked once
// they draw; without module workers they mesh on the page's thread as before. Either way the figures draw,
// take their pictures for print and come back after a lost device.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useServerAndBrowser, openClosedAfterEach, pixelStats } from './helpers.js';

useServerAndBrowser();

const open = openClosedAfterEach({ viewport: { width: 960, height: 700 } });
const FOUR = 'tests/e2e/fixtures/grid.html?n=4&cols=2&res=128&spheres=16';
// How long the long tasks are counted, in ms, and the most blocking time (the target of a page whose
// figures never block it: Lighthouse's total blocking time of 200 ms for a whole load) they may add up to.
const WATCHED_MS = 10_000;
const BLOCKING_MS = 200;

// Counts the page's long tasks from its start (before any script of the page).
function watchLongTasks() {
  window.longTasks = [];
  new PerformanceObserver((list) => {
    for (const entry of list.getEntries()) window.longTasks.push({ start: entry.startTime, ms: entry.duration });
  }).observe({ type: 'longtask', buffered: true });
}

// Hides the page's Worker, as in a browser without module workers.
function noWorkers() {
  delete window.Worker;
}

const allDrawn = (page, frames) => page.waitForFunction((n) => {
  const figures = [...document.querySelectorAll('metaballs-view')];
  return figures.length === 4 && figures.every((e) => e.framesDrawn >= n && e.stats?.triangles > 0);
}, frames, { timeout: 90_000 });
const framesOf = (page) => page.evaluate(() => [...document.querySelectorAll('metaballs-view')].map((e) => e.framesDrawn));

test('four animating figures of 128³ × 16 spheres mesh off the page\'s thread: it is not blocked once they draw', async () => {
  const { page, errors } = await open(FOUR, { initScript: watchLongTasks });
  await allDrawn(page, 3);
  assert.equal(await page.evaluate(() => customElements.get('metaballs-view').meshingOffThread), true);
  const from = await page.evaluate(() => performance.now());
  const before = await framesOf(page);
  await page.waitForTimeout(WATCHED_MS);
  const after = await framesOf(page);
  const tasks = await page.evaluate((t) => window.longTasks.filter((task) => task.start >= t), from);
  const drawn = after.map((n, i) => n - before[i]);
  console.log(`in ${WATCHED_MS / 1000} s: frames ${drawn.join(', ')}; long tasks ${tasks.length}`
    + `${tasks.length ? ` (${tasks.map((task) => Math.round(task.ms)).join(', ')} ms)` : ''}`);
  assert.ok(drawn.every((n) => n >= 5), `the figures drew ${drawn.join(', ')} frames in ${WATCHED_MS / 1000} s`);
  // Blocking time as Lighthouse counts it: each long task's time past 50 ms. On two cores shared with
  // SwiftShader's rasteriser and the worker, a task of a few milliseconds of the thread's own work can
  // still wait that long for a core; meshing on the page's thread blocks it for seconds.
  const blocking = tasks.reduce((sum, task) => sum + Math.max(0, task.ms - 50), 0);
  assert.ok(blocking <= BLOCKING_MS, `${Math.round(blocking)} ms of blocking time in ${WATCHED_MS / 1000} s`);
  assert.deepEqual(errors, []);
});

// Counts the page's animation frames from its start.
function countAnimationFrames() {
  window.animationFrames = 0;
  const count = () => { window.animationFrames += 1; requestAnimationFrame(count); };
  requestAnimationFrame(count);
}

const LIGHT = 'tests/e2e/fixtures/grid.html?n=1&cols=1&aspect=3/2&res=32&spheres=4';
// The share of animation frames a lightly meshed figure draws on at least, meshed by the worker: each
// mesh is made while the frame before it shows, so none waits a whole animation frame for its own.
const DRAWN_SHARE = 0.8;

test('a lightly meshed figure meshed by the worker draws on nearly every animation frame', async () => {
  const { page, errors } = await open(LIGHT, { initScript: countAnimationFrames });
  await page.waitForFunction(() => document.querySelector('metaballs-view')?.framesDrawn >= 30, null, { timeout: 60_000 });
  assert.equal(await page.evaluate(() => customElements.get('metaballs-view').meshingOffThread), true);
  const counts = () => page.evaluate(() => [window.animationFrames, document.querySelector('metaballs-view').framesDrawn]);
  const [framesBefore, drawnBefore] = await counts();
  await page.waitForTimeout(4000);
  const [framesAfter, drawnAfter] = await counts();
  const [frames, drawn] = [framesAfter - framesBefore, drawnAfter - drawnBefore];
  console.log(`32³ × 4 spheres meshed by the worker: drawn on ${drawn} of ${frames} animation frames`);
  assert.ok(frames > 20, `only ${frames} animation frames in 4 s`);
  assert.ok(drawn >= DRAWN_SHARE * frames, `drawn on ${drawn} of ${frames} animation frames`);
  assert.deepEqual(errors, []);
});

// The page's pool of mesher workers, whatever the machine's cores: one, or two that mesh a grid in slabs.
const oneWorker = () => { window.metaballsMeshWorkers = 1; };
const twoWorkers = () => { window.metaballsMeshWorkers = 2; };

// Spheres placed by hand, as `sphere-list` takes them.
const PLACED = ['-0.4,0,0,0.32;0.4,0.05,0,0.3;0,0.45,0.1,0.25', '-0.2,-0.3,0,0.4;0.5,0.4,-0.2,0.22'];

test('a paused figure draws exactly the spheres set, with one worker, with two meshing in slabs, and on the page\'s thread', async () => {
  const drawnTriangles = async (initScript) => {
    const { page, errors } = await open(LIGHT.replace('res=32', 'res=64'), initScript ? { initScript } : {});
    await page.waitForFunction(() => document.querySelector('metaballs-view')?.framesDrawn >= 3, null, { timeout: 60_000 });
    const triangles = await page.evaluate(async (placed) => {
      const figure = document.querySelector('metaballs-view');
      figure.pause();
      const out = [];
      for (const list of [placed[0], placed[1], placed[0]]) {
        figure.setAttribute('sphere-list', list);
        out.push((await figure.nextFrame()).triangles);
      }
      // A list set while the last one's mesh may still be on its way: the frame asked for is of the last.
      figure.setAttribute('sphere-list', placed[0]);
      await new Promise(requestAnimationFrame);
      figure.setAttribute('sphere-list', placed[1]);
      out.push((await figure.nextFrame()).triangles);
      return out;
    }, PLACED);
    const offThread = await page.evaluate(() => customElements.get('metaballs-view').meshingOffThread);
    assert.deepEqual(errors, []);
    await page.context().close();
    return { triangles, offThread };
  };
  const worker = await drawnTriangles(oneWorker);
  const pool = await drawnTriangles(twoWorkers);
  const here = await drawnTriangles(noWorkers);
  console.log(`triangles drawn of the lists set: one worker ${worker.triangles.join(', ')}; two workers, in slabs `
    + `${pool.triangles.join(', ')}; page's thread ${here.triangles.join(', ')}`);
  assert.equal(worker.offThread, true);
  assert.equal(pool.offThread, true);
  assert.equal(here.offThread, false);
  assert.deepEqual(worker.triangles, here.triangles);
  assert.deepEqual(pool.triangles, here.triangles);
  const [first, second, again, last] = worker.triangles;
  assert.notEqual(first, second);
  assert.equal(again, first);
  assert.equal(last, second);
});

// Counts the meshes asked of the page's mesher workers (whole grids and slabs).
function countJobs() {
  window.jobsPosted = 0;
  const post = Worker.prototype.postMessage;
  Worker.prototype.postMessage = function postMessage(data, ...rest) {
    if (data?.job) window.jobsPosted += 1;
    return post.call(this, data, ...rest);
  };
}

test('a paused figure turned by its camera draws each frame from the mesh it has, without meshing again', async () => {
  const { page, errors } = await open(LIGHT.replace('res=32', 'res=64'), { initScript: [oneWorker, countJobs] });
  await page.waitForFunction(() => document.querySelector('metaballs-view')?.framesDrawn >= 3, null, { timeout: 60_000 });
  assert.equal(await page.evaluate(() => customElements.get('metaballs-view').meshingOffThread), true);
  const seen = await page.evaluate(async () => {
    const figure = document.querySelector('metaballs-view');
    figure.pause();
    // Two frames: a mesh the worker was asked for before the pause took effect is not the turning's.
    await figure.nextFrame();
    await figure.nextFrame();
    const [jobs, drawn] = [window.jobsPosted, figure.framesDrawn];
    for (let yaw = 10; yaw <= 80; yaw += 10) {
      figure.yaw = yaw;
      await figure.nextFrame();
    }
    const turned = [window.jobsPosted - jobs, figure.framesDrawn - drawn];
    // A change to what the mesh is made of is meshed again.
    figure.iso = figure.iso * 1.1;
    await figure.nextFrame();
    return { turned, changed: window.jobsPosted - jobs - turned[0] };
  });
  console.log(`turned 8 times: ${seen.turned[1]} frames drawn, ${seen.turned[0]} meshes asked of the worker; `
    + `the iso level changed: ${seen.changed}`);
  assert.ok(seen.turned[1] >= 8, `${seen.turned[1]} frames drawn for 8 turns`);
  assert.equal(seen.turned[0], 0, 'the camera turning meshed the same spheres again');
  assert.ok(seen.changed >= 1, 'a new iso level was not meshed');
  assert.deepEqual(errors, []);
});

for (const [path, initScript] of [['the mesher worker', null], ['the page\'s thread', noWorkers]]) {
  test(`meshing on ${path}: the figures draw, print and come back after a lost device`, async () => {
    const { page, errors } = await open(FOUR, initScript ? { initScript } : {});
    await allDrawn(page, 2);
    assert.equal(await page.evaluate(() => customElements.get('metaballs-view').meshingOffThread), !initScript);
    // A paused figure asked for a frame draws one, with its whole mesh.
    const triangles = await page.evaluate(async () => {
      const figure = document.querySelector('metaballs-view');
      figure.pause();
      return (await figure.nextFrame()).triangles;
    });
    console.log(`meshing on ${path}: the first figure, paused, draws ${triangles} triangles`);
    assert.ok(triangles > 10_000, `${triangles} triangles at 128³ × 16 spheres`);

    // Pictures for print, taken of drawn frames.
    await page.evaluate(() => Promise.all([...document.querySelectorAll('metaballs-view')].map((e) => e.printable())));
    const picture = await page.evaluate(async () => {
      const image = document.querySelector('metaballs-view').shadowRoot.getElementById('print-frame');
      await image.decode();
      const canvas = Object.assign(document.createElement('canvas'), { width: image.naturalWidth, height: image.naturalHeight });
      canvas.getContext('2d').drawImage(image, 0, 0);
      return { width: image.naturalWidth, url: canvas.toDataURL('image/png') };
    });
    assert.ok(picture.width > 100, `the picture for print is ${picture.width} pixels wide`);
    const { surface } = await pixelStats(page, Buffer.from(picture.url.split(',')[1], 'base64'));
    assert.ok(surface > 0.01, `the picture for print shows ${(surface * 100).toFixed(2)}% of surface`);

    // A lost device: every figure draws again.
    const before = await framesOf(page);
    await page.evaluate(() => customElements.get('metaballs-view').destroyDevice());
    await page.waitForFunction(() => customElements.get('metaballs-view').devicesCreated === 2, null, { timeout: 60_000 });
    await page.waitForFunction((b) => [...document.querySelectorAll('metaballs-view')].every((e, i) => e.framesDrawn > b[i] + 2),
      before, { timeout: 60_000 });
    assert.deepEqual(errors.filter((e) => !/lost|destroy/i.test(e)), []);
  });
}
