// Device loss for real: Chromium's GPU process is killed while figures draw, as a driver reset or a GPU
// crash would do. Every figure on the page must draw again, with its settings, without a reload. On
// WebGL2 the context is lost and given back through WEBGL_lose_context, as the browser does after a
// GPU reset: the figure draws again, and stops with "Try again" after three losses in a minute.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import { chromium } from 'playwright-core';
import {
  useServerAndBrowser, baseUrl, browser, CHROMIUM, FLAGS, differingFraction, frameDrawn, open, picture, pixelStats,
} from './helpers.js';

let server;
useServerAndBrowser({
  launch: async () => {
    server = await chromium.launchServer({ executablePath: CHROMIUM, args: FLAGS, headless: true });
    return chromium.connect(server.wsEndpoint());
  },
});
after(async () => { await server?.close(); });

// The GPU process: a descendant of the browser process started with --type=gpu-process.
function gpuProcess() {
  const browserPid = server.process().pid;
  const parents = new Map();
  const commands = new Map();
  for (const entry of readdirSync('/proc')) {
    if (!/^\d+$/.test(entry)) continue;
    try {
      const stat = readFileSync(`/proc/${entry}/stat`, 'utf8');
      parents.set(Number(entry), Number(stat.slice(stat.lastIndexOf(')') + 2).split(' ')[1]));
      commands.set(Number(entry), readFileSync(`/proc/${entry}/cmdline`, 'utf8'));
    } catch { /* gone */ }
  }
  const descends = (pid) => {
    for (let p = pid, depth = 0; p > 1 && depth < 10; p = parents.get(p), depth++) if (p === browserPid) return true;
    return false;
  };
  for (const [pid, command] of commands) {
    if (command.includes('--type=gpu-process') && descends(pid)) return pid;
  }
  return null;
}

async function killGpuProcess() {
  const pid = gpuProcess();
  assert.ok(pid, 'no GPU process found under the browser');
  process.kill(pid, 'SIGKILL');
  return pid;
}

const waitForDrawing = (page, selector, after = 0) => page.waitForFunction(
  ([s, n]) => [...document.querySelectorAll(s)].every((e) => e.framesDrawn > n + 5 && e.stats?.triangles > 0),
  [selector, after], { timeout: 30_000 });

async function surface(page, selector) {
  const png = await page.locator(selector).screenshot();
  return (await pixelStats(page, png)).surface;
}

test('figures draw again after the GPU process is killed', async () => {
  const context = await browser.newContext({ viewport: { width: 840, height: 600 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`${baseUrl}tests/e2e/fixtures/five.html`);
  await waitForDrawing(page, '.row metaballs-view');
  await page.$eval('#a', (e) => e.setAttribute('iso', '0.8'));
  await page.$eval('#b', (e) => e.setAttribute('spheres', '7'));
  await Promise.all([frameDrawn(page, '#a'), frameDrawn(page, '#b')]);
  const drawn = await page.$eval('#a', (e) => e.framesDrawn);
  const killed = await killGpuProcess();
  console.log(`killed the GPU process ${killed}`);
  await page.waitForFunction(() => customElements.get('metaballs-view').devicesCreated >= 2, null, { timeout: 30_000 });
  const started = Date.now();
  await waitForDrawing(page, '.row metaballs-view', drawn);
  console.log(`the figures drew again ${Date.now() - started} ms after the new device`);
  assert.deepEqual(await page.evaluate(() => [document.getElementById('a').iso, document.getElementById('b').spheres]), [0.8, 7]);
  for (const id of ['a', 'b']) {
    const covered = await surface(page, `#${id}`);
    assert.ok(covered > 0.01, `figure ${id} is blank after the loss (${(covered * 100).toFixed(2)}%)`);
  }
  assert.deepEqual(errors, []);
  await context.close();
});

test('the full page draws again after the GPU process is killed', async () => {
  const context = await browser.newContext({ viewport: { width: 960, height: 640 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`${baseUrl}?spheres=9&res=40`);
  await waitForDrawing(page, 'metaballs-view');
  const drawn = await page.$eval('metaballs-view', (e) => e.framesDrawn);
  await killGpuProcess();
  await page.waitForFunction(() => customElements.get('metaballs-view').devicesCreated >= 2, null, { timeout: 30_000 });
  await waitForDrawing(page, 'metaballs-view', drawn);
  assert.deepEqual(await page.$eval('metaballs-view', (e) => [e.spheres, e.resolution]), [9, 40]);
  assert.ok(await surface(page, 'metaballs-view') > 0.01, 'the page is blank after the loss');
  assert.equal(await page.isVisible('#message'), false, 'the page shows an error instead of drawing');
  assert.deepEqual(errors, []);
  await context.close();
});

// The figure's WebGL2 context, lost or given back (the canvas returns the context it already has; a
// lost context gives no extensions, so the one taken before the loss is kept).
const loseContext = (page, restore = false) => page.$eval('metaballs-view', (e, again) => {
  const gl = e.shadowRoot.getElementById('view').getContext('webgl2');
  if (!gl.isContextLost()) window.loseExtension = gl.getExtension('WEBGL_lose_context');
  if (again) window.loseExtension.restoreContext();
  else window.loseExtension.loseContext();
}, restore);

test('a WebGL2 figure whose context is lost draws again with its settings, and stops after three losses in a minute', async () => {
  const { page, errors, close } = await open('?paused=1&res=32&aa=0&spheres=6&iso=0.9', {
    initScript: () => { delete Navigator.prototype.gpu; },
  });
  try {
    await page.waitForFunction(() => document.querySelector('metaballs-view').stats?.triangles > 0, null, { timeout: 30_000 });
    await frameDrawn(page);
    assert.match(await page.textContent('#adapter'), /^WebGL2/);
    const before = await picture(page);
    for (let loss = 1; loss <= 2; loss++) {
      const drawn = await page.$eval('metaballs-view', (e) => e.framesDrawn);
      await loseContext(page);
      await page.waitForFunction(() => /context was lost/.test(
        document.querySelector('metaballs-view').shadowRoot.getElementById('notice').textContent), null, { timeout: 10_000 });
      await page.waitForTimeout(300);
      await loseContext(page, true);
      const started = Date.now();
      await page.waitForFunction((n) => {
        const e = document.querySelector('metaballs-view');
        return e.framesDrawn > n && e.stats.triangles > 0;
      }, drawn, { timeout: 30_000 });
      console.log(`loss ${loss}: drawn again ${Date.now() - started} ms after the context came back`);
      assert.deepEqual(await page.$eval('metaballs-view', (e) => [e.spheres, e.iso, e.resolution]), [6, 0.9, 32]);
      const differing = await differingFraction(page, before, await picture(page));
      assert.ok(differing < 0.001, `${(100 * differing).toFixed(2)} % of the picture differs from the one before the loss`);
    }
    await loseContext(page);
    await page.waitForSelector('#message:not([hidden])', { timeout: 10_000 });
    assert.match(await page.textContent('#message-title'), /keeps failing/);
    assert.match(await page.textContent('#message-text'), /lost 3 times within a minute/);
    assert.equal(await page.isVisible('#retry'), true, 'the figure offers to try again');
    await loseContext(page, true);
    const drawn = await page.$eval('metaballs-view', (e) => e.framesDrawn);
    await page.waitForTimeout(1000);
    assert.equal(await page.$eval('metaballs-view', (e) => e.framesDrawn), drawn, 'a stopped figure waits for the person');
    await page.click('#retry');
    await page.waitForFunction((n) => document.querySelector('metaballs-view').framesDrawn > n, drawn, { timeout: 30_000 });
    assert.equal(await page.isVisible('#message'), false);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
