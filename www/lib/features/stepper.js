// The step-through of the march in 3D: `march="x,y,z"` (a link, an attribute, or the panel's "Step
// through the march") walks marching cubes one cell at a time, x fastest, then y, then z. At each step
// the cell is selected in the inspector (highlighted, with its corners, crossed edges, vertices and
// triangles), the box beside it builds the case bit by bit and lights its row among the 256 grouped
// into the gallery's classes, and the renderer draws the triangles of the cells reached so far, on the
// GPU's passes and the CPU's mesher alike. The spheres hold still while it is open.

import { caseGallery } from '../engine/wasm.js';
import { stepperPanel } from '../plane/stepper-panel.js';
import { caseBits, Playhead } from '../plane/stepper.js';
import { className } from './cell-drawing.js';
import { escape, Inspector, markup } from './inspector.js';

/** Reads `x,y,z` as a cell, or null (`off`). */
export function parseCell(text) {
  if (!text || text === 'off') return null;
  return text.split(',').map(Number);
}

/** The 256 cases grouped into the gallery's classes, as the stepper panel's table (its words HTML). */
function caseTable(words) {
  return {
    name: markup(words, 'march.table'),
    head: [markup(words, 'march.table-case'), markup(words, 'march.table-bits')],
    groups: caseGallery().classes.map((k) => ({
      title: markup(words, 'march.table-class', { class: k.class, name: escape(className(words, k.class)), count: k.cases }),
      rows: Array.from(k.members, (c) => [c, c.toString(2).padStart(8, '0')]),
    })),
  };
}

export class Stepper {
  static attributes = ['march', 'resolution', 'lod', 'method'];
  #ctx;
  #box;
  #panel = null;
  #play = new Playhead();
  #last = 0;
  // What the inspector shows for the step: the view and cell last selected, and the report shown.
  #selected = null;
  #shown = null;

  constructor(ctx) {
    this.#ctx = ctx;
    this.#box = ctx.$('march');
    ctx.actions.stepThrough = () => this.open();
  }

  controls() {
    return {
      'step-through': ({ makeButton }) => {
        const button = makeButton('step-through', this.#ctx.t('action.step-through'),
          this.#ctx.t('march.step-through-title'), () => this.open());
        button.dataset.t = 'action.step-through';
        button.dataset.tTitle = 'march.step-through-title';
        return button;
      },
    };
  }

  // The panel and its account of the step in the reader's language.
  language(words) {
    if (!this.#panel) return;
    this.#panel.language(words);
    if (!this.#box.hidden) this.#show(this.#shown);
  }

  /** The cell the march stands at, or null when the stepper is off. */
  get cell() {
    const cell = parseCell(this.#ctx.state.march);
    const n = this.#ctx.state.resolution;
    return cell && cell.map((v) => Math.min(v, n - 1));
  }

  /** The step (cell x + n (y + n z)), or null. */
  get index() {
    const cell = this.cell;
    const n = this.#ctx.state.resolution;
    return cell && cell[0] + n * (cell[1] + n * cell[2]);
  }

  /** Opens the stepper at the first cell, or at the inspected one. */
  open() {
    const report = this.#ctx.get(Inspector).report;
    this.#ctx.set('march', report ? report.cell.join(',') : '0,0,0');
  }

  close() {
    this.#play.playing = false;
    this.#ctx.set('march', 'off');
  }

  /** Moves the march to step `k`, clamped to the grid's cells. */
  stepTo(k) {
    const n = this.#ctx.state.resolution;
    const m = Math.max(0, Math.min(n ** 3 - 1, Math.round(k)));
    this.#ctx.set('march', [m % n, Math.floor(m / n) % n, Math.floor(m / (n * n))].join(','));
  }

  /** The next cell the surface crosses (the last cell when none is left). */
  nextCrossed() {
    if (this.#wholeMesh()) return;
    const cell = this.cell;
    const next = cell && this.#ctx.view?.next_crossed_cell(...cell);
    if (next) this.#ctx.set('march', Array.from(next).join(','));
    else this.stepTo(Infinity);
  }

  // With level of detail or a dual method the whole mesh is drawn: says so, and says true.
  #wholeMesh() {
    const { lod, method } = this.#ctx.state;
    if (!lod && method === 'marching_cubes') return false;
    this.#ctx.notice(this.#ctx.t('march.whole-mesh'));
    return true;
  }

  changed(name) {
    if (name !== 'march') this.#selected = null;
    const cell = this.cell;
    if (name !== 'resolution' && cell) this.#wholeMesh();
    // On a coarser grid the march stands at the cell it is drawn at.
    if (name === 'resolution' && cell && `${cell}` !== this.#ctx.state.march) this.#ctx.set('march', cell.join(','));
    if (!cell) {
      this.#play.playing = false;
      this.#box.hidden = true;
      if (this.#selected) this.#ctx.get(Inspector).deselect();
      this.#selected = null;
    }
    this.#ctx.redraw(1);
  }

  // The spheres hold still while the march is open.
  holds() { return this.cell !== null; }

  afterTick(now, view) {
    const cell = this.cell;
    if (!cell || !view) {
      this.#last = 0;
      return;
    }
    if (this.#play.playing) {
      const steps = this.#play.steps(this.#last ? Math.min(0.1, (now - this.#last) / 1000) : 0);
      const last = this.#ctx.state.resolution ** 3 - 1;
      if (steps > 0) this.stepTo(Math.min(last, this.index + steps));
      if (this.index >= last) this.#play.playing = false;
    }
    this.#last = now;
    const key = `${cell}`;
    const inspector = this.#ctx.get(Inspector);
    if (this.#selected?.view !== view || this.#selected.key !== key) {
      this.#selected = { view, key };
      inspector.select(...cell);
      this.#show(inspector.report);
    } else if (!inspector.report) {
      // The inspector let go of the cell (Esc, its ×): the step-through ends with it.
      this.close();
    } else if (`${inspector.report.cell}` !== key) {
      // A click picked another cell: the march goes there.
      this.#ctx.set('march', inspector.report.cell.join(','));
    } else if (inspector.report !== this.#shown) {
      // The report followed a change (the iso level, the blend): so does the box.
      this.#show(inspector.report);
    }
  }

  #show(report) {
    const words = this.#ctx.words;
    if (!this.#panel) {
      // (The table is worded by the panel, in each language it speaks.)
      this.#panel = stepperPanel(this.#box, {
        back: () => { this.#play.playing = false; this.stepTo(this.index - 1); },
        forward: () => { this.#play.playing = false; this.stepTo(this.index + 1); },
        next: () => { this.#play.playing = false; this.nextCrossed(); },
        play: () => { this.#play.toggle(); this.#show(this.#ctx.get(Inspector).report); },
        speed: (perSecond) => { this.#play.speed = perSecond; },
        close: () => this.close(),
      }, caseTable, words);
    }
    // (The box covers the panel, whose controls leave the tab order while it shows: FigureSheets.)
    this.#box.hidden = false;
    this.#shown = report;
    const n = this.#ctx.state.resolution;
    const [x, y, z] = this.cell;
    const head = markup(words, 'march.step', { step: this.index + 1, steps: n ** 3, x, y, z });
    // The corners' values and signs are in the inspector's box beside it; here, their bits add up.
    const account = report
      ? `${head}<br>${caseSum(words, report.corners, this.#ctx.state.iso)}<br>${markup(words, 'march.class', {
        class: report.class,
        name: escape(className(words, report.class)),
        count: report.triangles.length,
        edges: report.triangles.map((t) => t.join('–')).join(', ') || markup(words, 'inspector.none'),
      })}`
      : head;
    this.#panel({ playing: this.#play.playing, account, lit: report?.case ?? null });
  }
}

/** The case of corner values `corners` at `iso` as the sum of its bits, as HTML (the inside ones marked). */
function caseSum(words, corners, iso) {
  const { bits, case: sum } = caseBits(corners, iso);
  return markup(words, 'march.case-sum', {
    case: `<b class="case">${sum}</b>`,
    sum: bits.map((b) => (b.inside ? `<span class="in">${b.bit}</span>` : b.bit)).join(' + '),
  });
}
