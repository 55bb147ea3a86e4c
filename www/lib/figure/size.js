// A figure's canvas size: its CSS box times the pixel ratio, which follows the screen up to a cap and
// stays at 1 or less on software adapters (they shade every pixel on the CPU), and at half that there
// while the exact surface is ray cast (every pixel marches through the field); times the render scale
// (see detail.js) while it animates; and the notice, given once, that the exact surface is drawn at a
// lower ratio on a software renderer.

import { FigureDetail } from './detail.js';

/** Device pixels per CSS pixel drawing the exact surface on a software adapter. */
const SOFTWARE_EXACT_RATIO = 0.5;

/** True when the settings `s` ray cast the exact surface. */
const drawsExact = (s) => s.display === 'exact' || (s.compare ?? 'none') !== 'none';

/** Device pixels per CSS pixel for a figure whose cap is `cap`. */
function pixelRatio(cap, software, exact = false) {
  return Math.min(devicePixelRatio, cap, software ? (exact ? SOFTWARE_EXACT_RATIO : 1) : Infinity);
}

/**
 * [width, height] in pixels for `canvas` at `ratio`, from a ResizeObserver `entry` when there is one;
 * null while its box is empty (the canvas is not shown: in print, in a closed container).
 */
function canvasPixels(canvas, ratio, entry = null) {
  const box = entry?.devicePixelContentBoxSize?.[0];
  let width;
  let height;
  if (box) {
    width = (box.inlineSize * ratio) / devicePixelRatio;
    height = (box.blockSize * ratio) / devicePixelRatio;
  } else {
    const rect = canvas.getBoundingClientRect();
    width = rect.width * ratio;
    height = rect.height * ratio;
  }
  if (!(width > 0 && height > 0)) return null;
  return [Math.max(1, Math.round(width)), Math.max(1, Math.round(height))];
}

export class FigureSize {
  static attributes = ['max-pixel-ratio', 'min-render-scale', 'paused', 'speed', 'display', 'compare'];
  #ctx;
  #exactNoticed = false;
  /** True on a software adapter (set when the renderer starts). */
  software = false;

  constructor(ctx) {
    this.#ctx = ctx;
  }

  /** The render scale in effect: 1 while the figure is still. */
  get renderScale() {
    return this.#ctx.get(FigureDetail).renderScale;
  }

  #ratio() {
    const s = this.#ctx.state;
    return pixelRatio(s['max-pixel-ratio'], this.software, drawsExact(s)) * this.renderScale;
  }

  /**
   * Sizes the canvas for its box now (a ResizeObserver `entry` when there is one); returns the new
   * [width, height] in pixels, or null when it kept its size (also while its box is empty: the
   * frames drawn meanwhile keep the size they had).
   */
  fit(entry = null) {
    const { canvas } = this.#ctx;
    const pixels = canvasPixels(canvas, this.#ratio(), entry);
    if (!pixels) return null;
    const [width, height] = pixels;
    this.#ctx.each('scaled', this.renderScale, width, height);
    if (canvas.width === width && canvas.height === height) return null;
    canvas.width = width;
    canvas.height = height;
    return [width, height];
  }

  // A still figure draws at full scale, an animating one at its render scale; the exact surface at a
  // lower pixel ratio on a software renderer.
  changed() {
    this.#ctx.frames.resize();
    this.#exactChanged();
  }

  starting({ software }) {
    this.software = software;
    this.fit();
    this.#exactChanged();
  }

  // Says once what a software renderer does with the exact surface.
  #exactChanged() {
    if (drawsExact(this.#ctx.state) && this.software && !this.#exactNoticed) {
      this.#exactNoticed = true;
      this.#ctx.notice(this.#ctx.t('notice.exact-software', { ratio: SOFTWARE_EXACT_RATIO }), 4000);
    }
  }
}
