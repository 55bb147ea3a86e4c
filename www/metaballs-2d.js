// <metaballs-2d>: marching squares on circles in the plane, the figure a course starts with. The field
// f = Σ qᵢ rᵢ² / |p − cᵢ|² is sampled on a grid; the figure shows each sample's value and sign, each
// square's case, the saddle squares with the value that decided them, the crossings and the contour,
// and further iso levels as lines and filled bands. It draws on a 2D canvas (no GPU, no WebAssembly),
// exports its picture as SVG and its contour as data, and its circles move and can be dragged.
// Importing it only defines the element, and only where `customElements` exists.
//
// Its settings are read with the ranges, words and defaults of their rows in the parameter table.

import { PLANE_TABLE } from './lib/attributes.js';
import { DEFAULT_SHOWN, paint, picture, toSvg } from './lib/plane/picture.js';
import { PANEL_CONTROLS, planePanel, readControls } from './lib/plane/panel.js';
import { CircleGestures } from './lib/plane/circle-gestures.js';
import { circlesText, moveCircles, parseCircles, seededCircles } from './lib/plane/circles.js';
import { readLevels, readSetting, readShown } from './lib/plane/settings.js';
import { download, readScene, writeScene } from './lib/plane/scene-file.js';
import { followed, sliceKey, sliceSource } from './lib/plane/slice-source.js';
import { sampleField } from './lib/plane/squares.js';
import { readStep } from './lib/plane/stepper.js';
import { SquareStepper } from './lib/plane/square-stepper.js';

const STYLE = `
:host { display: block; position: relative; max-width: 100%; contain: content; font: 13px system-ui, sans-serif; }
/* With the stepper, the figure and its panel side by side in halves: the panel scrolls within the
   figure's height, so the element is as tall as half its width (metaballs-view.css reserves that). */
:host([march]) { display: grid; grid-template-columns: minmax(0, 1fr) minmax(0, 1fr); }
.figure { position: relative; aspect-ratio: 1; }
.side { min-height: 0; contain: size; margin-left: 8px; }
.side:empty { display: none; }
canvas { display: block; width: 100%; height: 100%; touch-action: none; cursor: crosshair; border-radius: 6px; }
#notice { position: absolute; left: 8px; right: 8px; bottom: 8px; padding: 6px 8px; border-radius: 6px;
  background: #3b2f12; border: 1px solid #8a6a1f; color: #ffe2a3; }
#notice[hidden] { display: none; }
/* In print: the picture as vector art (kept while the figure is still, and made before printing) in
   place of the canvas, without the controls or the step-through's panel. */
.print { display: none; position: absolute; inset: 0; }
.print svg { display: block; width: 100%; height: 100%; }
@media print {
  :host([march]) { display: block; }
  .print:not(:empty) { display: block; }
  .print:not(:empty) + canvas, .controls, .side, #notice { display: none; }
}`;

// The figure's settings, each declared once: the rows of the parameter table it shares with
// <metaballs-view> and its own (scene/src/params/plane.rs, written into attributes.js).
const ROWS = new Map(PLANE_TABLE.map((row) => [row.name, row]));
const rowOf = (name) => ROWS.get(name);
// The settings a scene document holds (beside the circles).
const SCENE = PLANE_TABLE.filter((row) => row.scene && row.name !== 'circles').map((row) => row.name);

// Settings read by a part of the figure of their own (the step-through, the panel, the description and
// the figure followed), not by `readValue`.
const OWN_READERS = ['march', 'controls', 'alt', 'slice-of'];

/** A setting's value read from text as the figure reads it; throws with what is accepted. */
function readValue(name, text) {
  if (name === 'circles') return parseCircles(text);
  if (name === 'levels') return readLevels(text, rowOf('iso'));
  if (name === 'show') return readShown(text);
  return readSetting(rowOf(name), text);
}

// Where there is no DOM (a static-site build importing the module), a plain class stands in.
const Base = globalThis.HTMLElement ?? class {};

export class Metaballs2d extends Base {
  static observedAttributes = PLANE_TABLE.map((row) => row.name);

  /** The controls `controls` may list. */
  static controls = PANEL_CONTROLS;

  #canvas;
  #notice;
  // The settings in effect: each row's default until given.
  #settings = {
    ...Object.fromEntries(['iso', 'resolution', 'interpolation', 'saddle', 'spheres', 'seed', 'speed', 'paused', 'theme']
      .map((name) => [name, rowOf(name).value])),
    levels: [], shown: DEFAULT_SHOWN,
  };
  #circles = null;
  #given = null;
  #frame = 0;
  #last = 0;
  #gestures;
  #result = null;
  #size = 0;
  #observer = null;
  /** The last frame's time to sample, march and paint, in ms. */
  frameMs = 0;
  // The stepper: the step shown (null when it is off), whether it plays, steps per second, the time
  // carried towards the next step, and the panel's update.
  #stepper;

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    root.innerHTML = `<style>${STYLE}</style><div class="figure"><div class="print"></div><canvas part="canvas" role="img"></canvas>`
      + '<div id="notice" part="notice" role="status" hidden></div><div class="controls"></div></div><div class="side"></div>';
    this.#canvas = root.querySelector('canvas');
    this.#notice = root.getElementById('notice');
    this.#gestures = new CircleGestures(this.#canvas, {
      circles: () => this.circleList,
      size: () => this.#size,
      locked: () => this.hasAttribute('slice-of'),
      moved: () => {
        this.#draw();
        this.dispatchEvent(new CustomEvent('metaballs-2d-drag', { detail: { circles: this.circleList }, bubbles: true, composed: true }));
      },
      edited: () => this.#setInside('circles', circlesText(this.circleList)),
      refused: (text) => this.#say(text),
    });
    this.#stepper = new SquareStepper(root.querySelector('.side'), {
      cells: () => this.#cells(),
      result: () => this.#result ?? this.#draw(),
      redraw: () => this.#schedule(),
      moved: (k) => this.#reflectStep(k),
    });
  }

  // The picture for print, as vector art: made while the figure is still, and before printing.
  #forPrint = () => {
    const print = this.shadowRoot.querySelector('.print');
    print.innerHTML = this.toSVG(Math.max(1, this.#size));
    print.firstElementChild?.setAttribute('aria-hidden', 'true');
  };

  #printTimer = 0;

  connectedCallback() {
    globalThis.addEventListener('beforeprint', this.#forPrint);
    this.#observer = new ResizeObserver(() => this.#redraw());
    this.#observer.observe(this);
    this.#label();
    this.#schedule();
  }

  disconnectedCallback() {
    globalThis.removeEventListener('beforeprint', this.#forPrint);
    clearTimeout(this.#printTimer);
    this.#observer?.disconnect();
    cancelAnimationFrame(this.#frame);
    this.#frame = 0;
  }

  attributeChangedCallback(name, _old, text) {
    try {
      if (name === 'alt') this.#label();
      else if (name === 'slice-of') this.#schedule();
      else if (name === 'march') this.#openStepper(text);
      else if (name === 'controls') this.#buildPanel(text);
      else if (name === 'circles') this.#given = text === null ? null : readValue(name, text);
      else if (name === 'levels') this.#settings.levels = text === null ? [] : readValue(name, text);
      else if (name === 'show') this.#settings.shown = text === null ? DEFAULT_SHOWN : readValue(name, text);
      else this.#settings[name] = text === null ? rowOf(name).value : readValue(name, text);
      if (['circles', 'spheres', 'seed'].includes(name)) this.#circles = null;
      // A square named i,j stays that square on a new grid.
      if (name === 'resolution' && this.hasAttribute('march')) this.#openStepper(this.getAttribute('march'));
    } catch (error) {
      this.#say(`${error.message}; kept the previous value`);
    }
    this.#label();
    this.#panelUpdate?.();
    this.#schedule();
  }

  // ---------------------------------------------------------------- the panel and edits by hand

  #panelUpdate = null;

  #buildPanel(text) {
    const names = readControls(text);
    const host = this.shadowRoot.querySelector('.controls');
    this.#panelUpdate = null;
    host.replaceChildren();
    if (names.length === 0) return;
    this.#panelUpdate = planePanel(host, names, rowOf, {
      get: (name) => this.#valueText(name),
      set: (name, value) => this.#setInside(name, value),
      action: (name) => {
        if (name === 'step-through') this.#setInside('march', this.hasAttribute('march') ? null : '0');
        else if (name === 'save-scene') this.downloadScene();
        else if (name === 'load-scene') host.querySelector('input[type=file]').click();
      },
    });
    const file = host.querySelector('input[type=file]');
    file?.addEventListener('change', () => this.#loadFile(file));
    this.#panelUpdate();
  }

  // A setting in effect, as its attribute would write it.
  #valueText(name) {
    const s = this.#settings;
    if (name === 'levels') return s.levels.join(',');
    if (name === 'show') return s.shown.join(',');
    return String(s[name]);
  }

  // A change made in the figure (its panel, a gesture): set as the attribute, so that it is checked and
  // reflected like one given by the page, and announced for the page's link.
  #setInside(name, text) {
    // A value the figure would refuse is not set: the notice says why, the panel shows the value kept.
    if (text !== null && !OWN_READERS.includes(name)) {
      try {
        readValue(name, text);
      } catch (error) {
        this.#say(`${error.message}; kept the previous value`);
        this.#panelUpdate?.();
        return;
      }
    }
    if (text === null) this.removeAttribute(name);
    else this.setAttribute(name, text);
    this.dispatchEvent(new CustomEvent('metaballs-change', { detail: { attribute: name, value: text }, bubbles: true, composed: true }));
  }

  // ---------------------------------------------------------------- scene files

  /** The circles and every setting of the picture, as the 2D figure's scene document (JSON text). */
  saveScene() {
    const settings = Object.fromEntries(SCENE.map((name) => [name, name === 'levels' ? this.#settings.levels
      : name === 'show' ? this.#settings.shown.join(',') : this.#settings[name]]));
    return writeScene(this.circleList, settings);
  }

  /** Loads a scene document; throws with what is wrong, changing nothing. */
  loadScene(text) {
    const { circles, settings } = readScene(text, SCENE, (name, value) => readValue(name, value));
    this.#setInside('circles', circles);
    for (const [name, value] of settings) this.#setInside(name, value);
  }

  /** Downloads the scene document. */
  downloadScene() {
    download(this.saveScene(), 'metaballs-2d-scene.json');
  }

  async #loadFile(input) {
    const file = input.files?.[0];
    input.value = '';
    try {
      if (file) this.loadScene(await file.text());
    } catch (error) {
      this.#say(`${file.name}: ${error.message}; the scene is unchanged`);
    }
  }

  #say(text) {
    this.#notice.textContent = text;
    this.#notice.hidden = !text;
    clearTimeout(this.#noticeTimer);
    if (text) this.#noticeTimer = setTimeout(() => { this.#notice.hidden = true; }, 8000);
  }

  #noticeTimer = 0;

  #label() {
    const s = this.#settings;
    const alt = this.getAttribute('alt');
    this.#canvas.setAttribute('aria-label', alt || `Marching squares: ${this.circleList.length} circles on ${s.resolution} × ${s.resolution} squares, contour at iso ${s.iso}`);
  }

  /** The circles, as placed (each `{ x, y, r, charge }`). */
  get circleList() {
    if (!this.#circles) {
      const given = this.#given;
      this.#circles = given ? given.map((c) => ({ ...c })) : seededCircles(this.#settings.seed, this.#settings.spheres);
    }
    return this.#circles;
  }

  set circleList(list) {
    this.#given = list.map((c) => ({ x: c.x, y: c.y, r: Math.abs(c.r), charge: c.charge ?? Math.sign(c.r) ?? 1, vx: 0, vy: 0 }));
    this.#circles = null;
    this.#schedule();
  }

  play() { this.removeAttribute('paused'); this.#settings.paused = false; this.#schedule(); }

  /** The stepper's step (square j · resolution + i, in the march's order), or null when it is off. */
  get stepIndex() { return this.#stepper.step; }

  /** Opens the stepper at step `k` (clamped to the march), or moves it there. */
  stepTo(k) {
    this.#stepper.to(k);
    this.#reflectStep(this.#stepper.step);
  }

  // The step as the `march` attribute (`i,j`, or the step number at the end), so that links carry it.
  #reflectStep(k) {
    const cells = this.#cells();
    const text = k < cells * cells ? `${k % cells},${Math.floor(k / cells)}` : String(k);
    const given = this.getAttribute('march');
    const same = given !== null && (() => { try { return readStep(given, cells) === k; } catch { return false; } })();
    if (!same) this.#setInside('march', text);
  }

  stepForward() { this.stepTo((this.#stepper.step ?? -1) + 1); }

  stepBack() { this.stepTo((this.#stepper.step ?? 1) - 1); }

  /** Moves the stepper to the next square the contour crosses (stays at the end when there is none). */
  nextCrossed() { this.#stepper.nextCrossed(); }

  #openStepper(text) {
    if (text === null || /^\s*(off|none)\s*$/i.test(text)) this.#stepper.close();
    else this.#stepper.to(readStep(text, this.#cells()));
  }

  pause() { this.#settings.paused = true; }

  /**
   * The contour at the iso level as data: `{ iso, cells, rings, saddles, crossings, cases }`, each ring
   * a closed list of points [x, y] in the box [-1, 1]² with the inside on its left, and each square's
   * case in the march's order (square (i, j) at j · cells + i).
   */
  contours() {
    const r = this.#result ?? this.#draw();
    return {
      iso: this.following ? Number(this.following.iso) : this.#settings.iso, cells: this.#cells(), rings: r.rings, saddles: r.saddles,
      crossings: r.crossings, cases: Array.from(r.cases),
    };
  }

  /** The picture as an SVG document (vector: the grid, labels, bands and contour as drawn). */
  toSVG(size = 640) {
    const { shapes } = this.#picture(size);
    return toSvg(shapes, size, this.getAttribute('alt') || this.#canvas.getAttribute('aria-label'));
  }

  /**
   * The <metaballs-view> whose slice plane this figure follows (`slice-of`: its id), or null. It must
   * have a `slice` (`z:0.2`): the plane is then sampled as that figure samples it.
   */
  get following() { return followed(this, this.getAttribute('slice-of')); }

  /** What is sampled: this figure's circles, or the followed figure's slice plane and its settings. */
  #source() {
    const s = this.#settings;
    const view = this.following;
    if (view) return sliceSource(view);
    return {
      values: sampleField(this.circleList, s.resolution), cells: s.resolution, iso: s.iso,
      options: { placement: s.interpolation, saddle: s.saddle }, circles: this.circleList,
    };
  }

  #lastFollowed = null;

  // Squares per axis of the grid drawn: this figure's, or the followed figure's.
  #cells() {
    const view = this.following;
    return view ? Number(view.resolution) : this.#settings.resolution;
  }

  /** The samples drawn: `{ cells, values }`, (cells + 1)² values row by row from the lower left. */
  samples() {
    const { cells, values } = this.#source();
    return { cells, values: Array.from(values) };
  }

  #picture(size) {
    const s = this.#settings;
    const { values, cells, iso, options, circles } = this.#source();
    return picture({
      values, cells, iso, levels: s.levels, circles, shown: s.shown, options, size, theme: s.theme, step: this.#stepper.step,
    });
  }

  #redraw() {
    if (this.isConnected) this.#draw();
  }

  #draw() {
    const start = performance.now();
    const box = this.#canvas.parentElement.getBoundingClientRect();
    const size = Math.max(1, Math.round(Math.min(box.width, box.height || box.width)));
    const ratio = globalThis.devicePixelRatio || 1;
    const pixels = Math.round(size * ratio);
    if (this.#canvas.width !== pixels) this.#canvas.width = this.#canvas.height = pixels;
    this.#size = size;
    const { shapes, result } = this.#picture(size);
    paint(this.#canvas.getContext('2d'), shapes, pixels / size);
    this.#result = result;
    this.#stepper.show(result, this.following ? Number(this.following.iso) : this.#settings.iso);
    this.frameMs = performance.now() - start;
    return result;
  }

  // A change to draw: the next frame draws (`#lastFollowed` set apart from any key).
  #schedule() {
    this.#lastFollowed = undefined;
    this.#request();
  }

  #request() {
    if (!this.isConnected || this.#frame) return;
    this.#frame = requestAnimationFrame((now) => this.#tick(now));
  }

  #tick(now) {
    this.#frame = 0;
    const dt = this.#last ? Math.min(0.05, (now - this.#last) / 1000) : 0;
    this.#last = now;
    // While the stepper is open the circles hold still, and a playing stepper advances.
    const moving = !this.#settings.paused && !this.#gestures.dragged && this.#stepper.step === null && !this.hasAttribute('slice-of');
    if (moving) moveCircles(this.circleList, dt * this.#settings.speed);
    this.#stepper.advance(dt);
    // A figure following a 3D figure's slice looks every frame (its spheres move), and draws when what
    // it samples has changed.
    const view = this.following;
    const key = view ? sliceKey(view) : null;
    const changing = moving || this.#stepper.playing;
    const drawing = changing || key !== this.#lastFollowed;
    if (drawing) this.#draw();
    this.#lastFollowed = key;
    if (changing || this.hasAttribute('slice-of')) this.#request();
    else this.#last = 0;
    // The picture for print, once a changed picture has settled.
    if (drawing) clearTimeout(this.#printTimer);
    if (drawing && !changing) this.#printTimer = setTimeout(this.#forPrint, 300);
  }
}

if (globalThis.customElements && !customElements.get('metaballs-2d')) {
  customElements.define('metaballs-2d', Metaballs2d);
}
