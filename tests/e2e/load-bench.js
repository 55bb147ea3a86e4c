// How much a visitor fetches and how soon the first figure draws: the raw and gzipped size of both wasm
// builds, and the time from navigation to the first drawn frame of index.html in headless Chromium's
// WebGPU (median of 7 loads, each in a fresh context): `npm run bench:load` (after www/build.sh). Not a
// test: times depend on the machine.

import { spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import { gzipSync } from 'node:zlib';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { root, CHROMIUM, FLAGS, freePort, waitForServer } from './helpers.js';

const sizes = {};
for (const build of ['pkg', 'pkg-webgl']) {
  const bytes = readFileSync(path.join(root, build, 'metaballs_bg.wasm'));
  sizes[build] = { raw: bytes.length, gzip: gzipSync(bytes, { level: 9 }).length };
  console.log(`${build}/metaballs_bg.wasm: ${(bytes.length / 1024).toFixed(0)} KB, ${(sizes[build].gzip / 1024).toFixed(0)} KB gzipped`);
}

const port = await freePort();
const server = spawn('python3', ['-m', 'http.server', '--bind', '127.0.0.1', String(port), '--directory', root], { stdio: 'ignore' });
const url = `http://127.0.0.1:${port}/index.html`;
await waitForServer(url);
const browser = await chromium.launch({ executablePath: CHROMIUM, args: FLAGS, headless: true });
const times = [];
try {
  for (let i = 0; i < 7; i++) {
    const context = await browser.newContext({ viewport: { width: 960, height: 640 } });
    const page = await context.newPage();
    await page.addInitScript(() => {
      const watch = () => {
        if (document.querySelector('metaballs-view')?.framesDrawn > 0) window.firstFrameMs = performance.now();
        else requestAnimationFrame(watch);
      };
      requestAnimationFrame(watch);
    });
    await page.goto(url);
    await page.waitForFunction(() => window.firstFrameMs > 0, null, { timeout: 60_000 });
    times.push(await page.evaluate(() => window.firstFrameMs));
    await context.close();
  }
} finally {
  await browser.close();
  server.kill();
}
times.sort((a, b) => a - b);
const median = times[Math.floor(times.length / 2)];
console.log(`first frame of index.html: ${median.toFixed(0)} ms after navigation (median of ${times.length}; ${times.map((t) => t.toFixed(0)).join(', ')})`);
console.log(`metaballs-load ${JSON.stringify({ sizes, first_frame_ms: median, runs: times })}`);
