// The figure's statistics: frames per second, frame time, triangles, adapter and mesher (GPU or CPU
// meshing), with level of detail the cells' size on screen (larger while frames are slow), the
// effective resolution and each level's blocks and triangles, with color-by=error or quality the
// mesh's distance to the exact surface and its shape histogram, and a warning when the triangle
// budget stays full. Figures update twice a second from the GPU's asynchronous reports.

import { hub } from '../engine/hub.js';
import { FigureDetail } from '../figure/detail.js';
import { levelColor } from './legends.js';
import { FigureSheets } from './sheets.js';

// A count with thousands separators (12,345). In English not `Intl.NumberFormat`: setting one up takes
// tens to hundreds of milliseconds on the page's thread the first time, just when the first statistics
// show; in another language the figure's words write it.
const formatNumber = (n) => String(Math.round(n)).replace(/\B(?=(\d{3})+$)/g, ',');
const english = (words) => words.chain[0].split('-')[0] === 'en';
/** `n` rounded, with thousands separators, as the reader writes it. */
const count = (words, n) => (english(words) ? formatNumber(n) : words.number(Math.round(n), 0));
/** A whole number without separators (a size in pixels, a resolution), as the reader writes it. */
const whole = (words, n) => (english(words) ? String(n) : words.number(n, 0));
/** `x` with exactly `digits` decimals, as the reader writes it. */
const fixed = (words, x, digits) => (english(words) ? x.toFixed(digits) : words.fixed(x, digits));
/** `x` to two significant digits (0.034, 1.2e-7), as the reader writes it. */
const precise = (words, x) => (english(words) ? x.toPrecision(2) : words.number(Number(x.toPrecision(2)), 12));
/** `x` with at most two decimals. */
const upTo2 = (words, x) => (english(words) ? String(Number(x.toFixed(2))) : words.number(x, 2));

export class Hud {
  static attributes = ['hud'];
  #ctx;
  // What each readout shows, by what it writes: each writes again in a new language.
  #shown = new Map();

  /** Writes into the readouts of the figure's shadow root. */
  constructor(ctx) {
    this.#ctx = ctx;
    this.root = ctx.root;
    this.frames = 0;
    this.since = 0;
    this.ticksAtSince = 0;
    this.overflows = 0;
    this.stats = { triangles: 0, fps: 0, frameTime: 0, adapter: '', mesher: '', overflowed: false, lod: null, error: null, quality: null, topology: null, renderScale: 1 };
    this.adapterLabel = '';
  }

  changed(name, value) { this.root.getElementById('hud').hidden = value !== 'on'; }

  loaded() { this.root.getElementById('hud').hidden = this.#ctx.state.hud !== 'on'; }

  /** Very small figures start with their statistics folded, like the panel (but as a sheet, open). */
  firstStart() {
    if (this.#ctx.get(FigureSheets)?.compact) return;
    const width = this.#ctx.element.clientWidth;
    this.root.querySelector('#hud details').open = !(width > 0 && width < 300);
  }

  started() { this.setAdapter(hub.adapter?.label ?? 'WebGPU'); }

  scaled(scale, width, height) { this.setScale(scale, width, height); }

  frameDrawn() { this.countFrame(); }

  /** Every animation frame: the readouts, and the frame times measured for the features that use them. */
  afterTick(now, view, { animating }) {
    const since = this.since;
    const ticks = this.#ctx.frames.animationFrames - this.ticksAtSince;
    const frameMs = this.update(now, view);
    // A new window of counts began.
    if (this.since !== since) this.ticksAtSince = this.#ctx.frames.animationFrames;
    if (!frameMs) return;
    // The time between the animation frames the figure was given, drawn or not: a frame that waited
    // for its mesh from the worker cost the page nothing, and fewer pixels would not bring it sooner.
    const tickMs = ticks > 0 ? (now - since) / ticks : frameMs;
    this.#ctx.each('timed', { since, frameMs, tickMs: Math.min(tickMs, frameMs), animating });
  }

  /** True once the statistics read back are of frame `frame` or later. */
  statsOf(view, frame) { return this.readStats(view) >= frame; }

  shape(shape) { this.showTopology(shape); }

  language(words) {
    for (const write of this.#shown.values()) write(words);
  }

  // Writes readout `name` with `write(words)` now, and again when the language changes.
  #show(name, write) {
    this.#shown.set(name, write);
    write(this.#ctx.words);
  }

  /** The adapter's name (`WebGPU · google swiftshader`, `WebGL2`); the mesher in use follows it. */
  setAdapter(label) {
    this.adapterLabel = label;
    this.#showAdapter();
  }

  #showAdapter() {
    const mesher = this.stats.mesher ? ` · ${this.stats.mesher.toUpperCase()} meshing` : '';
    this.stats.adapter = `${this.adapterLabel}${mesher}`;
    const [adapter, shown] = [this.adapterLabel, this.stats.mesher.toUpperCase()];
    this.#show('adapter', (words) => {
      this.root.getElementById('adapter').textContent = shown
        ? words.t('hud.adapter-meshing', { adapter, mesher: shown }) : adapter;
    });
  }

  /** The render scale (a fraction of the pixel ratio) and the canvas's size in pixels. */
  setScale(scale, width, height) {
    this.stats.renderScale = scale;
    this.#show('scale', (words) => {
      this.root.getElementById('hud-scale').textContent = words.t('hud.scale-value', {
        scale: fixed(words, scale, 2), width: whole(words, width), height: whole(words, height) });
    });
  }

  /** Counts a frame drawn. */
  countFrame() {
    this.frames += 1;
  }

  /**
   * Called every animation frame; refreshes the figures every half second from `view`'s stats (the
   * first ones as soon as there are any).
   * Returns the mean frame time when it refreshed with frames drawn, else null.
   */
  update(now, view) {
    if (!this.since) this.since = now;
    const elapsed = now - this.since;
    // The first counts show as soon as the GPU reports them; then every half second.
    if (this.frameRead === undefined) this.readStats(view);
    if (elapsed < 500) return null;
    const $ = (id) => this.root.getElementById(id);
    this.stats.fps = (this.frames * 1000) / elapsed;
    this.stats.frameTime = this.frames ? elapsed / this.frames : 0;
    const [fps, frameTime] = this.frames ? [this.stats.fps, this.stats.frameTime] : [null, null];
    this.#show('fps', (words) => {
      $('fps').textContent = fps === null ? '–' : fixed(words, fps, 1);
      $('frame-time').textContent = frameTime === null ? words.t('hud.idle')
        : words.t('hud.frame-ms', { ms: fixed(words, frameTime, 1) });
    });
    this.frames = 0;
    this.since = now;
    this.readStats(view);
    return frameTime;
  }

  /**
   * Takes in the view's newest figures (mesher, triangles, overflow); returns the frame they are for,
   * or 0 while the GPU has reported none.
   */
  readStats(view) {
    const $ = (id) => this.root.getElementById(id);
    const mesher = view.mesh_source();
    if (mesher !== this.stats.mesher) {
      this.stats.mesher = mesher;
      this.#showAdapter();
    }
    this.#showLevels(view.lod_levels(), view.lod_cell_pixels());
    this.#showMeasures(view.measures());
    const stats = view.stats();
    if (!stats) return 0;
    this.stats.triangles = stats.triangles;
    const { triangles, max_triangles: budget } = stats;
    this.#show('triangles', (words) => {
      $('triangles').textContent = count(words, triangles);
      $('triangles').title = words.t('hud.budget', { count: budget, triangles: count(words, budget) });
    });
    // The buffers grow a frame after an overflow; warn only when it lasts (they hit the device's limit).
    if (stats.frame !== this.frameRead) this.overflows = stats.overflowed ? this.overflows + 1 : 0;
    this.frameRead = stats.frame;
    this.stats.overflowed = this.overflows >= 2;
    $('overflow').hidden = !this.stats.overflowed;
    const { frame } = stats;
    stats.free();
    return frame;
  }

  /** The surface's shape from the topology watch: blobs, genus, closed and manifold. */
  showTopology(shape) {
    const $ = (id) => this.root.getElementById(id);
    this.stats.topology = shape;
    $('hud-topology').hidden = false;
    const form = shape.manifold ? 'manifold' : shape.closed ? 'closed' : 'open';
    this.#show('topology', (words) => {
      $('hud-topology-text').textContent = words.t(`hud.topology-${form}`, { count: shape.components, genus: shape.genus });
    });
  }

  /**
   * The mesh's error and shape (with color-by=error or quality): `[frame, rms, max, vertices, bins…]`
   * from the view, or empty.
   */
  #showMeasures(m) {
    const $ = (id) => this.root.getElementById(id);
    const showing = m.length > 0;
    $('hud-error').hidden = $('hud-quality').hidden = !showing;
    if (!showing) {
      this.stats.error = this.stats.quality = null;
      return;
    }
    const [, rms, max, vertices, ...bins] = m;
    this.stats.error = { rms, max, vertices };
    this.stats.quality = bins;
    const top = Math.max(1, ...bins);
    const bars = $('hud-quality-bars');
    bars.replaceChildren(...bins.map((n) => {
      const bar = document.createElement('i');
      bar.style.height = `${Math.max(1, Math.round((14 * n) / top))}px`;
      return bar;
    }));
    const total = bins.reduce((a, b) => a + b, 0) || 1;
    const slivers = bins.slice(0, 2).reduce((a, b) => a + b, 0);
    this.#show('measures', (words) => {
      $('hud-error-text').textContent = words.t('hud.error-value', { rms: precise(words, rms), max: precise(words, max) });
      $('hud-error-text').title = words.t('hud.error-title', { count: vertices, vertices: count(words, vertices) });
      [...bars.children].forEach((bar, k) => {
        bar.title = words.t('hud.shape-bar', {
          from: fixed(words, k / 10, 1), to: fixed(words, (k + 1) / 10, 1), count: bins[k], triangles: count(words, bins[k]) });
      });
      bars.setAttribute('aria-label', words.t('hud.shapes-label', {
        percent: count(words, (100 * slivers) / total), limit: fixed(words, 0.2, 1) }));
    });
  }

  /**
   * Level of detail: `[resolution, blocks₀, triangles₀, …]` from the view, or empty without it, and
   * the cell size the selection uses (held below what was asked where larger cells would let touching
   * blocks differ by more than one level).
   */
  #showLevels(flat, heldPixels) {
    const $ = (id) => this.root.getElementById(id);
    if (!flat.length) {
      this.stats.lod = null;
      $('hud-lod').hidden = $('hud-lod-cell').hidden = true;
      return;
    }
    const levels = [];
    for (let i = 1; i + 1 < flat.length; i += 2) levels.push({ blocks: flat[i], triangles: flat[i + 1] });
    const used = levels.filter((l) => l.blocks > 0).length;
    const state = this.#ctx.state;
    const asked = this.#ctx.get(FigureDetail).lodPixels ?? state['lod-pixels'];
    const held = heldPixels > 0 && heldPixels < asked * (1 - 1e-6);
    const cellPixels = held ? heldPixels : asked;
    this.stats.lod = { resolution: flat[0], levels, cellPixels };
    $('hud-lod').hidden = $('hud-lod-cell').hidden = false;
    const [least, most] = [state['lod-pixels'], Math.max(state['lod-pixels'], state['max-lod-pixels'])];
    this.#show('lod', (words) => {
      $('hud-lod-cell-text').textContent = words.t(held ? 'hud.lod-cell-held' : 'hud.lod-cell-value', {
        cell: upTo2(words, cellPixels), least: upTo2(words, least), most: upTo2(words, most) });
      $('hud-lod-summary').textContent = words.t('hud.lod-summary', { resolution: whole(words, flat[0]), count: used });
      $('hud-lod-levels').replaceChildren(...levels.map(({ blocks, triangles }, k) => {
        const item = document.createElement('li');
        item.innerHTML = `<i style="background: ${levelColor(k)}"></i>`;
        item.append(words.t('hud.lod-level', { level: whole(words, k), blocks: count(words, blocks), triangles: count(words, triangles) }));
        item.hidden = blocks === 0;
        return item;
      }));
    });
  }
}
