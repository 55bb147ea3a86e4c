// A figure's settings as the parameter table defines them: the values in effect, the ones the renderer
// holds, the ones changed since the last frame, and which the author gave. Attributes are read through
// the table's parser (in the wasm) and written back without being taken in again. The table itself is
// a plain module, so the element knows its attributes and defaults before the wasm arrives.

import { parseParameter } from './engine.js';
import { TABLE } from './attributes.js';

export { TABLE };
export const NAMES = TABLE.map((p) => p.name);
export const CONTROL_NAMES = TABLE.find((p) => p.name === 'controls')?.words ?? [];
/** Attributes of plain text (a description, a URL): taken as written, even before the wasm arrives. */
export const TEXT_NAMES = new Set(TABLE.filter((p) => p.kind === 'text').map((p) => p.name));
// Settings a renderer takes at creation; every other renderer setting is applied after.
export const CREATION = new Set(['spheres', 'iso', 'resolution', 'seed', 'antialiasing']);

/** The default values of every parameter, typed. */
export function defaults() {
  return Object.fromEntries(TABLE.map((p) => [p.name, p.value]));
}

/** The default value of one parameter, typed. */
export function defaultOf(name) {
  return TABLE.find((p) => p.name === name).value;
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
    if (TEXT_NAMES.has(name)) return { value: text };
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
