// What a reader sees of animating figures in headless Chromium (SwiftShader here): frames drawn per
// second over `--seconds` (10) after `--settle` (6) seconds, the share of the page's animation frames
// each figure drew on, and the render scale it settled at, for one figure of 32³ cells × 4 spheres and
// of 128³ × 16 (960×640) and four of 128³ × 16 in a 960-pixel-wide 2×2 grid, each with the page's
// mesher workers and without them (`Worker` removed), on WebGPU and on WebGL2 (`navigator.gpu`
// removed); then the page's `?bench` CPU mesh and frame times at 64³ and 128³ × 16 against three.js's
// `MarchingCubes` (r187, from npm) timed the same way in the same browser (fixtures/three-bench.html).
// `npm run bench:figures` (after www/build.sh). Options: `--root DIR`, repeatable, measures other
// checkouts built the same way, interleaved with this one, for a before and after in one run;
// `--passes N` (1) repeats everything; `--only TEXT` keeps the cases whose name holds TEXT; `--fixed`
// holds every figure at full render scale; `--workers N` starts N mesher workers whatever the cores;
// `--threads` also says, per case, how busy each of the browser's threads was over the same seconds
// (from a trace: wall and CPU milliseconds per second of its top-level tasks), which shows whether
// the page, the mesher worker or the GPU process (SwiftShader's rasteriser behind its main thread)
// holds the frames back; and a canvas of the same size only cleared every animation frame (the floor:
// what the browser's compositing and presenting alone allow). One more case, "turned while paused", draws a still 128³ × 16 figure whose
// camera turns every animation frame: the mesh is kept, so it is the rate of drawing alone, at full
// scale and at the pixels of the lowest render scale.
// Prints a line per measurement and a JSON line starting "metaballs-figures ". Not a test: figures
// depend on the machine.

import path from 'node:path';
import { chromium } from 'playwright-core';
import { root as here, CHROMIUM, FLAGS, serve } from './helpers.js';

const values = (name) => process.argv.flatMap((a, i) => (a === `--${name}` ? [process.argv[i + 1]] : []));
const number = (name, fallback) => Number(values(name)[0] ?? fallback);
const roots = [here, ...values('root').map((r) => path.resolve(r))];
const seconds = number('seconds', 10);
const settle = number('settle', 6);
const passes = number('passes', 1);
const only = values('only')[0] ?? '';
const fixed = process.argv.includes('--fixed');
const workers = values('workers')[0];
const threads = process.argv.includes('--threads');

const CASES = [
  { name: 'one figure 32³ × 4', query: 'n=1&cols=1&aspect=3/2&res=32&spheres=4' },
  { name: 'one figure 128³ × 16', query: 'n=1&cols=1&aspect=3/2&res=128&spheres=16' },
  { name: 'four figures 128³ × 16', query: 'n=4&cols=2&res=128&spheres=16' },
].flatMap((c) => ['WebGPU', 'WebGL2'].flatMap((api) => [true, false].map((worker) => ({
  ...c, api, worker, name: `${c.name}, ${api}, ${worker ? 'workers' : 'no worker'}`,
})))).concat(['WebGPU', 'WebGL2'].flatMap((api) => [1, 0.5].map((ratio) => ({
  name: `one figure 128³ × 16 turned while paused${ratio < 1 ? ', half the pixels' : ''}, ${api}`,
  query: 'n=1&cols=1&aspect=3/2&res=128&spheres=16', api, worker: true, turn: ratio,
})))).filter((c) => c.name.includes(only));

// Before the page's scripts: its animation frames counted; the Worker or WebGPU taken away.
function countAnimationFrames() {
  window.animationFrames = 0;
  const count = () => { window.animationFrames += 1; requestAnimationFrame(count); };
  requestAnimationFrame(count);
}
const noWorker = () => { delete window.Worker; };
const noWebgpu = () => { delete Navigator.prototype.gpu; };
const fixedScale = () => { window.metaballsFixedScale = true; };
const poolOf = (n) => { window.metaballsMeshWorkers = n; };

// Pauses every figure and turns its camera by a degree each animation frame, at `ratio` CSS pixels per
// pixel at most (0.5: the pixels an animating figure draws at its lowest render scale).
function turnWhilePaused(ratio) {
  for (const figure of document.querySelectorAll('metaballs-view')) {
    figure.pause();
    figure.setAttribute('max-pixel-ratio', String(ratio));
    const turn = () => {
      figure.yaw = (figure.yaw + 1) % 360;
      requestAnimationFrame(turn);
    };
    requestAnimationFrame(turn);
  }
}

// Wall and CPU milliseconds per second of each thread's top-level tasks in a trace over `seconds`,
// the busiest by CPU first: "process / thread".
function busyThreads(trace, seconds) {
  const events = JSON.parse(trace.toString()).traceEvents;
  const names = new Map();
  const processes = new Map();
  for (const e of events) {
    if (e.name === 'thread_name') names.set(`${e.pid}:${e.tid}`, e.args.name);
    if (e.name === 'process_name') processes.set(e.pid, e.args.name);
  }
  const busy = new Map();
  for (const e of events) {
    if (e.ph !== 'X' || !e.cat?.split(',').includes('toplevel')) continue;
    const key = `${processes.get(e.pid) ?? e.pid} / ${names.get(`${e.pid}:${e.tid}`) ?? e.tid}`;
    const b = busy.get(key) ?? { wall_ms: 0, cpu_ms: 0 };
    b.wall_ms += e.dur / 1000 / seconds;
    b.cpu_ms += (e.tdur ?? 0) / 1000 / seconds;
    busy.set(key, b);
  }
  return [...busy].sort((a, b) => b[1].cpu_ms - a[1].cpu_ms).slice(0, 4)
    .map(([thread, b]) => ({ thread, wall_ms: Math.round(b.wall_ms), cpu_ms: Math.round(b.cpu_ms) }));
}

async function figures(browser, base, { query, api, worker, turn }) {
  const context = await browser.newContext({ viewport: { width: 960, height: 700 } });
  const page = await context.newPage();
  for (const script of [countAnimationFrames, worker ? null : noWorker, api === 'WebGL2' ? noWebgpu : null,
    fixed ? fixedScale : null].filter(Boolean)) await page.addInitScript(script);
  if (workers) await page.addInitScript(poolOf, Number(workers));
  try {
    await page.goto(`${base}tests/e2e/fixtures/grid.html?${query}`);
    await page.waitForFunction(() => [...document.querySelectorAll('metaballs-view')].every((e) => e.stats?.triangles > 0),
      null, { timeout: 120_000 });
    if (turn) await page.evaluate(turnWhilePaused, turn);
    await page.waitForTimeout(settle * 1000);
    const count = () => page.evaluate(() => ({
      frames: window.animationFrames,
      drawn: [...document.querySelectorAll('metaballs-view')].map((e) => e.framesDrawn),
    }));
    if (threads) await browser.startTracing(page, { categories: ['toplevel', '__metadata'] });
    const start = await count();
    await page.waitForTimeout(seconds * 1000);
    const end = await count();
    const busy = threads ? busyThreads(await browser.stopTracing(), seconds) : undefined;
    const seen = await page.evaluate(() => [...document.querySelectorAll('metaballs-view')].map((e) => ({
      scale: e.renderScale, adapter: e.stats?.adapter,
    })));
    const frames = end.frames - start.frames;
    const drawn = end.drawn.map((n, i) => n - start.drawn[i]);
    return {
      fps: drawn.map((n) => Math.round((n / seconds) * 10) / 10),
      animation_fps: Math.round((frames / seconds) * 10) / 10,
      drawn_share: Math.round((Math.min(...drawn) / frames) * 100) / 100,
      render_scale: seen.map((s) => s.scale),
      adapter: seen[0]?.adapter,
      busy,
    };
  } finally {
    await context.close();
  }
}

// The floor under every figure's frame rate in this browser: a canvas of the one figure's size
// (fixtures/clear-canvas.html) cleared every animation frame and nothing else drawn, frames per second.
async function floor(browser, base, api, ratio) {
  const page = await browser.newPage({ viewport: { width: 960, height: 700 } });
  try {
    await page.addInitScript(countAnimationFrames);
    await page.goto(`${base}tests/e2e/fixtures/clear-canvas.html?api=${api.toLowerCase()}&ratio=${ratio}`);
    await page.waitForFunction(() => window.framesDrawn > 10, null, { timeout: 60_000 });
    await page.waitForTimeout(2000);
    const count = () => page.evaluate(() => [window.framesDrawn, window.animationFrames]);
    const [drawn, frames] = await count();
    await page.waitForTimeout(seconds * 1000);
    const [drawnAfter, framesAfter] = await count();
    return { fps: round((drawnAfter - drawn) / seconds), animation_fps: round((framesAfter - frames) / seconds) };
  } finally {
    await page.close();
  }
}

// Records logged on the console as a line starting with `prefix`, by the page at `url`.
async function logged(browser, url, prefix) {
  const page = await browser.newPage({ viewport: { width: 960, height: 640 } });
  try {
    const line = new Promise((resolve) => {
      page.on('console', (message) => {
        if (message.text().startsWith(prefix)) resolve(JSON.parse(message.text().slice(prefix.length)));
      });
    });
    await page.goto(url);
    return await Promise.race([line, page.waitForTimeout(300_000).then(() => null)]);
  } finally {
    await page.close();
  }
}

const ours = async (browser, base) => {
  const rows = await logged(browser, `${base}index.html?bench&bench_meshers=cpu&bench_resolutions=64,128&bench_spheres=16`
    + '&bench_lod=0&bench_frames=40', 'metaballs-bench ');
  return Object.fromEntries((rows ?? []).filter((r) => !r.lod)
    .map((r) => [r.resolution, { mesh_ms: r.mesh_ms, alone_ms: r.alone_ms, frame_ms: r.frame_ms }]));
};
const three = async (browser, base, res) => logged(browser, `${base}tests/e2e/fixtures/three-bench.html?res=${res}&spheres=16&frames=40`,
  'three-bench ');

const round = (x) => Math.round(x * 10) / 10;
const servers = await Promise.all(roots.map(serve));
const browser = await chromium.launch({ executablePath: CHROMIUM, args: FLAGS, headless: true });
const results = [];
try {
  for (let pass = 1; pass <= passes; pass++) {
    for (const c of CASES) {
      for (const [k, { base }] of servers.entries()) {
        const seen = await figures(browser, base, c);
        results.push({ pass, root: roots[k], case: c.name, ...seen });
        console.log(`${c.name}${roots.length > 1 ? ` [${roots[k]}]` : ''}: ${seen.fps.join(' / ')} fps, drawn on `
          + `${Math.round(seen.drawn_share * 100)} % of ${seen.animation_fps} animation frames/s, render scale `
          + `${seen.render_scale.map((s) => s?.toFixed(2)).join(', ')} (${seen.adapter})`);
        for (const b of seen.busy ?? []) console.log(`    ${b.thread}: busy ${b.wall_ms} ms/s, CPU ${b.cpu_ms} ms/s`);
      }
    }
    for (const api of ['WebGPU', 'WebGL2']) {
      for (const ratio of [1, 0.5]) {
        const name = `cleared canvas, ${api}, ratio ${ratio}`;
        if (!name.includes(only)) continue;
        const seen = await floor(browser, servers[0].base, api, ratio);
        results.push({ pass, case: name, ...seen });
        console.log(`a 960×640 canvas at ${ratio} pixels per CSS pixel, only cleared every frame, ${api}: `
          + `${seen.fps} fps of ${seen.animation_fps} animation frames/s`);
      }
    }
    for (const [k, { base }] of servers.entries()) {
      const mine = await ours(browser, base);
      results.push({ pass, root: roots[k], case: '?bench', ...mine });
      console.log(`?bench CPU mesher, 16 spheres${roots.length > 1 ? ` [${roots[k]}]` : ''}: `
        + Object.entries(mine).map(([n, r]) => `${n}³ mesh ${round(r.mesh_ms)} ms (the mesher alone `
          + `${r.alone_ms == null ? '–' : round(r.alone_ms)} ms), frame ${round(r.frame_ms)} ms`).join('; '));
    }
    for (const res of [64, 128]) {
      const theirs = await three(browser, servers[0].base, res);
      results.push({ pass, case: `three.js ${res}`, ...theirs });
      if (theirs) {
        console.log(`three.js MarchingCubes ${res}³ × 16: mesh ${round(theirs.mesh_ms)} ms, frame ${round(theirs.frame_ms)} ms `
          + `(${theirs.triangles} triangles)`);
      }
    }
  }
} finally {
  await browser.close();
  for (const server of servers) server.stop();
}
console.log(`metaballs-figures ${JSON.stringify(results)}`);
