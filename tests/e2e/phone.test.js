// The lecture and the 2D page on a phone (390 × 844 CSS px, touch, two device pixels per CSS pixel), as
// a student opens them: every teaching box of every figure opened in turn, and after each, nothing of a
// figure drawn past its box, no sideways scrolling, at least 40 % of the picture uncovered and every
// control at least 24 × 24 CSS px (WCAG 2.2, 2.5.8); the teaching gestures by touch; axe-core's WCAG 2.2
// AA rules at phone and desktop widths in both themes; and the contrast of every text a figure shows
// against what is behind it. Screenshots of each section go to tests/output/phone-*.png.

import { test } from 'node:test';
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
  const { page, errors, close } = await openAs(PHONE, LECTURE);
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
      }
      await handle.evaluate((e) => e.scrollIntoView({ block: 'start' }));
      await assertLaidOut(page, handle, `${name} with ${box}`);
      await page.screenshot({ path: path.join(outputDir, `phone-${name}-${box}.png`) });
      seen.push(`${name}:${box}`);
      // Its tab again closes the sheet: the figure is the picture alone.
      await tap(page, tab);
      await page.waitForFunction(([e, b]) => !e.shadowRoot.getElementById(b).classList.contains('shown'), [handle, box]);
    }
  }
  console.log(`boxes opened on a phone: ${seen.join(', ')}`);
  for (const box of ['merge-tree:levels-box', 'march-3d:march', 'ambiguity-1:hud', 'below:panel']) {
    assert.ok(seen.includes(box), `${box} was opened (${seen.join(', ')})`);
  }
  assert.deepEqual(errors, []);
  await close();
});
