// The critical points' search in headless Chromium: `criticalPoints()` on the seeded layouts of 5, 16
// and 64 spheres (seed 1, as `metaballs critical` times them natively), on the topology worker; the
// median of ten searches after one to warm up, as the worker measures it and as the page waits for it.
// Not a test: times depend on the machine. `node critical-bench.js` from tests/e2e (serves the
// repository itself).

import { benchSetup } from './helpers.js';

const { base, browser, close } = await benchSetup();
try {
  for (const spheres of [5, 16, 64]) {
    const page = await browser.newPage({ viewport: { width: 960, height: 640 } });
    await page.goto(`${base}index.html?spheres=${spheres}&seed=1&paused=1&aa=0`);
    await page.waitForFunction(() => document.querySelector('metaballs-view')?.stats?.triangles > 0, null, { timeout: 120000 });
    const [worker, waited, points, complete] = await page.evaluate(async () => {
      const e = document.querySelector('metaballs-view');
      const median = (list) => list.sort((a, b) => a - b)[list.length >> 1];
      let last = await e.criticalPoints();
      const inWorker = [];
      const roundTrip = [];
      for (let k = 0; k < 10; k += 1) {
        const start = performance.now();
        last = await e.criticalPoints();
        roundTrip.push(performance.now() - start);
        inWorker.push(last.milliseconds);
      }
      return [median(inWorker), median(roundTrip), last.points.length, last.complete && last.undecided === 0];
    });
    console.log(`${spheres} spheres: ${worker.toFixed(1)} ms in the worker, ${waited.toFixed(1)} ms from asking to the answer (median of 10); ${points} critical points, proven complete: ${complete}`);
    await page.close();
  }
} finally {
  await close();
}
