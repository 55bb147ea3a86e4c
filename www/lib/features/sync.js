// Figures with the same `sync` name share their spheres, their animation time and their camera. The
// first of them on the page leads: it animates, and the others take its spheres before each of their
// frames (all run on the page's one device). A camera change in any of them is made in all.

import { ONE_FRAME } from '../core/redraw.js';
import { CAMERA } from './camera.js';

// Every figure on the page that can sync, in the order they joined (their Sync features).
const members = new Set();

const peersOf = (member) => {
  const name = member.name();
  return name ? [...members].filter((m) => m.name() === name) : [];
};

/** A figure as a member of its `sync` group. */
export class Sync {
  #ctx;
  // The leader's frame whose spheres this figure last took.
  #ledFrame = -1;

  constructor(ctx) {
    this.#ctx = ctx;
  }

  /** The figure's `sync` setting (empty: none). */
  name() { return this.#ctx.state.sync; }

  connected() { members.add(this); }

  disconnected() { members.delete(this); }

  /** The figure whose spheres and time this one follows, or null when it leads or syncs with none. */
  get leader() {
    const leader = peersOf(this)[0];
    return leader && leader !== this ? leader : null;
  }

  // A figure that does not lead takes the leader's spheres instead of animating.
  holds() { return this.leader !== null; }

  beforeFrame(now, view) {
    const frames = this.leader?.#ctx.frames;
    if (!frames?.view || frames.framesDrawn === this.#ledFrame) return;
    this.#ledFrame = frames.framesDrawn;
    view.set_spheres(frames.shownSpheres());
    this.#ctx.redraw(ONE_FRAME);
  }

  /** A camera change made here is made in the other figures of the group. */
  madeInside(name, value, share) {
    if (!share || !CAMERA.includes(name)) return;
    for (const peer of peersOf(this)) {
      if (peer !== this) peer.#ctx.set(name, value, false);
    }
  }
}
