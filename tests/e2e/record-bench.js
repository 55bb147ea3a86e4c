// How long a recording takes in headless Chromium (SwiftShader here), and how large it is: the default
// figure paused at 960×540, `record()` of 4 s at 30 fps at 640×360 in every format this Chromium writes.
// `npm run bench:record` (after www/build.sh); `-- --seconds S`, `-- --fps F`, `-- --size WxH` change
// the clip. Prints one line per format: the time, the frames, the bytes. Not a test: figures depend on
// the machine and on what else runs on it.

import { benchSetup } from './helpers.js';

const option = (name, fallback) => {
  const at = process.argv.indexOf(`--${name}`);
  return at > 0 ? process.argv[at + 1] : fallback;
};
const seconds = Number(option('seconds', 4));
const fps = Number(option('fps', 30));
const [width, height] = option('size', '640x360').split('x').map(Number);

const { base, browser, close } = await benchSetup();
try {
  const page = await browser.newPage({ viewport: { width: 960, height: 540 } });
  await page.goto(`${base}index.html`);
  await page.waitForFunction(() => window.metaballs?.element, null, { timeout: 60_000 });
  await page.$eval('metaballs-view', async (e) => { await e.ready(); e.pause(); await e.nextFrame(); });
  const formats = await page.evaluate(async ([w, h, f]) => (await import('/www/lib/figure/clip.js')).clipFormats(w, h, f), [width, height, fps]);
  console.log(`${seconds} s at ${fps} fps, ${width}×${height}, on ${await page.$eval('metaballs-view', (e) => e.stats.adapter)}`);
  for (const { id } of formats) {
    const result = await page.$eval('metaballs-view', async (e, options) => {
      const started = performance.now();
      const clip = await e.record(options);
      return { ms: performance.now() - started, bytes: clip.size };
    }, { seconds, fps, width, height, format: id });
    console.log(`${id.padEnd(9)} ${(result.ms / 1000).toFixed(1).padStart(6)} s  ${Math.round(seconds * fps)} frames  ${(result.bytes / 1e6).toFixed(2)} MB`);
  }
} finally {
  await close();
}
