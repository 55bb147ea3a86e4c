// A figure's settings as the parameter table defines them: the values in effect, the ones the renderer
// holds, the ones changed since the last frame, and which the author gave. Attributes are read through
// the table's parser and written back without being taken in again.

import { caseGallery, loadWasm, parameterTable, parseParameter } from './engine.js';

export const wasmError = await loadWasm().then(() => null, (error) => error);
export const TABLE = wasmError ? [] : parameterTable();
export const NAMES = TABLE.map((p) => p.name);
export const CONTROL_NAMES = TABLE.find((p) => p.name === 'controls')?.words ?? [];
export const GALLERY = wasmError ? { classes: [], cube: { corners: [], edges: [] } } : caseGallery();
// Settings a renderer takes at creation; every other renderer setting is applied after.
export const CREATION = new Set(['spheres', 'iso', 'resolution', 'seed', 'antialiasing']);

/** The default values of every parameter, typed. */
export function defaults() {
  return Object.fromEntries(TABLE.map((p) => [p.name, parseParameter(p.name, p.default)]));
}

/** The default value of one parameter, typed. */
export function defaultOf(name) {
  return parseParameter(name, TABLE.find((p) => p.name === name).default);
}

export class FigureState {
  /** The values in effect. */
  state = defaults();
  /** The values the renderer holds. */
  applied = { ...this.state };
  /** Names changed since the renderer last took them. */
  changed = new Set();
  /** Names the author or the person set (the others follow the adapter's defaults). */
  given = new Set();
  #element;
  #reflecting = false;

  constructor(element) {
    this.#element = element;
  }

  /** True while a value is being written back to its attribute (its callback must not take it in). */
  get reflecting() { return this.#reflecting; }

  /** Reads an attribute's text: `{ value }`, or `{ message }` saying what is wrong and what is kept. */
  parse(name, text) {
    try {
      return { value: parseParameter(name, text) };
    } catch (error) {
      return { message: `${name}="${text}": ${error.message}; keeping ${this.format(name)}` };
    }
  }

  /** The value in effect, as an attribute would show it. */
  format(name) {
    const value = this.state[name];
    return typeof value === 'string' ? `"${value}"` : String(value);
  }

  /** Writes a value to its attribute without taking it in again. */
  reflect(name, value = this.state[name]) {
    this.#reflecting = true;
    try {
      this.#element.setAttribute(name, String(value));
    } finally {
      this.#reflecting = false;
    }
  }
}
