// Clips encoded in the browser (www/lib/figure/clip.js): every format headless Chromium offers at
// 160 × 90 and 30 frames per second is written from 2 s of synthetic frames (a square moving across a
// gradient, each frame's index drawn as six coloured blocks), read back by ffprobe and ffmpeg (Debian's
// ffmpeg package) in Node: 60 frames of 160 × 90 in the codec named, at i / 30 s, lasting 2 s, and each
// frame's blocks spelling its own index, top row first. WebM (VP9 or VP8) and GIF must be offered; MP4
// (H.264) is checked where this Chromium has an encoder for it. A GIF at 60 frames per second holds
// every second frame. An abort at frame 10 rejects with an AbortError at once, bad input is refused
// with what is accepted, and the encoders' bundle is fetched only when a clip is encoded.

import { test, before } from 'node:test';
import assert from 'node:assert/strict';
import { execFileSync } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import path from 'node:path';
import { browser, baseUrl, outputDir, root, useServerAndBrowser } from './helpers.js';

useServerAndBrowser();

const WIDTH = 160;
const HEIGHT = 90;
const FPS = 30;
const COUNT = 60;
// The codec ffprobe names for each format.
const CODECS = { 'webm-vp9': 'vp9', 'webm-vp8': 'vp8', 'mp4-h264': 'h264', gif: 'gif' };

before(() => {
  // The encoders' bundle, built when missing or older than its pins (www/build.sh builds it too).
  execFileSync('bash', ['-c', 'source www/need-deb.sh && need_clip_codecs'], { cwd: root, stdio: 'pipe' });
});

/** A blank page of the served repository with the clip module loaded as `window.clip`. */
async function clipPage() {
  const context = await browser.newContext();
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.route(`${baseUrl}blank.html`, (route) => route.fulfill({
    contentType: 'text/html', body: '<!doctype html><html lang="en"><title>clip</title></html>',
  }));
  await page.goto(`${baseUrl}blank.html`);
  await page.evaluate(async () => {
    window.clip = await import('/www/lib/figure/clip.js');
    // Frame i of a clip of `count`: a gradient, a white square moving left to right, and i's six bits as
    // blocks along the top left (yellow for 1, dark blue for 0).
    window.syntheticFrame = (i, count, width, height) => {
      const pixels = new Uint8ClampedArray(width * height * 4);
      const side = Math.round(height / 3);
      const left = Math.round((i / Math.max(1, count - 1)) * (width - side));
      for (let y = 0; y < height; y++) {
        for (let x = 0; x < width; x++) {
          const at = 4 * (y * width + x);
          const inSquare = x >= left && x < left + side && y >= height - side - 8 && y < height - 8;
          const bit = y >= 4 && y < 16 && x >= 4 && x < 4 + 6 * 14 && (x - 4) % 14 < 12 ? 5 - Math.floor((x - 4) / 14) : -1;
          let colour = [Math.round((255 * x) / width), Math.round((180 * y) / height), 120];
          if (inSquare) colour = [255, 255, 255];
          if (bit >= 0) colour = (i >> bit) & 1 ? [255, 230, 0] : [0, 0, 90];
          pixels.set([...colour, 255], at);
        }
      }
      return pixels;
    };
    window.base64 = async (blob) => {
      const bytes = new Uint8Array(await blob.arrayBuffer());
      let text = '';
      for (let i = 0; i < bytes.length; i += 0x8000) text += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      return btoa(text);
    };
  });
  return { page, errors, close: () => context.close() };
}

/** Whether the page has fetched the encoders' bundle. */
const codecsFetched = (page) => page.evaluate(() => performance.getEntriesByType('resource')
  .some((entry) => entry.name.endsWith('/www/vendor/clip-codecs.js')));

function probe(file) {
  const json = execFileSync('ffprobe', ['-v', 'error', '-count_frames', '-select_streams', 'v:0',
    '-show_entries', 'stream=nb_read_frames,width,height,codec_name:format=duration', '-of', 'json', file], { encoding: 'utf8' });
  const { streams: [stream], format } = JSON.parse(json);
  return { ...stream, duration: Number(format.duration) };
}

/** Each frame's presentation time, in seconds. */
function frameTimes(file) {
  const json = execFileSync('ffprobe', ['-v', 'error', '-select_streams', 'v:0', '-show_entries', 'frame=pts_time',
    '-of', 'json', file], { encoding: 'utf8' });
  return JSON.parse(json).frames.map((f) => Number(f.pts_time));
}

/** The index each decoded frame's blocks spell, frame by frame. */
function spelledIndices(file) {
  const raw = execFileSync('ffmpeg', ['-v', 'error', '-i', file, '-f', 'rawvideo', '-pix_fmt', 'rgb24', '-'],
    { maxBuffer: 64 << 20 });
  const size = WIDTH * HEIGHT * 3;
  const indices = [];
  for (let offset = 0; offset + size <= raw.length; offset += size) {
    let index = 0;
    for (let bit = 5; bit >= 0; bit--) {
      // The middle of the bit's block: yellow is bright, dark blue dark.
      const x = 4 + (5 - bit) * 14 + 6;
      const at = offset + 3 * (10 * WIDTH + x);
      const light = (raw[at] + raw[at + 1] + raw[at + 2]) / 3;
      index = 2 * index + (light > 110 ? 1 : 0);
    }
    indices.push(index);
  }
  return indices;
}

test('every format offered writes 60 frames of 160 × 90 at i / 30 s, in order, in the codec named', async () => {
  const { page, errors, close } = await clipPage();
  try {
    const formats = await page.evaluate(([w, h, fps]) => window.clip.clipFormats(w, h, fps), [WIDTH, HEIGHT, FPS]);
    const ids = formats.map((f) => f.id);
    console.log(`formats offered at ${WIDTH} × ${HEIGHT}, ${FPS} fps: ${formats.map((f) => f.label).join(', ')}`);
    assert.ok(ids.includes('webm-vp9') || ids.includes('webm-vp8'), `no WebM among ${ids}`);
    assert.equal(ids.at(-1), 'gif', 'GIF is offered, last');
    assert.deepEqual(ids, ['webm-vp9', 'webm-vp8', 'mp4-h264', 'gif'].filter((id) => ids.includes(id)), 'in preference order');
    for (const f of formats) assert.deepEqual(Object.keys(f).sort(), ['extension', 'id', 'label', 'type'], f.id);
    assert.equal(await codecsFetched(page), false, 'listing the formats fetched the encoders');

    for (const format of formats) {
      const started = Date.now();
      const { data, type, progress, asked } = await page.evaluate(async ([id, w, h, fps, count]) => {
        const progress = [];
        const asked = [];
        const blob = await window.clip.encodeClip({
          format: id, width: w, height: h, fps, count,
          frame: async (i) => {
            asked.push(i);
            return window.syntheticFrame(i, count, w, h);
          },
          onProgress: (done, total) => progress.push([done, total]),
        });
        return { data: await window.base64(blob), type: blob.type, progress, asked };
      }, [format.id, WIDTH, HEIGHT, FPS, COUNT]);
      const file = path.join(outputDir, `clip-${format.id}.${format.extension}`);
      const bytes = Buffer.from(data, 'base64');
      writeFileSync(file, bytes);
      console.log(`${format.label}: ${bytes.length} bytes in ${Date.now() - started} ms, ${path.relative(root, file)}`);

      assert.equal(type, format.type, format.id);
      assert.deepEqual(asked, Array.from({ length: COUNT }, (_, i) => i), `${format.id}: frames asked in order, once`);
      assert.deepEqual(progress, Array.from({ length: COUNT }, (_, i) => [i + 1, COUNT]), `${format.id}: progress`);
      const stream = probe(file);
      assert.equal(stream.codec_name, CODECS[format.id], format.id);
      assert.equal(Number(stream.nb_read_frames), COUNT, `${format.id}: frames`);
      assert.deepEqual([stream.width, stream.height], [WIDTH, HEIGHT], `${format.id}: size`);
      assert.ok(Math.abs(stream.duration - COUNT / FPS) < 0.05, `${format.id}: lasts ${stream.duration} s`);
      // Each frame at i / 30 s (to the container's millisecond, a GIF's hundredth), and its own.
      const times = frameTimes(file);
      const tolerance = format.id === 'gif' ? 0.006 : 0.0011;
      const late = times.map((t, i) => [i, t]).filter(([i, t]) => Math.abs(t - times[0] - i / FPS) > tolerance);
      assert.deepEqual(late, [], `${format.id}: frames not at i / ${FPS} s`);
      assert.deepEqual(spelledIndices(file), Array.from({ length: COUNT }, (_, i) => i), `${format.id}: frames' indices`);
    }
    assert.equal(await codecsFetched(page), true);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('a GIF at 60 fps holds every second frame, each shown at least 2/100 s, and lasts as long', async () => {
  const { page, errors, close } = await clipPage();
  try {
    const { data, asked, progress } = await page.evaluate(async ([w, h]) => {
      const asked = [];
      const progress = [];
      const blob = await window.clip.encodeClip({
        format: 'gif', width: w, height: h, fps: 60, count: 61,
        frame: (i) => {
          asked.push(i);
          return window.syntheticFrame(i, 61, w, h);
        },
        onProgress: (done) => progress.push(done),
      });
      return { data: await window.base64(blob), asked, progress };
    }, [WIDTH, HEIGHT]);
    const file = path.join(outputDir, 'clip-gif-60fps.gif');
    writeFileSync(file, Buffer.from(data, 'base64'));
    assert.deepEqual(asked, Array.from({ length: 31 }, (_, i) => 2 * i));
    assert.deepEqual(progress, [...Array.from({ length: 30 }, (_, i) => 2 * i + 2), 61]);
    const stream = probe(file);
    assert.equal(Number(stream.nb_read_frames), 31);
    // 61 frames of 1/60 s: 1.0167 s, the last frame held to its 2/100 s.
    assert.ok(Math.abs(stream.duration - 1.02) < 0.006, `lasts ${stream.duration} s`);
    const times = frameTimes(file);
    const gaps = times.slice(1).map((t, i) => Math.round(100 * (t - times[i])));
    assert.ok(gaps.every((gap) => gap === 3 || gap === 4), `delays ${gaps}`);
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('an abort at frame 10 rejects with an AbortError at once, in every format', async () => {
  const { page, errors, close } = await clipPage();
  try {
    const formats = await page.evaluate(([w, h, fps]) => window.clip.clipFormats(w, h, fps), [WIDTH, HEIGHT, FPS]);
    for (const { id } of formats) {
      const result = await page.evaluate(async ([format, w, h, fps, count]) => {
        const controller = new AbortController();
        const asked = [];
        let abortedAt = 0;
        try {
          await window.clip.encodeClip({
            format, width: w, height: h, fps, count, signal: controller.signal,
            frame: (i) => {
              asked.push(i);
              if (i < 10) return window.syntheticFrame(i, count, w, h);
              // Frame 10 is aborted while it renders, and never comes.
              setTimeout(() => {
                abortedAt = performance.now();
                controller.abort();
              }, 20);
              return new Promise(() => {});
            },
          });
          return { settled: 'resolved' };
        } catch (error) {
          return { settled: 'rejected', name: error.name, isDOMException: error instanceof DOMException,
            after: performance.now() - abortedAt, asked };
        }
      }, [id, WIDTH, HEIGHT, FPS, COUNT]);
      console.log(`${id}: rejected ${result.after?.toFixed(1)} ms after the abort`);
      assert.equal(result.settled, 'rejected', id);
      assert.equal(result.name, 'AbortError', id);
      assert.ok(result.isDOMException, id);
      assert.ok(result.after < 500, `${id}: settled ${result.after} ms after the abort`);
      assert.deepEqual(result.asked, Array.from({ length: 11 }, (_, i) => i), id);
    }
    // A signal aborted before the start rejects at once, and asks for no frame.
    const early = await page.evaluate(() => window.clip.encodeClip({
      format: 'gif', width: 16, height: 16, fps: 30, count: 4, signal: AbortSignal.abort(),
      frame: () => { throw new Error('asked for a frame'); },
    }).then(() => 'resolved', (error) => error.name));
    assert.equal(early, 'AbortError');
    assert.deepEqual(errors, []);
  } finally {
    await close();
  }
});

test('bad input is refused with a message that names it', async () => {
  const { page, close } = await clipPage();
  try {
    const messages = await page.evaluate(async () => {
      const frame = (i) => new Uint8Array(16 * 16 * 4).fill(i);
      const base = { format: 'gif', width: 16, height: 16, fps: 30, count: 2, frame };
      const cases = {
        format: { ...base, format: 'avi' },
        width: { ...base, width: 0 },
        oddVideo: { ...base, format: 'webm-vp8', width: 15 },
        fps: { ...base, fps: 25 },
        count: { ...base, count: 0 },
        frame: { ...base, frame: undefined },
        pixels: { ...base, frame: () => new Uint8Array(10) },
      };
      const out = {};
      for (const [name, options] of Object.entries(cases)) {
        out[name] = await window.clip.encodeClip(options).then(() => 'resolved', (error) => error.message);
      }
      out.formatsFps = await window.clip.clipFormats(16, 16, 50).then(() => 'resolved', (error) => error.message);
      out.oddFormats = (await window.clip.clipFormats(15, 16, 30)).map((f) => f.id).join();
      return out;
    });
    assert.match(messages.format, /one of webm-vp9, webm-vp8, mp4-h264, gif, not "avi"/);
    assert.match(messages.width, /width is a whole number of pixels from 1 to 8192, not 0/);
    assert.match(messages.oddVideo, /even width and height, not 15 × 16/);
    assert.match(messages.fps, /24, 30, 60 frames per second, not 25/);
    assert.match(messages.count, /at least 1, not 0/);
    assert.match(messages.frame, /needs frame\(i\)/);
    assert.match(messages.pixels, /frame\(0\) gave 10 bytes, not 1024/);
    assert.match(messages.formatsFps, /not 50/);
    assert.equal(messages.oddFormats, 'gif', 'an odd size is offered GIF only');
  } finally {
    await close();
  }
});
