// Frame time of a page with 1 and with 4 visible figures (48³ cells, 5 spheres each) in headless
// Chromium's WebGPU: `npm run bench:figures` (after www/build.sh). Prints one line per page and a JSON
// line starting "metaballs-figures ". Not a test: figures depend on the machine.

import { spawn } from 'node:child_process';
import { chromium } from 'playwright-core';
import { root, CHROMIUM, FLAGS, freePort, waitForServer } from './helpers.js';

const port = await freePort();
const server = spawn('python3', ['-m', 'http.server', '--bind', '127.0.0.1', String(port), '--directory', root], { stdio: 'ignore' });
const base = `http://127.0.0.1:${port}/tests/e2e/fixtures/grid.html`;
await waitForServer(base);
const browser = await chromium.launch({ executablePath: CHROMIUM, args: FLAGS, headless: true });
const results = [];
try {
  for (const n of [1, 4]) {
    const page = await browser.newPage({ viewport: { width: 960, height: 1100 } });
    await page.goto(`${base}?n=${n}&res=48`);
    await page.waitForFunction((k) => [...document.querySelectorAll('metaballs-view')].length === k
      && [...document.querySelectorAll('metaballs-view')].every((e) => e.stats?.triangles > 0), n, { timeout: 60_000 });
    await page.waitForTimeout(2000);
    const count = () => page.evaluate(() => [...document.querySelectorAll('metaballs-view')].map((e) => e.framesDrawn));
    const start = await count();
    const seconds = 8;
    await page.waitForTimeout(seconds * 1000);
    const end = await count();
    const frames = Math.min(...end.map((f, i) => f - start[i]));
    const record = { figures: n, resolution: 48, page_frame_ms: (seconds * 1000) / frames, fps: frames / seconds };
    console.log(`${n} visible figure(s) at 48³: ${record.page_frame_ms.toFixed(1)} ms per page frame (${record.fps.toFixed(1)} fps each)`);
    results.push(record);
    await page.close();
  }
} finally {
  await browser.close();
  server.kill();
}
console.log(`metaballs-figures ${JSON.stringify(results)}`);
