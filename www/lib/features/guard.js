// The slow-frame guard as a feature: a change that would make frames slower than a second on this
// adapter waits for the person's answer (see frame-cost.js), a figure starts with what its frames can
// afford, and the frames drawn and timed teach the estimate.

import { defaults } from '../core/table.js';
import { picturesTaken } from '../figure/look.js';
import { CostGuard } from './frame-cost.js';

export class Guard {
  #ctx;
  #guard;
  #picturesSeen = 0;

  constructor(ctx) {
    this.#ctx = ctx;
    this.#guard = new CostGuard(ctx.root, (name, value) => ctx.set(name, value), () => ctx.words);
  }

  /** The change waiting for the person's confirmation, or null. */
  get pending() { return this.#guard.pending ? { ...this.#guard.pending } : null; }

  veto(name, value) {
    const state = this.#ctx.state;
    if (!this.#guard.tooSlow(state, { ...state, [name]: value })) return false;
    this.#guard.ask(state, { [name]: value });
    return true;
  }

  // Before the first frame: the kind of adapter sets the first estimate, and costly settings go back
  // to the defaults (the person is asked).
  starting({ software, compute }) {
    this.#guard.start(software || !compute);
    for (const name of this.#guard.startAffordably(this.#ctx.state, defaults())) this.#ctx.settings.reflect(name);
  }

  started() { this.#guard.rendererStarted(); }

  language(words) { this.#guard.reword(words); }

  frameDrawn(now, { blockedMs }) { this.#guard.frameDrawn(this.#ctx.settings.applied, now, blockedMs); }

  // Frame times measured while a picture for print was taken (on any figure: it waits for the GPU)
  // say nothing about the settings.
  timed({ since, frameMs }) {
    const pictures = picturesTaken();
    if (!this.#ctx.state.paused && pictures === this.#picturesSeen) {
      this.#guard.framesTimed(this.#ctx.settings.applied, since, frameMs);
    }
    this.#picturesSeen = pictures;
  }
}
