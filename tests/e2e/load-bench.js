// How much a visitor fetches and how soon the first figure draws: the raw and gzipped size of both wasm
// builds, and the time from navigation to the first drawn frame of index.html in headless Chromium's
// WebGPU (median of 15 loads, each in a fresh context), as dist/ serves it (the bundled element, what
// www/serve.sh serves and authors deploy) and as the source tree serves it (every module on its own):
// `npm run bench:load` (after www/dist.sh). Not a test: times depend on the machine.

import { execFileSync, spawn } from 'node:child_process';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { root, CHROMIUM, FLAGS, freePort, waitForServer } from './helpers.js';

const sizes = {};
for (const build of ['pkg', 'pkg-webgl']) {
  const file = path.join(root, build, 'metaballs_bg.wasm');
  const bytes = readFileSync(file);
  sizes[build] = { raw: bytes.length, gzip: execFileSync('gzip', ['-9c', file], { maxBuffer: 64 << 20 }).length };
  console.log(`${build}/metaballs_bg.wasm: ${bytes.length} bytes, ${sizes[build].gzip} gzipped`);
}

const browser = await chromium.launch({ executablePath: CHROMIUM, args: FLAGS, headless: true });
const results = {};
try {
  for (const [name, directory] of [['dist', path.join(root, 'dist')], ['sources', root]]) {
    results[name] = await firstFrames(directory);
    const times = results[name];
    console.log(`first frame of index.html (${name}): ${median(times).toFixed(0)} ms after navigation `
      + `(median of ${times.length}; ${times.map((t) => t.toFixed(0)).join(', ')})`);
  }
} finally {
  await browser.close();
}
console.log(`metaballs-load ${JSON.stringify({ sizes, first_frame_ms: median(results.dist), runs: results })}`);

function median(times) {
  const sorted = [...times].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
}

// The times from navigation to the first frame of `directory`'s index.html, one per fresh context.
async function firstFrames(directory) {
  const port = await freePort();
  const server = spawn('python3', ['-m', 'http.server', '--bind', '127.0.0.1', String(port), '--directory', directory],
    { stdio: 'ignore' });
  const url = `http://127.0.0.1:${port}/index.html`;
  const times = [];
  try {
    await waitForServer(url);
    for (let i = 0; i < 15; i++) {
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
    server.kill();
  }
  return times;
}
