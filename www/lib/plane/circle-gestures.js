// The 2D figure's circles by hand: drag one to move it, double-click empty space to add one and a circle
// to remove it. The figure hands in its canvas and circles; each edit ends in `edited()` (the figure
// writes its `circles` attribute) and each move in `moved()` (it draws).

import { addOrRemove, circleAt } from './circles.js';

export class CircleGestures {
  /** The circle being dragged, or null. */
  dragged = null;
  #canvas;
  #figure;

  /**
   * `figure`: `{ circles(), size() (the picture's side in pixels), locked() (no edits: a followed
   * slice), moved(), edited(), refused() (the last circle stays) }`.
   */
  constructor(canvas, figure) {
    this.#canvas = canvas;
    this.#figure = figure;
    canvas.addEventListener('pointerdown', (e) => this.#grab(e));
    canvas.addEventListener('pointermove', (e) => this.#move(e));
    for (const end of ['pointerup', 'pointercancel']) canvas.addEventListener(end, () => this.#drop());
    canvas.addEventListener('dblclick', (e) => this.#addOrRemove(e));
  }

  // The pointer in the box [-1, 1]², y up.
  #toBox(event) {
    const rect = this.#canvas.getBoundingClientRect();
    return [((event.clientX - rect.left) / rect.width) * 2 - 1, 1 - ((event.clientY - rect.top) / rect.height) * 2];
  }

  // A finger's width (12 pixels) in the box's units: a small circle is found within it.
  #near() { return 24 / Math.max(1, this.#figure.size()); }

  #grab(event) {
    const [x, y] = this.#toBox(event);
    const found = circleAt(this.#figure.circles(), x, y, this.#near());
    if (!found || this.#figure.locked()) return;
    this.dragged = found;
    this.#canvas.setPointerCapture?.(event.pointerId);
  }

  #move(event) {
    if (!this.dragged) return;
    const [x, y] = this.#toBox(event);
    this.dragged.x = Math.max(-1, Math.min(1, x));
    this.dragged.y = Math.max(-1, Math.min(1, y));
    this.#figure.moved();
  }

  #drop() {
    if (this.dragged) this.#figure.edited();
    this.dragged = null;
  }

  // A double-click adds a circle where there is none, and removes the one under the pointer.
  #addOrRemove(event) {
    if (this.#figure.locked()) return;
    const [x, y] = this.#toBox(event);
    if (addOrRemove(this.#figure.circles(), x, y, this.#near())) this.#figure.edited();
    else this.#figure.refused();
  }
}
