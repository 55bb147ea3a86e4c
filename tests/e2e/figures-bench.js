// Frames per second of pages of animating figures in headless Chromium (SwiftShader here), 128³ cells
// and 16 spheres each: one figure 960×640, and four in a 960-pixel-wide 2×2 grid. `npm run
// bench:figures` (after www/build.sh); `-- --fixed` holds every figure at full render scale (as before
// the scale adapted). Prints one line per page, with each figure's render scale and, where /proc tells,
// the CPU time per frame of the page's process and of the GPU process (whose software rasteriser runs
// there), and a JSON line starting "metaballs-figures ". Not a test: figures depend on the machine.

import { spawn } from 'node:child_process';
import { chromium } from 'playwright-core';
import { root, CHROMIUM, FLAGS, cpuSeconds, freePort, waitForServer } from './helpers.js';

const fixed = process.argv.includes('--fixed');

const PAGES = [
  { name: 'one figure 960×640', query: 'n=1&cols=1&aspect=3/2' },
  { name: 'four figures in a 2×2 grid, 960 wide', query: 'n=4&cols=2' },
];
const port = await freePort();
const server = spawn('python3', ['-m', 'http.server', '--bind', '127.0.0.1', String(port), '--directory', root], { stdio: 'ignore' });
const base = `http://127.0.0.1:${port}/tests/e2e/fixtures/grid.html`;
await waitForServer(base);
const browser = await chromium.launch({ executablePath: CHROMIUM, args: FLAGS, headless: true });
const results = [];
try {
  for (const { name, query } of PAGES) {
    const page = await browser.newPage({ viewport: { width: 960, height: 700 } });
    if (fixed) await page.addInitScript(() => { window.metaballsFixedScale = true; });
    await page.goto(`${base}?${query}&res=128&spheres=16`);
    await page.waitForFunction(() => [...document.querySelectorAll('metaballs-view')].every((e) => e.stats?.triangles > 0),
      null, { timeout: 60_000 });
    // The scale settles within a few seconds.
    await page.waitForTimeout(6000);
    const count = () => page.evaluate(() => [...document.querySelectorAll('metaballs-view')].map((e) => e.framesDrawn));
    const start = await count();
    const cpuStart = cpuSeconds();
    const seconds = 10;
    await page.waitForTimeout(seconds * 1000);
    const end = await count();
    const cpuEnd = cpuSeconds();
    const scales = await page.evaluate(() => [...document.querySelectorAll('metaballs-view')].map((e) => e.renderScale));
    const fps = end.map((f, i) => (f - start[i]) / seconds);
    const frames = Math.min(...end.map((f, i) => f - start[i]));
    const cpuMs = (kind) => (frames > 0 && cpuEnd[kind] !== undefined
      ? Math.round((cpuEnd[kind] - (cpuStart[kind] ?? 0)) / frames * 1000 * 10) / 10 : null);
    const record = {
      page: name, fixed, fps_each: Math.min(...fps), render_scale: scales,
      cpu_ms_per_frame: { page: cpuMs('renderer'), gpu_process: cpuMs('gpu-process') },
    };
    const cpu = record.cpu_ms_per_frame.page === null ? ''
      : `; CPU per frame: page ${record.cpu_ms_per_frame.page} ms, GPU process ${record.cpu_ms_per_frame.gpu_process} ms`;
    console.log(`${name}: ${record.fps_each.toFixed(1)} fps each (slowest figure), render scale ${scales.map((s) => s?.toFixed(2)).join(', ')}${cpu}`);
    results.push(record);
    await page.close();
  }
} finally {
  await browser.close();
  server.kill();
}
console.log(`metaballs-figures ${JSON.stringify(results)}`);
