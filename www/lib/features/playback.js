// Playing and pausing: the play button over a paused figure (where the panel has no pause button),
// the panel's pause and step buttons and their keys, and a figure that starts paused (`autoplay="off"`,
// or a reader who prefers reduced motion).

import { pageWatch } from '../engine/page-watch.js';
import { listedControls } from './panel.js';

export class Playback {
  static attributes = ['paused', 'controls'];
  #ctx;

  constructor(ctx) {
    this.#ctx = ctx;
    Object.assign(ctx.actions, {
      togglePause: () => (ctx.state.paused ? this.play() : this.pause()),
      step: () => this.step(),
    });
    ctx.$('play').addEventListener('click', () => { this.play(); ctx.canvas.focus(); });
  }

  play() { this.#ctx.set('paused', false); }

  pause() { this.#ctx.set('paused', true); }

  /** Draws one frame of animation (1/60 s) and stays paused. */
  step() {
    if (!this.#ctx.state.paused) this.pause();
    this.#ctx.frames.stepOnce();
  }

  firstStart() {
    if (this.#ctx.state.autoplay === 'off' || pageWatch().reducedMotion.matches) this.#ctx.set('paused', true);
  }

  changed() { this.#showPlayButton(); }

  loaded() { this.#showPlayButton(); }

  #showPlayButton() {
    const { state } = this.#ctx;
    this.#ctx.$('play').hidden = !(state.paused && !listedControls(state.controls).includes('paused'));
  }

  controls() {
    const { actions } = this.#ctx;
    return {
      paused: ({ makeButton, updates }) => {
        const button = makeButton('pause', { key: 'play.pause' }, { key: 'play.pause-title' }, actions.togglePause);
        updates.push((s) => {
          button.setAttribute('aria-pressed', String(s.paused));
          // Marked too, so that a new language words it as it stands.
          button.dataset.t = s.paused ? 'play.play' : 'play.pause';
          button.textContent = this.#ctx.t(button.dataset.t);
        });
        return button;
      },
      step: ({ makeButton }) => makeButton('step', { key: 'action.step' }, { key: 'play.step-title' }, actions.step),
    };
  }
}
