// The 2D figure's step-through of the march: the step shown, playing at a speed, and its panel beside
// the figure (stepper-panel.js). The figure hands in how many squares per axis it has, its last march
// and how to draw again.

import { SQUARE_TABLE, squareAccount, stepperPanel } from './stepper-panel.js';
import { nextCrossed } from './stepper.js';

export class SquareStepper {
  /** The step shown (square j · cells + i; cells² at the end), or null when the step-through is off. */
  step = null;
  /** True while it plays. */
  playing = false;
  #speed = 4;
  #carry = 0;
  #update = null;
  #host;
  #figure;

  /** `host`: the element beside the figure; `figure`: `{ cells(), result(), redraw() }`. */
  constructor(host, figure) {
    this.#host = host;
    this.#figure = figure;
  }

  /** Opens it at step `k` (clamped to the march), or moves it there. */
  to(k) {
    const steps = this.#figure.cells() ** 2;
    this.step = Math.max(0, Math.min(steps, Math.round(k)));
    this.#update ??= stepperPanel(this.#host, {
      back: () => { this.playing = false; this.to(this.step - 1); },
      forward: () => { this.playing = false; this.to(this.step + 1); },
      next: () => { this.playing = false; this.nextCrossed(); },
      play: () => { this.playing = !this.playing; this.#carry = 0; this.#figure.redraw(); },
      speed: (perSecond) => { this.#speed = perSecond; },
    }, SQUARE_TABLE);
    this.#figure.redraw();
  }

  /** To the next square the contour crosses (the end when there is none). */
  nextCrossed() {
    const found = nextCrossed(this.#figure.result().cases, this.step ?? -1);
    this.to(found < 0 ? this.#figure.cells() ** 2 : found);
  }

  close() {
    this.step = null;
    this.playing = false;
    this.#host.replaceChildren();
    this.#update = null;
  }

  /** Moves a playing step-through on by `dt` seconds of steps; stops it at the end. */
  advance(dt) {
    if (!this.playing || this.step === null) return;
    this.#carry += dt * this.#speed;
    const steps = Math.floor(this.#carry);
    this.#carry -= steps;
    const end = this.#figure.cells() ** 2;
    this.step = Math.min(end, this.step + steps);
    if (this.step >= end) this.playing = false;
  }

  /** Shows the step of march `result` (at `iso`) in the panel. */
  show(result, iso) {
    if (!this.#update) return;
    const cells = this.#figure.cells();
    const k = this.step;
    const square = k < cells * cells ? result.square(k % cells, Math.floor(k / cells)) : null;
    this.#update({ playing: this.playing, lit: square?.case ?? null, account: squareAccount(k, cells * cells, square, iso) });
  }
}
