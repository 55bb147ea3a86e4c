// The march walked one square at a time, for the stepper: squares in order (row by row from the lower
// left), the square at each step with how its case is built bit by bit, and the segments drawn so far.
// No DOM: the 2D figure draws from it.

import { refusal } from '../i18n/words.js';

/** Square k of `cells` per axis, in the march's order. */
export const squareAt = (k, cells) => [k % cells, Math.floor(k / cells)];

/** The first step after `k` (or before, with `direction` -1) whose square the contour crosses, or -1. */
export function nextCrossed(cases, k, direction = 1) {
  for (let m = k + direction; m >= 0 && m < cases.length; m += direction) {
    if (cases[m] !== 0 && cases[m] !== 15) return m;
  }
  return -1;
}

/**
 * The case of a square with corner values `corners` at `iso`, built bit by bit: for each corner its
 * value, whether it is inside and the bit it adds; and the sum.
 */
export function caseBits(corners, iso) {
  const bits = corners.map((value, c) => ({ corner: c, value, inside: value > iso, bit: value > iso ? 1 << c : 0 }));
  return { bits, case: bits.reduce((sum, b) => sum + b.bit, 0) };
}

/** The segments of every square before step `k` (`march`'s `square`), as point pairs: the contour so far. */
export function segmentsBefore(result, cells, k) {
  const out = [];
  for (let m = 0; m < k; m += 1) {
    const c = result.cases[m];
    if (c === 0 || c === 15) continue;
    for (const segment of result.square(...squareAt(m, cells)).segments) out.push(segment.points);
  }
  return out;
}

/**
 * The step `march` names on a grid of `cells` per axis: a square `i,j`, a step number, or the first
 * square for empty text. Throws an Error saying what is accepted (a refusal, i18n/words.js: its `code`
 * and `fields` word it in a figure's language).
 */
export function readStep(text, cells) {
  const parts = text.split(',').map((t) => t.trim()).filter(Boolean).map(Number);
  const k = parts.length === 0 ? 0 : parts.length === 1 ? parts[0] : parts[1] * cells + parts[0];
  const inGrid = parts.length < 2 || parts.every((v) => v >= 0 && v < cells);
  if (!parts.every(Number.isInteger) || parts.length > 2 || !inGrid || k < 0 || k > cells * cells) {
    throw refusal(`march: "${text}" is not a square i,j of the ${cells} × ${cells} grid, nor a step from 0 to ${cells * cells}`,
      'plane-march-square', { text, cells, steps: cells * cells });
  }
  return k;
}

/** A step-through's play: while playing, how many steps `dt` seconds make at `speed` steps a second. */
export class Playhead {
  playing = false;
  speed = 4;
  #carry = 0;

  toggle() {
    this.playing = !this.playing;
    this.#carry = 0;
  }

  /** The whole steps `dt` more seconds of play make (none while paused); the rest is carried. */
  steps(dt) {
    if (!this.playing) return 0;
    this.#carry += dt * this.speed;
    const whole = Math.floor(this.#carry);
    this.#carry -= whole;
    return whole;
  }
}
