// The 2D figure's frame time in headless Chromium (SwiftShader here): 16 circles animating at 256² and
// 1024² squares, labels as the default `show` draws them (none are readable at these sizes) and with
// only the contour; the median of 60 frames of `frameMs` (sampling, marching and painting); and the
// stepper's cost per step at 64² and 256². Not a test:
// times depend on the machine. `node plane-bench.js` from tests/e2e (serves the repository itself).

import { benchSetup } from './helpers.js';

const { base, browser, close } = await benchSetup();
try {
  const page = await browser.newPage({ viewport: { width: 800, height: 800 } });
  await page.goto(`${base}www/examples/lecture.html`);
  for (const cells of [256, 1024]) {
    for (const show of ['', 'contour']) {
      const ms = await page.evaluate(async ([n, s]) => {
        const e = document.createElement('metaballs-2d');
        Object.assign(e.style, { position: 'fixed', left: '0', top: '0', width: '640px' });
        e.setAttribute('spheres', '16');
        e.setAttribute('resolution', String(n));
        if (s) e.setAttribute('show', s);
        document.body.append(e);
        const times = [];
        let last = -1;
        while (times.length < 60) {
          await new Promise((r) => requestAnimationFrame(r));
          if (e.frameMs !== last) times.push((last = e.frameMs));
        }
        e.remove();
        times.sort((a, b) => a - b);
        return times[30];
      }, [cells, show]);
      console.log(`${cells}² squares × 16 circles, show=${show || 'default'}: ${ms.toFixed(1)} ms per frame (median of 60)`);
    }
  }
  // The stepper's cost: a frame at a step halfway through the march (the contour so far rebuilt from
  // the squares before it), stepping one square per frame.
  for (const cells of [64, 256]) {
    const ms = await page.evaluate(async (n) => {
      const e = document.createElement('metaballs-2d');
      Object.assign(e.style, { position: 'fixed', left: '0', top: '0', width: '640px' });
      e.setAttribute('spheres', '16');
      e.setAttribute('resolution', String(n));
      document.body.append(e);
      e.stepTo((n * n) / 2);
      const times = [];
      for (let k = 0; k < 60; k += 1) {
        e.stepForward();
        await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
        times.push(e.frameMs);
      }
      e.remove();
      times.sort((a, b) => a - b);
      return times[30];
    }, cells);
    console.log(`stepper at ${cells}² squares × 16 circles, halfway: ${ms.toFixed(1)} ms per step (median of 60)`);
  }
} finally {
  await close();
}
