// The 2D figure's scene files: its circles and every setting of its picture as a small versioned JSON
// document, read whole and checked whole before anything changes, with one message naming what is
// wrong.
//
//   { "format": "metaballs-2d-scene", "version": 1,
//     "circles": [ { "center": [0.3, 0.1], "radius": 0.35 } ],
//     "settings": { "iso": 1.2, "resolution": 12, "saddle": "decider" } }

import { PlaneCircles, PlaneInside } from './plane-circles.js';

export const FORMAT = 'metaballs-2d-scene';
export const VERSION = 1;
// A document this long holds far more circles than a figure draws.
const MAX_CHARACTERS = 1 << 20;

/** The document for `circles` and `settings` (name → value in effect, for the rows a scene holds). */
export function writeScene(circles, settings) {
  const round = (v) => Math.round(v * 1e6) / 1e6;
  return `${JSON.stringify({
    format: FORMAT,
    version: VERSION,
    circles: circles.map((c) => ({ center: [round(c.x), round(c.y)], radius: round(c.r), ...(c.charge < 0 ? { charge: -1 } : {}) })),
    settings,
  }, null, 2)}\n`;
}

/**
 * Reads a document: `{ circles: 'x,y,r;…' text, settings: [[name, text]] }`, each setting (by any of
 * its spellings: `canonical(spelling)` gives its name) checked by `check(name, text)` (which throws with
 * what is accepted) among the names `names` a scene holds. Throws an Error saying what is wrong.
 */
export function readScene(text, names, check, canonical = (name) => name) {
  if (String(text).length > MAX_CHARACTERS) throw new Error('the file is too long for a scene document');
  let doc;
  try {
    doc = JSON.parse(text);
  } catch (error) {
    throw new Error(`the file is not JSON (${error.message})`);
  }
  if (doc?.format !== FORMAT) throw new Error(`format must be "${FORMAT}", got ${JSON.stringify(doc?.format ?? null)}`);
  if (doc.version !== VERSION) throw new Error(`version ${JSON.stringify(doc.version)} is not one this figure reads (${VERSION})`);
  if (!Array.isArray(doc.circles) || doc.circles.length === 0) throw new Error('circles must be a list of at least one circle');
  const circles = doc.circles.map((c, i) => {
    const field = `circles[${i}]`;
    const [x, y] = Array.isArray(c?.center) && c.center.length === 2 ? c.center : [NaN, NaN];
    if (![x, y, c?.radius].every(Number.isFinite)) throw new Error(`${field} must have a center [x, y] and a radius, as numbers`);
    if (Math.abs(x) > 1 || Math.abs(y) > 1) throw new Error(`${field}.center (${x}, ${y}) is outside the box [-1, 1]²`);
    if (!(c.radius > 0)) throw new Error(`${field}.radius must be above 0, got ${c.radius}`);
    return `${x},${y},${c.charge === -1 ? -c.radius : c.radius}`;
  }).join(';');
  const settings = Object.entries(doc.settings ?? {}).map(([spelling, value]) => {
    const name = canonical(spelling);
    if (!names.includes(name)) throw new Error(`settings.${spelling}: not a setting a scene holds (${names.join(', ')})`);
    const written = Array.isArray(value) ? value.join(',') : String(value);
    try {
      check(name, written);
    } catch (error) {
      throw new Error(`settings.${error.message}`);
    }
    return [name, written];
  });
  return { circles, settings };
}

/** Downloads `text` as a JSON file called `name`. */
export function download(text, name) {
  const link = document.createElement('a');
  link.href = URL.createObjectURL(new Blob([text], { type: 'application/json' }));
  link.download = name;
  link.click();
  setTimeout(() => URL.revokeObjectURL(link.href), 1000);
}

/**
 * The 2D figure's scene files as a feature: saved from the circles and the settings in effect (the
 * `save-scene` action downloads the document), loaded whole or not at all.
 */
export class PlaneScene {
  #ctx;

  constructor(ctx) {
    this.#ctx = ctx;
    ctx.actions['save-scene'] = () => download(this.save(), 'metaballs-2d-scene.json');
  }

  /** The settings a scene document holds (beside the circles). */
  get names() {
    return this.#ctx.settings.rows.rows.filter((row) => row.scene && row.name !== 'circles').map((row) => row.name);
  }

  /** The circles and every setting of the picture, as the scene document (JSON text). */
  save() {
    const circles = this.#ctx.get(PlaneCircles).list;
    const s = this.#ctx.state;
    const value = (name) => (name === 'iso-levels' ? (s[name] ? s[name].split(',').map(Number) : []) : s[name]);
    return writeScene(circles, Object.fromEntries(this.names.map((name) => [name, value(name)])));
  }

  /** Loads a scene document; throws with what is wrong, changing nothing. */
  load(text) {
    const setText = (name, value) => this.#ctx.get(PlaneInside).setText(name, value);
    const settings = this.#ctx.settings;
    const check = (name, written) => {
      try {
        settings.read(name, written);
      } catch (error) {
        throw new Error(`${name}: ${error.message}`);
      }
    };
    const read = readScene(text, this.names, check, (spelling) => settings.rows.canonical(spelling));
    setText('circles', read.circles);
    for (const [name, written] of read.settings) setText(name, written);
  }

  /** Loads the file chosen in `input`; a bad one is refused with a notice. */
  async loadFile(input) {
    const file = input.files?.[0];
    input.value = '';
    try {
      if (file) this.load(await file.text());
    } catch (error) {
      this.#ctx.notice(`${file.name}: ${error.message}; the scene is unchanged`);
    }
  }
}
