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
// holds every figure at full render scale; `--workers N` starts N mesher workers whatever the cores.
// Prints a line per measurement and a JSON line starting "metaballs-figures ". Not a test: figures
// depend on the machine.

import { spawn } from 'node:child_process';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { root as here, CHROMIUM, FLAGS, freePort, waitForServer } from './helpers.js';

const values = (name) => process.argv.flatMap((a, i) => (a === `--${name}` ? [process.argv[i + 1]] : []));
const number = (name, fallback) => Number(values(name)[0] ?? fallback);
const roots = [here, ...values('root').map((r) => path.resolve(r))];
const seconds = number('seconds', 10);
const settle = number('settle', 6);
const passes = number('passes', 1);
const only = values('only')[0] ?? '';
const fixed = process.argv.includes('--fixed');
const workers = values('workers')[0];

const CASES = [
  { name: 'one figure 32³ × 4', query: 'n=1&cols=1&aspect=3/2&res=32&spheres=4' },
  { name: 'one figure 128³ × 16', query: 'n=1&cols=1&aspect=3/2&res=128&spheres=16' },
  { name: 'four figures 128³ × 16', query: 'n=4&cols=2&res=128&spheres=16' },
].flatMap((c) => ['WebGPU', 'WebGL2'].flatMap((api) => [true, false].map((worker) => ({
  ...c, api, worker, name: `${c.name}, ${api}, ${worker ? 'workers' : 'no worker'}`,
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

function serve(directory) {
  return freePort().then(async (port) => {
    const server = spawn('python3', ['-m', 'http.server', '--bind', '127.0.0.1', String(port), '--directory', directory],
      { stdio: 'ignore' });
    const base = `http://127.0.0.1:${port}/`;
    await waitForServer(base);
    return { base, stop: () => server.kill() };
  });
}

async function figures(browser, base, { query, api, worker }) {
  const context = await browser.newContext({ viewport: { width: 960, height: 700 } });
  const page = await context.newPage();
  for (const script of [countAnimationFrames, worker ? null : noWorker, api === 'WebGL2' ? noWebgpu : null,
    fixed ? fixedScale : null].filter(Boolean)) await page.addInitScript(script);
  if (workers) await page.addInitScript(poolOf, Number(workers));
  try {
    await page.goto(`${base}tests/e2e/fixtures/grid.html?${query}`);
    await page.waitForFunction(() => [...document.querySelectorAll('metaballs-view')].every((e) => e.stats?.triangles > 0),
      null, { timeout: 120_000 });
    await page.waitForTimeout(settle * 1000);
    const count = () => page.evaluate(() => ({
      frames: window.animationFrames,
      drawn: [...document.querySelectorAll('metaballs-view')].map((e) => e.framesDrawn),
    }));
    const start = await count();
    await page.waitForTimeout(seconds * 1000);
    const end = await count();
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
    };
  } finally {
    await context.close();
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
    + '&bench_lod=0&bench_frames=10', 'metaballs-bench ');
  return Object.fromEntries((rows ?? []).filter((r) => !r.lod).map((r) => [r.resolution, { mesh_ms: r.mesh_ms, frame_ms: r.frame_ms }]));
};
const three = async (browser, base, res) => logged(browser, `${base}tests/e2e/fixtures/three-bench.html?res=${res}&spheres=16`,
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
      }
    }
    for (const [k, { base }] of servers.entries()) {
      const mine = await ours(browser, base);
      results.push({ pass, root: roots[k], case: '?bench', ...mine });
      console.log(`?bench CPU mesher, 16 spheres${roots.length > 1 ? ` [${roots[k]}]` : ''}: `
        + Object.entries(mine).map(([n, r]) => `${n}³ mesh ${round(r.mesh_ms)} ms, frame ${round(r.frame_ms)} ms`).join('; '));
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
