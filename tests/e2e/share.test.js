// The share box, as an author uses it: the view on screen (spheres placed by hand, the camera turned by
// a drag, paused) written as HTML, pasted into a blank page that loads the module, draws the same
// picture; so does the iframe page's URL, for both figures. Every row of both tables, set to another
// value, is written and read back from the HTML; the Python call builds a widget with the same traits
// (in the notebook's test environment); the MyST directive builds with `myst build`. Copy writes to
// the clipboard, or selects the text where the browser refuses.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, mkdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {
  browser, baseUrl, differingFraction, open, otherText, outputDir, root, tableRows, useServerAndBrowser, waitForTriangles,
} from './helpers.js';
import { figureContrast } from './phone-checks.js';

useServerAndBrowser();

const TABLE = tableRows();
const PLANE = tableRows(undefined, 'PLANE_TABLE');
const SIZE = { width: 640, height: 360 };
const VENV = process.env.METABALLS_JUPYTER_VENV ?? path.join(root, 'target/python/test-venv');

// A page of the author's own with `html` pasted into it, saved where the server serves it.
function pastedPage(name, html, style) {
  const dir = path.join(outputDir, 'share');
  mkdirSync(dir, { recursive: true });
  writeFileSync(path.join(dir, name), `<!doctype html>\n<html lang="en"><head><meta charset="utf-8"><link rel="icon" href="data:,"><title>${name}</title>`
    + `<style>body { margin: 0 } ${style}</style></head><body>\n${html}\n</body></html>\n`);
  return `/tests/output/share/${name}`;
}

// The 3D figure's picture at its box's size, once a frame of its settings is drawn.
async function posterOf(page) {
  return Buffer.from(await page.$eval('metaballs-view', async (e) => {
    await e.ready();
    await e.nextFrame();
    return [...new Uint8Array(await (await e.makePoster(1)).arrayBuffer())];
  }));
}

const SPHERES = [
  { center: [-0.35, 0.05, 0], radius: 0.38, velocity: [0.2, 0.1, 0], charge: 1 },
  { center: [0.3, -0.1, 0.1], radius: 0.33, velocity: [-0.1, 0.2, 0.1], charge: 1 },
  { center: [0.05, 0.4, -0.2], radius: 0.22, velocity: [0, -0.2, 0.1], charge: 1 },
];

test('the 3D view as shown (spheres placed by hand, the camera turned by a drag, paused), pasted as HTML into a blank page and opened as the iframe URL, draws the same picture', async () => {
  const { page, errors, close } = await open('index.html?iso=0.8&res=32', { viewport: SIZE });
  try {
    await waitForTriangles(page);
    // Paused, the figure draws its scene exactly once the step it had in hand is drawn.
    await page.$eval('metaballs-view', async (e, list) => { e.sphereList = list; e.pause(); await e.nextFrame(); await e.nextFrame(); }, SPHERES);
    const before = await page.$eval('metaballs-view', (e) => ({ yaw: e.yaw, pitch: e.pitch }));
    await page.mouse.move(430, 250);
    await page.mouse.down();
    await page.mouse.move(480, 280, { steps: 5 });
    await page.mouse.up();
    const figure = await page.$eval('metaballs-view', async (e) => {
      await e.nextFrame();
      await e.nextFrame();
      return { yaw: e.yaw, pitch: e.pitch, distance: e.distance, list: e.sphereList, texts: e.shareText() };
    });
    assert.notEqual(figure.yaw, before.yaw, 'the drag did not turn the camera');
    const { texts } = figure;
    console.log(texts.html);
    assert.match(texts.html, /<script type="module" src="http:\/\/127\.0\.0\.1:\d+\/www\/metaballs-view\.js"><\/script>/);
    assert.match(texts.html, /metaballs-view 0\.1\.0/);
    for (const name of ['iso', 'resolution', 'paused', 'yaw', 'pitch', 'sphere-list']) {
      assert.match(texts.html, new RegExp(`\\s${name}[=\\s>]`), `the HTML does not carry ${name}`);
    }
    assert.ok(!/antialiasing/.test(texts.html), 'a setting the figure chose for its software adapter was written');
    const original = await posterOf(page);
    writeFileSync(path.join(outputDir, 'share-original.png'), original);

    const pasted = await open(pastedPage('view.html', texts.html, 'metaballs-view { width: 640px; height: 360px }'), { viewport: SIZE });
    try {
      const copy = await pasted.page.$eval('metaballs-view', async (e) => {
        await e.ready();
        await e.nextFrame();
        return { yaw: e.yaw, pitch: e.pitch, distance: e.distance, list: e.sphereList };
      });
      assert.deepEqual(copy, { yaw: figure.yaw, pitch: figure.pitch, distance: figure.distance, list: figure.list });
      const picture = await posterOf(pasted.page);
      writeFileSync(path.join(outputDir, 'share-pasted.png'), picture);
      const differing = await differingFraction(page, original, picture);
      console.log(`pasted HTML: ${(differing * 100).toFixed(3)} % of pixels differ`);
      assert.ok(differing < 0.005, `the pasted figure's picture differs in ${(differing * 100).toFixed(2)} % of its pixels`);
      assert.deepEqual(pasted.errors, []);
    } finally {
      await pasted.close();
    }

    // The iframe: its page at the size the figure was seen at.
    assert.match(texts.iframe, /width="640"/);
    assert.match(texts.iframe, /height="360"/);
    assert.ok(texts.iframe.includes(`src="${texts.url.replace(/&/g, '&amp;')}"`));
    const framed = await open(texts.url, { viewport: SIZE });
    try {
      const picture = await posterOf(framed.page);
      const differing = await differingFraction(page, original, picture);
      console.log(`iframe URL: ${(differing * 100).toFixed(3)} % of pixels differ`);
      assert.ok(differing < 0.005, `the iframe page's picture differs in ${(differing * 100).toFixed(2)} % of its pixels`);
      assert.deepEqual(framed.errors, []);
    } finally {
      await framed.close();
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('the 2D figure with circles placed by hand, pasted as HTML and opened as the iframe URL, draws the same picture', async () => {
  const { page, errors, close } = await open('squares.html?iso=1.1&resolution=12', { viewport: { width: 700, height: 800 } });
  try {
    await page.waitForFunction(() => document.querySelector('metaballs-2d')?.shareText);
    const figure = await page.$eval('metaballs-2d', (e) => {
      e.circleList = [{ x: -0.3, y: 0.1, r: 0.32 }, { x: 0.35, y: -0.15, r: 0.3 }];
      e.pause();
      return { svg: e.toSVG(480), texts: e.shareText() };
    });
    assert.match(figure.texts.html, /circles="/);
    assert.match(figure.texts.python, /^from metaballs_widget import Metaballs2d\n\nMetaballs2d\(/);
    const svgOf = async (url) => {
      const opened = await open(url, { viewport: { width: 700, height: 800 } });
      try {
        await opened.page.waitForFunction(() => document.querySelector('metaballs-2d')?.toSVG);
        const svg = await opened.page.$eval('metaballs-2d', (e) => e.toSVG(480));
        assert.deepEqual(opened.errors, []);
        return svg;
      } finally {
        await opened.close();
      }
    };
    // The picture, not its accessible name: the full page's own description is not shared.
    const drawn = (svg) => svg.replace(/<title>.*?<\/title>/, '');
    for (const [what, url] of [['pasted HTML', pastedPage('plane.html', figure.texts.html, 'metaballs-2d { width: 600px }')], ['iframe URL', figure.texts.url]]) {
      const svg = drawn(await svgOf(url));
      assert.ok(svg === drawn(figure.svg), `the ${what} draws another picture (${svg.length} and ${figure.svg.length} characters of SVG)`);
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

// Every row set to a value other than its default on a figure of its own (not drawn): written in the
// HTML, and read back from it as the same value. The Python call of a figure with every row set builds
// a widget whose traits hold the same values.
for (const [tag, rows, url] of [['metaballs-view', TABLE, 'index.html'], ['metaballs-2d', PLANE, 'squares.html']]) {
  test(`every row of <${tag}>'s table, set to another value, is written in the share box's HTML and Python and read back`, async () => {
    const { page, close } = await open(url);
    try {
      await page.waitForFunction((t) => customElements.get(t) && (t === 'metaballs-2d' || window.metaballs), tag, { timeout: 60_000 });
      // Another value than the default in this table (the 2D figure's resolution is 16 by default).
      // Free text with what HTML, links, Python and MyST each escape.
      const other = (row) => (row.kind === 'text' && row.name !== 'circles' && row.name !== 'march' && row.name !== 'slice-of'
        ? 'A "figure" & <its> text\\ with ```ticks``` and é'
        : otherText(row) === row.default ? String(row.value + 2) : otherText(row));
      const given = rows.map((row) => [row.name, other(row), row.kind]);
      const result = await page.evaluate(([t, list]) => {
        const read = (html) => {
          const holder = document.createElement('div');
          holder.innerHTML = html;
          customElements.upgrade(holder);
          return holder.querySelector(t);
        };
        const problems = [];
        const property = (name) => name.replace(/-([a-z])/g, (_, c) => c.toUpperCase());
        // The sphere list's property is a list of the spheres in play (none without a renderer): its text.
        const kinds = Object.fromEntries(list.map(([name, , kind]) => [name, kind]));
        const valueOf = (e, name) => (kinds[name] === 'spheres' ? e.getAttribute(name) : e[property(name)]);
        const show = (v) => JSON.stringify(v);
        for (const [name, text] of list) {
          const figure = document.createElement(t);
          figure.setAttribute(name, text);
          const { html } = figure.shareText();
          if (!new RegExp(`\\s${name}[=\\s>]`).test(html)) problems.push(`${name}="${text}" is not in ${html}`);
          const back = read(html);
          const [a, b] = [valueOf(figure, name), valueOf(back, name)];
          if (show(a) !== show(b)) problems.push(`${name}: ${show(a)} came back as ${show(b)}`);
        }
        const every = document.createElement(t);
        for (const [name, text] of list) every.setAttribute(name, text);
        const values = Object.fromEntries(list.map(([name]) => [name, valueOf(every, name)]));
        return { problems, python: every.shareText().python, values };
      }, [tag, given]);
      assert.deepEqual(result.problems, []);

      if (!existsSync(path.join(VENV, 'bin/python'))) assert.fail(`${VENV} is missing: tests/run.sh makes it`);
      const traits = JSON.parse(execFileSync(path.join(VENV, 'bin/python'), ['-c', `
import ast, json, sys
code = sys.stdin.read()
tree = ast.parse(code)
names = {}
exec(compile(ast.Module(tree.body[:-1], []), 'share', 'exec'), names)
widget = eval(compile(ast.Expression(tree.body[-1].value), 'share', 'eval'), names)
print(json.dumps({name: getattr(widget, name) for name in json.loads(sys.argv[1])}))
`, JSON.stringify(rows.map((row) => row.python))], { input: result.python, encoding: 'utf8' }));
      const problems = [];
      for (const row of rows) {
        const want = result.values[row.name];
        const got = traits[row.python];
        if (JSON.stringify(got) !== JSON.stringify(want)) problems.push(`${row.python}: ${JSON.stringify(got)}, the figure ${JSON.stringify(want)}`);
      }
      assert.deepEqual(problems, [], `the widget's traits differ from the figure's settings:\n${result.python}`);
    } finally {
      await close();
    }
  });
}

test("the MyST directive builds with `myst build` into an anywidget node with the figure's settings", async () => {
  const { page, close } = await open('index.html?res=24&yaw=12.5&balls=0.1,0,0,0.4;-0.3,0.1,0,0.3&alt=The%20%60f%60%20of%20%22two%22%20spheres', { viewport: SIZE });
  let shared;
  try {
    shared = await page.$eval('metaballs-view', async (e) => { await e.ready(); return e.shareText(); });
  } finally {
    await close();
  }
  const book = mkdtempSync(path.join(os.tmpdir(), 'metaballs-share-book-'));
  try {
    writeFileSync(path.join(book, 'myst.yml'), readFileSync(path.join(root, 'examples/book/myst.yml')));
    writeFileSync(path.join(book, 'index.md'), `---\ntitle: Shared\n---\n\n${shared.myst}\n`);
    // As the example book's test does: the theme's description stands in for the one fetched from the web.
    const theme = path.join(book, '_build/templates/site/myst/book-theme');
    mkdirSync(theme, { recursive: true });
    writeFileSync(path.join(theme, 'template.yml'), 'myst: v1\nkind: site\n');
    execFileSync(path.join(root, 'tests/e2e/node_modules/.bin/myst'), ['build', '--site'], { cwd: book, stdio: ['ignore', 'pipe', 'pipe'] });
    const tree = JSON.parse(readFileSync(path.join(book, '_build/site/content/index.json'), 'utf8'));
    const nodes = (t) => (t && typeof t === 'object' ? [...(t.type === 'anywidget' ? [t] : []), ...Object.values(t).flatMap(nodes)] : []);
    const [widget] = nodes(tree.mdast);
    assert.ok(widget, 'no anywidget node was built');
    const model = JSON.parse(shared.myst.split('\n').slice(1, -1).join('\n'));
    assert.deepEqual(widget.model, model);
    assert.deepEqual([model.sphere_list, model.yaw, model.alt], ['0.1,0,0,0.4;-0.3,0.1,0,0.3', 12.5, 'The `f` of "two" spheres']);
  } finally {
    rmSync(book, { recursive: true, force: true });
  }
});

test('Copy writes the text to the clipboard where allowed, and selects it for the reader where the browser refuses', async () => {
  for (const allowed of [true, false]) {
    const context = await browser.newContext({ viewport: { width: 960, height: 640 } });
    if (allowed) await context.grantPermissions(['clipboard-read', 'clipboard-write'], { origin: baseUrl });
    const page = await context.newPage();
    try {
      if (!allowed) {
        await page.addInitScript(() => {
          Object.defineProperty(navigator, 'clipboard', { value: { writeText: () => Promise.reject(new DOMException('refused', 'NotAllowedError')) } });
        });
      }
      await page.goto(`${baseUrl}/squares.html`);
      await page.waitForFunction(() => document.querySelector('metaballs-2d')?.openShare);
      await page.click('#open-share');
      const dialog = page.locator('metaballs-2d dialog.share');
      await dialog.waitFor();
      await dialog.getByRole('tab', { name: 'Python' }).click();
      await dialog.getByRole('button', { name: 'Copy' }).click();
      await page.waitForFunction(() => document.querySelector('metaballs-2d').shadowRoot.querySelector('.copy-status').textContent !== '');
      const state = await page.$eval('metaballs-2d', (e) => {
        const area = e.shadowRoot.querySelector('dialog.share textarea');
        return {
          text: area.value, start: area.selectionStart, end: area.selectionEnd,
          focused: e.shadowRoot.activeElement === area, status: e.shadowRoot.querySelector('.copy-status').textContent,
        };
      });
      assert.match(state.text, /^from metaballs_widget import Metaballs2d/);
      if (allowed) {
        assert.equal(state.status, 'Copied.');
        assert.equal(await page.evaluate(() => navigator.clipboard.readText()), state.text);
      } else {
        assert.match(state.status, /selected/);
        assert.deepEqual([state.start, state.end, state.focused], [0, state.text.length, true]);
      }
    } finally {
      await context.close();
    }
  }
});

test("the share box of each figure, in both themes, meets axe-core's WCAG 2.2 AA rules and every text its contrast", async () => {
  for (const [url, tag] of [['index.html', 'metaballs-view'], ['squares.html', 'metaballs-2d']]) {
    const { page, errors, close } = await open(url, { viewport: { width: 960, height: 700 } });
    try {
      await page.waitForFunction((t) => document.querySelector(t)?.openShare, tag, { timeout: 60_000 });
      await page.addScriptTag({ path: path.join(root, 'tests/e2e/node_modules/axe-core/axe.min.js') });
      for (const theme of ['dark', 'light']) {
        await page.$eval(tag, (e, t) => { e.setAttribute('theme', t); e.openShare(); }, theme);
        const handle = await page.$(tag);
        const checked = await handle.evaluate(figureContrast);
        assert.deepEqual(checked.failing, [], `${url}, ${theme}: texts under their contrast`);
        const violations = await page.evaluate(async () => {
          const result = await window.axe.run(document, {
            runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa'] },
            resultTypes: ['violations'],
          });
          return result.violations.map((v) => `${v.id} (${v.impact}): ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(' | ')}`);
        });
        assert.deepEqual(violations, [], `${url}, ${theme}`);
        await page.screenshot({ path: path.join(outputDir, `share-box-${tag}-${theme}.png`) });
        await page.$eval(tag, (e) => e.shadowRoot.querySelector('dialog.share').close());
      }
      assert.deepEqual(errors, []);
    } finally {
      await close();
    }
  }
});

test("Download poster saves a PNG at 2× the figure's box, and the share box's HTML names it as the poster", async () => {
  const { page, errors, close } = await open('index.html?res=24', { viewport: SIZE });
  try {
    await waitForTriangles(page);
    await page.click('#open-share');
    const dialog = page.locator('metaballs-view dialog.share');
    await dialog.waitFor();
    const [download] = await Promise.all([page.waitForEvent('download'), dialog.getByRole('button', { name: 'PNG 2×' }).click()]);
    assert.equal(download.suggestedFilename(), 'metaballs-poster@2x.png');
    const png = readFileSync(await download.path());
    assert.deepEqual([...png.subarray(1, 4)], [...Buffer.from('PNG')]);
    assert.deepEqual([png.readUInt32BE(16), png.readUInt32BE(20)], [2 * SIZE.width, 2 * SIZE.height]);
    await page.waitForFunction(() => /poster="metaballs-poster@2x\.png"/.test(document.querySelector('metaballs-view').shadowRoot.querySelector('dialog.share textarea').value));
    assert.match(await page.$eval('metaballs-view', (e) => e.shareText().html), /poster="metaballs-poster@2x\.png"/);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
