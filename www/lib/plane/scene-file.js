// The 2D figure's scene files: its circles and every setting of its picture as a small versioned JSON
// document, read whole and checked whole before anything changes, with one message naming what is
// wrong.
//
//   { "format": "metaballs-2d-scene", "version": 1,
//     "circles": [ { "center": [0.3, 0.1], "radius": 0.35 } ],
//     "settings": { "iso": 1.2, "resolution": 12, "saddle": "decider" } }
//
// What is wrong is said in English to the page's code (the Error's message), and in the reader's
// language in the figure's notice (the Error is a refusal, i18n/words.js, with its code and fields).

import { refusal } from '../i18n/words.js';
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
 * What refusal `error` says in `words`' language: a refusal given as a field (what a setting's reader
 * said of its value) is worded in turn; an Error that is no refusal says its message.
 */
export function refusalIn(words, error) {
  if (!error?.code) return error?.message ?? String(error);
  const fields = {};
  for (const [name, value] of Object.entries(error.fields ?? {})) fields[name] = value instanceof Error ? refusalIn(words, value) : value;
  return words.refusal({ code: error.code, fields });
}

/**
 * Reads a document: `{ circles: 'x,y,r;…' text, settings: [[name, text]] }`, each setting (by any of
 * its spellings: `canonical(spelling)` gives its name) checked by `check(name, text)` (which throws with
 * what is accepted) among the names `names` a scene holds. Throws an Error saying what is wrong.
 */
export function readScene(text, names, check, canonical = (name) => name) {
  if (String(text).length > MAX_CHARACTERS) throw refusal('the file is too long for a scene document', 'plane-scene-long', {});
  let doc;
  try {
    doc = JSON.parse(text);
  } catch (error) {
    throw refusal(`the file is not JSON (${error.message})`, 'plane-scene-json', { detail: error.message });
  }
  if (doc?.format !== FORMAT) {
    const got = JSON.stringify(doc?.format ?? null);
    throw refusal(`format must be "${FORMAT}", got ${got}`, 'plane-scene-format', { format: FORMAT, got });
  }
  if (doc.version !== VERSION) {
    const version = JSON.stringify(doc.version);
    throw refusal(`version ${version} is not one this figure reads (${VERSION})`, 'plane-scene-version', { version, reads: String(VERSION) });
  }
  if (!Array.isArray(doc.circles) || doc.circles.length === 0) {
    throw refusal('circles must be a list of at least one circle', 'plane-scene-circles', {});
  }
  const circles = doc.circles.map((c, i) => {
    const field = `circles[${i}]`;
    const [x, y] = Array.isArray(c?.center) && c.center.length === 2 ? c.center : [NaN, NaN];
    if (![x, y, c?.radius].every(Number.isFinite)) {
      throw refusal(`${field} must have a center [x, y] and a radius, as numbers`, 'plane-scene-circle', { field });
    }
    if (Math.abs(x) > 1 || Math.abs(y) > 1) {
      throw refusal(`${field}.center (${x}, ${y}) is outside the box [-1, 1]²`, 'plane-scene-outside', { field, x: String(x), y: String(y) });
    }
    if (!(c.radius > 0)) throw refusal(`${field}.radius must be above 0, got ${c.radius}`, 'plane-scene-radius', { field, radius: String(c.radius) });
    return `${x},${y},${c.charge === -1 ? -c.radius : c.radius}`;
  }).join(';');
  const settings = Object.entries(doc.settings ?? {}).map(([spelling, value]) => {
    const name = canonical(spelling);
    if (!names.includes(name)) {
      throw refusal(`settings.${spelling}: not a setting a scene holds (${names.join(', ')})`, 'plane-scene-setting',
        { spelling, names: names.join(', ') });
    }
    const written = Array.isArray(value) ? value.join(',') : String(value);
    try {
      check(name, written);
    } catch (error) {
      throw refusal(`settings.${error.message}`, 'plane-scene-settings', { reason: error });
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
        throw refusal(`${name}: ${error.message}`, 'plane-scene-value', { name, reason: error });
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
      this.#ctx.notice(this.#ctx.t('plane.scene-refused', { name: file.name, reason: refusalIn(this.#ctx.words, error) }));
    }
  }
}
