// The example book (examples/book/, MyST / Jupyter Book 2): `myst build --site` run offline on it, the
// nodes it writes for the page's two figures checked, and the page drawn as MyST's theme draws it (the
// anywidget node's module with its props under a model with no kernel, the iframe on embed.html) from a
// folder laid out as the published site: the built site's public files at its root and dist/ as
// metaballs/. The static server is stopped by its process id (helpers.js).

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { browser, baseUrl, builtBy, differingFraction, outputDir, root, useServerAndBrowser } from './helpers.js';

const BOOK = path.join(root, 'examples/book');
const BUILD = path.join(BOOK, '_build');
const site = mkdtempSync(path.join(os.tmpdir(), 'metaballs-book-'));
let page;
let built;

// MyST fetches its site theme's description from the web on every build unless the theme is already in
// the build folder; a theme's description (kind and version, nothing else is read by `--site`) stands
// in for it, as a book built offline before would have it.
function offlineTheme() {
  const theme = path.join(BUILD, 'templates/site/myst/book-theme');
  mkdirSync(theme, { recursive: true });
  writeFileSync(path.join(theme, 'template.yml'), 'myst: v1\nkind: site\n');
}

const nodes = (tree, type) => (tree && typeof tree === 'object'
  ? [...(tree.type === type ? [tree] : []), ...Object.values(tree).flatMap((v) => nodes(v, type))]
  : []);

before(async () => {
  await builtBy('www/dist.sh', 'dist/widget.js');
  rmSync(BUILD, { recursive: true, force: true });
  offlineTheme();
  const started = Date.now();
  built = execFileSync(path.join(root, 'tests/e2e/node_modules/.bin/myst'), ['build', '--site'],
    { cwd: BOOK, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
  console.log(`myst build --site: ${Date.now() - started} ms`);
  page = JSON.parse(readFileSync(path.join(BUILD, 'site/content/index.json'), 'utf8'));
  cpSync(path.join(BUILD, 'site/public'), site, { recursive: true });
  cpSync(path.join(BUILD, 'site/content'), path.join(site, 'content'), { recursive: true });
  cpSync(path.join(root, 'dist'), path.join(site, 'metaballs'), { recursive: true });
  cpSync(path.join(root, 'tests/e2e/fixtures/myst-host.html'), path.join(site, 'myst-host.html'));
});

useServerAndBrowser({ directory: site });

after(() => {
  rmSync(BUILD, { recursive: true, force: true });
  rmSync(site, { recursive: true, force: true });
});

test('myst build --site builds the example book offline: an anywidget node with the module and its props, an iframe with its placeholder', () => {
  assert.match(built, /Built 1 page/);
  const [widget, ...more] = nodes(page.mdast, 'anywidget');
  assert.equal(more.length, 0);
  assert.match(widget.esm, /^\/widget-[0-9a-f]+\.js$/, 'the module was not copied into the site');
  assert.deepEqual(readFileSync(path.join(site, widget.esm)), readFileSync(path.join(root, 'dist/widget.js')));
  assert.deepEqual(widget.model, {
    spheres: 2, iso: 1, resolution: 48, controls: 'iso',
    alt: 'Two spheres whose surfaces merge as the iso level is lowered', wasm_url: '/metaballs/',
  });

  const [frame] = nodes(page.mdast, 'iframe');
  assert.match(frame.src, /^\/metaballs\/embed\.html\?/);
  const [placeholder] = frame.children;
  assert.equal(placeholder.placeholder, true);
  const poster = readFileSync(path.join(site, placeholder.url));
  assert.deepEqual([...poster.subarray(1, 4)], [...Buffer.from('PNG')], 'the placeholder is not a PNG');
  assert.ok(existsSync(path.join(site, 'metaballs', new URL(frame.src, 'http://x').pathname.slice('/metaballs/'.length))));
});

test("the built page's figures draw as MyST shows them: the widget under a model without a kernel, its wasm from wasm_url, and the iframe", async () => {
  const tab = await browser.newPage({ viewport: { width: 960, height: 1200 } });
  const errors = [];
  tab.on('pageerror', (e) => errors.push(String(e)));
  tab.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  const wasm = [];
  tab.on('request', (r) => { if (r.url().endsWith('.wasm')) wasm.push(new URL(r.url()).pathname); });
  await tab.goto(`${baseUrl}myst-host.html?page=/content/index.json`);
  await tab.waitForFunction(() => window.host?.figure()?.stats?.triangles > 0, null, { timeout: 60_000 });
  const figure = tab.locator('metaballs-view').first();
  assert.equal(await figure.evaluate((e) => [e.spheres, e.iso, e.resolution, e.controls].join()), '2,1,48,iso');
  assert.ok(wasm.length > 0 && wasm.every((p) => p.startsWith('/metaballs/pkg')), `wasm fetched from ${wasm}`);
  const before = await tab.evaluate(() => window.host.figure().stats.triangles);
  await tab.evaluate(() => window.host.figure().nextFrame());
  const shot = await figure.screenshot();

  // The page sets a prop: the figure takes it and draws a merged surface.
  await tab.evaluate(() => window.host.set('iso', 0.6));
  await tab.waitForFunction((b) => window.host.figure().stats.triangles !== b, before, { timeout: 30_000 });
  await tab.evaluate(() => window.host.figure().nextFrame());
  const changed = await differingFraction(tab, shot, await figure.screenshot());
  assert.ok(changed > 0.01, `iso 1 → 0.6 changed ${(changed * 100).toFixed(2)}% of the figure`);

  // The figure's own slider moves the model's value, although the model cannot save.
  await figure.evaluate((e) => { e.iso = 0.8; });
  await tab.waitForFunction(() => window.host.get('iso') === 0.8);

  // The iframe's figure draws too.
  const frame = tab.frameLocator('iframe');
  await frame.locator('metaballs-view').waitFor();
  await tab.waitForFunction(() => document.querySelector('iframe').contentDocument
    ?.querySelector('metaballs-view')?.stats?.triangles > 0, null, { timeout: 60_000 });
  await tab.screenshot({ path: path.join(outputDir, 'book-page.png'), fullPage: true });
  assert.deepEqual(errors, []);
  await tab.close();
});
