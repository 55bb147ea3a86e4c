// The lecture and the 2D page on a phone (390 × 844 CSS px, touch, two device pixels per CSS pixel), as
// a student opens them: every teaching box of every figure opened in turn, and after each, nothing of a
// figure drawn past its box, no sideways scrolling, at least 40 % of the picture uncovered and every
// control at least 24 × 24 CSS px (WCAG 2.2, 2.5.8); the teaching gestures by touch; axe-core's WCAG 2.2
// AA rules at phone and desktop widths in both themes; and the contrast of every text a figure shows
// against what is behind it. Screenshots of each section go to tests/output/phone-*.png.

import { after, test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { baseUrl, browser, outputDir, root, useServerAndBrowser } from './helpers.js';
import { figureContrast, figureLayout } from './phone-checks.js';

useServerAndBrowser();

const PHONE = { viewport: { width: 390, height: 844 }, deviceScaleFactor: 2, hasTouch: true, isMobile: true };
const DESKTOP = { viewport: { width: 1280, height: 900 } };
const LECTURE = 'www/examples/lecture.html';

async function openAs(device, url) {
  const context = await browser.newContext(device);
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => { if (m.type() === 'error') errors.push(m.text()); });
  await page.goto(`${baseUrl}${url}`);
  return { page, errors, close: () => context.close() };
}

// The lecture on a phone, opened once for the tests that read it (each leaves it as a reader would).
let shared = null;
const lectureOnPhone = () => (shared ??= openAs(PHONE, LECTURE));
after(async () => { await (await shared)?.close().catch(() => {}); });

/** Scrolls figure `handle` to the top of the screen and waits for its first frame (3D) or picture (2D). */
async function showFigure(page, handle) {
  await handle.evaluate((e) => e.scrollIntoView({ block: 'start' }));
  await page.waitForFunction((e) => (e.localName === 'metaballs-view' ? e.framesDrawn > 0 : e.frameMs !== undefined), handle, { timeout: 90_000 });
}

/** Asserts what a figure on a phone must be, in its state `what`. */
async function assertLaidOut(page, handle, what) {
  const layout = await handle.evaluate(figureLayout);
  assert.deepEqual(layout.past, [], `${what}: drawn past the figure's box (${layout.figure})`);
  assert.deepEqual(layout.small, [], `${what}: controls under 24 × 24 CSS px`);
  assert.ok(layout.uncovered >= 0.4, `${what}: ${(layout.uncovered * 100).toFixed(0)} % of the picture uncovered`);
  const [scroll, width] = await page.evaluate(() => [document.documentElement.scrollWidth, innerWidth]);
  assert.ok(scroll <= width, `${what}: the page scrolls sideways (${scroll} > ${width})`);
  return layout;
}

/** A waiting step's failure, named. */
const failed = (what) => (error) => { throw new Error(`${what}: ${error.message}`); };

/** Taps the centre of `locator` with a finger. */
async function tap(page, locator) {
  const box = await locator.boundingBox();
  await page.touchscreen.tap(box.x + box.width / 2, box.y + box.height / 2);
}

/** A finger's drag from (x0, y0) to (x1, y1), in CSS px of the page, in `steps` moves. */
async function touchDrag(page, [x0, y0], [x1, y1], { steps = 6, holdMs = 0 } = {}) {
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x: x0, y: y0 }] });
  if (holdMs) await page.waitForTimeout(holdMs);
  for (let i = 1; i <= steps; i += 1) {
    const t = i / steps;
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [{ x: x0 + (x1 - x0) * t, y: y0 + (y1 - y0) * t }] });
  }
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
  await cdp.detach();
}

test('on a phone, every box of every lecture figure opened in turn leaves the picture in view and stays in the figure', async () => {
  const { page, errors } = await lectureOnPhone();
  const figures = await page.$$('metaballs-view, metaballs-2d');
  const seen = [];
  for (const [index, handle] of figures.entries()) {
    const id = await handle.evaluate((e, i) => {
      e.dataset.phone = i;
      const around = e.closest('figure[id], div[id]');
      const peers = [...around.querySelectorAll('metaballs-view, metaballs-2d')];
      return peers.length > 1 ? `${around.id}-${peers.indexOf(e) + 1}` : around.id;
    }, index);
    const name = id;
    await showFigure(page, handle);
    await assertLaidOut(page, handle, name);
    await page.screenshot({ path: path.join(outputDir, `phone-${name}.png`) });
    // Each box the figure has, by its tab, in turn; the panel with every group open.
    const tabs = await handle.evaluate((e) => [...e.shadowRoot.querySelectorAll('#tabs button')].map((b) => b.dataset.box));
    for (const box of tabs) {
      const tab = page.locator(`[data-phone="${index}"] >> #tabs button[data-box="${box}"]`);
      await tab.scrollIntoViewIfNeeded();
      const open = () => handle.evaluate((e, b) => e.shadowRoot.getElementById(b).classList.contains('shown'), box);
      if (!(await open())) await tap(page, tab);
      await page.waitForFunction(([e, b]) => e.shadowRoot.getElementById(b).classList.contains('shown'), [handle, box])
        .catch((error) => { throw new Error(`${name}: the tab of ${box} did not open it (${error.message})`); });
      if (box === 'panel') {
        await handle.evaluate((e) => { for (const d of e.shadowRoot.querySelectorAll('#panel details')) d.open = true; });
        // Usable, whatever other box is open (a wide figure's step-through and levels cover the panel).
        const usable = await handle.evaluate((e) => {
          const panel = e.shadowRoot.getElementById('panel');
          const control = panel.querySelector('input, select, button');
          control.focus();
          return !panel.inert && e.shadowRoot.activeElement === control;
        });
        assert.ok(usable, `${name}: the Controls sheet takes focus`);
      }
      await handle.evaluate((e) => e.scrollIntoView({ block: 'start' }));
      await assertLaidOut(page, handle, `${name} with ${box}`);
      await page.screenshot({ path: path.join(outputDir, `phone-${name}-${box}.png`) });
      seen.push(`${name}:${box}`);
      // Its tab again closes the sheet: the figure is the picture alone.
      await tap(page, tab);
      await page.waitForFunction(([e, b]) => !e.shadowRoot.getElementById(b).classList.contains('shown'), [handle, box]);
      const [w, h] = await handle.evaluate((e) => [e.clientWidth, e.clientHeight]);
      assert.ok(Math.abs(h - (w * 9) / 16) < 2 || (await handle.evaluate((e) => e.localName === 'metaballs-2d')), `${name}: back to 16:9 (${w}×${h})`);
    }
  }
  console.log(`boxes opened on a phone: ${seen.join(', ')}`);
  for (const box of ['merge-tree:levels-box', 'march-3d:march', 'ambiguity-1:hud', 'below:panel']) {
    assert.ok(seen.includes(box), `${box} was opened (${seen.join(', ')})`);
  }
  assert.deepEqual(errors, []);
});

test('where the page fixes the figure\'s size (the full page, the iframe page), a sheet covers the picture\'s lower part only', async () => {
  for (const [url, device] of [['index.html?controls=all&hud=on', PHONE],
    ['embed.html?controls=all&hud=on&levels&march=2,3,3', { ...PHONE, viewport: { width: 390, height: 219 } }]]) {
    const { page, errors, close } = await openAs(device, url);
    const handle = await page.$('metaballs-view');
    await showFigure(page, handle);
    const tabs = await handle.evaluate((e) => [...e.shadowRoot.querySelectorAll('#tabs button')].map((b) => b.dataset.box));
    assert.ok(tabs.includes('panel') && tabs.includes('hud'), `${url}: tabs ${tabs}`);
    for (const box of tabs) {
      const tab = page.locator(`metaballs-view >> #tabs button[data-box="${box}"]`);
      // (The row of tabs scrolls sideways when they do not fit.)
      await tab.scrollIntoViewIfNeeded();
      if (!(await handle.evaluate((e, b) => e.shadowRoot.getElementById(b).classList.contains('shown'), box))) await tap(page, tab);
      await page.waitForFunction(([e, b]) => e.shadowRoot.getElementById(b).classList.contains('shown'), [handle, box]);
      assert.ok(await handle.evaluate((e) => e.matches(':state(over)')), `${url} with ${box}: over the picture`);
      await assertLaidOut(page, handle, `${url} with ${box}`);
      await page.screenshot({ path: path.join(outputDir, `phone-${url.split(/[.?]/)[0]}-${box}.png`) });
    }
    assert.deepEqual(errors, []);
    await close();
  }
});

test('on a phone, the 2D page with its panel and its step-through open stays in the figure, its picture in view', async () => {
  const { page, errors, close } = await openAs(PHONE, 'squares.html');
  const figure = await page.$('metaballs-2d');
  await showFigure(page, figure);
  await assertLaidOut(page, figure, 'the 2D page');
  await tap(page, page.locator('metaballs-2d >> .panel summary'));
  await page.waitForFunction((e) => e.shadowRoot.querySelector('.panel').open, figure);
  await assertLaidOut(page, figure, 'the 2D page with its panel');
  await page.screenshot({ path: path.join(outputDir, 'phone-squares-panel.png') });
  const step = page.locator('metaballs-2d >> button[data-action="step-through"]');
  await step.scrollIntoViewIfNeeded();
  await tap(page, step);
  await page.waitForFunction((e) => e.stepIndex !== null, figure);
  // The step-through below the picture, its steps by touch.
  const before = await figure.evaluate((e) => e.stepIndex);
  const forward = page.locator('metaballs-2d >> button[data-do="forward"]');
  await forward.scrollIntoViewIfNeeded();
  await tap(page, forward);
  await page.waitForFunction(([e, k]) => e.stepIndex === k + 1, [figure, before]);
  await figure.evaluate((e) => e.scrollIntoView({ block: 'start' }));
  await assertLaidOut(page, figure, 'the 2D page with its step-through');
  await page.screenshot({ path: path.join(outputDir, 'phone-squares-march.png') });
  assert.deepEqual(errors, []);
  await close();
});

/** Waits until every figure of the page has loaded and drawn, each scrolled to in turn. */
async function everyFigureLoaded(page) {
  for (const handle of await page.$$('metaballs-view, metaballs-2d')) await showFigure(page, handle);
}

for (const [width, device] of [['phone', PHONE], ['desktop', DESKTOP]]) {
  test(`axe-core's WCAG 2.2 AA rules and every text's contrast, on the lecture and the 2D page, ${width}, both themes`, async () => {
    for (const url of [LECTURE, 'squares.html']) {
      const own = !(width === 'phone' && url === LECTURE);
      const { page, errors, close } = own ? await openAs(device, url) : await lectureOnPhone();
      await everyFigureLoaded(page);
      await page.addScriptTag({ path: path.join(root, 'tests/e2e/node_modules/axe-core/axe.min.js') });
      for (const theme of ['dark', 'light']) {
        const what = `${url}, ${width}, ${theme} theme`;
        await page.$$eval('metaballs-view, metaballs-2d', (all, t) => Promise.all(all.map((e) => {
          e.setAttribute('theme', t);
          for (const d of e.shadowRoot.querySelectorAll('details')) d.open = true;
          return e.nextFrame?.();
        })), theme);
        let texts = 0;
        for (const handle of await page.$$('metaballs-view, metaballs-2d')) {
          const checked = await handle.evaluate(figureContrast);
          texts += checked.texts;
          assert.deepEqual(checked.failing, [], `${what}: texts under their contrast`);
        }
        assert.ok(texts >= 10, `${what}: ${texts} texts checked`);
        const violations = await page.evaluate(async () => {
          const result = await window.axe.run(document, {
            runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21a', 'wcag21aa', 'wcag22aa'] },
            resultTypes: ['violations'],
          });
          return result.violations.map((v) => `${v.id} (${v.impact}): ${v.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(' | ')}`);
        });
        assert.deepEqual(violations, [], what);
      }
      assert.deepEqual(errors, []);
      if (own) await close();
    }
  });
}

test('the teaching gestures work with a finger: a cell picked, a sphere and a circle dragged, the iso cursor, a join, a step', async () => {
  const { page, errors } = await lectureOnPhone();
  const figure = async (id) => {
    const handle = await page.$(`#${id} metaballs-view, #${id} metaballs-2d`);
    await showFigure(page, handle);
    // A figure off screen a while has let its renderer go: a frame drawn now has it back.
    await handle.evaluate((e) => e.nextFrame?.());
    return handle;
  };
  const at = async (handle, x, y) => {
    const box = await handle.boundingBox();
    return [box.x + x, box.y + y];
  };

  // A cell picked by a tap on the surface: the inspector opens, as the sheet below the picture.
  const cells = await figure('cells');
  const sphere = await cells.evaluate((e) => e.sphereOnScreen(0));
  await page.touchscreen.tap(...(await at(cells, sphere.x, sphere.y)));
  await page.waitForFunction((e) => e.inspected !== null, cells).catch(failed('a tap picks a cell'));
  await page.waitForFunction((e) => e.shadowRoot.getElementById('inspector').classList.contains('shown'), cells).catch(failed('the inspector opens as the sheet'));
  await cells.evaluate((e) => e.scrollIntoView({ block: 'start' }));
  await assertLaidOut(page, cells, 'cells with the inspector');
  await page.screenshot({ path: path.join(outputDir, 'phone-cells-inspector.png') });

  // A sphere grabbed by a long press and dragged: it moves.
  const byHand = await figure('by-hand');
  const grabbed = await byHand.evaluate((e) => e.sphereOnScreen(1));
  const listBefore = await byHand.evaluate((e) => e.sphereList);
  const from = await at(byHand, grabbed.x, grabbed.y);
  // A tap first focuses the figure (and selects the sphere), so that a finger's drag is the figure's.
  await page.touchscreen.tap(...from);
  await page.waitForFunction((e) => e.selectedSphere === 1, byHand).catch(failed('a tap selects the sphere'));
  await touchDrag(page, from, [from[0], from[1] + 50], { holdMs: 700, steps: 8 });
  await page.waitForFunction(([e, y]) => e.sphereList[1].center[1] < y - 0.05, [byHand, listBefore[1].center[1]]).catch(failed('a long press and a drag move the sphere'));

  // A circle of the 2D figure dragged.
  const squares = await figure('squares');
  const [circle] = await squares.evaluate((e) => e.circleList.map((c) => ({ ...c })));
  const box = await squares.boundingBox();
  const inPlane = (x, y) => [box.x + box.width * (0.03 + (0.94 * (x + 1)) / 2), box.y + box.height * (0.03 + (0.94 * (1 - y)) / 2)];
  await touchDrag(page, inPlane(circle.x, circle.y), inPlane(circle.x - 0.3, circle.y - 0.2), { steps: 8 });
  const [moved] = await squares.evaluate((e) => e.circleList);
  assert.ok(Math.abs(moved.x - (circle.x - 0.3)) < 0.05 && Math.abs(moved.y - (circle.y - 0.2)) < 0.05, JSON.stringify(moved));

  // The iso cursor dragged along the plot, and a join of the merge tree chosen.
  // (A box the earlier tests closed is opened by its tab, as a reader would.)
  const openSheet = async (id, handle, box) => {
    if (await handle.evaluate((e, b) => e.shadowRoot.getElementById(b).classList.contains('shown'), box)) return;
    const tab = page.locator(`#${id} >> #tabs button[data-box="${box}"]`);
    await tab.scrollIntoViewIfNeeded();
    await tap(page, tab);
    await page.waitForFunction(([e, b]) => e.shadowRoot.getElementById(b).classList.contains('shown'), [handle, box]);
    await handle.evaluate((e) => e.scrollIntoView({ block: 'start' }));
  };
  const tree = await figure('merge-tree');
  await openSheet('merge-tree', tree, 'levels-box');
  await page.waitForSelector('#merge-tree >> div.levels svg.levels-plot', { timeout: 90_000 });
  const plot = await page.locator('#merge-tree >> div.levels svg.levels-plot').boundingBox();
  const isoBefore = await tree.evaluate((e) => Number(e.iso));
  await touchDrag(page, [plot.x + plot.width * 0.6, plot.y + plot.height * 0.5], [plot.x + plot.width * 0.3, plot.y + plot.height * 0.5]);
  const isoDragged = await tree.evaluate((e) => Number(e.iso));
  assert.ok(isoDragged < isoBefore, `iso after a drag to the left: ${isoDragged} (was ${isoBefore})`);
  // (The last join drawn is on top of its neighbours' targets.)
  // The plot and the tree are drawn again for the new level (and again as its measures come in): the
  // join is tapped once the tree drawn stays the same for 300 ms.
  await page.waitForFunction((e) => {
    const drawn = e.shadowRoot.querySelector('svg.merge-tree');
    const same = drawn === window.treeSeen;
    window.treeSeen = drawn;
    return same;
  }, tree, { polling: 300 });
  const join = page.locator('#merge-tree >> svg.merge-tree g.join').last();
  const joinLevel = Number((await join.getAttribute('aria-label')).match(/f = ([\d.]+)/)[1]);
  await join.scrollIntoViewIfNeeded();
  await tap(page, join);
  await page.waitForFunction(([e, f]) => Number(e.iso) < f && Number(e.iso) > f * 0.9, [tree, joinLevel]).catch(failed('a tap on a join sets the iso level just below it'));

  // The march stepped by a tap on its forward button.
  const march = await figure('march-3d');
  await openSheet('march-3d', march, 'march');
  const where = () => march.evaluate((e) => e.shadowRoot.querySelector('#march .where').textContent);
  const stepBefore = Number((await where()).match(/Step (\d+)/)[1]);
  const forward = page.locator('#march-3d >> button[data-do="forward"]');
  await forward.scrollIntoViewIfNeeded();
  await tap(page, forward);
  await page.waitForFunction(([e, k]) => e.shadowRoot.querySelector('#march .where').textContent.startsWith(`Step ${k + 1} `), [march, stepBefore]).catch(failed('a tap steps the march'));
  assert.deepEqual(errors, []);
});
