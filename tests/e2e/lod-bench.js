// Frames per second of a zoomed level-of-detail figure in headless Chromium (SwiftShader here):
// `?lod=on&res=2048&fov=15` at 960×640, its 2048³ applied when the page asks, measured over 10 s once
// it has had 20 s to settle. `npm run bench:lod` (after www/build.sh); `-- --root DIR` serves another
// checkout (to compare with an earlier version), `-- --runs N` opens it N times (3), `-- --query Q`
// measures another link. Prints one line per run, with the render scale, the cell size in pixels where
// the figure adapts it, the triangles, and the CPU time per frame of this browser's page and GPU
// processes (whose software rasteriser runs there), then the median. Not a test: figures depend on the
// machine and on what else runs on it.

import { spawn } from 'node:child_process';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { root, CHROMIUM, FLAGS, cpuSeconds, freePort, waitForServer } from './helpers.js';

const option = (name, fallback) => {
  const at = process.argv.indexOf(`--${name}`);
  return at > 0 ? process.argv[at + 1] : fallback;
};
const directory = path.resolve(option('root', root));
const runs = Number(option('runs', 3));
const query = option('query', '?lod=on&res=2048&fov=15');

const port = await freePort();
const server = spawn('python3', ['-m', 'http.server', '--bind', '127.0.0.1', String(port), '--directory', directory],
  { stdio: 'ignore' });
const base = `http://127.0.0.1:${port}/`;
await waitForServer(base);
const browser = await chromium.launch({ executablePath: CHROMIUM, args: FLAGS, headless: true });
const results = [];
try {
  for (let run = 0; run < runs; run++) {
    const page = await browser.newPage({ viewport: { width: 960, height: 640 } });
    await page.goto(`${base}${query}`);
    const asked = await page.waitForSelector('#confirm:not([hidden])', { timeout: 20_000 }).catch(() => null);
    if (asked) await page.locator('#confirm-apply').click();
    await page.waitForFunction(() => document.querySelector('metaballs-view')?.stats?.triangles > 0, null, { timeout: 60_000 });
    await page.waitForTimeout(20_000);
    const frames = () => page.$eval('metaballs-view', (e) => e.framesDrawn);
    const [start, cpuStart] = [await frames(), cpuSeconds()];
    const seconds = 10;
    await page.waitForTimeout(seconds * 1000);
    const [end, cpuEnd] = [await frames(), cpuSeconds()];
    const figure = await page.$eval('metaballs-view', (e) => ({
      resolution: e.resolution, scale: e.renderScale, cell: e.stats.lod?.cellPixels ?? null, triangles: e.stats.triangles,
    }));
    const drawn = end - start;
    const cpuMs = (kind) => (drawn > 0 ? Math.round(((cpuEnd[kind] ?? 0) - (cpuStart[kind] ?? 0)) / drawn * 1e4) / 10 : null);
    const record = { ...figure, fps: drawn / seconds, cpu_ms_per_frame: { page: cpuMs('renderer'), gpu_process: cpuMs('gpu-process') } };
    const cell = record.cell === null ? '' : `, cells ≤ ${record.cell} px`;
    console.log(`${query} ${record.resolution}³: ${record.fps.toFixed(1)} fps at render scale ${record.scale}${cell}, `
      + `${record.triangles} triangles; CPU per frame: page ${record.cpu_ms_per_frame.page} ms, `
      + `GPU process ${record.cpu_ms_per_frame.gpu_process} ms`);
    results.push(record);
    await page.close();
  }
} finally {
  await browser.close();
  server.kill();
}
const fps = results.map((r) => r.fps).sort((a, b) => a - b);
console.log(`median of ${runs}: ${fps[Math.floor(fps.length / 2)].toFixed(1)} fps`);
console.log(`metaballs-lod ${JSON.stringify(results)}`);
