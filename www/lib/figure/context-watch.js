// A WebGL2 figure's drawing context: the browser may take it away (a GPU reset, a driver update, too
// many contexts on the page, a phone putting the tab to sleep) and give it back later. A lost context
// is treated as a lost WebGPU device is: the figure keeps its scene on the CPU, starts again when the
// context comes back (after a wait that doubles with each loss), and stops after three losses in a
// minute with "Try again". The events only ever fire on a canvas drawn with WebGL, so every figure
// watches its canvas.

import { LossCount } from '../engine/losses.js';

export class ContextWatch {
  #losses = new LossCount();
  #lost = false;
  #timer = 0;

  /**
   * `on`: { lost(reason) (let go of the renderer), restored() (start again), stop(count) (too many
   * losses: show why, with "Try again") }.
   */
  constructor(canvas, on) {
    canvas.addEventListener('webglcontextlost', (event) => {
      // Without this the browser never gives the context back.
      event.preventDefault();
      this.#lost = true;
      clearTimeout(this.#timer);
      const count = this.#losses.record();
      on.lost('its WebGL2 context was lost');
      if (this.#losses.exhausted) on.stop(count);
    });
    canvas.addEventListener('webglcontextrestored', () => {
      this.#lost = false;
      if (this.#losses.exhausted) return;
      this.#timer = setTimeout(() => on.restored(), this.#losses.backoff());
    });
  }

  /** True between a loss and the context coming back: nothing can be drawn. */
  get lost() { return this.#lost; }

  /** Forgets the losses so far ("Try again"). */
  clear() { this.#losses.clear(); }
}
