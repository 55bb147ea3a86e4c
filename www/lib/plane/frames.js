// The 2D figure's frames: what is sampled (its circles, or a followed 3D figure's slice plane), the
// picture drawn on the canvas at the device's pixel ratio, and the animation (circles moving, the
// step-through playing, a followed figure watched); each frame drawn is told to the features (`drawn`).

import { paint, picture, SHOWN, toSvg } from './picture.js';
import { moveCircles } from './circles.js';
import { followed, sliceKey, sliceSource } from './slice-source.js';
import { sampleField } from './squares.js';

/** What `show` holds, as the list of things drawn. */
export function shownList(text) {
  return text === 'all' ? SHOWN : text === 'none' ? [] : text.split(',');
}

/** The further iso levels `iso-levels` holds, as numbers. */
export const levelList = (text) => (text ? text.split(',').map(Number) : []);

export class PlaneFrames {
  /** The last frame's time to sample, march and paint, in ms. */
  frameMs = 0;
  /** The last march drawn. */
  result = null;
  /** True while a recording moves the circles itself: the figure's own animation holds still. */
  held = false;
  #ctx;
  #frame = 0;
  #last = 0;
  #size = 0;
  // What a followed figure's samples depended on when last drawn (undefined: draw on the next frame).
  #lastFollowed = null;

  /** `ctx`: the figure's context; `parts`: `{ circles, stepper, dragged() }`. */
  constructor(ctx, parts) {
    this.#ctx = ctx;
    this.parts = parts;
  }

  get size() { return this.#size; }

  /** The <metaballs-view> whose slice plane the figure follows (`slice-of`), or null. */
  get following() { return followed(this.#ctx.element, this.#ctx.state['slice-of']); }

  /** The iso level drawn: the figure's, or the followed figure's. */
  get iso() { return this.following ? Number(this.following.iso) : this.#ctx.state.iso; }

  /** Squares per axis of the grid drawn: the figure's, or the followed figure's. */
  get cells() {
    const view = this.following;
    return view ? Number(view.resolution) : this.#ctx.state.resolution;
  }

  /** What is sampled: `{ values, cells, iso, options, circles }`. */
  source() {
    const s = this.#ctx.state;
    const view = this.following;
    if (view) return sliceSource(view);
    const circles = this.parts.circles.list;
    return {
      values: sampleField(circles, s.resolution, s.kernel, Number(s.blobbiness)), cells: s.resolution, iso: s.iso,
      options: { placement: s.interpolation, saddle: s.saddle }, circles,
    };
  }

  /** The picture at `size` CSS pixels, its labels in the figure's language: `{ shapes, result }`. */
  picture(size) {
    const s = this.#ctx.state;
    const { values, cells, iso, options, circles } = this.source();
    return picture({
      values, cells, iso, levels: levelList(s['iso-levels']), circles, shown: shownList(s.show), options, size,
      theme: s.theme, step: this.parts.stepper.step, words: this.#ctx.words,
    });
  }

  /** The picture as an SVG document. */
  svg(size) {
    const canvas = this.#ctx.canvas;
    return toSvg(this.picture(size).shapes, size, this.#ctx.state.alt || canvas.getAttribute('aria-label'));
  }

  /** Draws the picture now, at the canvas's size; returns the march. */
  draw() {
    const start = performance.now();
    const canvas = this.#ctx.canvas;
    const box = canvas.parentElement.getBoundingClientRect();
    const size = Math.max(1, Math.round(Math.min(box.width, box.height || box.width)));
    const pixels = Math.round(size * (globalThis.devicePixelRatio || 1));
    if (canvas.width !== pixels) canvas.width = canvas.height = pixels;
    this.#size = size;
    const { shapes, result } = this.picture(size);
    paint(canvas.getContext('2d'), shapes, pixels / size);
    this.result = result;
    this.parts.stepper.show(result, this.iso);
    this.frameMs = performance.now() - start;
    return result;
  }

  /** Something changed: the next animation frame draws. */
  redraw() {
    this.#lastFollowed = undefined;
    this.#request();
  }

  #request() {
    if (!this.#ctx.element.isConnected || this.#frame) return;
    this.#frame = requestAnimationFrame((now) => this.#tick(now));
  }

  #tick(now) {
    this.#frame = 0;
    const s = this.#ctx.state;
    const dt = this.#last ? Math.min(0.05, (now - this.#last) / 1000) : 0;
    this.#last = now;
    const stepper = this.parts.stepper;
    // While the step-through is open the circles hold still, and a playing step-through advances.
    const moving = !s.paused && !this.held && !this.parts.dragged() && stepper.step === null && !s['slice-of'];
    if (moving) moveCircles(this.parts.circles.list, dt * s.speed);
    stepper.advance(dt);
    // A figure following a 3D figure's slice looks every frame (its spheres move), and draws when what
    // it samples has changed.
    const view = this.following;
    const key = view ? sliceKey(view) : null;
    const changing = moving || stepper.playing;
    const drawing = changing || key !== this.#lastFollowed;
    if (drawing) this.draw();
    this.#lastFollowed = key;
    if (changing || s['slice-of']) this.#request();
    else this.#last = 0;
    if (drawing) this.#ctx.each('drawn', now, { changing });
  }

  /** Starts drawing (the element was connected). */
  start() { this.redraw(); }

  /** Stops drawing (the element was disconnected). */
  stop() {
    cancelAnimationFrame(this.#frame);
    this.#frame = 0;
  }
}

/**
 * The 2D figure in print: its picture as vector art in place of the canvas, made once a changed
 * picture has settled (the figure still) and again before printing.
 */
export class PlanePrint {
  #ctx;
  #timer = 0;

  constructor(ctx) { this.#ctx = ctx; }

  #make = () => {
    const print = this.#ctx.root.querySelector('.print');
    print.innerHTML = this.#ctx.frames.svg(Math.max(1, this.#ctx.frames.size));
    print.firstElementChild?.setAttribute('aria-hidden', 'true');
  };

  connected() { globalThis.addEventListener('beforeprint', this.#make); }

  disconnected() {
    globalThis.removeEventListener('beforeprint', this.#make);
    clearTimeout(this.#timer);
  }

  drawn(_now, { changing }) {
    clearTimeout(this.#timer);
    if (!changing) this.#timer = setTimeout(this.#make, 300);
  }
}
