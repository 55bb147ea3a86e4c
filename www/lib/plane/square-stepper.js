// The 2D figure's step-through of the march: the step shown, its play, and its panel beside the figure
// (stepper-panel.js). The figure hands in how many squares per axis it draws, its last march, how to
// draw again, and where the step goes (its `march` attribute, so that links and widgets carry it). The
// panel speaks the figure's language.

import { squareAccount, squareTable, stepperPanel } from './stepper-panel.js';
import { nextCrossed, Playhead, readStep } from './stepper.js';

export class SquareStepper {
  /** The step shown (square j · cells + i; cells² at the end), or null when the step-through is off. */
  step = null;
  play = new Playhead();
  #update = null;
  #host;
  #figure;

  /**
   * `host`: the element beside the figure; `figure`: `{ cells(), result(), redraw(), moved(k), words() }`
   * (`words()`: the figure's words, i18n/words.js).
   */
  constructor(host, figure) {
    this.#host = host;
    this.#figure = figure;
  }

  get playing() { return this.play.playing; }

  /** Opens it at step `k` (clamped to the march), or moves it there. */
  to(k) {
    const steps = this.#figure.cells() ** 2;
    this.step = Math.max(0, Math.min(steps, Math.round(k)));
    this.#update ??= stepperPanel(this.#host, {
      back: () => { this.play.playing = false; this.#move(this.step - 1); },
      forward: () => { this.play.playing = false; this.#move(this.step + 1); },
      next: () => { this.play.playing = false; this.nextCrossed(); },
      play: () => { this.play.toggle(); this.#figure.redraw(); },
      speed: (perSecond) => { this.play.speed = perSecond; },
    }, squareTable, this.#figure.words());
    this.#figure.redraw();
  }

  /** Words the open panel in `words`' language (its account follows on the next drawing). */
  language(words) {
    this.#update?.language(words);
    if (this.#update) this.#figure.redraw();
  }

  // A step the person asked for: taken, and told to the figure.
  #move(k) {
    this.to(k);
    this.#figure.moved(this.step);
  }

  /** To the next square the contour crosses (the end when there is none). */
  nextCrossed() {
    const found = nextCrossed(this.#figure.result().cases, this.step ?? -1);
    this.#move(found < 0 ? this.#figure.cells() ** 2 : found);
  }

  close() {
    this.step = null;
    this.play.playing = false;
    this.#host.replaceChildren();
    this.#update = null;
  }

  /** Moves a playing step-through on by `dt` seconds of steps; stops it at the end. */
  advance(dt) {
    if (this.step === null) return;
    const end = this.#figure.cells() ** 2;
    this.step = Math.min(end, this.step + this.play.steps(dt));
    if (this.step >= end) this.play.playing = false;
  }

  /** Shows the step of march `result` (at `iso`) in the panel. */
  show(result, iso) {
    if (!this.#update) return;
    const cells = this.#figure.cells();
    const k = this.step;
    const square = k < cells * cells ? result.square(k % cells, Math.floor(k / cells)) : null;
    const account = squareAccount(k, cells * cells, square, iso, this.#figure.words());
    this.#update({ playing: this.playing, lit: square?.case ?? null, account });
  }
}

/**
 * The step-through as a feature of the 2D figure: opened, moved and closed by `march` (a square `i,j`
 * or a step; `off`, `none` or no attribute closes it), kept on its square when the grid changes, and
 * each step the person takes written back to `march`.
 */
export class PlaneStepper {
  static attributes = ['march', 'resolution'];
  #ctx;

  constructor(ctx) {
    this.#ctx = ctx;
    const frames = () => ctx.frames;
    this.stepper = new SquareStepper(ctx.root.querySelector('.side'), {
      cells: () => frames().cells,
      result: () => frames().result ?? frames().draw(),
      redraw: () => frames().redraw(),
      moved: (k) => this.reflect(k),
      words: () => ctx.words,
    });
    ctx.actions['step-through'] = () => this.toggle();
  }

  changed(name) {
    const ctx = this.#ctx;
    const text = ctx.state.march;
    // A square named i,j stays that square on a new grid (and one not on the old grid may be on the new).
    if (name === 'resolution' && !text) return;
    try {
      if (!text) this.stepper.close();
      else this.stepper.to(readStep(text, ctx.frames.cells));
    } catch (error) {
      ctx.notice(ctx.words.refusal(error));
      ctx.emit('metaballs-error', { message: error.message, attribute: 'march' });
    }
  }

  language(words) { this.stepper.language(words); }

  /** Opens it at step `k` (clamped to the march), or moves it there, and writes the step to `march`. */
  to(k) {
    this.stepper.to(k);
    this.reflect(this.stepper.step);
  }

  /** Opens or closes it (the panel's button). */
  toggle() {
    if (this.stepper.step === null) this.#ctx.set('march', '0');
    else this.#ctx.element.removeAttribute('march');
  }

  // The step as `march` (`i,j`, or the step number at the end), so that links carry it.
  reflect(k) {
    const cells = this.#ctx.frames.cells;
    const text = k < cells * cells ? `${k % cells},${Math.floor(k / cells)}` : String(k);
    const given = this.#ctx.state.march;
    const same = Boolean(given) && (() => { try { return readStep(given, cells) === k; } catch { return false; } })();
    if (!same) this.#ctx.set('march', text);
  }
}
