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
import { circlesText, parseCircles, readLevels, readSetting, readShown, seededCircles } from './lib/plane/settings.js';
import { sampleField, sampleSlice } from './lib/plane/squares.js';
import { nextCrossed } from './lib/plane/stepper.js';
import { SQUARE_TABLE, squareAccount, stepperPanel } from './lib/plane/stepper-panel.js';

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
#notice[hidden] { display: none; }`;

// The figure's settings, each declared once: the rows of the parameter table it shares with
// <metaballs-view> and its own (src/scene/params/plane.rs, written into attributes.js).
const ROWS = new Map(PLANE_TABLE.map((row) => [row.name, row]));
const rowOf = (name) => ROWS.get(name);

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
  #drag = null;
  #result = null;
  #size = 0;
  #observer = null;
  /** The last frame's time to sample, march and paint, in ms. */
  frameMs = 0;
  // The stepper: the step shown (null when it is off), whether it plays, steps per second, the time
  // carried towards the next step, and the panel's update.
  #step = null;
  #stepping = false;
  #stepSpeed = 4;
  #stepCarry = 0;
  #panel = null;

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    root.innerHTML = `<style>${STYLE}</style><div class="figure"><canvas part="canvas" role="img"></canvas>`
      + '<div id="notice" part="notice" role="status" hidden></div><div class="controls"></div></div><div class="side"></div>';
    this.#canvas = root.querySelector('canvas');
    this.#notice = root.getElementById('notice');
    this.#canvas.addEventListener('pointerdown', (e) => this.#grab(e));
    this.#canvas.addEventListener('pointermove', (e) => this.#move(e));
    for (const end of ['pointerup', 'pointercancel']) this.#canvas.addEventListener(end, () => this.#drop());
    this.#canvas.addEventListener('dblclick', (e) => this.#addOrRemove(e));
  }

  connectedCallback() {
    this.#observer = new ResizeObserver(() => this.#redraw());
    this.#observer.observe(this);
    this.#label();
    this.#schedule();
  }

  disconnectedCallback() {
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
      else if (name === 'circles') this.#given = text === null ? null : parseCircles(text);
      else if (name === 'levels') this.#settings.levels = text === null ? [] : readLevels(text, rowOf('iso'));
      else if (name === 'show') this.#settings.shown = text === null ? DEFAULT_SHOWN : readShown(text);
      else this.#settings[name] = text === null ? rowOf(name).value : readSetting(rowOf(name), text);
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
      action: () => this.#setInside('march', this.hasAttribute('march') ? null : '0'),
    });
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
    if (text === null) this.removeAttribute(name);
    else this.setAttribute(name, text);
    this.dispatchEvent(new CustomEvent('metaballs-change', { detail: { attribute: name, value: text }, bubbles: true, composed: true }));
  }

  // A double-click adds a circle where there is none, and removes the one under the pointer.
  #addOrRemove(event) {
    const [x, y] = this.#toBox(event);
    const list = this.circleList;
    const hit = this.#circleAt(x, y);
    if (hit) {
      if (list.length === 1) {
        this.#say('circles: the last circle stays (the figure needs one)');
        return;
      }
      list.splice(list.indexOf(hit), 1);
    } else {
      list.push({ x, y, r: 0.2, charge: 1, vx: 0, vy: 0 });
    }
    this.#setInside('circles', circlesText(list));
  }

  #drop() {
    if (this.#drag) this.#setInside('circles', circlesText(this.circleList));
    this.#drag = null;
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
  get stepIndex() { return this.#step; }

  /** Opens the stepper at step `k` (clamped to the march), or moves it there. */
  stepTo(k) {
    const steps = this.#settings.resolution ** 2;
    this.#step = Math.max(0, Math.min(steps, Math.round(k)));
    this.#ensurePanel();
    this.#schedule();
  }

  stepForward() { this.stepTo((this.#step ?? -1) + 1); }

  stepBack() { this.stepTo((this.#step ?? 1) - 1); }

  /** Moves the stepper to the next square the contour crosses (stays at the end when there is none). */
  nextCrossed() {
    const result = this.#result ?? this.#draw();
    const found = nextCrossed(result.cases, this.#step ?? -1);
    this.stepTo(found < 0 ? this.#settings.resolution ** 2 : found);
  }

  #openStepper(text) {
    if (text === null) {
      this.#step = null;
      this.#stepping = false;
      this.shadowRoot.querySelector('.side').replaceChildren();
      this.#panel = null;
      return;
    }
    const cells = this.#settings.resolution;
    const parts = text.split(',').map((t) => t.trim()).filter(Boolean).map(Number);
    const k = parts.length === 0 ? 0 : parts.length === 1 ? parts[0] : parts[1] * cells + parts[0];
    const ok = parts.every(Number.isInteger) && parts.length <= 2
      && (parts.length < 2 || (parts[0] >= 0 && parts[0] < cells && parts[1] >= 0 && parts[1] < cells)) && k >= 0 && k <= cells * cells;
    if (!ok) throw new Error(`march: "${text}" is not a square i,j of the ${cells} × ${cells} grid, nor a step from 0 to ${cells * cells}`);
    this.stepTo(k);
  }

  #ensurePanel() {
    if (this.#panel) return;
    this.#panel = stepperPanel(this.shadowRoot.querySelector('.side'), {
      back: () => { this.#stepping = false; this.stepBack(); },
      forward: () => { this.#stepping = false; this.stepForward(); },
      next: () => { this.#stepping = false; this.nextCrossed(); },
      play: () => { this.#stepping = !this.#stepping; this.#stepCarry = 0; this.#schedule(); },
      speed: (perSecond) => { this.#stepSpeed = perSecond; },
    }, SQUARE_TABLE);
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
      iso: this.#settings.iso, cells: this.#settings.resolution, rings: r.rings, saddles: r.saddles,
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
  get following() {
    const id = this.getAttribute('slice-of');
    const view = id ? this.getRootNode().getElementById?.(id) ?? document.getElementById(id) : null;
    return view && view.localName === 'metaballs-view' && /^[xyz]:/.test(view.slice ?? '') ? view : null;
  }

  /** What is sampled: this figure's circles, or the followed figure's slice plane and its settings. */
  #source() {
    const s = this.#settings;
    const view = this.following;
    if (!view) {
      return {
        values: sampleField(this.circleList, s.resolution), cells: s.resolution, iso: s.iso,
        options: { placement: s.interpolation, saddle: s.saddle }, circles: this.circleList,
      };
    }
    const cells = Number(view.resolution);
    const [axisName, position] = view.slice.split(':');
    const axis = 'xyz'.indexOf(axisName);
    // The plane as the 3D figure rounds it to its grid.
    const plane = Math.min(cells, Math.round((Number(position) + 1) * 0.5 * cells));
    return {
      values: sampleSlice(view.sphereList, cells, axis, plane, view.blend), cells, iso: Number(view.iso),
      options: { placement: view.interpolation, saddle: view.saddle }, circles: [],
    };
  }

  #lastFollowed = null;

  // What the followed figure's samples depend on, as text; null when none is followed.
  #followedKey() {
    const view = this.following;
    if (!view) return null;
    const spheres = view.sphereList.map((b) => [...b.center, b.radius, b.charge].join(',')).join(';');
    return [spheres, view.slice, view.resolution, view.iso, view.saddle, view.interpolation, view.blend].join('|');
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
      values, cells, iso, levels: s.levels, circles, shown: s.shown, options, size, theme: s.theme, step: this.#step,
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
    if (this.#panel) {
      const cells = this.#settings.resolution;
      const k = this.#step;
      const square = k < cells * cells ? result.square(k % cells, Math.floor(k / cells)) : null;
      this.#panel({
        playing: this.#stepping, lit: square?.case ?? null,
        account: squareAccount(k, cells * cells, square, this.#settings.iso),
      });
    }
    this.frameMs = performance.now() - start;
    return result;
  }

  // A change to draw: the next frame draws whatever it follows.
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
    const moving = !this.#settings.paused && !this.#drag && this.#step === null && !this.hasAttribute('slice-of');
    if (moving) this.#moveCircles(dt * this.#settings.speed);
    if (this.#stepping && this.#step !== null) {
      this.#stepCarry += dt * this.#stepSpeed;
      const steps = Math.floor(this.#stepCarry);
      this.#stepCarry -= steps;
      this.#step = Math.min(this.#settings.resolution ** 2, this.#step + steps);
      if (this.#step >= this.#settings.resolution ** 2) this.#stepping = false;
    }
    // A figure following a 3D figure's slice looks every frame (its spheres move), and draws when what
    // it samples has changed.
    const followed = this.#followedKey();
    if (followed === null || followed !== this.#lastFollowed || moving || this.#stepping) this.#draw();
    this.#lastFollowed = followed;
    if (moving || this.#stepping || this.hasAttribute('slice-of')) this.#request();
    else this.#last = 0;
  }

  // One Euler step, the walls elastic.
  #moveCircles(dt) {
    for (const c of this.circleList) {
      c.x += c.vx * dt;
      c.y += c.vy * dt;
      if (Math.abs(c.x) > 1 - c.r) { c.vx = -Math.sign(c.x) * Math.abs(c.vx); c.x = Math.sign(c.x) * (1 - c.r); }
      if (Math.abs(c.y) > 1 - c.r) { c.vy = -Math.sign(c.y) * Math.abs(c.vy); c.y = Math.sign(c.y) * (1 - c.r); }
    }
  }

  #toBox(event) {
    const rect = this.#canvas.getBoundingClientRect();
    return [((event.clientX - rect.left) / rect.width) * 2 - 1, 1 - ((event.clientY - rect.top) / rect.height) * 2];
  }

  #grab(event) {
    const [x, y] = this.#toBox(event);
    const found = this.#circleAt(x, y);
    if (!found || this.hasAttribute('slice-of')) return;
    this.#drag = found;
    this.#canvas.setPointerCapture?.(event.pointerId);
  }

  // The circle under a point of the box (within a finger's width of a small one), or undefined.
  #circleAt(x, y) {
    const near = 12 / Math.max(1, this.#size) * 2;
    return this.circleList.find((c) => Math.hypot(c.x - x, c.y - y) < Math.max(c.r, near));
  }

  #move(event) {
    if (!this.#drag) return;
    const [x, y] = this.#toBox(event);
    this.#drag.x = Math.max(-1, Math.min(1, x));
    this.#drag.y = Math.max(-1, Math.min(1, y));
    this.#draw();
    this.dispatchEvent(new CustomEvent('metaballs-2d-drag', { detail: { circles: this.circleList }, bubbles: true, composed: true }));
  }
}

if (globalThis.customElements && !customElements.get('metaballs-2d')) {
  customElements.define('metaballs-2d', Metaballs2d);
}
