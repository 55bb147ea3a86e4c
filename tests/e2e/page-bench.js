// What a page with figures weighs and how it feels, in headless Chromium (SwiftShader here):
// - each wasm build's size, raw and gzipped (`gzip -9`, as www/build.sh and the budget test measure it);
// - index.html as dist/ serves it: the time from navigation to its figure's first drawn frame and to its
//   first statistics, median of five cold loads (each in a fresh context);
// - long tasks (a `PerformanceObserver` for `longtask`) on the page's thread over 15 s of animation after the
//   first frame, on index.html, the example lecture and four figures of 128³ cells × 16 spheres in a
//   960-pixel grid;
// - the CPU mesher's time at 64³ and 128³ cells × 16 spheres, from the page's `?bench`.
// `npm run bench:page` (after www/dist.sh); `-- --root DIR` measures another checkout built the same way
// (its dist/ and pkg/), for a before and after in one run; `-- --seconds N` watches each page N seconds.
// Prints a line per figure and a JSON line starting "metaballs-page ". Not a test: times depend on the
// machine.

import { execFileSync, spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { root as here, CHROMIUM, FLAGS, freePort, waitForServer } from './helpers.js';

const argument = (name, fallback) => {
  const at = process.argv.indexOf(`--${name}`);
  return at > 0 ? process.argv[at + 1] : fallback;
};
const root = path.resolve(argument('root', here));
const seconds = Number(argument('seconds', 15));
// `--sources`: the pages as the source tree serves them (every module on its own), without dist/.
const site = process.argv.includes('--sources') ? '' : 'dist/';
const LOADS = 5;

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
const round = (value) => Math.round(value);

// Serves `directory` on a free port for the length of `f(url)`.
async function serving(directory, f) {
  const port = await freePort();
  const server = spawn('python3', ['-m', 'http.server', '--bind', '127.0.0.1', String(port), '--directory', directory],
    { stdio: 'ignore' });
  try {
    await waitForServer(`http://127.0.0.1:${port}/`);
    return await f(`http://127.0.0.1:${port}/`);
  } finally {
    server.kill();
  }
}

// Before any script of the page: the long tasks from the start, and the times of the first figure's
// first frame and first statistics.
function watchPage() {
  window.longTasks = [];
  new PerformanceObserver((list) => {
    for (const entry of list.getEntries()) window.longTasks.push({ start: entry.startTime, ms: entry.duration });
  }).observe({ type: 'longtask', buffered: true });
  const watch = () => {
    const figure = document.querySelector('metaballs-view');
    if (!window.firstFrameMs && figure?.framesDrawn > 0) window.firstFrameMs = performance.now();
    if (!window.firstStatsMs && figure?.stats?.triangles > 0) window.firstStatsMs = performance.now();
    if (!window.firstStatsMs) requestAnimationFrame(watch);
  };
  requestAnimationFrame(watch);
}

async function firstFrames(browser, base) {
  const frames = [];
  const stats = [];
  for (let i = 0; i < LOADS; i++) {
    const context = await browser.newContext({ viewport: { width: 960, height: 640 } });
    const page = await context.newPage();
    await page.addInitScript(watchPage);
    await page.goto(`${base}index.html`);
    await page.waitForFunction(() => window.firstStatsMs > 0, null, { timeout: 60_000 });
    const seen = await page.evaluate(() => [window.firstFrameMs, window.firstStatsMs]);
    frames.push(seen[0]);
    stats.push(seen[1]);
    await context.close();
  }
  return { first_frame_ms: round(median(frames)), first_stats_ms: round(median(stats)), frames: frames.map(round), stats: stats.map(round) };
}

// Long tasks on `url` during `seconds` of animation after every figure on it has drawn.
async function longTasks(browser, url) {
  const context = await browser.newContext({ viewport: { width: 960, height: 700 } });
  const page = await context.newPage();
  await page.addInitScript(watchPage);
  await page.goto(url);
  await page.waitForFunction(() => {
    const figures = [...document.querySelectorAll('metaballs-view')];
    return figures.length > 0 && figures.every((e) => e.getBoundingClientRect().top > innerHeight || e.framesDrawn > 0);
  }, null, { timeout: 120_000 });
  const from = await page.evaluate(() => performance.now());
  await page.waitForTimeout(seconds * 1000);
  const tasks = await page.evaluate((t) => window.longTasks.filter((task) => task.start >= t), from);
  const before = await page.evaluate((t) => window.longTasks.filter((task) => task.start < t), from);
  const frames = await page.evaluate(() => [...document.querySelectorAll('metaballs-view')].map((e) => e.framesDrawn));
  await context.close();
  const durations = tasks.map((task) => task.ms);
  return {
    count: tasks.length,
    longest_ms: round(Math.max(0, ...durations)),
    blocking_ms: round(durations.reduce((sum, ms) => sum + Math.max(0, ms - 50), 0)),
    before_first_frame: { count: before.length, longest_ms: round(Math.max(0, ...before.map((task) => task.ms))) },
    frames_drawn: frames,
  };
}

// The CPU mesher's median mesh time at `resolutions` × 16 spheres, from the page's benchmark.
async function cpuMeshTimes(browser, base) {
  const page = await browser.newPage({ viewport: { width: 960, height: 640 } });
  const records = new Promise((resolve) => {
    page.on('console', (message) => {
      const text = message.text();
      if (text.startsWith('metaballs-bench ')) resolve(JSON.parse(text.slice('metaballs-bench '.length)));
    });
  });
  await page.goto(`${base}index.html?bench&bench_meshers=cpu&bench_resolutions=64,128&bench_spheres=16&bench_lod=0&bench_frames=10`);
  const rows = await Promise.race([records, page.waitForTimeout(300_000).then(() => [])]);
  await page.close();
  return Object.fromEntries(rows.filter((r) => !r.lod).map((r) => [`${r.resolution}`, Math.round(r.mesh_ms * 10) / 10]));
}

const sizes = {};
for (const build of ['pkg', 'pkg-webgl']) {
  const file = path.join(root, build, 'metaballs_bg.wasm');
  const bytes = readFileSync(file);
  sizes[build] = { raw: bytes.length, gzip: execFileSync('gzip', ['-9c', file], { maxBuffer: 64 << 20 }).length };
  console.log(`${build}/metaballs_bg.wasm: ${bytes.length} bytes, ${sizes[build].gzip} gzipped`);
}

const browser = await chromium.launch({ executablePath: CHROMIUM, args: FLAGS, headless: true });
const result = { root, sizes };
try {
  await serving(path.join(root, site), async (base) => {
    result.index = await firstFrames(browser, base);
    console.log(`index.html: first frame ${result.index.first_frame_ms} ms, first statistics ${result.index.first_stats_ms} ms `
      + `after navigation (median of ${LOADS}: ${result.index.frames.join(', ')} / ${result.index.stats.join(', ')})`);
  });
  await serving(root, async (base) => {
    result.long_tasks = {};
    const pages = {
      index: `${base}${site}index.html`,
      lecture: `${base}${site}www/examples/lecture.html`,
      four_figures: `${base}tests/e2e/fixtures/grid.html?n=4&cols=2&res=128&spheres=16`,
    };
    for (const [name, url] of Object.entries(pages)) {
      const seen = await longTasks(browser, url);
      result.long_tasks[name] = seen;
      console.log(`${name}: ${seen.count} long tasks in ${seconds} s after the first frame, longest ${seen.longest_ms} ms, `
        + `${seen.blocking_ms} ms blocking; before it ${seen.before_first_frame.count}, longest `
        + `${seen.before_first_frame.longest_ms} ms; frames ${seen.frames_drawn.join(', ')}`);
    }
    result.cpu_mesh_ms = await cpuMeshTimes(browser, `${base}${site}`);
    console.log(`CPU mesher, 16 spheres: ${Object.entries(result.cpu_mesh_ms).map(([n, ms]) => `${n}³ ${ms} ms`).join(', ')}`);
  });
} finally {
  await browser.close();
}
console.log(`metaballs-page ${JSON.stringify(result)}`);
