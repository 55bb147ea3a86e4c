// The 3D step-through's cost in headless Chromium (SwiftShader here): the page at 32³ and 64³ with 16
// spheres, the march opened by its link and moved one cell at a time; the median time from setting the
// cell to the frame drawn with it (the cell inspected, the mesh of the cells reached made and drawn),
// against the same frame with the march off. Not a test: times depend on the machine.
// `node march-bench.js` from tests/e2e (serves the repository itself).

import { benchSetup } from './helpers.js';

const { base, browser, close } = await benchSetup();
try {
  for (const cells of [32, 64]) {
    const page = await browser.newPage({ viewport: { width: 960, height: 640 } });
    await page.goto(`${base}index.html?spheres=16&res=${cells}&paused=1&aa=0&march=0,0,${cells / 2}`);
    await page.waitForFunction(() => document.querySelector('metaballs-view')?.inspected, null, { timeout: 120000 });
    const times = await page.evaluate(async (n) => {
      const e = document.querySelector('metaballs-view');
      const time = async (value) => {
        const start = performance.now();
        e.setAttribute('march', value);
        await e.nextFrame();
        return performance.now() - start;
      };
      const median = (list) => list.sort((a, b) => a - b)[list.length >> 1];
      const stepped = [];
      const whole = [];
      for (let k = 0; k < 30; k += 1) {
        stepped.push(await time(`${(k * 7) % n},${(k * 3) % n},${n / 2}`));
        whole.push(await time(k % 2 ? 'off' : `${n - 1},${n - 1},${n - 1}`));
      }
      return [median(stepped), median(whole)];
    }, cells);
    console.log(`${cells}³ × 16 spheres: a step of the march ${times[0].toFixed(1)} ms to its frame; the whole mesh ${times[1].toFixed(1)} ms (median of 30)`);
    await page.close();
  }
} finally {
  await close();
}
