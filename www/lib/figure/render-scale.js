// The render scale: the fraction of its pixel ratio a figure draws at while it animates. Software
// renderers and slow phones shade every pixel at a cost, so, as <model-viewer> does, a figure whose
// frames run slower than the page's budget draws fewer pixels (the browser scales the canvas up),
// down to a floor (the `min-render-scale` attribute, 0.5 by default), and more again once frames are
// fast. The budget is the page's: every visible figure draws in the same animation frame, so the time
// between frames is the figures' work together, and each lowers its own scale while that is over
// budget. A still figure (paused, or at speed 0) draws at full scale.

import { frameBudget } from '../engine/page-watch.js';

/** The scales a figure steps through, from full down. */
const STEPS = [1, 0.85, 0.7, 0.6, 0.5, 0.42, 0.35, 0.3, 0.25];

export class RenderScale {
  #step = 0;
  #fastWindows = 0;
  // Measurements skipped after a change: the first frames at a new size say little.
  #settle = 0;

  /** The scale in effect, never below `floor`. */
  value(floor) {
    return Math.max(floor, STEPS[this.#step]);
  }

  /**
   * Takes the mean time between frames over the last half second; returns true when the scale changed.
   * Far over budget it drops several steps at once (pixels cost as the square of the scale); under 60 %
   * of the budget twice running it rises a step.
   */
  observe(frameMs, floor) {
    if (globalThis.metaballsFixedScale || !(frameMs > 0)) return false;
    if (this.#settle > 0) {
      this.#settle -= 1;
      return false;
    }
    const before = this.value(floor);
    const budget = frameBudget();
    if (frameMs > budget * 1.15 && before > floor) {
      const wanted = before * Math.sqrt(budget / frameMs);
      do this.#step += 1;
      while (this.#step < STEPS.length - 1 && STEPS[this.#step] > Math.max(wanted, floor));
      this.#fastWindows = 0;
    } else if (frameMs < budget * 0.6 && this.#step > 0) {
      this.#fastWindows += 1;
      if (this.#fastWindows >= 2) {
        this.#fastWindows = 0;
        this.#step -= 1;
        while (this.#step > 0 && STEPS[this.#step] < floor) this.#step -= 1;
      }
    } else {
      this.#fastWindows = 0;
    }
    const changed = this.value(floor) !== before;
    if (changed) this.#settle = 1;
    return changed;
  }
}
