// Detail that follows the frame times. Software renderers and slow phones pay for every pixel and
// every triangle, so, as <model-viewer> does with pixels, a figure whose frames run slower than the
// page's budget draws less, and more again once frames are fast. What it can give up is a chain of
// ladders, each a list of steps of detail from full (1) down to a floor its settings give, and each
// costing as the square of its step (pixels as the square of the render scale; triangles as the
// square of one over the cells' size on screen). Frames far over budget take the ladders down in
// order, the first as far as its floor before the next, by as many steps as the overrun asks; frames
// well under budget twice running bring the last ladder taken down up a step, so the chain climbs back
// in the order it came down. This module only counts: the figure's ladders are in detail.js.

/** Frames this much over the budget take detail down. */
const SLOW = 1.15;
/** Frames under this share of the budget, twice running, give a step back. */
const FAST = 0.6;
/** Fast windows in a row that give a step back. */
const FAST_WINDOWS = 2;

/** The render scale's steps: fractions of the pixel ratio. */
export const RENDER_SCALES = [1, 0.85, 0.7, 0.6, 0.5, 0.42, 0.35, 0.3, 0.25];

/** Level of detail's steps: its smallest cell size over the size cells may look. */
export const LOD_STEPS = [1, 1.25, 1.5, 2, 2.5, 3, 4, 5, 6, 8, 10, 12, 16, 20, 24, 32, 40, 48, 64, 80, 96, 128, 160,
  192, 256].map((coarsening) => 1 / coarsening);

/** One ladder: steps of detail from 1 down; its floor is given with each question. */
export class Ladder {
  #step = 0;

  constructor(steps) {
    this.steps = steps;
  }

  /** The detail in effect: the step's, never below `floor` nor above 1. */
  value(floor) {
    return Math.min(1, Math.max(floor, this.steps[this.#step]));
  }

  /** True while it can go down: above its floor, with steps left. */
  canLower(floor) {
    return this.value(floor) > floor && this.#step < this.steps.length - 1;
  }

  /** True while it can go up: below full detail. */
  canRaise(floor) {
    return this.value(floor) < 1;
  }

  /** Goes down at least one step, and on to the first step at or below `wanted` (or `floor`). */
  lower(wanted, floor) {
    const target = Math.max(wanted, floor);
    do this.#step += 1;
    while (this.#step < this.steps.length - 1 && this.steps[this.#step] > target);
  }

  /** Goes up to the next step above the detail in effect. */
  raise(floor) {
    const now = this.value(floor);
    while (this.#step > 0 && this.steps[this.#step] <= now) this.#step -= 1;
  }

  /** Back to full detail. */
  reset() {
    this.#step = 0;
  }
}

/** Moves a chain of ladders as a figure's frame times come in. */
export class DetailBudget {
  #fastWindows = 0;
  // Measurements skipped after a change: the first frames with less or more detail say little.
  #settle = 0;

  /**
   * Takes the mean time between frames over the last half second, the page's budget and the chain,
   * `[{ ladder, floor }]` in the order detail is given up; returns true when a ladder's detail changed.
   */
  observe(frameMs, budgetMs, chain) {
    if (!(frameMs > 0)) return false;
    if (this.#settle > 0) {
      this.#settle -= 1;
      return false;
    }
    const before = chain.map(({ ladder, floor }) => ladder.value(floor));
    if (frameMs > budgetMs * SLOW) {
      this.#fastWindows = 0;
      // The share of detail to keep: the cost goes as its square.
      let keep = Math.sqrt(budgetMs / frameMs);
      for (const { ladder, floor } of chain) {
        // What is left to give up is less than the overrun that starts a step.
        if (keep >= 1 / Math.sqrt(SLOW)) break;
        if (!ladder.canLower(floor)) continue;
        const from = ladder.value(floor);
        ladder.lower(from * keep, floor);
        keep /= ladder.value(floor) / from;
      }
    } else if (frameMs < budgetMs * FAST) {
      const last = chain.findLast(({ ladder, floor }) => ladder.canRaise(floor));
      this.#fastWindows = last ? this.#fastWindows + 1 : 0;
      if (this.#fastWindows >= FAST_WINDOWS) {
        this.#fastWindows = 0;
        last.ladder.raise(last.floor);
      }
    } else {
      this.#fastWindows = 0;
    }
    const changed = chain.some(({ ladder, floor }, i) => ladder.value(floor) !== before[i]);
    if (changed) this.#settle = 1;
    return changed;
  }
}
