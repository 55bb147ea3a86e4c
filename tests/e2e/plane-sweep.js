// What the 2D figure's page (`squares.html`) makes of hostile values in its link, in headless Chromium:
// for each setting and value, whether the figure refused it (its notice) or took it, and what it then
// draws: the iso level and grid of its contour, whether its circles move, and its further levels.
// `npm run sweep:plane` (no build needed: the 2D figure has no WebAssembly). Options: `--root DIR`,
// repeatable, runs the same sweep on other checkouts (a before and after). Prints a line per value and
// checkout, and a JSON line starting "metaballs-plane-sweep ". Not a test: it reports what happens;
// `table.test.js` holds the reader.

import path from 'node:path';
import { chromium } from 'playwright-core';
import { root as here, CHROMIUM, FLAGS, serve } from './helpers.js';

const args = process.argv.slice(2);
const roots = [here, ...args.flatMap((a, i) => (a === '--root' ? [path.resolve(args[i + 1])] : []))];

// Setting → hostile values a link may carry.
const SWEEP = {
  iso: ['0x10', 'Infinity', '1e1', ' 2 ', '1_0', '١', '', '0.049999999'],
  resolution: ['0x10', '16.0', '1e1', '+12', '12 '],
  spheres: ['3.0', '0x3', '-0'],
  speed: ['-0', 'NaN', '.5'],
  paused: ['no', 'banana', 'off', '', 'YES'],
  saddle: ['DECIDER', ' decider '],
  theme: ['Light', 'sepia'],
  show: ['', 'ALL', 'grid,,contour', 'GRID'],
  levels: ['0x1', 'Infinity', '0.5,abc', '0.5, 1.5'],
  'iso-levels': ['0.5,1.5', '30'],
  circles: ['  ', '0,0', '0,0,0x1'],
  march: ['', 'off', '20,3', '1.5'],
};

async function sweepOne(browser, base, name, value) {
  const context = await browser.newContext({ viewport: { width: 720, height: 720 } });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(`${base}squares.html?${encodeURIComponent(name)}=${encodeURIComponent(value)}`);
  await page.waitForFunction(() => document.querySelector('metaballs-2d')?.frameMs > 0, null, { timeout: 15_000 });
  const seen = await page.$eval('metaballs-2d', async (e) => {
    const frames = () => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const before = JSON.stringify(e.samples().values.slice(0, 40));
    await frames();
    await new Promise((r) => setTimeout(r, 250));
    await frames();
    const notice = e.shadowRoot.getElementById('notice');
    const { iso, cells } = e.contours();
    return {
      refused: notice.hidden ? null : notice.textContent, iso, cells,
      moving: JSON.stringify(e.samples().values.slice(0, 40)) !== before,
      levels: e.getAttribute('iso-levels') ?? e.getAttribute('levels'),
    };
  });
  await context.close();
  return { ...seen, errors };
}

const servers = await Promise.all(roots.map(serve));
let browser;
const results = [];
try {
  browser = await chromium.launch({ executablePath: CHROMIUM, args: FLAGS, headless: true });
  for (const [name, values] of Object.entries(SWEEP)) {
    for (const value of values) {
      for (const [k, { base }] of servers.entries()) {
        const seen = await sweepOne(browser, base, name, value);
        results.push({ root: roots[k], name, value, ...seen });
        const what = seen.refused ? `refused: ${seen.refused}` : `taken: iso ${seen.iso}, ${seen.cells}², ${seen.moving ? 'moving' : 'still'}`
          + `${seen.levels ? `, levels ${seen.levels}` : ''}`;
        console.log(`${name}=${JSON.stringify(value)}${roots.length > 1 ? ` [${roots[k]}]` : ''}: ${what}${seen.errors.length ? ` (page errors: ${seen.errors.join('; ')})` : ''}`);
      }
    }
  }
} finally {
  await browser?.close();
  for (const server of servers) server.stop();
}
console.log(`metaballs-plane-sweep ${JSON.stringify(results)}`);
