// Shared by the end-to-end tests: a static server over the repository on 127.0.0.1, headless Chromium
// with real WebGPU (SwiftShader), and checks of what a person sees, computed on decoded pixels.

import { before, after, afterEach } from 'node:test';
import { execFileSync, spawn } from 'node:child_process';
import { createServer } from 'node:net';
import { existsSync, mkdirSync, readFileSync, readdirSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import path from 'node:path';
import { chromium } from 'playwright-core';

export const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
export const outputDir = path.join(root, 'tests/output');
mkdirSync(outputDir, { recursive: true });

export const CHROMIUM = process.env.CHROMIUM ?? '/usr/bin/chromium';
export const FLAGS = [
  '--enable-unsafe-webgpu',
  '--enable-features=Vulkan',
  '--use-vulkan=swiftshader',
  '--use-angle=swiftshader',
  '--no-sandbox',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-quic',
];

// What the build scripts make their outputs from: the WebAssembly (pkg/, pkg-webgl/ and pkg-levels/,
// from the crates and the shaders), the page, the element and the widget's module.
const WASM_SOURCES = ['src', 'core', 'scene', 'levels', 'shaders', 'Cargo.toml', 'Cargo.lock'];
const SOURCES = [...WASM_SOURCES, 'pkg', 'pkg-webgl', 'pkg-levels', 'www', 'python/js', 'index.html', 'embed.html'];

function newestChange(file) {
  if (!existsSync(file)) return 0;
  const stat = statSync(file);
  if (!stat.isDirectory()) return stat.mtimeMs;
  return readdirSync(file).filter((name) => name !== 'node_modules')
    .reduce((newest, name) => Math.max(newest, newestChange(path.join(file, name))), stat.mtimeMs);
}

/** True when `output` (relative to the repository) is newer than every one of `sources`. */
const newerThan = (output, sources) => existsSync(path.join(root, output))
  && statSync(path.join(root, output)).mtimeMs > Math.max(...sources.map((s) => newestChange(path.join(root, s))));

/** Runs `f` while holding the build lock: test files running side by side build one at a time. */
async function exclusively(f) {
  const lock = path.join(root, 'target/e2e-build.lock');
  mkdirSync(path.dirname(lock), { recursive: true });
  for (;;) {
    try {
      writeFileSync(lock, String(process.pid), { flag: 'wx' });
      break;
    } catch {
      // Taken: wait for its holder, or take it over from a holder that is gone.
      const holder = Number(readFileSync(lock, 'utf8'));
      try {
        if (holder) process.kill(holder, 0);
      } catch {
        rmSync(lock, { force: true });
        continue;
      }
      await new Promise((r) => setTimeout(r, 200));
    }
  }
  try {
    return await f();
  } finally {
    rmSync(lock, { force: true });
  }
}

/**
 * Runs the build script `script` unless `output` (the last file it writes, relative to the repository)
 * is newer than every source: tests/run.sh builds dist/, the npm package and the wheel once before the
 * tests, and a test file run on its own builds what is missing or out of date (the WebAssembly too, only
 * when it is older than the crate).
 */
export async function builtBy(script, output) {
  if (newerThan(output, SOURCES)) return;
  await exclusively(async () => {
    if (newerThan(output, SOURCES)) return;
    const wasmBuilt = ['pkg/metaballs_bg.wasm', 'pkg-webgl/metaballs_bg.wasm', 'pkg-levels/metaballs_levels_bg.wasm']
      .every((file) => newerThan(file, WASM_SOURCES));
    console.log(`building ${output} (bash ${script})`);
    try {
      execFileSync('bash', [path.join(root, script)], {
        encoding: 'utf8', stdio: 'pipe', env: { ...process.env, METABALLS_WASM_BUILT: wasmBuilt ? '1' : '' },
      });
    } catch (error) {
      throw new Error(`bash ${script} failed:\n${error.stdout}\n${error.stderr}`);
    }
  });
}

let server;
export let browser;
export let baseUrl;

export function freePort() {
  return new Promise((resolve, reject) => {
    const probe = createServer();
    probe.once('error', reject);
    probe.listen(0, '127.0.0.1', () => {
      const { port } = probe.address();
      probe.close(() => resolve(port));
    });
  });
}

/** Waits until `url` answers (a server just started), at most `timeoutMs`. */
export async function waitForServer(url, timeoutMs = 10_000) {
  for (const end = Date.now() + timeoutMs; Date.now() < end;) {
    try {
      if ((await fetch(url)).ok) return;
    } catch {
      // not up yet
    }
    await new Promise((r) => setTimeout(r, 100));
  }
  throw new Error(`the server at ${url} did not start`);
}

/** Serves `directory` on a free port of 127.0.0.1 (for benchmarks of other checkouts): `{ base, stop() }`. */
export async function serve(directory) {
  const port = await freePort();
  const server = spawn('python3', ['-m', 'http.server', '--bind', '127.0.0.1', String(port), '--directory', directory],
    { stdio: 'ignore' });
  const base = `http://127.0.0.1:${port}/`;
  await waitForServer(base);
  return { base, stop: () => server.kill() };
}

/** Serves `directory` (the repository by default) and starts the browser before a file's tests. */
export function useServerAndBrowser({ directory = root, launch = null } = {}) {
before(async () => {
  server = await serve(directory);
  baseUrl = server.base;
  browser = launch ? await launch() : await chromium.launch({ executablePath: CHROMIUM, args: FLAGS, headless: true });
});

after(async () => {
  await browser?.close();
  server?.stop();
});
}

/**
 * Opens `url` (relative to the server, or whole) in a new context and collects console errors and
 * uncaught exceptions. Options: initScript (one function or a list, run before the page's scripts),
 * viewport, reducedMotion, on (another browser).
 */
export async function open(url = '', { initScript, viewport = { width: 960, height: 640 }, reducedMotion, on = browser } = {}) {
  const context = await on.newContext({ viewport, reducedMotion });
  const page = await context.newPage();
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  for (const script of [initScript ?? []].flat()) await page.addInitScript(script);
  await page.goto(url.startsWith('http') ? url : `${baseUrl}${url}`);
  return { page, errors, close: () => context.close() };
}

/**
 * An `open` whose pages are closed after each test (for files whose tests each open their own): call
 * once at the top of a test file; `defaults` are options for every page.
 */
export function openClosedAfterEach(defaults = {}) {
  const pages = new Set();
  afterEach(async () => {
    for (const page of pages) await page.context().close().catch(() => {});
    pages.clear();
  });
  return async (url, options) => {
    const opened = await open(url, { ...defaults, ...options });
    pages.add(opened.page);
    return opened;
  };
}

export async function waitForTriangles(page, differentFrom = null) {
  await page.waitForFunction(
    (prev) => {
      // Before the element is defined (the wasm still loading) it has no shadow root yet.
      const readout = document.querySelector('metaballs-view')?.shadowRoot?.getElementById('triangles');
      const text = (readout?.textContent ?? '').replace(/,/g, '');
      return /^\d+$/.test(text) && Number(text) > 0 && (prev === null || Number(text) !== prev);
    },
    differentFrom,
    { timeout: 60_000 },
  );
  return Number((await page.textContent('#triangles')).replace(/,/g, ''));
}

/**
 * Resolves with the statistics of a frame the figure (the first by default) draws of its current
 * settings: it draws one even while paused or off screen (`nextFrame()`), and its HUD shows them.
 */
export function frameDrawn(page, selector = 'metaballs-view') {
  return page.$eval(selector, (e) => e.nextFrame());
}

// Renders settle once the stats for the current settings are in: two frames in a row, each drawn and
// its statistics read back, with the same count in the HUD.
export async function settledTriangles(page) {
  let previous = await waitForTriangles(page);
  for (let i = 0; i < 20; i++) {
    await frameDrawn(page);
    const now = Number((await page.textContent('#triangles')).replace(/,/g, ''));
    if (now === previous) return now;
    previous = now;
  }
  return previous;
}

export async function screenshot(page, name) {
  const file = path.join(outputDir, `e2e-${name}.png`);
  const png = await page.locator('#view').screenshot({ path: file });
  console.log(`screenshot: ${file}`);
  return png;
}

// Pixel statistics of a canvas screenshot, computed in the page (it decodes PNGs for us).
/**
 * The first figure's own picture as PNG bytes (not a screenshot, which would include the notices over
 * it), 480 pixels wide whatever the canvas's pixel ratio.
 */
export async function picture(page, selector = 'metaballs-view') {
  return Buffer.from(await page.$eval(selector, async (e) => {
    const blob = await e.picture(480 / e.shadowRoot.querySelector('canvas').width);
    return [...new Uint8Array(await blob.arrayBuffer())];
  }));
}

export async function pixelStats(page, png) {
  return page.evaluate(async (b64) => {
    const image = await createImageBitmap(await (await fetch(`data:image/png;base64,${b64}`)).blob());
    const canvas = new OffscreenCanvas(image.width, image.height);
    const context = canvas.getContext('2d');
    context.drawImage(image, 0, 0);
    const { data } = context.getImageData(0, 0, image.width, image.height);
    let surface = 0;
    let highlight = 0;
    for (let i = 0; i < data.length; i += 4) {
      const [r, g, b] = [data[i], data[i + 1], data[i + 2]];
      if (r > b + 30) surface += 1; // the default surface colour is red; the background is blue-grey
      if (r > 215 && g > 215 && b > 215) highlight += 1;
    }
    const pixels = data.length / 4;
    return { surface: surface / pixels, highlight, pixels };
  }, png.toString('base64'));
}

export async function differingFraction(page, a, b) {
  return page.evaluate(async ([x, y]) => {
    const decode = async (b64) => {
      const image = await createImageBitmap(await (await fetch(`data:image/png;base64,${b64}`)).blob());
      const canvas = new OffscreenCanvas(image.width, image.height);
      const context = canvas.getContext('2d');
      context.drawImage(image, 0, 0);
      return context.getImageData(0, 0, image.width, image.height).data;
    };
    const [p, q] = [await decode(x), await decode(y)];
    let differing = 0;
    for (let i = 0; i < p.length; i += 4) {
      if (Math.abs(p[i] - q[i]) + Math.abs(p[i + 1] - q[i + 1]) + Math.abs(p[i + 2] - q[i + 2]) > 24) differing += 1;
    }
    return differing / (p.length / 4);
  }, [a.toString('base64'), b.toString('base64')]);
}

export async function setRange(page, id, value) {
  await page.$eval(`#${id}`, (input, v) => {
    input.value = String(v);
    input.dispatchEvent(new Event('input', { bubbles: true }));
  }, value);
}


/** Opens every group of the figure's panel (they start folded, but Surface). */
export async function openPanelGroups(page, selector = 'metaballs-view') {
  await page.$eval(selector, (element) => {
    for (const group of element.shadowRoot.querySelectorAll('details')) group.open = true;
  });
}

/** CPU seconds used so far by this browser's processes, by kind (`renderer`, `gpu-process`). */
export function cpuSeconds() {
  const rows = execFileSync('ps', ['-eo', 'pid=,ppid='], { encoding: 'utf8' }).trim().split('\n')
    .map((line) => line.trim().split(/\s+/));
  const ours = new Set([String(process.pid)]);
  for (let grew = true; grew;) {
    grew = false;
    for (const [pid, parent] of rows) {
      if (ours.has(parent) && !ours.has(pid)) {
        ours.add(pid);
        grew = true;
      }
    }
  }
  const seconds = {};
  for (const pid of ours) {
    try {
      const command = readFileSync(`/proc/${pid}/cmdline`, 'utf8');
      if (!command.split('\0')[0].includes('chrom')) continue;
      const kind = command.match(/--type=([a-z-]+)/)?.[1] ?? 'browser';
      // utime and stime, in clock ticks (100 per second on Linux), after the command's name.
      const fields = readFileSync(`/proc/${pid}/stat`, 'utf8').split(') ')[1].split(' ');
      seconds[kind] = (seconds[kind] ?? 0) + (Number(fields[11]) + Number(fields[12])) / 100;
    } catch { /* the process ended meanwhile */ }
  }
  return seconds;
}

/**
 * For the benchmarks: serves the repository on a free port and starts headless Chromium. Returns
 * `{ base, browser, close }`; `close()` stops both.
 */
export async function benchSetup() {
  const port = await freePort();
  const server = spawn('python3', ['-m', 'http.server', '--bind', '127.0.0.1', String(port), '--directory', root], { stdio: 'ignore' });
  const base = `http://127.0.0.1:${port}/`;
  await waitForServer(base);
  const browser = await chromium.launch({ executablePath: CHROMIUM, args: FLAGS, headless: true });
  return { base, browser, close: async () => { await browser.close(); server.kill(); } };
}

/**
 * The rows of one of the lists in a generated table (`www/lib/attributes.js`, one row a line):
 * `TABLE` (<metaballs-view>'s) or `PLANE_TABLE` (<metaballs-2d>'s).
 */
export function tableRows(file = path.join(root, 'www/lib/attributes.js'), list = 'TABLE') {
  const source = readFileSync(file, 'utf8');
  return source.split(`export const ${list} = Object.freeze([\n`)[1].split('\n]);')[0]
    .split('\n').map((line) => JSON.parse(line.trim().replace(/,$/, '')));
}

/** A value of `row` other than its default, as text, that a software renderer draws quickly. */
export function otherText(row) {
  switch (row.kind) {
    case 'integer':
    case 'number': {
      if (row.name === 'resolution') return '16';
      if (row.name === 'spheres') return '2';
      if (row.sliderMax === row.sliderMin) return String(row.value + 6);
      return String(row.sliderMin !== row.value ? row.sliderMin : row.sliderMax);
    }
    case 'boolean': return String(!row.value);
    case 'color': return '#123456';
    case 'choice': return row.words.find((w) => w !== row.value);
    case 'list': return row.words.find((w) => w !== row.value);
    case 'slice': return 'z:0.25';
    case 'cell': return '1,2,3';
    case 'spheres': return '0,0,0,0.3';
    case 'levels': return '0.5,1.5';
    default: return { circles: '0.3,0.1,0.35', march: '1,2' }[row.name] ?? 'a figure';
  }
}
