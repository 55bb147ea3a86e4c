// What an animating figure gives up while the page's frames run longer than its budget (see
// ladder.js), and takes back once they are fast: first pixels, the render scale, down to
// `min-render-scale`; then, with level of detail, the cells' size on screen, from `lod-pixels` up to
// `max-lod-pixels`. Fast frames give the cells back first, then the pixels. The budget is the page's:
// every visible figure draws in the same animation frame, so the time between frames is the figures'
// work together, and each gives up its own detail while that is over budget. A still figure (paused,
// or at speed 0) draws at full scale and with cells of `lod-pixels`.

import { frameBudget } from '../engine/page-watch.js';
import { DetailBudget, Ladder, LOD_STEPS, RENDER_SCALES } from './ladder.js';

export class FigureDetail {
  static attributes = ['lod'];
  #ctx;
  #budget = new DetailBudget();
  #scale = new Ladder(RENDER_SCALES);
  #cells = new Ladder(LOD_STEPS);
  // The coarsening the renderer was given, and which renderer.
  #given = { view: null, coarsening: 1 };

  constructor(ctx) {
    this.#ctx = ctx;
  }

  get #still() {
    const s = this.#ctx.state;
    return s.paused || s.speed === 0;
  }

  // The lowest detail the cells may have: their smallest size over their largest.
  get #cellFloor() {
    const s = this.#ctx.state;
    return s.lod ? Math.min(1, s['lod-pixels'] / s['max-lod-pixels']) : 1;
  }

  /** The render scale in effect: 1 while the figure is still. */
  get renderScale() {
    return this.#still ? 1 : this.#scale.value(this.#ctx.state['min-render-scale']);
  }

  /** How many times `lod-pixels` the cells may look on screen now: 1 while still or without LOD. */
  get lodCoarsening() {
    // Rounded: a step's coarsening is the number in its list, whatever the division's last bit.
    return this.#still ? 1 : Number((1 / this.#cells.value(this.#cellFloor)).toPrecision(6));
  }

  /** With level of detail, the largest a cell may look now, in pixels; else null. */
  get lodPixels() {
    const s = this.#ctx.state;
    return s.lod ? s['lod-pixels'] * this.lodCoarsening : null;
  }

  /** Level of detail turned on starts from cells of `lod-pixels`. */
  changed(name, value) {
    if (name === 'lod' && value) this.#cells.reset();
  }

  /**
   * Frame times came in: an animating figure's detail follows the time between the animation frames
   * it drew or waited in (`tickMs`), not the time it waited for a mesh from the worker.
   */
  timed({ tickMs, animating }) {
    if (!animating) return;
    const chain = [{ ladder: this.#cells, floor: this.#cellFloor }];
    // Benchmarks fix the render scale to compare figures at the same pixels.
    if (!globalThis.metaballsFixedScale) chain.unshift({ ladder: this.#scale, floor: this.#ctx.state['min-render-scale'] });
    const scale = this.renderScale;
    if (this.#budget.observe(tickMs, frameBudget(), chain) && this.renderScale !== scale) this.#ctx.frames.resize();
  }

  /** Before each frame: the renderer draws the cells at the size in effect. */
  beforeFrame(now, view) {
    const coarsening = this.lodCoarsening;
    if (this.#given.view === view && this.#given.coarsening === coarsening) return;
    view.set_lod_coarsening(coarsening);
    this.#given = { view, coarsening };
  }
}
