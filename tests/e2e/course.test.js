// The figure where course material lives: printed to PDF, audited for accessibility, restyled by the
// host page, on reveal.js slides, and measured for layout shift. The package, the static-site build
// and the server-side import are in package.test.js.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { browser, baseUrl, open as openPage, root, useServerAndBrowser } from './helpers.js';

useServerAndBrowser();

const FIXTURES = 'tests/e2e/fixtures';

const everyFigureDrawn = (page) => page.waitForFunction(
  () => [...document.querySelectorAll('metaballs-view')].every((e) => e.framesDrawn > 0), null, { timeout: 60_000 });

// Decodes a PNG in the page and returns RGBA statistics of the rectangle `box` (pixels): the share of
// dark pixels (a figure's background), of reddish ones (its surface) and of near-white ones (paper).
async function boxStats(page, png, box) {
  return page.evaluate(async ([b64, r]) => {
    const image = await createImageBitmap(await (await fetch(`data:image/png;base64,${b64}`)).blob());
    const canvas = new OffscreenCanvas(image.width, image.height);
    const context = canvas.getContext('2d');
    context.drawImage(image, 0, 0);
    const x0 = Math.max(0, Math.round(r.x)), y0 = Math.max(0, Math.round(r.y));
    const w = Math.min(image.width - x0, Math.round(r.width)), h = Math.min(image.height - y0, Math.round(r.height));
    const { data } = context.getImageData(x0, y0, w, h);
    let dark = 0, red = 0, white = 0;
    for (let i = 0; i < data.length; i += 4) {
      const [R, G, B] = [data[i], data[i + 1], data[i + 2]];
      if (R + G + B < 240) dark += 1;
      if (R > B + 30 && R > 90) red += 1;
      if (R > 235 && G > 235 && B > 235) white += 1;
    }
    const n = data.length / 4;
    return { dark: dark / n, red: red / n, white: white / n, pixels: n };
  }, [png.toString('base64'), box]);
}

test('printed to PDF right after load, every figure on the first page is a picture without its controls', async () => {
  // A4 at 96 pixels per inch: the page's layout in print is the layout at this width.
  const size = { width: 794, height: 1123 };
  const { page, errors } = await openPage('www/examples/lecture.html', { viewport: size });
  const started = Date.now();
  await page.waitForFunction(() => document.readyState === 'complete');
  // Each figure has a picture for print: the drawn ones of their frame, the others drawn once while the
  // page was idle.
  await page.evaluate(() => Promise.all([...document.querySelectorAll('metaballs-view')].map((e) => e.printable())));
  console.log(`every figure of the lecture had a picture for print ${Date.now() - started} ms after navigation`);
  await page.emulateMedia({ media: 'print' });
  // A while in print layout, where the canvases are hidden: the pictures taken before stand.
  await page.evaluate(() => new Promise((resolve) => setTimeout(resolve, 1500)));
  const boxes = await page.$$eval('metaballs-view', (figures) => figures.map((e) => {
    const r = e.getBoundingClientRect();
    const hidden = ['panel', 'hud', 'play', 'notice', 'view'].map((id) => getComputedStyle(e.shadowRoot.getElementById(id)).display);
    const picture = e.shadowRoot.getElementById('print-frame');
    return { x: r.x, y: r.y + scrollY, width: r.width, height: r.height, hidden, id: e.closest('figure')?.id,
      picture: [picture.naturalWidth, picture.naturalHeight] };
  }));
  for (const box of boxes.filter((b) => b.picture[0] > 0)) {
    assert.ok(box.picture[0] >= box.width / 2 && box.picture[1] >= box.height / 2,
      `${box.id}: the picture for print is ${box.picture.join(' × ')} pixels in a box of ${box.width} × ${box.height}`);
  }
  const directory = mkdtempSync(path.join(os.tmpdir(), 'metaballs-print-'));
  try {
    const pdf = path.join(directory, 'lecture.pdf');
    writeFileSync(pdf, await page.pdf({ width: `${size.width}px`, height: `${size.height}px`, printBackground: true,
      margin: { top: '0px', right: '0px', bottom: '0px', left: '0px' } }));
    execFileSync('pdftoppm', ['-r', '96', '-f', '1', '-l', '1', '-png', pdf, path.join(directory, 'page')]);
    const file = readdirSync(directory).find((name) => name.startsWith('page') && name.endsWith('.png'));
    const png = readFileSync(path.join(directory, file));
    writeFileSync(path.join(root, 'tests/output/e2e-print-page1.png'), png);
    const onFirstPage = boxes.filter((b) => b.y + b.height <= size.height);
    assert.ok(onFirstPage.length >= 1, 'no figure on the first printed page');
    for (const box of onFirstPage) {
      assert.deepEqual(box.hidden, ['none', 'none', 'none', 'none', 'none'], `${box.id}: controls or canvas in print`);
      const stats = await boxStats(page, png, box);
      console.log(`printed figure ${box.id}: ${(stats.dark * 100).toFixed(1)} % dark, ${(stats.red * 100).toFixed(2)} % surface, ${(stats.white * 100).toFixed(1)} % paper`);
      assert.ok(stats.dark > 0.5 && stats.white < 0.05, `${box.id}: the printed box is not a picture`);
      assert.ok(stats.red > 0.003, `${box.id}: the printed picture shows no surface`);
    }
  } finally {
    rmSync(directory, { recursive: true, force: true });
  }
  assert.deepEqual(errors, []);
  await page.close();
});

test('a poster shows before the wasm arrives, and in print', async () => {
  // The wasm is slow to arrive: the poster is all there is for now.
  const page = await browser.newPage({ viewport: { width: 640, height: 480 } });
  await page.route('**/metaballs_bg.wasm', (route) => setTimeout(() => route.continue().catch(() => {}), 8000));
  await page.goto(`${baseUrl}embed.html?poster=docs/metaballs.png&alt=A%20poster`);
  const poster = page.locator('metaballs-view >> #poster');
  await page.waitForFunction(() => document.querySelector('metaballs-view')?.shadowRoot?.getElementById('poster').complete);
  assert.equal(await poster.isVisible(), true, 'the poster is not shown');
  assert.match(await poster.getAttribute('src'), /docs\/metaballs\.png$/);
  for (const media of ['screen', 'print']) {
    await page.emulateMedia({ media });
    const png = await page.screenshot();
    const stats = await boxStats(page, png, { x: 0, y: 0, width: 640, height: 480 });
    assert.ok(stats.red > 0.01, `${media}: the poster does not show (${(stats.red * 100).toFixed(2)} % surface)`);
  }
  assert.equal(await page.$eval('metaballs-view', (e) => e.framesDrawn), 0);
  await page.close();
});

test('layout shift on the lecture stays under 0.05 while its figures load', async () => {
  const { page, errors } = await openPage('www/examples/lecture.html', {
    initScript: () => {
      window.layoutShift = 0;
      new PerformanceObserver((list) => {
        for (const entry of list.getEntries()) if (!entry.hadRecentInput) window.layoutShift += entry.value;
      }).observe({ type: 'layout-shift', buffered: true });
    },
  });
  await page.waitForFunction(() => document.querySelector('#merge metaballs-view')?.framesDrawn > 0, null,
    { timeout: 60_000 });
  // A second more for what loads after the first frame (the other figures, their posters) to shift.
  await page.waitForTimeout(1500);
  const shift = await page.evaluate(() => window.layoutShift);
  console.log(`lecture cumulative layout shift: ${shift.toFixed(4)}`);
  assert.ok(shift <= 0.05, `cumulative layout shift ${shift}`);
  assert.deepEqual(errors, []);
  await page.close();
});

async function axeViolations(page) {
  await page.addScriptTag({ path: path.join(root, 'tests/e2e/node_modules/axe-core/axe.min.js') });
  const violations = await page.evaluate(async () => {
    const result = await window.axe.run(document, { resultTypes: ['violations'] });
    return result.violations.map((v) => ({ id: v.id, impact: v.impact, nodes: v.nodes.length,
      target: v.nodes[0]?.target.join(' ') }));
  });
  return violations;
}

test('axe-core finds no serious or critical violations on the three pages, drawn, panels open', async () => {
  for (const url of ['index.html', 'embed.html?controls=all&hud=on', 'www/examples/lecture.html']) {
    const { page, errors } = await openPage(url);
    const figures = await page.$$('metaballs-view');
    for (const figure of figures) {
      await figure.scrollIntoViewIfNeeded();
      await page.waitForFunction((e) => e.framesDrawn > 0, figure, { timeout: 60_000 });
      await figure.evaluate((e) => { for (const d of e.shadowRoot.querySelectorAll('details')) d.open = true; });
    }
    const violations = await axeViolations(page);
    console.log(`axe-core on ${url}: ${violations.length ? violations.map((v) => `${v.id} (${v.impact}, ${v.nodes})`).join(', ') : 'no violations'}`);
    const serious = violations.filter((v) => v.impact === 'serious' || v.impact === 'critical');
    assert.deepEqual(serious, [], `${url}: ${JSON.stringify(serious)}`);
    assert.deepEqual(errors, []);
    await page.close();
  }
});

test('alt names the figure, the name follows the state without one, and control changes are announced', async () => {
  const { page, errors } = await openPage(`${FIXTURES}/themes.html`);
  await everyFigureDrawn(page);
  assert.equal(await page.getByRole('img', { name: 'Five spheres for the styling test' }).count(), 1);
  const derived = await page.$eval('#dark', (e) => e.shadowRoot.getElementById('view').getAttribute('aria-label'));
  assert.match(derived, /5 spheres, iso 1, 16³ cells, paused/);
  await page.$eval('#dark', (e) => { e.iso = 0.8; });
  assert.match(await page.$eval('#dark', (e) => e.shadowRoot.getElementById('view').getAttribute('aria-label')), /iso 0\.8/);
  // A control: the iso slider of #parts, moved by keyboard. The figure is small (420 px): its panel is
  // opened by its tab, as the sheet.
  await page.click('#parts >> #tabs button[data-box="panel"]');
  await page.$eval('#parts', (e) => { for (const d of e.shadowRoot.querySelectorAll('details')) d.open = true; });
  await page.locator('#parts >> #iso').focus();
  await page.keyboard.press('ArrowRight');
  await page.waitForFunction(() => /^iso level 1\.01$/.test(
    document.getElementById('parts').shadowRoot.getElementById('announce').textContent));
  // The panel's focus ring is visible on a keyboard-focused control.
  const ring = await page.$eval('#parts', (e) => getComputedStyle(e.shadowRoot.getElementById('iso')).outlineStyle);
  assert.equal(ring, 'solid');
  assert.deepEqual(errors, []);
  await page.close();
});

test('theme="light" and the background custom properties change the drawn picture; every part can be styled', async () => {
  const { page, errors } = await openPage(`${FIXTURES}/themes.html`);
  await everyFigureDrawn(page);
  await page.$$eval('metaballs-view', (all) => Promise.all(all.map((e) => e.nextFrame())));
  const corner = async (id) => {
    const png = await page.locator(`#${id}`).screenshot();
    const { dark, white } = await boxStats(page, png, { x: 0, y: 0, width: 40, height: 20 });
    return { dark, white };
  };
  const dark = await corner('dark');
  const light = await corner('light');
  const custom = await corner('custom');
  console.log(`background corners: dark ${JSON.stringify(dark)}, light ${JSON.stringify(light)}, custom ${JSON.stringify(custom)}`);
  assert.ok(dark.dark > 0.9, 'the dark theme is not dark');
  assert.ok(light.dark < 0.05, 'theme="light" drew a dark background');
  assert.ok(custom.white > 0.9, '--metaballs-background-top/-bottom did not reach the drawn background');
  // A property changed later is followed too.
  await page.$eval('#custom', (e) => e.style.setProperty('--metaballs-background-top', '#000000'));
  await page.$eval('#custom', (e) => e.style.setProperty('--metaballs-background-bottom', '#000000'));
  // The figure reads them at most every half second: frames until it has, for a few seconds at most.
  let followed = await corner('custom');
  for (const end = Date.now() + 5000; followed.dark <= 0.9 && Date.now() < end;) {
    await page.$eval('#custom', (e) => e.nextFrame());
    followed = await corner('custom');
  }
  assert.ok(followed.dark > 0.9, 'a changed custom property was not followed');
  const outlines = await page.$eval('#parts', (e) => ['view', 'panel', 'hud', 'notice', 'poster'].map(
    (id) => getComputedStyle(e.shadowRoot.getElementById(id)).outlineColor));
  assert.deepEqual(outlines, ['rgb(1, 2, 3)', 'rgb(4, 5, 6)', 'rgb(7, 8, 9)', 'rgb(10, 11, 12)', 'rgb(13, 14, 15)']);
  assert.deepEqual(errors, []);
  await page.close();
});

test('on reveal.js slides: off-slide figures draw nothing, the current one draws, the iframe pauses with its slide', async () => {
  const { page, errors } = await openPage(`${FIXTURES}/deck.html`);
  await page.waitForFunction(() => window.Reveal?.isReady());
  const frames = () => page.evaluate(() => ['two', 'three'].map((id) => document.getElementById(id).framesDrawn));
  await page.waitForTimeout(1500);
  assert.deepEqual(await frames(), [0, 0], 'figures drew on slides that are not shown');
  await page.evaluate(() => window.Reveal.slide(1));
  await page.waitForFunction(() => document.getElementById('two').framesDrawn > 3, null, { timeout: 60_000 });
  assert.equal((await frames())[1], 0, 'the figure on the next slide drew');
  await page.evaluate(() => window.Reveal.slide(2));
  await page.waitForFunction(() => document.getElementById('three').framesDrawn > 3, null, { timeout: 60_000 });
  const left = (await frames())[0];
  await page.waitForTimeout(1000);
  assert.equal((await frames())[0], left, 'the figure kept drawing after its slide was left');
  // The iframe's figure plays while its slide is shown and pauses when it is left.
  await page.evaluate(() => window.Reveal.slide(3));
  const inner = () => page.evaluate(() => {
    const e = document.getElementById('frame').contentWindow.metaballs?.element;
    return e ? { paused: e.paused, frames: e.framesDrawn } : null;
  });
  await page.waitForFunction(() => document.getElementById('frame').contentWindow.metaballs?.element.framesDrawn > 3,
    null, { timeout: 60_000 });
  assert.equal((await inner()).paused, false);
  await page.evaluate(() => window.Reveal.slide(2));
  await page.waitForFunction(() => document.getElementById('frame').contentWindow.metaballs.element.paused === true);
  await page.evaluate(() => window.Reveal.slide(3));
  await page.waitForFunction(() => document.getElementById('frame').contentWindow.metaballs.element.paused === false);
  assert.deepEqual(errors, []);
  await page.close();
});
