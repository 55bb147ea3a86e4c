// The notebook widget in a real JupyterLab: a server started on 127.0.0.1 with a token (from the virtual
// environment tests/run.sh makes, JupyterLab plus the built wheel), a notebook whose cells are run as a
// person runs them, and the figure checked in the page while Python sets and reads its traits. The
// server (and with it the kernel) is stopped by its process group at the end.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { copyFileSync, mkdtempSync, openSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
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
    '    found = await w.critical_points()',
    "    print('CRITICAL', len(found['points']), found['complete'], found['counts']['blobs'])",
    'except ValueError as error:',
    "    print('CRITICAL-FAILED', error)",
    'try:',
    "    await w.load_scene('{')",
    'except ValueError as error:',
    "    print('REFUSED', error)",
  ].join('\n'),
  "gif = await w.record(seconds=0.5, fps=24, width=160, height=90, format='gif')\nprint('GIF', gif[:6] == b'GIF89a', len(gif))",
  "w2 = Metaballs(spheres=3, resolution=24, paused=True, lang='ja', controls='iso')\nw2",
];

let server;
let directory;
const consoleLines = [];
let browser;
let port;

before(async () => {
  directory = mkdtempSync(path.join(os.tmpdir(), 'metaballs-notebook-'));
  const notebook = {
    cells: CELLS.map((source) => ({ cell_type: 'code', metadata: {}, source, outputs: [], execution_count: null })),
    metadata: { kernelspec: { name: 'python3', display_name: 'Python 3', language: 'python' } },
    nbformat: 4,
    nbformat_minor: 5,
  };
  writeFileSync(path.join(directory, 'figure.ipynb'), JSON.stringify(notebook));
  copyFileSync(path.join(root, 'examples/metaballs.ipynb'), path.join(directory, 'metaballs.ipynb'));
  port = await freePort();
  // `expose_app_in_browser` gives the test JupyterLab's command registry (window.jupyterapp): cells are
  // run by the commands the menus and keys run, once the kernel is ready.
  const args = ['lab', '--no-browser', '--ip', '127.0.0.1', '--port', String(port), `--IdentityProvider.token=${TOKEN}`,
    `--ServerApp.root_dir=${directory}`, '--LabApp.expose_app_in_browser=True',
    ...(process.getuid?.() === 0 ? ['--allow-root'] : [])];
  const log = openSync(path.join(directory, 'server.log'), 'w');
  server = spawn(path.join(VENV, 'bin/jupyter'), args, { stdio: ['ignore', log, log], detached: true, cwd: directory,
    env: { ...process.env, JUPYTER_CONFIG_DIR: path.join(directory, '.jupyter'), JUPYTER_DATA_DIR: path.join(directory, '.data'),
      JUPYTER_RUNTIME_DIR: path.join(directory, '.runtime'), IPYTHONDIR: path.join(directory, '.ipython') } });
  // A first start in a new environment compiles JupyterLab's Python modules: give it a minute.
  await waitForServer(`http://127.0.0.1:${port}/api/status?token=${TOKEN}`, 60_000);
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

const V = (page, f, arg) => page.evaluate(f, arg);
// The open notebook's panel, its outputs' text, and what a failed wait reports.
const outputText = (page) => V(page, () => [...window.jupyterapp.shell.currentWidget.node.querySelectorAll('.jp-OutputArea-output')]
  .map((e) => e.textContent).join('\n'));
async function state(page) {
  const seen = await V(page, () => {
    const panel = window.jupyterapp?.shell.currentWidget;
    const figures = [...(panel?.node.querySelectorAll('metaballs-view') ?? [])];
    return {
      kernel: panel?.sessionContext?.session?.kernel?.status ?? 'none',
      outputs: [...(panel?.node.querySelectorAll('.jp-OutputArea-output') ?? [])].map((e) => e.textContent.slice(0, 300)),
      figures: figures.map((f) => ({ frames: f.framesDrawn, stats: f.stats, notice: f.shadowRoot?.querySelector('[part~=notice]')?.textContent })),
    };
  }).catch((e) => ({ page: String(e) }));
  const log = readFileSync(path.join(directory, 'server.log'), 'utf8').split('\n').slice(-15).join('\n');
  return `${JSON.stringify(seen)}\nthe page's console ends:\n${consoleLines.join('\n')}\nthe server's log ends:\n${log}`;
}
const waitFor = (page, what, f, arg, timeout = 60_000) => page.waitForFunction(f, arg, { timeout })
  .catch(async () => assert.fail(`${what}: ${await state(page)}`));
// Waits until the open notebook's outputs (not its sources) match `pattern`.
const waitForOutput = (page, pattern, timeout = 60_000) => waitFor(page, `no output matching ${pattern}`,
  (source) => new RegExp(source).test([...window.jupyterapp.shell.currentWidget.node.querySelectorAll('.jp-OutputArea-output')]
    .map((e) => e.textContent).join('\n')), pattern.source, timeout);

// Opens a notebook of the server's folder in a page of its own and waits for its kernel.
async function openNotebook(name) {
  const page = await browser.newPage({ viewport: { width: 1280, height: 900 } });
  // The page's last messages, for a failed wait's report.
  page.on('console', (m) => { consoleLines.push(`${m.type()}: ${m.text().slice(0, 300)}`); consoleLines.splice(0, consoleLines.length - 20); });
  page.on('pageerror', (e) => consoleLines.push(`pageerror: ${String(e).slice(0, 300)}`));
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(`http://127.0.0.1:${port}/lab/tree/${name}?reset&token=${TOKEN}`);
  await waitFor(page, `${name} did not open with a ready kernel`, (file) => {
    const panel = window.jupyterapp?.shell.currentWidget;
    return panel?.context?.path === file && panel.content.widgets.length > 0
      && panel.sessionContext.session?.kernel?.status === 'idle';
  }, name, 120_000);
  return { page, errors };
}

// Runs the open notebook's cell `index` (or every cell) with JupyterLab's own commands, without waiting
// for it to finish.
const run = (page, index) => V(page, (i) => {
  const app = window.jupyterapp;
  if (i === 'all') {
    app.commands.execute('notebook:run-all-cells');
    return;
  }
  app.shell.currentWidget.content.activeCellIndex = i;
  app.commands.execute('notebook:run-cell');
}, index);
test('in JupyterLab the widget draws, follows Python, reports back, exports, shares one device and does not leak', async () => {
  const { page, errors } = await openNotebook('figure.ipynb');

  // Cell 1: the figure draws.
  const started = Date.now();
  await run(page, 0);
  await waitFor(page, 'the figure did not draw', () => document.querySelector('metaballs-view')?.stats?.triangles > 0, null, 120_000);
  console.log(`first frame ${Date.now() - started} ms after the cell was run`);
  const figure = page.locator('metaballs-view').first();
  await V(page, () => document.querySelector('metaballs-view').nextFrame());
  const before = await V(page, () => document.querySelector('metaballs-view').stats.triangles);
  const shot = await figure.screenshot();

  // Cell 2: Python sets the iso level; the picture and the triangle count change.
  await run(page, 1);
  await waitFor(page, 'w.iso = 0.7 did not reach the figure', () => document.querySelector('metaballs-view').iso === 0.7);
  await waitFor(page, 'the count did not change', (b) => document.querySelector('metaballs-view').stats.triangles !== b, before);
  await V(page, () => document.querySelector('metaballs-view').nextFrame());
  const changed = await differingFraction(page, shot, await figure.screenshot());
  assert.ok(changed > 0.01, `w.iso = 0.7 changed ${(changed * 100).toFixed(2)}% of the figure`);

  // The figure's slider moves; a later cell reads the new value, and the count the figure reported.
  await V(page, () => {
    const slider = document.querySelector('metaballs-view').shadowRoot.querySelector('#iso input[type=range], input#iso');
    slider.value = '0.8';
    slider.dispatchEvent(new Event('input', { bubbles: true }));
    slider.dispatchEvent(new Event('change', { bubbles: true }));
  });
  // The widget sends a change to the kernel once the kernel has answered its previous message: time for
  // it to arrive before the next cell runs.
  await page.waitForTimeout(1500);
  await run(page, 2);
  await waitForOutput(page, /ISO 0\.8 TRIANGLES [1-9]/);

  // Cell 4: the mesh, a picture and the scene, asked of the figure from Python.
  await run(page, 3);
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
  // The critical points' module came through the kernel too: two spheres, their join, proven complete.
  const critical = printed.match(/CRITICAL (\d+) (\w+) (\d+)/);
  assert.ok(critical, `the cell printed: ${printed}`);
  assert.ok(Number(critical[1]) >= 1 && critical[2] === 'True', printed);

  // Cell 5: a clip of the figure's animation, made in the browser, as bytes in Python.
  await run(page, 4);
  await waitForOutput(page, /GIF (True|False) \d+/, 120_000);
  assert.match(await outputText(page), /GIF True \d{4,}/);

  // Cell 6: a second widget shares the page's one device (scrolled to, as a person reading on would).
  await run(page, 5);
  await waitFor(page, 'no second figure', () => document.querySelectorAll('metaballs-view').length === 2);
  await page.locator('metaballs-view').nth(1).scrollIntoViewIfNeeded();
  await waitFor(page, 'the second figure did not draw',
    () => { const all = [...document.querySelectorAll('metaballs-view')]; return all.length === 2 && all.every((e) => e.framesDrawn > 0); }, null, 90_000);
  const shared = await V(page, () => {
    const View = customElements.get('metaballs-view');
    return { devices: View.devices, created: View.devicesCreated, renderers: View.liveRenderers };
  });
  assert.deepEqual(shared, { devices: 1, created: 1, renderers: 2 });
  // Its `lang` trait makes it speak Japanese, while the first figure keeps the page's English.
  const japanese = (await import('../../www/lib/i18n/ja/index.js')).default['setting.iso'];
  await waitFor(page, 'the lang="ja" figure did not speak Japanese', (label) => {
    const said = (figure) => [...figure.shadowRoot.querySelectorAll('label')].map((l) => l.textContent.trim());
    const [one, two] = document.querySelectorAll('metaballs-view');
    return two.lang === 'ja' && said(two).includes(label) && !said(one).includes(label);
  }, japanese);

  // Running that cell again replaces its figure: the live renderers stay two.
  const first = await page.evaluateHandle(() => document.querySelectorAll('metaballs-view')[1]);
  await run(page, 5);
  await waitFor(page, 'the cell run again showed no new figure',
    (old) => { const all = document.querySelectorAll('metaballs-view'); return all.length === 2 && all[1] !== old; }, first);
  await page.locator('metaballs-view').nth(1).scrollIntoViewIfNeeded();
  await waitFor(page, 'the new figure did not draw', () => document.querySelectorAll('metaballs-view')[1].framesDrawn > 0, null, 90_000);
  await waitFor(page, 'the live renderers did not go back to two', () => customElements.get('metaballs-view').liveRenderers === 2, null, 30_000);
  assert.deepEqual(errors, []);
  await page.close();
});

test('the example notebook runs from top to bottom: the figure, its iso slider, the triangle count, an STL file and a picture', async () => {
  const { page, errors } = await openNotebook('metaballs.ipynb');
  await run(page, 'all');
  await waitForOutput(page, /two-spheres\.stl: \d+ bytes, \d+ triangles/, 120_000);
  await waitFor(page, 'the picture was not shown',
    () => window.jupyterapp.shell.currentWidget.node.querySelector('.jp-OutputArea-output img[src^="data:image/png"]'), null, 60_000);
  const printed = await outputText(page);
  assert.doesNotMatch(printed, /Traceback|Error/, printed);
  const [, counted] = printed.match(/iso 1(?:\.0)?: (\d+) triangles at 48³ cells, drawn with .+/).map(Number);
  const [, bytes, count] = printed.match(/two-spheres\.stl: (\d+) bytes, (\d+) triangles/).map(Number);
  assert.equal(bytes, 84 + 50 * count);
  assert.ok(count > 0);
  assert.equal(count, counted, 'the STL and w.stats() disagree');
  assert.equal(readFileSync(path.join(directory, 'two-spheres.stl')).length, bytes);

  // The notebook's slider (ipywidgets, linked to w.iso through the kernel) moves the figure's iso level.
  const readout = page.locator('.widget-slider .widget-readout').first();
  await readout.click();
  await page.keyboard.press('Control+A');
  await page.keyboard.type('0.6');
  await page.keyboard.press('Enter');
  await waitFor(page, "the notebook's slider did not reach the figure", () => document.querySelector('metaballs-view')?.iso === 0.6);
  assert.deepEqual(errors, []);
  await page.close();
});
