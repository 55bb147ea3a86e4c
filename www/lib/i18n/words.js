// The words a figure shows, in its reader's language. Every word is a message of a catalogue, found by
// a stable key: `setting.<name>`, `noun.<name>`, `group.<group>`, `word.<name>.<word>`, `action.<name>`
// derived from the parameter table (English made from the table here, so a new row has its keys with
// no line of its own), and the figure's own messages by code (English in www/lib/i18n/en/). The
// shipped languages load on demand, one module each (a reader downloads only theirs); a page adds a
// language or overrides a word with `registerTranslation`. A key missing from a catalogue falls back key
// by key: the language and region asked for, the language, English.
//
// A message is a string with `{field}` placeholders, or, where it counts something, an object of
// plural forms (`zero`, `one`, `two`, `few`, `many`, `other`) chosen by `Intl.PluralRules` from its
// `count` field. Number fields are written with `Intl.NumberFormat`, list fields with
// `Intl.ListFormat`; text fields as given (a value typed is echoed as typed). What machines read
// (attributes, links, scene files, exports) is never worded here.

import { CONTROLS, PLANE_TABLE, TABLE } from '../attributes.js';
import CODE_MESSAGES from './en/index.js';

/** The languages shipped with the figures (besides English), each loaded when a reader needs it. */
export const SHIPPED = Object.freeze({
  de: () => import('./de/index.js'),
  es: () => import('./es/index.js'),
  fr: () => import('./fr/index.js'),
  'pt-BR': () => import('./pt-BR/index.js'),
  'zh-CN': () => import('./zh-CN/index.js'),
  ja: () => import('./ja/index.js'),
  ar: () => import('./ar/index.js'),
});

// Languages written right to left, where `Intl.Locale`'s text info is missing.
const RIGHT_TO_LEFT = new Set(['ar', 'arc', 'ckb', 'dv', 'fa', 'he', 'ku', 'ps', 'sd', 'ug', 'ur', 'yi']);
// Unicode's isolates: a number or a typed value keeps its own direction inside a sentence.
const LTR_ISOLATE = (text) => `\u2066${text}\u2069`;
const FIRST_STRONG_ISOLATE = (text) => `\u2068${text}\u2069`;

/**
 * A number a sentence writes whole, as the language writes numbers but without rounding or grouping:
 * the ends of a range a value was refused for (`exact(0.8766)`, `exact(4294967295)`).
 */
export class Exact {
  constructor(x) { this.x = Number(x); }
}
export const exact = (x) => new Exact(x);

/** The English message of every key the parameter tables give (labels, nouns, groups, words). */
export function tableMessages() {
  const messages = {};
  const words = (row, prefix) => {
    for (const word of row.words ?? []) messages[`${prefix}word.${row.name}.${word}`] = word.replace(/_/g, ' ');
  };
  for (const row of TABLE) {
    messages[`setting.${row.name}`] = row.label;
    messages[`noun.${row.name}`] = row.noun || row.name;
    if (row.group) messages[`group.${groupKey(row.group)}`] = row.group;
    if (row.kind !== 'controls') words(row, '');
  }
  for (const control of CONTROLS.filter((c) => !c.parameter)) messages[`action.${control.name}`] = control.label;
  // The 2D figure's rows share the 3D figure's keys where they say the same; else they have their own.
  for (const row of PLANE_TABLE) {
    const same = (key, text) => messages[key] === undefined || messages[key] === text;
    const label = same(`setting.${row.name}`, row.label) ? '' : 'plane.';
    messages[`${label}setting.${row.name}`] = row.label;
    const noun = same(`noun.${row.name}`, row.noun || row.name) ? '' : 'plane.';
    messages[`${noun}noun.${row.name}`] = row.noun || row.name;
    if (row.group) messages[`group.${groupKey(row.group)}`] = row.group;
    if (row.kind === 'controls') continue;
    for (const word of row.words ?? []) {
      const key = `word.${row.name}.${word}`;
      messages[same(key, word.replace(/_/g, ' ')) ? key : `plane.${key}`] = word.replace(/_/g, ' ');
    }
  }
  return messages;
}

/**
 * An Error with the table's English `message` (what the console, the events and Python say), the
 * refusal's `code` and its `fields`, from which a figure words it in its reader's language
 * (`Words.refusal`).
 */
export function refusal(message, code, fields) {
  return Object.assign(new Error(message), { code, fields });
}

/**
 * The key of `row`'s noun (the words a message names its setting by): `noun.<name>`, or
 * `plane.noun.<name>` for a 2D row whose noun differs from the 3D row's of the same name.
 */
export const nounKey = (row) => (EN[`noun.${row.name}`] === (row.noun || row.name) ? `noun.${row.name}` : `plane.noun.${row.name}`);

// Nouns of the Rust checks that name no row of the tables.
const OTHER_NOUNS = {
  'slice position': 'noun.slice-position',
  'sphere radius': 'noun.sphere-radius',
  resolution: 'noun.grid-resolution',
  'centre coordinate (inside the box for this radius)': 'noun.sphere-centre-inside',
  'sphere centre coordinate': 'noun.sphere-centre',
  velocity: 'noun.velocity',
  'sphere velocity': 'noun.sphere-velocity',
  'LOD coarsening': 'noun.lod-coarsening',
  'triangle budget': 'noun.triangle-budget',
};

/**
 * An Error of the WebAssembly whose message holds a refusal as its code and fields (`ParamError::coded`
 * in scene/src/checks.rs: joined by U+001F, after a place such as `spheres[0].radius: `) made as
 * core/read.js makes its refusals: the English message (for the console, the events and tests), `code`,
 * `fields` and the `place`. Other errors come back as they are.
 */
export function fromWasm(error) {
  const text = error?.message;
  if (typeof text !== 'string' || !text.includes('\u001f')) return error;
  const decoded = decode(text);
  return Object.assign(new Error(ENGLISH.refusal(decoded)), decoded);
}

function decode(text) {
  const first = text.indexOf('\u001f');
  const start = text.lastIndexOf(': ', first) + 1;
  const place = start > 0 ? text.slice(0, start + 1) : '';
  const [code, noun, value, a, b, c] = text.slice(start > 0 ? start + 1 : 0).split('\u001f');
  const row = [...TABLE, ...PLANE_TABLE].find((r) => r.noun && r.noun === noun);
  const fields = { noun, value };
  const key = row ? nounKey(row) : OTHER_NOUNS[noun];
  if (key) fields.nounKey = key;
  if (code === 'out-of-range') Object.assign(fields, { min: exact(a), max: exact(b) });
  if (code === 'device-limit') fields.detail = a;
  if (code === 'invalid') {
    fields.expected = a;
    Object.assign(fields, {
      whole: { min: exact(b), max: exact(c) },
      number: { min: exact(b), max: exact(c) },
      'one-of': { words: b },
      'list-of': { words: b },
      // A refusal inside the detail (a sphere's radius) keeps its fields apart with U+001E.
      spheres: { detail: b?.includes('\u001e') ? decode(b.replaceAll('\u001e', '\u001f')) : b },
      'lod-multiple': { block: Number(b) },
      'uniform-at-most': { max: exact(b), lodMax: exact(c) },
      text: { text: b },
    }[a]);
  }
  return { code, fields, place };
}

/** A panel group's key: its English name in lower case. */
export const groupKey = (group) => group.toLowerCase();

/** Every English message: the tables' and the code's, by key. */
export const EN = Object.freeze({ ...tableMessages(), ...CODE_MESSAGES });

// Catalogues by language tag in lower case: `shipped` as loaded, `registered` by pages.
const shipped = new Map([['en', EN]]);
const registered = new Map();
const loading = new Map();
const listeners = new Set();
let version = 0;

const lower = (tag) => String(tag).toLowerCase();
const shippedTag = (tag) => Object.keys(SHIPPED).find((name) => lower(name) === lower(tag));

/**
 * The catalogues tried for `lang`, nearest first: the tag, the tag without its region or script, the
 * shipped variant of that language (`pt` → `pt-BR`, `zh` → `zh-CN`, but not for Traditional Chinese),
 * English.
 */
export function chainOf(lang) {
  const chain = [];
  const add = (tag) => { if (tag && !chain.includes(lower(tag))) chain.push(lower(tag)); };
  let tag = lang;
  try { tag = Intl.getCanonicalLocales(lang)[0] ?? 'en'; } catch { tag = 'en'; }
  add(tag);
  const parts = tag.split('-');
  for (let n = parts.length - 1; n >= 1; n -= 1) add(parts.slice(0, n).join('-'));
  const base = parts[0];
  const traditional = base === 'zh' && /-(hant|tw|hk|mo)\b/i.test(tag);
  const variant = Object.keys(SHIPPED).find((name) => name.split('-')[0] === base);
  if (variant && !traditional) add(variant);
  add('en');
  return chain;
}

/**
 * Adds the messages of `lang` (a language tag such as `de`, `pt-BR` or `nl`) or overrides some of them:
 * `messages` maps keys to strings or to plural forms. Figures on the page show them at once.
 */
export function registerTranslation(lang, messages) {
  if (typeof lang !== 'string' || !lang) throw new TypeError('registerTranslation(lang, messages): lang must be a language tag such as "nl"');
  if (!messages || typeof messages !== 'object') throw new TypeError('registerTranslation(lang, messages): messages must be an object of key → text');
  for (const [key, message] of Object.entries(messages)) {
    const ok = typeof message === 'string'
      || (message && typeof message === 'object' && typeof message.other === 'string');
    if (!ok) throw new TypeError(`registerTranslation: "${key}" must be a text, or plural forms with at least "other"`);
  }
  const tag = lower(lang);
  registered.set(tag, { ...registered.get(tag), ...messages });
  changed();
}

/** Calls `listener()` whenever a catalogue arrives or is registered (returns a function that stops it). */
export function onCatalogues(listener) {
  listeners.add(listener);
  return () => listeners.delete(listener);
}

/** A number that changes whenever a catalogue arrives or is registered. */
export const catalogueVersion = () => version;

function changed() {
  version += 1;
  for (const listener of [...listeners]) listener();
}

/** Starts loading the shipped catalogues `lang` falls back through (once each); resolves when they are in. */
export function loadLanguage(lang) {
  const pending = [];
  for (const tag of chainOf(lang)) {
    const name = shippedTag(tag);
    if (!name || shipped.has(tag)) continue;
    if (!loading.has(tag)) {
      loading.set(tag, SHIPPED[name]().then((module) => {
        shipped.set(tag, module.default);
        changed();
      }, (error) => console.warn(`metaballs: the ${name} words could not load (${error?.message ?? error}); English is shown`)));
    }
    pending.push(loading.get(tag));
  }
  return Promise.all(pending);
}

/** The words of one language: `t(key, fields)` and the formats of numbers and lists. */
export class Words {
  #formats = new Map();

  constructor(lang = 'en', dir = directionOfLanguage(lang)) {
    this.lang = lang;
    this.dir = dir;
    this.chain = chainOf(lang);
    /** Changes whenever a catalogue arrives or is registered (a figure compares it to reword). */
    this.version = version;
    this.plurals = new Intl.PluralRules(this.chain[0]);
  }

  /** The message of `key` nearest this language, or undefined. */
  message(key) {
    for (const tag of this.chain) {
      const own = registered.get(tag)?.[key] ?? shipped.get(tag)?.[key];
      if (own !== undefined) return own;
    }
    return undefined;
  }

  /** True where some catalogue has `key`. */
  has(key) { return this.message(key) !== undefined; }

  /** Message `key` worded with `fields`; the key itself where no catalogue has it. */
  t(key, fields = {}) {
    let message = this.message(key);
    if (message === undefined) return key;
    if (typeof message === 'object') {
      const count = Number(fields.count ?? 0);
      message = message[this.plurals.select(count)] ?? message.other;
    }
    return message.replace(/\{([a-zA-Z0-9_]+)\}/g, (whole, name) => (
      Object.hasOwn(fields, name) ? this.field(fields[name]) : whole));
  }

  /**
   * A refused value's message in this language: from the Error's `code` and `fields` (core/read.js,
   * the WebAssembly's refusals), else its English message.
   */
  refusal(error) {
    const message = error?.message;
    const coded = typeof error?.code === 'string' && this.has(`refused.${error.code}`);
    if (!coded && typeof message === 'string' && message.includes('\u001f')) return this.refusal(decode(message));
    if (!coded) return message ?? String(error);
    const fields = { ...error.fields };
    if (fields.nounKey) fields.noun = this.t(fields.nounKey);
    if (typeof fields.detail === 'object') fields.detail = this.refusal(fields.detail);
    if (fields.expected) fields.expected = this.t(`expected.${fields.expected}`, fields);
    return `${error.place ?? ''}${this.t(`refused.${error.code}`, fields)}`;
  }

  /** A field as a sentence shows it: numbers and lists formatted, text as given. */
  field(value) {
    if (value instanceof Exact) return this.field(this.#format('exact', () => new Intl.NumberFormat(this.chain[0], {
      maximumFractionDigits: 20, useGrouping: false })).format(value.x));
    if (typeof value === 'number') return this.rtl ? LTR_ISOLATE(this.number(value)) : this.number(value);
    if (Array.isArray(value)) return this.list(value.map((v) => this.field(v)));
    const text = String(value);
    return this.rtl ? FIRST_STRONG_ISOLATE(text) : text;
  }

  get rtl() { return this.dir === 'rtl'; }

  /** `x` written for the reader, with at most `digits` decimals (3). */
  number(x, digits = 3) {
    if (!Number.isFinite(x)) return String(x);
    return this.#format(`n${digits}`, () => new Intl.NumberFormat(this.chain[0], { maximumFractionDigits: digits, useGrouping: 'min2' })).format(x);
  }

  /** `x` written with exactly `digits` decimals. */
  fixed(x, digits) {
    if (!Number.isFinite(x)) return String(x);
    return this.#format(`f${digits}`, () => new Intl.NumberFormat(this.chain[0], {
      minimumFractionDigits: digits, maximumFractionDigits: digits })).format(x);
  }

  /** `x` as a percentage with `digits` decimals. */
  percent(x, digits = 0) {
    return this.#format(`p${digits}`, () => new Intl.NumberFormat(this.chain[0], {
      style: 'percent', minimumFractionDigits: digits, maximumFractionDigits: digits })).format(x);
  }

  /** `items` joined as the language joins a list (`type`: conjunction or disjunction). */
  list(items, type = 'conjunction') {
    return this.#format(`l${type}`, () => new Intl.ListFormat(this.chain[0], { type })).format(items.map(String));
  }

  #format(key, make) {
    if (!this.#formats.has(key)) this.#formats.set(key, make());
    return this.#formats.get(key);
  }
}

/** The English words, for what the console, the events and the page's code are told. */
export const ENGLISH = new Words('en', 'ltr');

/** `ltr` or `rtl`: the direction `lang` is written in. */
export function directionOfLanguage(lang) {
  try {
    const locale = new Intl.Locale(lang);
    const info = locale.getTextInfo?.() ?? locale.textInfo;
    if (info?.direction) return info.direction;
    return RIGHT_TO_LEFT.has(locale.language) ? 'rtl' : 'ltr';
  } catch {
    return 'ltr';
  }
}

/** Sets the words of every `[data-t]` (text), `[data-t-label]` (aria-label) and `[data-t-title]` under `root`. */
export function relabel(root, words) {
  for (const node of root.querySelectorAll('[data-t], [data-t-label], [data-t-title]')) word(node, words);
}

// Sets `node`'s own marked words.
function word(node, words) {
  const { t, tLabel, tTitle } = node.dataset;
  if (t) node.textContent = words.t(t);
  if (tLabel) node.setAttribute('aria-label', words.t(tLabel));
  if (tTitle) node.title = words.t(tTitle);
}

/**
 * Marks `node`'s words by key (`text`, `label`: its aria-label, `title`) for `relabel` to set in each
 * language, and sets them now in `words` where given; returns `node`.
 */
export function mark(node, { text, label, title } = {}, words = null) {
  if (text) node.dataset.t = text;
  if (label) node.dataset.tLabel = label;
  if (title) node.dataset.tTitle = title;
  if (words) word(node, words);
  return node;
}
