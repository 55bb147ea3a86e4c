// The figures in their reader's language, in Chromium: a page in German shows German words and writes
// numbers as German does (a refused iso level says 0,05); switching the document's `lang` rewords every
// figure without a reload, an element's own `lang` wins over the page's; Arabic mirrors the panels and
// not the pictures; a page's registered words show; links and saved scenes are the same bytes in every
// language. Pseudo-languages (accented English 40 % longer, and one written right to left) clip and
// overflow nothing in the panel at its narrowest and on a 390-px phone, and axe-core passes.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import path from 'node:path';
import { openClosedAfterEach, openPanelGroups, outputDir, root, useServerAndBrowser } from './helpers.js';
import { EN, SHIPPED } from '../../www/lib/i18n/words.js';
import { pseudoLanguages } from './pseudo.js';

useServerAndBrowser();
const open = openClosedAfterEach();
const PAGE = 'tests/e2e/fixtures/languages.html';
// The whole page as seen, both figures (tests/output/e2e-NAME.png).
const screenshot = (page, name) => page.screenshot({ path: path.join(outputDir, `e2e-${name}.png`) });
const catalogue = async (lang) => (lang === 'en' ? EN : { ...EN, ...(await SHIPPED[lang]()).default });

// The text of the 3D figure's label for `name` and of the 2D figure's.
const labels = (page, name) => page.evaluate((name) => {
  const label = (id) => [...document.getElementById(id).shadowRoot.querySelectorAll('label')]
    .find((l) => l.htmlFor && l.htmlFor.endsWith(name))?.textContent.trim() ?? null;
  return { three: label('three'), two: label('two') };
}, name);

// Sets the document's language and waits until the 3D figure's iso label reads `expected`.
async function switchTo(page, lang, expected) {
  await page.evaluate((lang) => { document.documentElement.lang = lang; }, lang);
  await page.waitForFunction((expected) => [...document.getElementById('three').shadowRoot.querySelectorAll('label')]
    .some((l) => l.htmlFor.endsWith('iso') && l.textContent.trim() === expected), expected, { timeout: 10_000 });
}

// The 3D figure has drawn (its triangle count is written in the page's language, so it is not read).
async function ready(page) {
  await page.waitForFunction(() => document.getElementById('three')?.framesDrawn > 0, null, { timeout: 60_000 });
  await openPanelGroups(page, '#three');
}

test('a German page shows German words, numbers written 0,05, and the same links and scenes as every language', async () => {
  const { page, errors } = await open(PAGE);
  await ready(page);
  const de = await catalogue('de');
  assert.deepEqual(await labels(page, 'iso'), { three: de['setting.iso'], two: de['setting.iso'] });
  await page.evaluate(() => document.getElementById('three').setAttribute('iso', '0.01'));
  const notice = await page.evaluate(() => document.getElementById('three').shadowRoot.getElementById('notice').textContent);
  assert.match(notice, /0,05/, `the notice writes numbers as German does: ${notice}`);
  assert.match(notice, /"0\.01"/, 'the value typed is echoed as typed');
  assert.doesNotMatch(notice, /must be/, `the notice is German: ${notice}`);
  await screenshot(page, 'languages-de');

  const saved = {};
  for (const lang of ['en', 'de', 'ja', 'ar', 'zh-CN', 'fr', 'es', 'pt-BR']) {
    await switchTo(page, lang, (await catalogue(lang))['setting.iso']);
    saved[lang] = await page.evaluate(async () => {
      const three = document.getElementById('three');
      const two = document.getElementById('two');
      return { link: three.shareText().link, python: three.shareText().python, scene: await three.saveScene(),
        plane: two.shareText().link, planeScene: await two.saveScene?.() };
    });
  }
  for (const [lang, texts] of Object.entries(saved)) assert.deepEqual(texts, saved.en, `${lang}: the machines' texts`);
  assert.deepEqual(errors, []);
});

test('an element\'s own lang wins over the page\'s, and Arabic mirrors the panels but not the pictures', async () => {
  const { page, errors } = await open(PAGE);
  await ready(page);
  const [ja, de, ar] = await Promise.all(['ja', 'de', 'ar'].map(catalogue));
  await page.evaluate(() => { document.getElementById('three').lang = 'ja'; });
  await page.waitForFunction((expected) => [...document.getElementById('three').shadowRoot.querySelectorAll('label')]
    .some((l) => l.htmlFor.endsWith('iso') && l.textContent.trim() === expected), ja['setting.iso']);
  assert.equal((await labels(page, 'iso')).two, de['setting.iso'], 'the 2D figure keeps the page\'s German');
  await page.evaluate(() => { document.getElementById('three').removeAttribute('lang'); });
  await switchTo(page, 'ar', ar['setting.iso']);
  const layout = await page.evaluate(() => {
    const three = document.getElementById('three');
    const box = three.getBoundingClientRect();
    const panel = three.shadowRoot.getElementById('panel');
    const canvas = three.shadowRoot.getElementById('view');
    const two = document.getElementById('two').shadowRoot;
    return {
      panel: getComputedStyle(panel).direction,
      panelRightGap: box.right - panel.getBoundingClientRect().right,
      panelLeftGap: panel.getBoundingClientRect().left - box.left,
      canvas: getComputedStyle(canvas).direction,
      twoControls: getComputedStyle(two.querySelector('.controls')).direction,
      twoCanvas: getComputedStyle(two.getElementById('view')).direction,
    };
  });
  assert.equal(layout.panel, 'rtl');
  assert.ok(layout.panelRightGap < layout.panelLeftGap, `the panel moves to the right: ${JSON.stringify(layout)}`);
  assert.equal(layout.canvas, 'ltr', 'the picture does not mirror');
  assert.equal(layout.twoControls, 'rtl');
  assert.equal(layout.twoCanvas, 'ltr');
  await screenshot(page, 'languages-ar');
  assert.deepEqual(errors, []);
});

test('a page registers its own language and overrides a word, key by key over English', async () => {
  const { page, errors } = await open(PAGE);
  await ready(page);
  await page.evaluate(async () => {
    const { registerTranslation } = await import('/www/metaballs-view.js');
    registerTranslation('nl', { 'setting.iso': 'Isoniveau' });
    registerTranslation('de', { 'setting.resolution': 'Gitterauflösung' });
  });
  await page.waitForFunction(() => [...document.getElementById('three').shadowRoot.querySelectorAll('label')]
    .some((l) => l.htmlFor.endsWith('resolution') && l.textContent.trim() === 'Gitterauflösung'));
  await switchTo(page, 'nl', 'Isoniveau');
  assert.equal((await labels(page, 'speed')).three, EN['setting.speed'], 'a word nl lacks is English');
  const thrown = await page.evaluate(async () => {
    const { registerTranslation } = await import('/www/metaballs-2d.js');
    try { registerTranslation('nl', { 'setting.iso': 42 }); } catch (error) { return error.message; }
    return null;
  });
  assert.match(thrown, /must be a text, or plural forms/);
  assert.deepEqual(errors, []);
});

for (const { width, height, name } of [{ width: 640, height: 420, name: 'the panel at its narrowest' }, { width: 390, height: 800, name: 'a 390-px phone' }]) {
  test(`pseudo-languages clip and overflow nothing in ${name}, and axe-core passes`, async () => {
    const { page, errors } = await open(PAGE, { viewport: { width, height } });
    await ready(page);
    await page.evaluate(async (languages) => {
      const { registerTranslation } = await import('/www/metaballs-view.js');
      for (const [lang, messages] of Object.entries(languages)) registerTranslation(lang, messages);
    }, pseudoLanguages(EN));
    for (const lang of ['en-XA', 'ar-XB']) {
      const iso = pseudoLanguages(EN)[lang]['setting.iso'];
      await switchTo(page, lang, iso);
      await page.evaluate(() => document.getElementById('three').setAttribute('iso', '99'));
      const overflowing = await page.evaluate(() => {
        const found = [];
        for (const host of document.querySelectorAll('metaballs-view, metaballs-2d')) {
          const nodes = host.shadowRoot.querySelectorAll('label, output, summary, button, select, #hud div, #notice, .control, [role=tab], h2, h3, p, li');
          for (const node of nodes) {
            if (!node.getClientRects().length) continue;
            if (node.scrollWidth > node.clientWidth + 1 && getComputedStyle(node).overflowX !== 'auto') {
              found.push(`${host.id} ${node.tagName.toLowerCase()}#${node.id || node.className}: ${node.textContent.trim().slice(0, 40)} (${node.scrollWidth} > ${node.clientWidth})`);
            }
          }
          for (const id of ['panel', 'hud']) {
            const box = host.shadowRoot.getElementById(id);
            if (box?.getClientRects().length && box.scrollWidth > box.clientWidth + 1) found.push(`${host.id} #${id} scrolls sideways`);
          }
        }
        return found;
      });
      assert.deepEqual(overflowing, [], `${lang}: clipped or overflowing`);
      await screenshot(page, `languages-${lang}-${width}`);
    }
    await page.addScriptTag({ path: path.join(root, 'tests/e2e/node_modules/axe-core/axe.min.js') });
    const violations = await page.evaluate(async () => {
      const result = await window.axe.run(document, { runOnly: { type: 'tag', values: ['wcag2a', 'wcag2aa', 'wcag21aa', 'wcag22aa'] }, rules: { 'color-contrast': { enabled: false } } });
      return result.violations.map((v) => `${v.id}: ${v.nodes.length} (${v.nodes[0]?.target})`);
    });
    assert.deepEqual(violations, []);
    assert.deepEqual(errors, []);
  });
}
