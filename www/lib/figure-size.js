// A figure's canvas size: its CSS box times the pixel ratio (see canvas-size.js) times the render
// scale (see render-scale.js) while it animates; and the notice, given once, that the exact surface is
// drawn at a lower ratio on a software renderer.

import { canvasPixels, drawsExact, pixelRatio, SOFTWARE_EXACT_RATIO } from './canvas-size.js';
import { RenderScale } from './render-scale.js';

export class FigureSize {
  #canvas;
  #state;
  #hud;
  #scale = new RenderScale();
  #exactNoticed = false;
  /** True on a software adapter (set when the renderer starts). */
  software = false;

  /** `state()`: the figure's settings in effect; `hud`: where the scale is shown. */
  constructor(canvas, state, hud) {
    this.#canvas = canvas;
    this.#state = state;
    this.#hud = hud;
  }

  /** The render scale in effect: 1 while the figure is still. */
  get renderScale() {
    const s = this.#state();
    return s.paused || s.speed === 0 ? 1 : this.#scale.value(s['min-render-scale']);
  }

  #ratio() {
    const s = this.#state();
    return pixelRatio(s['max-pixel-ratio'], this.software, drawsExact(s)) * this.renderScale;
  }

  /**
   * Sizes the canvas for its box now (a ResizeObserver `entry` when there is one); returns the new
   * [width, height] in pixels, or null when it kept its size.
   */
  fit(entry = null) {
    const canvas = this.#canvas;
    const [width, height] = canvasPixels(canvas, this.#ratio(), entry);
    this.#hud.setScale(this.renderScale, width, height);
    if (canvas.width === width && canvas.height === height) return null;
    canvas.width = width;
    canvas.height = height;
    return [width, height];
  }

  /** Takes the time between frames of an animating figure; true when the scale changed. */
  observe(frameMs) {
    return this.#scale.observe(frameMs, this.#state()['min-render-scale']);
  }

  /** The exact surface was switched on or off: says once what a software renderer does with it. */
  exactChanged(notice) {
    if (drawsExact(this.#state()) && this.software && !this.#exactNoticed) {
      this.#exactNoticed = true;
      notice(`The exact surface is drawn at ${SOFTWARE_EXACT_RATIO}× pixel ratio on this software renderer.`);
    }
  }
}
