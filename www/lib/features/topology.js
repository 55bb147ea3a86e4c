// The surface's shape, live: how many blobs, their genus, closed and manifold. It is worked out from
// the CPU mesher's mesh, or from one readback of the GPU's mesh, on the page's mesher worker where there
// is one (meshers.js; tens of milliseconds on a large mesh), only when asked: every second while the
// statistics show. Merges and splits of the mesh are announced in the figure's live region; the
// field's own merges (and `pause-on=merge`) are levels.js's, from its critical points.

import { meshShape } from '../engine/meshers.js';

const HUD_EVERY_MS = 1000;

export class TopologyWatch {
  #ctx;
  #pending = null;
  // The frames drawn when the pending question was asked, and when the answer taken last was.
  #pendingFrame = -1;
  // A question put off until the statistics' second is up.
  #later = null;
  #takenFrame = -1;
  #last = null;
  #askedAt = -Infinity;

  constructor(ctx) {
    this.#ctx = ctx;
  }

  /** The newest answer: { components, genus, closed, manifold }, or null. */
  get latest() {
    return this.#last;
  }

  /** The view changed (rebuilt, new spheres): the next answer starts a new count. */
  reset() {
    this.#last = null;
  }

  /**
   * Called after each frame drawn: asks when `pause-on` or the statistics want an answer. A frame the
   * statistics could not ask about yet (within the second, or while an answer is on its way) is asked
   * about once the second is up, so that the last frame drawn, as after a change to a still figure,
   * always gets its answer.
   */
  frameDrawn(now) {
    const state = this.#ctx.state;
    const showing = state.hud === 'on' && now - this.#askedAt >= HUD_EVERY_MS;
    if (this.#pending || !showing) {
      if (state.hud === 'on') this.#askLater(now);
      return;
    }
    this.#askedAt = now;
    this.check().catch(() => {});
  }

  #askLater(now) {
    if (this.#later) return;
    const wait = Math.max(0, HUD_EVERY_MS - (now - this.#askedAt));
    this.#later = setTimeout(() => {
      this.#later = null;
      if (this.#ctx.state.hud !== 'on' || !this.#ctx.view) return;
      this.#askedAt = performance.now();
      this.check().catch(() => {});
    }, wait);
  }

  /**
   * Asks the view now; resolves to the answer for the mesh drawn now. A question asked since the
   * last frame shares its answer; one asked before it was of an older mesh, so a new one is asked.
   */
  check() {
    const view = this.#ctx.view;
    if (!view) return Promise.reject(new Error('the figure is not drawing'));
    const frame = this.#ctx.frames.framesDrawn;
    if (this.#pending && this.#pendingFrame === frame) return this.#pending;
    const answer = view.mesh_triangles().then(([vertices, triangles]) => meshShape(vertices, triangles))
      .then((a) => this.#take(a, frame)).finally(() => {
        if (this.#pending === answer) this.#pending = null;
      });
    this.#pending = answer;
    this.#pendingFrame = frame;
    return answer;
  }

  #take([components, genus, closed, manifold], frame) {
    const shape = { components, genus, closed: closed === 1, manifold: manifold === 1 };
    // An answer about an older mesh than the last one taken (overtaken on the way) is not the news.
    if (frame < this.#takenFrame) return shape;
    this.#takenFrame = frame;
    const before = this.#last;
    this.#last = shape;
    this.#ctx.each('shape', shape);
    if (before && before.components !== components && this.#ctx.state['pause-on'] !== 'merge') {
      this.#ctx.each('announce', this.#ctx.t('topology.merge', { count: before.components, blobs: components }));
    }
    return shape;
  }
}
