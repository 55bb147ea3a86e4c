// The notebook widget in a real JupyterLab: a server started on 127.0.0.1 with a token (from the virtual
// environment tests/run.sh makes, JupyterLab plus the built wheel), a notebook whose cells are run as a
// person runs them, and the figure checked in the page while Python sets and reads its traits. The
// server (and with it the kernel) is stopped by its process group at the end.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { CHROMIUM, FLAGS, differingFraction, freePort, root, waitForServer } from './helpers.js';

const VENV = process.env.METABALLS_JUPYTER_VENV ?? path.join(root, 'target/python/test-venv');
const TOKEN = `t${Math.random().toString(36).slice(2)}`;

const CELLS = [
  "from metaballs_widget import Metaballs\nw = Metaballs(spheres=2, iso=1, resolution=32, paused=True, controls='iso', hud='on')\nw",
  'w.iso = 0.7',
  "print('ISO', w.iso, 'TRIANGLES', w.triangles)",
  [
    'import struct',
    "stl = await w.export_mesh('stl')",
    "print('STL', len(stl), struct.unpack('<I', stl[80:84])[0], w.triangles)",
    'png = await w.picture()',
    "print('PNG', png[:4] == bytes([137, 80, 78, 71]), len(png))",
    'await w.load_scene(await w.save_scene())',
    'try:',
    "    await w.load_scene('{')",
    'except ValueError as error:',
    "    print('REFUSED', error)",
  ].join('\n'),
  'w2 = Metaballs(spheres=3, resolution=24, paused=True)\nw2',
];

let server;
let directory;
let browser;
let url;

before(async () => {
  directory = mkdtempSync(path.join(os.tmpdir(), 'metaballs-notebook-'));
  const notebook = {
    cells: CELLS.map((source) => ({ cell_type: 'code', metadata: {}, source, outputs: [], execution_count: null })),
    metadata: { kernelspec: { name: 'python3', display_name: 'Python 3', language: 'python' } },
    nbformat: 4,
    nbformat_minor: 5,
  };
  writeFileSync(path.join(directory, 'figure.ipynb'), JSON.stringify(notebook));
  const port = await freePort();
  const args = ['lab', '--no-browser', '--ip', '127.0.0.1', '--port', String(port), `--IdentityProvider.token=${TOKEN}`,
    `--ServerApp.root_dir=${directory}`, ...(process.getuid?.() === 0 ? ['--allow-root'] : [])];
  server = spawn(path.join(VENV, 'bin/jupyter'), args, { stdio: 'ignore', detached: true, cwd: directory,
    env: { ...process.env, JUPYTER_CONFIG_DIR: path.join(directory, '.jupyter'), JUPYTER_RUNTIME_DIR: path.join(directory, '.runtime') } });
  url = `http://127.0.0.1:${port}/lab/tree/figure.ipynb?token=${TOKEN}`;
  await waitForServer(`http://127.0.0.1:${port}/api/status?token=${TOKEN}`);
  browser = await chromium.launch({ executablePath: CHROMIUM, args: FLAGS, headless: true });
});

after(async () => {
  await browser?.close();
  if (server?.pid) {
    try {
      process.kill(-server.pid, 'SIGTERM');
    } catch { /* already gone */ }
  }
  rmSync(directory, { recursive: true, force: true });
});

const V = (page, f) => page.evaluate(f);
const outputText = (page) => V(page, () => [...document.querySelectorAll('.jp-OutputArea-output')].map((e) => e.textContent).join('\n'));
// Waits until the cells' outputs (not their sources) match `pattern`.
const waitForOutput = (page, pattern, timeout = 60_000) => page.waitForFunction(
  (source) => new RegExp(source).test([...document.querySelectorAll('.jp-OutputArea-output')].map((e) => e.textContent).join('\n')),
  pattern.source, { timeout }).catch(async () => assert.fail(`no output matching ${pattern}; the cells printed: ${await outputText(page)}`));

test('in JupyterLab the widget draws, follows Python, reports back, exports, shares one device and does not leak', async () => {
  const page = await browser.newPage({ viewport: { width: 1280, height: 900 } });
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(url);
  await page.waitForSelector('.jp-Notebook .jp-Cell', { timeout: 90_000 });
  await page.locator('.jp-Cell').first().click();

  // Cell 1: the figure draws.
  const started = Date.now();
  await page.keyboard.press('Shift+Enter');
  const figure = page.locator('metaballs-view').first();
  await page.waitForFunction(() => document.querySelector('metaballs-view')?.stats?.triangles > 0, null, { timeout: 120_000 });
  console.log(`first frame ${Date.now() - started} ms after the cell was run`);
  await page.waitForTimeout(500);
  const before = await V(page, () => document.querySelector('metaballs-view').stats.triangles);
  const shot = await figure.screenshot();

  // Cell 2: Python sets the iso level; the picture and the triangle count change.
  await page.keyboard.press('Shift+Enter');
  await page.waitForFunction(() => document.querySelector('metaballs-view').iso === 0.7, null, { timeout: 60_000 });
  await page.waitForFunction((b) => document.querySelector('metaballs-view').stats.triangles !== b, before, { timeout: 60_000 });
  await page.waitForTimeout(500);
  const changed = await differingFraction(page, shot, await figure.screenshot());
  assert.ok(changed > 0.01, `w.iso = 0.7 changed ${(changed * 100).toFixed(2)}% of the figure`);

  // The figure's slider moves; a later cell reads the new value, and the count the figure reported.
  await V(page, () => {
    const slider = document.querySelector('metaballs-view').shadowRoot.querySelector('#iso input[type=range], input#iso');
    slider.value = '0.8';
    slider.dispatchEvent(new Event('input', { bubbles: true }));
    slider.dispatchEvent(new Event('change', { bubbles: true }));
  });
  await page.waitForTimeout(1500);
  await page.keyboard.press('Shift+Enter');
  await waitForOutput(page, /ISO 0\.8 TRIANGLES [1-9]/);

  // Cell 4: the mesh, a picture and the scene, asked of the figure from Python.
  await page.keyboard.press('Shift+Enter');
  await waitForOutput(page, /REFUSED/, 120_000);
  const printed = await outputText(page);
  const stl = printed.match(/STL (\d+) (\d+) (\d+)/);
  assert.ok(stl, `the cell printed: ${printed}`);
  const [, bytes, count, reported] = stl.map(Number);
  const drawn = await V(page, () => document.querySelector('metaballs-view').stats.triangles);
  console.log(`export_mesh('stl'): ${bytes} bytes, ${count} triangles; the figure drew ${drawn}`);
  assert.equal(bytes, 84 + 50 * count, 'not a binary STL');
  assert.equal(count, drawn, 'the STL does not hold the drawn triangles');
  assert.equal(reported, drawn);
  assert.match(printed, /PNG True \d{4,}/);
  assert.match(printed, /REFUSED .+/);

  // Cell 5: a second widget shares the page's one device.
  await page.keyboard.press('Shift+Enter');
  await page.waitForFunction(() => [...document.querySelectorAll('metaballs-view')].length === 2
    && [...document.querySelectorAll('metaballs-view')].every((e) => e.framesDrawn > 0), null, { timeout: 90_000 });
  const shared = await V(page, () => {
    const View = customElements.get('metaballs-view');
    return { devices: View.devices, created: View.devicesCreated, renderers: View.liveRenderers };
  });
  assert.deepEqual(shared, { devices: 1, created: 1, renderers: 2 });

  // Running that cell again replaces its figure: the live renderers stay two.
  await page.locator('.jp-Cell').nth(4).click();
  await page.keyboard.press('Control+Enter');
  await page.waitForTimeout(3000);
  await page.waitForFunction(() => [...document.querySelectorAll('metaballs-view')].every((e) => e.framesDrawn > 0), null, { timeout: 90_000 });
  await page.waitForFunction(() => customElements.get('metaballs-view').liveRenderers === 2, null, { timeout: 30_000 })
    .catch(async () => assert.fail(`live renderers after running the cell again: ${await V(page, () => customElements.get('metaballs-view').liveRenderers)}`));
  assert.equal(await V(page, () => document.querySelectorAll('metaballs-view').length), 2);
  assert.deepEqual(errors, []);
  await page.close();
});
