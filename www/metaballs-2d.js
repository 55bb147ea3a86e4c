// <metaballs-2d>: marching squares on circles in the plane, the figure a course starts with. The field
// f = Σ qᵢ rᵢ² / |p − cᵢ|² is sampled on a grid; the figure shows each sample's value and sign, each
// square's case, the saddle squares with the value that decided them, the crossings and the contour,
// and further iso levels as lines and filled bands. It draws on a 2D canvas (no GPU, no WebAssembly),
// exports its picture as SVG and its contour as data, and its circles move and can be dragged.
// Importing it only defines the element, and only where `customElements` exists.
//
// It is built as <metaballs-view> is: a figure context (lib/core/context.js) holding its settings, read
// from attributes, properties, its panel and scene files by the table's reader (lib/core/read.js) with
// the rows of its table (scene/src/params/plane.rs, written into lib/attributes.js), and its features
// (lib/plane/): the circles and their gestures, the step-through, the panel, the scene files, its
// accessible name and print; its frames are lib/plane/frames.js.

import { PLANE_TABLE } from './lib/attributes.js';
import { Rows } from './lib/core/rows.js';
import { FigureState } from './lib/core/state.js';
import { FigureContext } from './lib/core/context.js';
import { watchLanguage } from './lib/core/language.js';
import { customStates, defineSettingProperties, flasher, takeAttribute } from './lib/core/element.js';
import { parseF64, readValue } from './lib/core/read.js';
import { refusal } from './lib/i18n/words.js';
import { PANEL_CONTROLS, PlanePanel } from './lib/plane/panel.js';
import { parseCircles } from './lib/plane/circles.js';
import { PlaneCircles, PlaneInside, PlaneLabel } from './lib/plane/plane-circles.js';
import { PlaneFrames, PlanePrint } from './lib/plane/frames.js';
import { PlaneScene } from './lib/plane/scene-file.js';
import { PlaneStepper } from './lib/plane/square-stepper.js';
import { PlaneShare } from './lib/features/plane-share.js';

const STYLE = `
:host { display: block; position: relative; max-width: 100%; contain: content; font: 13px system-ui, sans-serif; }
/* With the stepper, the figure and its panel side by side in halves: the panel scrolls within the
   figure's height, so the element is as tall as half its width (metaballs-view.css reserves that), but
   for a narrow figure, which stacks them. */
:host([march]) { display: grid; grid-template-columns: minmax(0, 1fr) minmax(0, 1fr); }
.figure { position: relative; aspect-ratio: 1; }
.side { min-height: 0; contain: size; margin-inline-start: 8px; }
.side:empty { display: none; }
canvas { display: block; width: 100%; height: 100%; touch-action: none; cursor: crosshair; border-radius: 6px; }
/* A language written right to left: the panel, the step-through and the notice run its way (and the
   step-through goes to the picture's left); the picture and its print do not mirror. */
/* The figure runs its own language's way, whatever way the page around it runs. */
:host { direction: ltr; }
:host(:state(rtl)) { direction: rtl; }
canvas, .print { direction: ltr; }
#notice { position: absolute; left: 8px; right: 8px; bottom: 8px; padding: 6px 8px; border-radius: 6px;
  background: #3b2f12; border: 1px solid #8a6a1f; color: #ffe2a3; }
#notice[hidden] { display: none; }
/* A narrow figure: the step-through below the picture, scrolling within its own height; a small one:
   the panel over the picture's upper part. Controls a finger can hit: at least 24 × 24 CSS px. */
:host([march]:state(stacked)) { display: block; }
:host(:state(stacked)) .side { contain: none; height: min(70vh, 480px); margin: 8px 0 0; }
:host(:state(compact)) .panel { max-height: 55%; }
:is(button, select, summary, input:not([type=checkbox])) { min-height: 24px; }
:host(:state(compact)) input[type=checkbox] { width: 24px; height: 24px; margin: 0; }
button { min-width: 24px; }
/* In print: the picture as vector art (kept while the figure is still, and made before printing) in
   place of the canvas, without the controls or the step-through's panel. */
.print { display: none; position: absolute; inset: 0; }
.print svg { display: block; width: 100%; height: 100%; }
@media print {
  :host([march]) { display: block; }
  .print:not(:empty) { display: block; }
  .print:not(:empty) + canvas, .controls, .side, #notice { display: none; }
}`;

/** Narrower than this (CSS pixels), the step-through goes below the picture; the panel gets smaller. */
const STACK_PX = 520;
const COMPACT_PX = 440;

/** The 2D figure's rows of the parameter table, by every spelling. */
export const PLANE_ROWS = new Rows(PLANE_TABLE);

// A setting's text read by the table's reader; circles and the step-through's square also by their own
// grammar. A `march` given empty opens the step-through at its first square, `off` or `none` closes it;
// a square is checked against the grid drawn when the step-through opens (the grid may change after).
function readSetting(spelling, text) {
  const row = PLANE_ROWS.rowOf(spelling);
  const value = readValue(row, text, spelling);
  if (row.name === 'circles' && value.trim()) {
    // Each number as the table's numbers are read (no hexadecimal, no `1_0`).
    const bad = value.split(/[;,]/).map((part) => part.trim()).find((part) => part && parseF64(part) === null);
    if (bad !== undefined) throw refusal(`circles: "${bad}" is not a number`, 'plane-circle-number', { part: bad });
    parseCircles(value);
  }
  if (row.name === 'march') {
    const march = value.trim();
    if (/^(off|none)$/i.test(march)) return '';
    if (!/^[0-9]+\s*(,\s*[0-9]+)?$/.test(march || '0')) {
      throw refusal(`march: "${text}" is not a square i,j, a step number, off or none`, 'plane-march', { text });
    }
    return march || '0';
  }
  return value;
}

// The features of the figure, in the order they hear of changes.
const FEATURES = [PlaneInside, PlaneCircles, PlaneStepper, PlaneScene, PlaneShare, PlanePanel, PlaneLabel, PlanePrint];

// Where there is no DOM (a static-site build importing the module), a plain class stands in.
const Base = globalThis.HTMLElement ?? class {};

export class Metaballs2d extends Base {
  /** Where this module was loaded from: the share box's script tags and pages are found from it. */
  static moduleUrl = import.meta.url;

  static observedAttributes = PLANE_ROWS.spellings;

  /** The controls `controls` may list. */
  static controls = PANEL_CONTROLS;

  #ctx;
  #states = customStates(this);

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    root.innerHTML = `<style>${STYLE}</style><div class="figure"><div class="print"></div><canvas id="view" part="canvas" role="img"></canvas>`
      + '<div id="notice" part="notice" role="status" hidden></div><div class="controls"></div></div><div class="side"></div>';
    const ctx = new FigureContext(this, root, new FigureState(this, PLANE_ROWS, readSetting), this.#states);
    this.#ctx = ctx;
    ctx.flash = flasher(root);
    for (const Feature of FEATURES) ctx.use(Feature);
    const circles = ctx.get(PlaneCircles);
    ctx.frames = new PlaneFrames(ctx, {
      circles, stepper: ctx.get(PlaneStepper).stepper, dragged: () => circles.gestures.dragged,
    });
  }

  // Properties mirror the attributes, as on <metaballs-view>.
  static {
    defineSettingProperties(this, PLANE_ROWS, (element) => element.#ctx.state);
  }

  connectedCallback() {
    this.#observer = new ResizeObserver(([entry]) => {
      this.#fit(entry.contentRect.width);
      if (this.isConnected) this.#ctx.frames.draw();
    });
    this.#observer.observe(this);
    this.#unwatchLanguage = watchLanguage(this, (words) => this.#ctx.speak(words));
    this.#ctx.each('refresh', this.#ctx.state);
    this.#ctx.each('connected');
    this.#ctx.frames.start();
  }

  #observer = null;
  #unwatchLanguage = null;

  // A narrow figure (its own width, not the page's) stacks the step-through below the picture
  // (`:state(stacked)`), and a small one keeps its panel over the picture's upper part (`:state(compact)`).
  #fit(width) {
    if (!(width > 0)) return;
    this.#states.set('stacked', width < STACK_PX);
    this.#states.set('compact', width < COMPACT_PX);
  }

  disconnectedCallback() {
    this.#observer?.disconnect();
    this.#unwatchLanguage?.();
    this.#ctx.each('disconnected');
    this.#ctx.frames.stop();
  }

  attributeChangedCallback(spelling, _old, text) {
    const ctx = this.#ctx;
    const again = !ctx.settings.reflecting && PLANE_ROWS.canonical(spelling) === 'march' && ctx.state.march;
    takeAttribute(ctx, 'metaballs-2d', spelling, text);
    // The square it holds, asked for again, is shown again (the step-through may have played on).
    if (again && ctx.state.march === again) ctx.get(PlaneStepper).changed('march');
  }

  /** Shows a short message inside the figure. */
  showNotice(text, ms = 8000) { this.#ctx.notice(text, ms); }

  /** The figure as it is now, written to paste: { html, url, iframe, python, myst, link }. */
  shareText() { return this.#ctx.get(PlaneShare).texts(); }

  /** A PNG of the picture at the figure's size times `scale`. */
  makePoster(scale = 1) { return this.#ctx.get(PlaneShare).poster(scale); }

  /** A clip of the circles moving: { seconds, fps, width, height, format, onProgress, signal } → a Blob. */
  record(options) { return this.#ctx.get(PlaneShare).record(options); }

  /** Opens the share box. */
  openShare() { this.#ctx.get(PlaneShare).open(); }

  /** The last frame's time to sample, march and paint, in ms. */
  get frameMs() { return this.#ctx.frames.frameMs; }

  // ---------------------------------------------------------------- the circles

  /** The circles, as placed (each `{ x, y, r, charge }`). Set to such a list to place them. */
  get circleList() { return this.#ctx.get(PlaneCircles).list; }

  set circleList(list) { this.#ctx.get(PlaneCircles).place(list); }

  play() { this.#ctx.set('paused', false); }

  pause() { this.#ctx.set('paused', true); }

  // ---------------------------------------------------------------- the step-through

  /** The step-through's step (square j · resolution + i, in the march's order), or null when it is off. */
  get stepIndex() { return this.#ctx.get(PlaneStepper).stepper.step; }

  /** Opens the step-through at step `k` (clamped to the march), or moves it there. */
  stepTo(k) { this.#ctx.get(PlaneStepper).to(k); }

  stepForward() { this.stepTo((this.stepIndex ?? -1) + 1); }

  stepBack() { this.stepTo((this.stepIndex ?? 1) - 1); }

  /** Moves the step-through to the next square the contour crosses (stays at the end when there is none). */
  nextCrossed() { this.#ctx.get(PlaneStepper).stepper.nextCrossed(); }

  // ---------------------------------------------------------------- scene files

  /** The circles and every setting of the picture, as the 2D figure's scene document (JSON text). */
  saveScene() { return this.#ctx.get(PlaneScene).save(); }

  /** Loads a scene document; throws with what is wrong, changing nothing. */
  loadScene(text) { this.#ctx.get(PlaneScene).load(text); }

  /** Downloads the scene document. */
  downloadScene() { this.#ctx.actions['save-scene'](); }

  // ---------------------------------------------------------------- what it draws, as data

  /**
   * The contour at the iso level as data: `{ iso, cells, rings, saddles, crossings, cases }`, each ring
   * a closed list of points [x, y] in the box [-1, 1]² with the inside on its left, and each square's
   * case in the march's order (square (i, j) at j · cells + i).
   */
  contours() {
    const frames = this.#ctx.frames;
    const r = frames.result ?? frames.draw();
    return {
      iso: frames.iso, cells: frames.cells, rings: r.rings, saddles: r.saddles, crossings: r.crossings, cases: Array.from(r.cases),
    };
  }

  /** The picture as an SVG document (vector: the grid, labels, bands and contour as drawn). */
  toSVG(size = 640) { return this.#ctx.frames.svg(size); }

  /**
   * The <metaballs-view> whose slice plane this figure follows (`slice-of`: its id), or null. It must
   * have a `slice` (`z:0.2`): the plane is then sampled as that figure samples it.
   */
  get following() { return this.#ctx.frames.following; }

  /** The samples drawn: `{ cells, values }`, (cells + 1)² values row by row from the lower left. */
  samples() {
    const { cells, values } = this.#ctx.frames.source();
    return { cells, values: Array.from(values) };
  }
}

/**
 * Adds a language, or overrides some of a language's words, for every figure on the page:
 * `registerTranslation('nl', { 'setting.iso': 'Isoniveau', … })`; `englishWords` is every English
 * message by its key (docs/embedding.md, "Languages").
 */
export { registerTranslation, EN as englishWords } from './lib/i18n/words.js';

if (globalThis.customElements && !customElements.get('metaballs-2d')) {
  customElements.define('metaballs-2d', Metaballs2d);
}
