// A clip of a figure's frames, encoded in the browser: WebM (VP9 or VP8) or MP4 (H.264) through
// WebCodecs' VideoEncoder, muxed by mediabunny, or an animated GIF written by gifenc. The caller renders
// the frames; this module asks for them one at a time, in order, and hands back the whole file.
//
// Both libraries sit in www/vendor/clip-codecs.js (bundled by www/build.sh from www/tools/), which is
// imported only when a clip is encoded: a reader who never records downloads nothing more.

// The formats, in the order they are offered. `codec` is mediabunny's name for the video codec.
const FORMATS = [
  { id: 'webm-vp9', label: 'WebM (VP9)', type: 'video/webm', extension: 'webm', codec: 'vp9', container: 'webm' },
  { id: 'webm-vp8', label: 'WebM (VP8)', type: 'video/webm', extension: 'webm', codec: 'vp8', container: 'webm' },
  { id: 'mp4-h264', label: 'MP4 (H.264)', type: 'video/mp4', extension: 'mp4', codec: 'avc', container: 'mp4' },
  { id: 'gif', label: 'Animated GIF', type: 'image/gif', extension: 'gif' },
];

/** The frame rates a clip may have. */
export const CLIP_RATES = Object.freeze([24, 30, 60]);

// The largest side of a clip, in pixels.
const MAX_SIDE = 8192;

// Video bits per pixel of each frame: a figure's flat colours and smooth shading stay clean at this rate
// (about 1.4 Mbit/s at 640 × 360 and 30 frames per second).
const BITS_PER_PIXEL = 0.2;
// A key frame every this many seconds.
const KEY_FRAME_SECONDS = 2;

// The H.264 levels (level_idc: most macroblocks in a frame, most macroblocks a second), and VP9's (level:
// most luma samples in a frame, most a second). The codec string names the lowest level that holds the
// clip, as a player expects.
const H264_LEVELS = [
  [0x1e, 1620, 40500], [0x1f, 3600, 108000], [0x20, 5120, 216000], [0x28, 8192, 245760],
  [0x2a, 8704, 522240], [0x32, 22080, 589824], [0x33, 36864, 983040], [0x34, 36864, 2073600],
];
const VP9_LEVELS = [
  [10, 36864, 829440], [11, 73728, 2764800], [20, 122880, 4608000], [21, 245760, 9216000],
  [30, 552960, 20736000], [31, 983040, 36864000], [40, 2228224, 83558400], [41, 2228224, 160432128],
  [50, 8912896, 311951360], [51, 8912896, 588251136], [52, 8912896, 1176502272], [60, 35651584, 1176502272],
];

// A GIF's delays are whole hundredths of a second, and browsers show a delay under 2/100 s as 10/100 s:
// a GIF frame stands for at least this long.
const GIF_SHORTEST_CS = 2;
// The palette is chosen from this many pixels standing for all the clip's pixels (below).
const GIF_PALETTE_SAMPLE = 1 << 18;

let codecs = null;

/** The bundled libraries, loaded the first time a clip is encoded (again after a failed load). */
function loadCodecs() {
  codecs ??= import('../../vendor/clip-codecs.js').catch((error) => {
    codecs = null;
    throw new Error(`the clip encoders (www/vendor/clip-codecs.js) could not be loaded: ${error.message}`);
  });
  return codecs;
}

function formatOf(id) {
  const format = FORMATS.find((f) => f.id === id);
  if (!format) {
    throw new Error(`a clip's format is one of ${FORMATS.map((f) => f.id).join(', ')}, not ${JSON.stringify(id)}`);
  }
  return format;
}

function checkSize(width, height, fps) {
  for (const [name, value] of [['width', width], ['height', height]]) {
    if (!Number.isInteger(value) || value < 1 || value > MAX_SIDE) {
      throw new Error(`a clip's ${name} is a whole number of pixels from 1 to ${MAX_SIDE}, not ${value}`);
    }
  }
  if (!CLIP_RATES.includes(fps)) {
    throw new Error(`a clip's rate is ${CLIP_RATES.join(', ')} frames per second, not ${fps}`);
  }
}

/** The lowest of `levels` whose picture and rate limits hold `perFrame` units a frame at `fps`. */
function levelFor(levels, perFrame, fps) {
  return levels.find(([, frame, second]) => perFrame <= frame && perFrame * fps <= second)?.[0] ?? null;
}

/**
 * The WebCodecs encoder configurations that would write `format` at this size and rate, best first
 * (H.264: High profile, then Constrained Baseline, which more software encoders write); none for an odd
 * side (4:2:0 video has whole chroma samples only for even sides) or a size beyond the codec's levels.
 */
function encoderConfigs(format, width, height, fps) {
  if (width % 2 || height % 2) return [];
  const base = {
    width, height, framerate: fps, bitrate: Math.round(BITS_PER_PIXEL * width * height * fps),
    bitrateMode: 'variable', latencyMode: 'quality',
  };
  if (format.codec === 'vp8') return [{ ...base, codec: 'vp8' }];
  if (format.codec === 'vp9') {
    const level = levelFor(VP9_LEVELS, width * height, fps);
    return level === null ? [] : [{ ...base, codec: `vp09.00.${level}.08` }];
  }
  const level = levelFor(H264_LEVELS, Math.ceil(width / 16) * Math.ceil(height / 16), fps);
  if (level === null) return [];
  const hex = level.toString(16).padStart(2, '0');
  return [`avc1.6400${hex}`, `avc1.42e0${hex}`].map((codec) => ({ ...base, codec, avc: { format: 'avc' } }));
}

/** The first of `format`'s encoder configurations this browser's VideoEncoder takes, or null. */
async function supportedConfig(format, width, height, fps) {
  if (typeof VideoEncoder === 'undefined') return null;
  for (const config of encoderConfigs(format, width, height, fps)) {
    try {
      if ((await VideoEncoder.isConfigSupported(config)).supported) return config;
    } catch {
      // A configuration the browser cannot even read is one it does not support.
    }
  }
  return null;
}

/**
 * The formats this browser can write a clip of `width` × `height` pixels at `fps` frames per second
 * in, in the order to offer them: `{ id, label, type, extension }` (`type` is the file's MIME type,
 * `extension` its file name's, without the dot). The ids are `webm-vp9`, `webm-vp8` and `mp4-h264`,
 * each where WebCodecs' VideoEncoder says it can encode that codec at that size and rate, and always
 * `gif` last. Video needs an even width and height: at an odd size only `gif` is offered, so a caller
 * that wants video rounds its size down to even numbers first. Loads nothing.
 * @param {number} width whole pixels, 1 to 8192
 * @param {number} height whole pixels, 1 to 8192
 * @param {number} fps 24, 30 or 60
 * @returns {Promise<{ id: string, label: string, type: string, extension: string }[]>}
 */
export async function clipFormats(width, height, fps) {
  checkSize(width, height, fps);
  const offered = [];
  for (const format of FORMATS) {
    if (format.codec && !(await supportedConfig(format, width, height, fps))) continue;
    const { id, label, type, extension } = format;
    offered.push({ id, label, type, extension });
  }
  // VP8 only where VP9 is missing: browsers tag a VP8 track made from RGBA frames as full range, which
  // its data is not, and players that follow the tag (ffmpeg's) show the clip darker.
  const vp9 = offered.some((f) => f.id === 'webm-vp9');
  return offered.filter((f) => !(vp9 && f.id === 'webm-vp8'));
}

function abortError() {
  return new DOMException('the clip was not finished: its encoding was aborted', 'AbortError');
}

/** `promise`, or a rejection with an AbortError as soon as `signal` aborts, whichever comes first. */
function abortable(promise, signal) {
  if (!signal) return promise;
  return new Promise((resolve, reject) => {
    const onAbort = () => reject(abortError());
    if (signal.aborted) onAbort();
    else signal.addEventListener('abort', onAbort, { once: true });
    promise.then(resolve, reject).finally(() => signal.removeEventListener('abort', onAbort));
  });
}

/** The pixels `frame(i)` resolved to, checked. */
function checkPixels(pixels, i, width, height) {
  if (!(pixels instanceof Uint8Array || pixels instanceof Uint8ClampedArray)) {
    throw new Error(`frame(${i}) resolved to ${Object.prototype.toString.call(pixels)}, not a Uint8Array or Uint8ClampedArray of RGBA pixels`);
  }
  if (pixels.length !== width * height * 4) {
    throw new Error(`frame(${i}) gave ${pixels.length} bytes, not ${width * height * 4} (${width} × ${height} RGBA pixels)`);
  }
  return pixels;
}

// Lets the page's thread breathe between two long steps.
const breathe = () => globalThis.scheduler?.yield?.() ?? new Promise((resolve) => setTimeout(resolve, 0));

/**
 * Encodes a clip of `count` frames and resolves to its whole file as a Blob of the format's type.
 *
 * `frame(i)` resolves to frame i's pixels: a Uint8Array or Uint8ClampedArray of `width` × `height` RGBA
 * bytes, the top row first (alpha is not kept: each pixel is taken as opaque). Frames are asked for one
 * at a time, in order, each once the one before is encoded, so the caller may render into the same
 * buffer each time. Frame i is shown from i / `fps` seconds for 1 / `fps` (timestamps come from the
 * index, never from a clock). A GIF at 60 frames per second holds every second frame only (a GIF's
 * delays are hundredths of a second, and browsers slow shorter delays than 2/100 s down to 1/10 s):
 * `frame` is asked for the even frames only, each shown for 2 / `fps`, and the clip lasts as long.
 *
 * `onProgress(done, count)` is called after each frame, `done` being how many of the `count` frames
 * the clip has covered so far. A GIF is written once every frame is in (its one palette is chosen from
 * all of them), after the last call.
 *
 * When `signal` (an AbortSignal) aborts, encoding stops at once (a `frame(i)` still pending is left to
 * settle on its own and not used), the encoders are closed, and the promise rejects with a DOMException
 * named 'AbortError'.
 *
 * Video is WebM (VP9, VP8) or MP4 (H.264) at about 0.2 bits per pixel of each frame, a key frame every
 * 2 seconds, and needs an even width and height and an encoder `clipFormats` offers; a GIF has one
 * palette of 256 colours for the whole clip and loops forever.
 *
 * @param {object} options
 * @param {'webm-vp9' | 'webm-vp8' | 'mp4-h264' | 'gif'} options.format an id from `clipFormats`
 * @param {number} options.width whole pixels, 1 to 8192 (even for video)
 * @param {number} options.height whole pixels, 1 to 8192 (even for video)
 * @param {number} options.fps 24, 30 or 60
 * @param {number} options.count the number of frames, at least 1
 * @param {(i: number) => Promise<Uint8Array | Uint8ClampedArray> | Uint8Array | Uint8ClampedArray} options.frame
 * @param {(done: number, count: number) => void} [options.onProgress]
 * @param {AbortSignal} [options.signal]
 * @returns {Promise<Blob>}
 */
export async function encodeClip({ format: id, width, height, fps, count, frame, onProgress, signal } = {}) {
  const format = formatOf(id);
  checkSize(width, height, fps);
  if (!Number.isInteger(count) || count < 1) {
    throw new Error(`a clip has a whole number of frames, at least 1, not ${count}`);
  }
  if (typeof frame !== 'function') throw new Error('encodeClip needs frame(i), resolving to frame i\'s RGBA pixels');
  if (onProgress !== undefined && typeof onProgress !== 'function') throw new Error('onProgress, when given, is a function');
  if (signal?.aborted) throw abortError();
  const job = { format, width, height, fps, count, frame, onProgress, signal };
  if (!format.codec) return encodeGif(job, await abortable(loadCodecs(), signal));
  if (width % 2 || height % 2) {
    throw new Error(`a ${format.label} clip needs an even width and height, not ${width} × ${height}`);
  }
  const config = await abortable(supportedConfig(format, width, height, fps), signal);
  if (!config) throw new Error(`this browser cannot encode ${format.label} at ${width} × ${height}, ${fps} frames per second`);
  return encodeVideo(job, config, await abortable(loadCodecs(), signal));
}

/** The video formats: each frame a VideoSample, encoded by mediabunny's VideoEncoder and muxed. */
async function encodeVideo({ format, width, height, fps, count, frame, onProgress, signal }, config, lib) {
  const output = new lib.Output({
    // In memory, the MP4's index goes before its frames, so that a player starts it before it has it all.
    format: format.container === 'mp4' ? new lib.Mp4OutputFormat({ fastStart: 'in-memory' }) : new lib.WebMOutputFormat(),
    target: new lib.BufferTarget(),
  });
  const source = new lib.VideoSampleSource({
    codec: format.codec,
    fullCodecString: config.codec,
    quality: new lib.Quality({ bitrate: config.bitrate, bitrateMode: 'variable' }),
    keyFrameInterval: KEY_FRAME_SECONDS,
    latencyMode: 'quality',
  });
  output.addVideoTrack(source, { frameRate: fps });
  try {
    await abortable(output.start(), signal);
    for (let i = 0; i < count; i++) {
      const pixels = checkPixels(await abortable(Promise.resolve(frame(i)), signal), i, width, height);
      // The sample copies the pixels, so the caller may reuse its buffer for the next frame.
      const sample = new lib.VideoSample(pixels, {
        format: 'RGBA', codedWidth: width, codedHeight: height, timestamp: i / fps, duration: 1 / fps,
      });
      try {
        await abortable(source.add(sample), signal);
      } finally {
        sample.close();
      }
      onProgress?.(i + 1, count);
    }
    await abortable(output.finalize(), signal);
  } catch (error) {
    // Closes the encoder; what it had made is dropped.
    await output.cancel().catch(() => {});
    throw error;
  }
  return new Blob([output.target.buffer], { type: format.type });
}

/**
 * The GIF. Its one palette is chosen for the whole clip, and the frames arrive one at a time, once, and
 * are too many to keep as RGBA (4 s at 60 frames per second of 640 × 360 is 220 MB). So each frame is
 * kept as it comes in the 32,768 colours of 5 bits a channel (2 bytes a pixel: 55 MB for 4 s of
 * 640 × 360 at 30 frames per second, or at 60, of which a GIF keeps every second frame), while every
 * pixel of every frame is counted into those colours' histogram, with the sum of its exact colours.
 * Once the last frame is in, gifenc's quantiser chooses 256 colours from a sample that stands for the
 * histogram (each colour its mean exact colour, about in proportion to its count, and never fewer than
 * one pixel, so a small highlight seen in a few frames keeps a colour near its own); each of the
 * 32,768 colours is given its nearest palette colour, and the frames are written through that table.
 * gifenc maps its own pixels through the same 5-bit colours, so nothing is lost against indexing the
 * RGBA frames directly, and a figure of up to 256 flat colours keeps them exactly.
 */
async function encodeGif({ width, height, fps, count, frame, onProgress, signal }, lib) {
  const step = Math.ceil((GIF_SHORTEST_CS * fps) / 100);
  const pixelsPerFrame = width * height;
  const counts = new Float64Array(1 << 15);
  const sums = new Float64Array(3 << 15);
  const kept = [];
  for (let i = 0; i < count; i += step) {
    const rgba = checkPixels(await abortable(Promise.resolve(frame(i)), signal), i, width, height);
    const keys = new Uint16Array(pixelsPerFrame);
    for (let p = 0, q = 0; p < pixelsPerFrame; p++, q += 4) {
      const r = rgba[q];
      const g = rgba[q + 1];
      const b = rgba[q + 2];
      const key = ((r >> 3) << 10) | ((g >> 3) << 5) | (b >> 3);
      keys[p] = key;
      counts[key] += 1;
      sums[3 * key] += r;
      sums[3 * key + 1] += g;
      sums[3 * key + 2] += b;
    }
    kept.push(keys);
    onProgress?.(Math.min(i + step, count), count);
  }
  if (signal?.aborted) throw abortError();

  // Each colour's mean exact colour, and the sample standing for the histogram.
  const total = kept.length * pixelsPerFrame;
  const means = new Uint8Array(3 << 15);
  let samples = 0;
  for (let key = 0; key < counts.length; key++) {
    if (!counts[key]) continue;
    for (let c = 0; c < 3; c++) means[3 * key + c] = Math.round(sums[3 * key + c] / counts[key]);
    samples += Math.max(1, Math.round((counts[key] * GIF_PALETTE_SAMPLE) / total));
  }
  // gifenc reads the sample through its own Uint32Array view of the whole buffer: a buffer of its own.
  const sample = new Uint8Array(samples * 4);
  for (let key = 0, at = 0; key < counts.length; key++) {
    if (!counts[key]) continue;
    const n = Math.max(1, Math.round((counts[key] * GIF_PALETTE_SAMPLE) / total));
    for (let k = 0; k < n; k++, at += 4) {
      sample[at] = means[3 * key];
      sample[at + 1] = means[3 * key + 1];
      sample[at + 2] = means[3 * key + 2];
      sample[at + 3] = 255;
    }
  }
  const palette = lib.quantize(sample, 256);
  const nearest = new Uint8Array(1 << 15);
  for (let key = 0; key < counts.length; key++) {
    if (!counts[key]) continue;
    const [r, g, b] = [means[3 * key], means[3 * key + 1], means[3 * key + 2]];
    let best = 0;
    let bestDistance = Infinity;
    palette.forEach(([pr, pg, pb], index) => {
      const distance = (pr - r) ** 2 + (pg - g) ** 2 + (pb - b) ** 2;
      if (distance < bestDistance) [best, bestDistance] = [index, distance];
    });
    nearest[key] = best;
  }

  // Frame j (the caller's frame j × step) shows from its time to the next one's, in hundredths of a
  // second rounded on the clip's own clock, so that the rounding does not add up: the whole lasts
  // count / fps, to the hundredth (a last frame that stands for a single frame at 60 frames per second
  // may be held a hundredth longer, to its 2/100 s).
  const at = (j) => Math.round((100 * Math.min(j * step, count)) / fps);
  const delay = (j) => Math.max(GIF_SHORTEST_CS, at(j + 1) - at(j));
  const gif = lib.GIFEncoder();
  const indices = new Uint8Array(pixelsPerFrame);
  for (let j = 0; j < kept.length; j++) {
    if (signal?.aborted) throw abortError();
    const keys = kept[j];
    for (let p = 0; p < pixelsPerFrame; p++) indices[p] = nearest[keys[p]];
    kept[j] = null;
    // gifenc takes the delay in milliseconds and writes it in hundredths; repeat 0 loops forever.
    gif.writeFrame(indices, width, height, { palette: j === 0 ? palette : undefined, delay: 10 * delay(j), repeat: 0 });
    if (j % 8 === 7) await breathe();
  }
  if (signal?.aborted) throw abortError();
  gif.finish();
  return new Blob([gif.bytesView()], { type: 'image/gif' });
}
