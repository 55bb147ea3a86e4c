// Recording a 3D figure (`record()` and the share box's Record): 2 s at 30 fps at 320 × 180 in every
// format this Chromium writes is a file ffprobe (Debian's ffmpeg) reads with 60 frames of that size; its
// first frame, decoded by ffmpeg, is the figure's picture at that step (within the codec's loss), its
// frames move, and the figure's spheres are back where they were afterwards. From the share box, Cancel
// leaves no file and the figure animating. The 2D figure records its circles moving the same way.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { readFileSync, rmSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { differingFraction, open, outputDir, useServerAndBrowser, waitForTriangles } from './helpers.js';

useServerAndBrowser();

const VIEWPORT = { width: 640, height: 360 };
const [WIDTH, HEIGHT] = [320, 180];

// Pauses the figure and waits until its spheres hold still: a figure meshing on a worker takes the
// time it owed the animation in the next step it meshes, even just after a pause.
async function pauseAndSettle(page) {
  await page.$eval('metaballs-view', async (e) => {
    e.pause();
    let before = null;
    for (let tries = 0; tries < 10; tries += 1) {
      await e.nextFrame();
      const now = JSON.stringify(e.sphereList);
      if (now === before) return;
      before = now;
    }
  });
}

const probe = (file) => JSON.parse(execFileSync('ffprobe', ['-v', 'error', '-count_frames', '-select_streams', 'v:0',
  '-show_entries', 'stream=nb_read_frames,width,height,codec_name', '-of', 'json', file], { encoding: 'utf8' })).streams[0];

// Frame `index` of a clip as a PNG, decoded by ffmpeg.
function frameOf(file, index) {
  const out = `${file}.frame${index}.png`;
  execFileSync('ffmpeg', ['-v', 'error', '-y', '-i', file, '-vf', `select=eq(n\\,${index})`, '-frames:v', '1', out]);
  const png = readFileSync(out);
  rmSync(out);
  return png;
}

test('a recording of 2 s at 30 fps is 60 frames of the asked size in every format, its first frame the figure\'s picture, the spheres back where they were', async () => {
  const { page, errors, close } = await open('index.html?res=32&spheres=4&controls=none&hud=off', { viewport: VIEWPORT });
  try {
    await waitForTriangles(page).catch(() => {});
    await page.$eval('metaballs-view', (e) => e.ready());
    await pauseAndSettle(page);
    const formats = await page.evaluate(async () => (await import('/www/lib/figure/clip.js')).clipFormats(320, 180, 30));
    const ids = formats.map((f) => f.id);
    console.log(`formats offered: ${ids.join(', ')}`);
    assert.ok(ids.includes('gif') && (ids.includes('webm-vp9') || ids.includes('webm-vp8')), `offered: ${ids}`);
    for (const format of ids) {
      const result = await page.$eval('metaballs-view', async (e, [f, w, h]) => {
        const before = JSON.stringify(e.sphereList);
        const picture = await e.makePoster(w / e.clientWidth);
        let calls = 0;
        const started = performance.now();
        const clip = await e.record({ seconds: 2, fps: 30, width: w, height: h, format: f, onProgress: () => { calls += 1; } });
        const ms = performance.now() - started;
        return {
          clip: [...new Uint8Array(await clip.arrayBuffer())], picture: [...new Uint8Array(await picture.arrayBuffer())],
          type: clip.type, calls, ms, restored: JSON.stringify(e.sphereList) === before,
        };
      }, [format, WIDTH, HEIGHT]);
      const file = path.join(outputDir, `record-${format}.${format === 'gif' ? 'gif' : format.split('-')[0]}`);
      writeFileSync(file, Buffer.from(result.clip));
      console.log(`${format}: ${result.clip.length} bytes in ${result.ms.toFixed(0)} ms (${file})`);
      const stream = probe(file);
      assert.deepEqual([Number(stream.nb_read_frames), stream.width, stream.height], [60, WIDTH, HEIGHT], `${format}: ${JSON.stringify(stream)}`);
      assert.equal(result.calls, 60);
      assert.ok(result.restored, `${format}: the spheres were not put back`);
      // The first frame is the picture of the figure now; later frames have moved on.
      const picture = Buffer.from(result.picture);
      const first = frameOf(file, 0);
      const last = frameOf(file, 59);
      const [firstOff, lastOff] = [await differingFraction(page, picture, first), await differingFraction(page, picture, last)];
      console.log(`${format}: first frame differs from the picture in ${(firstOff * 100).toFixed(2)} % of pixels, the last in ${(lastOff * 100).toFixed(2)} %`);
      assert.ok(firstOff < 0.03, `${format}: the first frame is not the figure's picture (${(firstOff * 100).toFixed(2)} % differ)`);
      assert.ok(lastOff > firstOff + 0.01, `${format}: the clip does not move`);
    }
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a recording of the 2D figure is 60 frames of the asked size, its circles moving, and back where they were after', async () => {
  const { page, errors, close } = await open('squares.html?resolution=12', { viewport: { width: 700, height: 800 } });
  try {
    await page.waitForFunction(() => document.querySelector('metaballs-2d')?.record);
    const result = await page.$eval('metaballs-2d', async (e) => {
      e.pause();
      const before = JSON.stringify(e.circleList);
      const clip = await e.record({ seconds: 2, fps: 30, width: 320, height: 180, format: 'gif' });
      return { clip: [...new Uint8Array(await clip.arrayBuffer())], restored: JSON.stringify(e.circleList) === before };
    });
    const file = path.join(outputDir, 'record-2d.gif');
    writeFileSync(file, Buffer.from(result.clip));
    const stream = probe(file);
    assert.deepEqual([Number(stream.nb_read_frames), stream.width, stream.height], [60, WIDTH, HEIGHT], JSON.stringify(stream));
    assert.ok(result.restored, 'the circles were not put back');
    const moved = await differingFraction(page, frameOf(file, 0), frameOf(file, 59));
    assert.ok(moved > 0.005, `the circles did not move (${(moved * 100).toFixed(2)} % of pixels differ)`);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a figure taken off the page while it records stops the clip, and put back it goes on from where it was; a second recording at once is refused', async () => {
  const { page, errors, close } = await open('index.html?res=24&spheres=3&controls=none&hud=off', { viewport: VIEWPORT });
  try {
    await waitForTriangles(page).catch(() => {});
    await pauseAndSettle(page);
    const result = await page.$eval('metaballs-view', async (e) => {
      const before = JSON.stringify(e.sphereList);
      let moved = null;
      const clip = e.record({ seconds: 10, fps: 30, width: 160, height: 90, format: 'webm-vp9',
        onProgress: (done) => { if (done === 5 && !moved) moved = e.remove(); } });
      const second = await e.record({ seconds: 1, format: 'gif' }).then(() => 'made', (error) => error.message);
      const first = await clip.then(() => 'made', (error) => `${error.name}: ${error.message}`);
      document.querySelector('main').append(e);
      await e.nextFrame();
      return { first, second, back: JSON.stringify(e.sphereList) === before };
    });
    console.log(`taken off the page: ${result.first}; a second at once: ${result.second}`);
    assert.match(result.first, /AbortError/);
    assert.match(result.second, /recording already/);
    assert.ok(result.back, 'the spheres are not where they were');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('Record in the share box shows its progress; Cancel leaves no file, the spheres where they were and the figure animating', async () => {
  const { page, errors, close } = await open('index.html?res=24&spheres=3', { viewport: { width: 960, height: 640 } });
  try {
    await waitForTriangles(page);
    await pauseAndSettle(page);
    const before = await page.$eval('metaballs-view', (e) => JSON.stringify(e.sphereList));
    const downloads = [];
    page.on('download', (d) => downloads.push(d.suggestedFilename()));
    await page.click('#open-share');
    const dialog = page.locator('metaballs-view dialog.share');
    await dialog.waitFor();
    await dialog.locator('input.seconds').fill('20');
    await dialog.locator('select.format').selectOption('gif');
    await dialog.getByRole('button', { name: 'Record' }).click();
    await page.waitForFunction(() => document.querySelector('metaballs-view').shadowRoot.querySelector('dialog.share progress').value > 0.02);
    await dialog.getByRole('button', { name: 'Cancel' }).click();
    const status = dialog.locator('.record-status');
    await page.waitForFunction(() => /Cancelled/.test(document.querySelector('metaballs-view').shadowRoot.querySelector('.record-status').textContent));
    assert.match(await status.textContent(), /nothing was saved/);
    await page.waitForFunction(() => document.querySelector('metaballs-view').shadowRoot.querySelector('dialog.share .record').disabled === false);
    assert.equal(await page.$eval('metaballs-view', (e) => JSON.stringify(e.sphereList)), before, 'the spheres are not back where they were');
    await dialog.getByRole('button', { name: 'Close' }).click();
    await page.$eval('metaballs-view', (e) => e.play());
    const drawn = await page.$eval('metaballs-view', (e) => e.framesDrawn);
    await page.waitForFunction((n) => document.querySelector('metaballs-view').framesDrawn > n + 5, drawn);
    assert.equal(await page.$eval('metaballs-view', (e) => e.paused), false);
    assert.deepEqual(downloads, []);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});
