// The npm package as a course author gets it: packed by www/pack.sh, installed from the tarball into a
// fresh project, imported by its bare name, checked by publint and TypeScript, imported in Node, and
// built into a VitePress site whose page draws its figures.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync, spawn } from 'node:child_process';
import { cpSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { CHROMIUM, FLAGS, builtBy, freePort, root, tableRows, waitForServer } from './helpers.js';

const e2e = path.join(root, 'tests/e2e');
const version = readFileSync(path.join(root, 'Cargo.toml'), 'utf8').match(/^version = "([^"]+)"/m)[1];
const tarball = path.join(root, `target/npm/metaballs-view-${version}.tgz`);
let project;
let browser;

/** Runs `command` and returns its output; a failure shows what it printed. */
function run(command, args, options = {}) {
  try {
    return execFileSync(command, args, { encoding: 'utf8', stdio: 'pipe', ...options });
  } catch (error) {
    throw new Error(`${command} ${args.join(' ')} failed:\n${error.stdout}\n${error.stderr}`);
  }
}

/** Installs the packed tarball into `directory` (a new project), without the registry. */
function installPackage(directory) {
  writeFileSync(path.join(directory, 'package.json'), JSON.stringify({ name: 'course', private: true, type: 'module' }));
  run('npm', ['install', '--offline', '--no-audit', '--no-fund', tarball], { cwd: directory });
}

/** Serves `directory` on 127.0.0.1 while `f(url)` runs; the server is stopped by its process. */
async function serving(directory, f) {
  const port = await freePort();
  const server = spawn('python3', ['-m', 'http.server', '--bind', '127.0.0.1', String(port), '--directory', directory],
    { stdio: 'ignore' });
  try {
    const url = `http://127.0.0.1:${port}/`;
    await waitForServer(url);
    return await f(url);
  } finally {
    server.kill();
  }
}

/** Opens `url` and waits until every figure on it has drawn a surface; returns the console errors. */
async function drawsEveryFigure(url, count) {
  const page = await browser.newPage({ viewport: { width: 900, height: 1400 } });
  const errors = [];
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(url);
  await page.waitForFunction((n) => {
    const figures = [...document.querySelectorAll('metaballs-view')];
    return figures.length === n && figures.every((e) => e.stats?.triangles > 0);
  }, count, { timeout: 60_000 });
  await page.close();
  return errors;
}

before(async () => {
  await builtBy('www/pack.sh', path.relative(root, tarball));
  project = mkdtempSync(path.join(os.tmpdir(), 'metaballs-course-'));
  installPackage(project);
  browser = await chromium.launch({ executablePath: CHROMIUM, args: FLAGS, headless: true });
});

after(async () => {
  await browser?.close();
  if (project) rmSync(project, { recursive: true, force: true });
});

test('the packed package installs from its tarball and draws when imported by its bare name', async () => {
  const installed = JSON.parse(readFileSync(path.join(project, 'node_modules/metaballs-view/package.json'), 'utf8'));
  assert.equal(installed.version, version, 'the package version is not the crate version');
  writeFileSync(path.join(project, 'index.html'), `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>Course</title><link rel="icon" href="data:,">
<link rel="stylesheet" href="node_modules/metaballs-view/www/metaballs-view.css">
<script type="importmap">{ "imports": { "metaballs-view": "./node_modules/metaballs-view/www/metaballs-view.js" } }</script>
<script type="module">import 'metaballs-view';</script></head>
<body><main><metaballs-view spheres="3" resolution="24"></metaballs-view></main></body></html>`);
  const errors = await serving(project, (url) => drawsEveryFigure(url, 1));
  assert.deepEqual(errors, []);
});

test('publint passes, and the packed manifest lists every attribute of the table with its default', () => {
  const report = run('npx', ['--no-install', 'publint', path.join(root, 'target/npm/package')], { cwd: e2e });
  console.log(report.trim().split('\n').at(-1));
  assert.match(report, /All good/);
  const packed = path.join(project, 'node_modules/metaballs-view');
  const manifest = JSON.parse(readFileSync(path.join(packed, 'www/custom-elements.json'), 'utf8'));
  // Both elements: <metaballs-view> with the table's rows, <metaballs-2d> with its own.
  for (const [module, list, tag] of [[0, 'TABLE', 'metaballs-view'], [1, 'PLANE_TABLE', 'metaballs-2d']]) {
    const declaration = manifest.modules[module].declarations[0];
    assert.equal(declaration.tagName, tag);
    const table = tableRows(path.join(packed, 'www/lib/attributes.js'), list);
    assert.deepEqual(declaration.attributes.map((a) => a.name), table.map((p) => p.name));
    for (const [a, p] of declaration.attributes.map((a, i) => [a, table[i]])) assert.equal(JSON.parse(a.default), p.default, a.name);
  }
  assert.equal(JSON.parse(readFileSync(path.join(packed, 'package.json'), 'utf8')).customElements, 'www/custom-elements.json');
});

test('TypeScript checks a file that uses both elements\' properties, methods and events', () => {
  writeFileSync(path.join(project, 'use.ts'), `import 'metaballs-view';
import type { MetaballsView } from 'metaballs-view';
import type { Metaballs2d } from 'metaballs-view/metaballs-2d';

const plane: Metaballs2d = document.querySelector('metaballs-2d')!;
plane.isoLevels = '0.5,1.5';
plane.saddle = 'decider';
plane.pause();
plane.circleList = [{ x: 0, y: 0, r: 0.3 }];
const step: number | null = plane.stepIndex;
plane.addEventListener('metaballs-2d-drag', (event) => console.log(event.detail.circles.length, step));
// @ts-expect-error: not a saddle rule
plane.saddle = 'middle';

const figure = document.querySelector('metaballs-view')!;
const iso: number = figure.iso;
figure.theme = 'light';
figure.maxPixelRatio = iso > 1 ? 1.5 : 2;
figure.play();
figure.inspectCell(1, 2, 3);
const made: MetaballsView = document.createElement('metaballs-view');
made.addEventListener('metaballs-change', (event) => {
  const property: string = event.detail.property;
  console.log(property, event.detail.value);
});
made.addEventListener('metaballs-export', (event) => console.log(event.detail.bytes));
figure.ready().then(() => figure.picture(2)).then((blob: Blob) => console.log(blob.size));
figure.nextFrame().then((stats) => console.log(stats.triangles));
figure.exportMesh('stl').then((bytes: Uint8Array) => console.log(bytes.length));
// @ts-expect-error: not a theme
figure.theme = 'blue';
// @ts-expect-error: not a method
figure.fly();
`);
  writeFileSync(path.join(project, 'tsconfig.json'), JSON.stringify({
    compilerOptions: { strict: true, noEmit: true, target: 'es2022', module: 'esnext', moduleResolution: 'bundler',
      lib: ['es2022', 'dom'] },
    files: ['use.ts'],
  }));
  run('node', [path.join(e2e, 'node_modules/typescript/bin/tsc'), '-p', project]);
});

test('importing the module in Node does nothing and throws nothing, twice, from two copies', () => {
  const copy = path.join(project, 'copy');
  cpSync(path.join(project, 'node_modules/metaballs-view'), copy, { recursive: true });
  const script = `
    const a = await import('metaballs-view');
    const b = await import(${JSON.stringify(path.join(copy, 'www/metaballs-view.js'))});
    await import('metaballs-view');
    if (typeof a.MetaballsView !== 'function' || typeof b.MetaballsView !== 'function') process.exit(3);
    if (typeof customElements !== 'undefined') process.exit(4);`;
  run('node', ['--input-type=module', '-e', script], { cwd: project });
});

test('a VitePress site that imports the element builds, and its page draws both figures', async () => {
  const site = mkdtempSync(path.join(e2e, '.site-'));
  try {
    installPackage(site);
    mkdirSync(path.join(site, '.vitepress/theme'), { recursive: true });
    writeFileSync(path.join(site, '.vitepress/config.mjs'), `export default {
  title: 'Marching cubes',
  head: [['link', { rel: 'icon', href: 'data:,' }]],
  vue: { template: { compilerOptions: { isCustomElement: (tag) => tag === 'metaballs-view' } } },
};
`);
    // As VitePress's docs register components: the theme imports the element (in Node while building).
    writeFileSync(path.join(site, '.vitepress/theme/index.mjs'), `import DefaultTheme from 'vitepress/theme';
import 'metaballs-view';
import 'metaballs-view/metaballs-view.css';

export default DefaultTheme;
`);
    writeFileSync(path.join(site, 'index.md'), `# Two figures

<metaballs-view spheres="2" resolution="24" alt="Two spheres"></metaballs-view>

Some text between the figures.

<metaballs-view spheres="4" resolution="24" display="wireframe"></metaballs-view>
`);
    const started = Date.now();
    run('node', [path.join(e2e, 'node_modules/vitepress/bin/vitepress.js'), 'build'], { cwd: site });
    console.log(`vitepress build: ${Date.now() - started} ms`);
    const errors = await serving(path.join(site, '.vitepress/dist'), (url) => drawsEveryFigure(url, 2));
    assert.deepEqual(errors, []);
  } finally {
    rmSync(site, { recursive: true, force: true });
  }
});
