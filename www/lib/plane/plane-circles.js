// The 2D figure's circles as a feature: the ones given (`circles`) or seeded (`spheres`, `seed`), kept
// as they move, dragged, added and removed by hand (circle-gestures.js), and written back to `circles`
// when an edit ends, so that links, scene files and notebooks carry them. Also the figure's accessible
// name, in its reader's language.

import { CircleGestures } from './circle-gestures.js';
import { numeral } from './picture.js';
import { circlesExactText, circlesText, parseCircles, seededCircles } from './circles.js';

export class PlaneCircles {
  static attributes = ['circles', 'spheres', 'seed'];
  #ctx;
  #list = null;

  constructor(ctx) {
    this.#ctx = ctx;
    this.gestures = new CircleGestures(ctx.canvas, {
      circles: () => this.list,
      size: () => ctx.frames.size,
      locked: () => Boolean(ctx.state['slice-of']),
      moved: () => {
        ctx.frames.draw();
        ctx.emit('metaballs-2d-drag', { circles: this.list });
      },
      edited: () => ctx.get(PlaneInside).setText('circles', circlesText(this.list)),
      refused: () => ctx.notice(ctx.t('plane.last-circle')),
    });
  }

  /** The circles, as placed (each `{ x, y, r, charge, vx, vy }`). */
  get list() {
    const s = this.#ctx.state;
    this.#list ??= s.circles.trim() ? parseCircles(s.circles) : seededCircles(s.seed, s.spheres);
    return this.#list;
  }

  /** Places circles given as `{ x, y, r, charge }` (at full precision; refused like the attribute). */
  place(list) {
    this.#ctx.get(PlaneInside).setText('circles', circlesExactText(list));
  }

  changed() { this.#list = null; }
}

/**
 * Changes made inside the figure (its panel, a gesture, a method), given as text: read as an attribute
 * would be, refused with a notice (the panel then shows the value kept), else set and reflected.
 */
export class PlaneInside {
  #ctx;

  constructor(ctx) { this.#ctx = ctx; }

  setText(name, text) {
    const ctx = this.#ctx;
    const { value, message, said } = ctx.settings.parse(name, text);
    if (message) {
      ctx.notice(ctx.settings.constructor.refused(ctx.words, said));
      ctx.each('refresh', ctx.state);
      return false;
    }
    ctx.set(name, value);
    return true;
  }
}

/** The figure's accessible name: the author's `alt`, else what it shows. */
export class PlaneLabel {
  #ctx;

  constructor(ctx) { this.#ctx = ctx; }

  refresh(s) {
    const { words } = this.#ctx;
    const count = this.#ctx.get(PlaneCircles).list.length;
    this.#ctx.canvas.setAttribute('aria-label', s.alt
      || words.t('plane.label', { count, cells: s.resolution, iso: numeral(words, String(s.iso)) }));
  }

  language() { this.refresh(this.#ctx.state); }
}
