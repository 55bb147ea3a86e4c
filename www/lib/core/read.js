// A setting's text read as its row of the parameter table says, without the WebAssembly: numbers,
// whole numbers, flags, colours, words, lists, further levels and free text, for both figures. It reads
// as the Rust table's parser (`Parameter::parse`, scene/src/params/parse.rs) reads: the same texts are
// accepted, with the same values, and the others refused with the same message. `metaballs manifest`
// writes that parser's answers for hostile texts into www/parameter-vectors.json, and
// tests/e2e/read.test.js holds this module to every one of them (python/tests the notebook's reader).
// Slices, cells and sphere lists have grammars of their own: `readsInJavaScript(row)` is false for them.

import { exact, nounKey, refusal } from '../i18n/words.js';

/** True for the rows this module reads (the others go to the table's parser in the WebAssembly). */
export const readsInJavaScript = (row) => !['slice', 'cell', 'spheres'].includes(row.kind);

/**
 * Reads `text` as `row`'s value: a number, true or false, or normalised text. Throws an Error with the
 * table's message (naming the parameter by `given`, the spelling it was given by, where the row has no
 * noun of its own).
 */
export function readValue(row, text, given = row.name) {
  const noun = row.noun || given;
  const trimmed = trim(text);
  const invalid = (expected, code, fields = {}) => refusal(`${noun} must be ${expected}, got ${quoted(text)}`,
    'invalid', { ...nounOf(row, noun), value: quoted(text), expected: code, ...fields });
  switch (row.kind) {
    case 'integer': {
      const expected = `a whole number from ${f64Text(row.min)} to ${f64Text(row.max)}`;
      if (!/^[0-9]+$/.test(trimmed)) throw invalid(expected, 'whole', { min: exact(row.min), max: exact(row.max) });
      return inRange(row, noun, Number(trimmed), row.min, row.max, f64Text);
    }
    case 'number':
      return readNumber(row, noun, trimmed, text);
    case 'boolean': {
      const word = asciiLower(trimmed);
      if (['', '1', 'true', 'on', 'yes'].includes(word)) return true;
      if (['0', 'false', 'off', 'no'].includes(word)) return false;
      throw invalid('true or false (also 1/0, on/off)', 'flag');
    }
    case 'color': {
      const hex = trimmed.startsWith('#') ? trimmed.slice(1) : trimmed;
      if (/^[0-9a-fA-F]{6}$/.test(hex)) return `#${asciiLower(hex)}`;
      throw invalid('a colour written #rrggbb', 'colour');
    }
    case 'choice': {
      const word = asciiLower(trimmed);
      if (row.words.includes(word)) return word;
      throw invalid(`one of ${row.words.join(', ')}`, 'one-of', { words: row.words.join(', ') });
    }
    case 'list': {
      const list = asciiLower(trimmed);
      if (list === 'all' || list === 'none') return list;
      const older = row.wordAliases ?? {};
      const items = list.split(',').map(trim).filter(Boolean).map((item) => (Object.hasOwn(older, item) ? older[item] : item));
      if (items.length === 0 || !items.every((item) => row.words.includes(item))) {
        throw invalid(`all, none, or a comma list of ${row.words.join(', ')}`, 'list-of', { words: row.words.join(', ') });
      }
      return items.join(',');
    }
    case 'levels':
      return trimmed.split(',').map(trim).filter(Boolean)
        .map((item) => f64Text(readNumber(row, noun, item, item))).join(',');
    case 'text':
      return String(text);
    default:
      throw new Error(`${noun}: a ${row.kind} is read by the figure's WebAssembly`);
  }
}

/** A number read as the renderer keeps it (an f32), held as that f32's shortest decimal. */
function readNumber(row, noun, trimmed, text) {
  const value = parseF64(trimmed);
  const named = nounOf(row, noun);
  if (value === null) {
    const [min, max] = [f32Text(row.min), f32Text(row.max)];
    throw refusal(`${noun} must be a number from ${min} to ${max}, got ${quoted(text)}`,
      'invalid', { ...named, value: quoted(text), expected: 'number', min: exact(min), max: exact(max) });
  }
  const single = Math.fround(value);
  if (Number.isNaN(single)) throw refusal(`${noun} must be a number, got NaN`, 'not-a-number', named);
  if (!Number.isFinite(single)) throw refusal(`${noun} must be finite, got infinity`, 'infinite', named);
  inRange(row, noun, single, Math.fround(row.min), Math.fround(row.max), f32Text);
  return Number(shortestF32(single));
}

function inRange(row, noun, value, min, max, written) {
  if (value < min || value > max) {
    throw refusal(`${noun} must be between ${written(min)} and ${written(max)}, got ${shortNumber(written(value))}`,
      'out-of-range', { ...nounOf(row, noun), min: exact(written(min)), max: exact(written(max)), value: shortNumber(written(value)) });
  }
  return value;
}


// The noun a refusal names its setting by: the row's, worded by key, or the spelling given (an
// attribute's name, kept as written).
const nounOf = (row, noun) => (row.noun ? { noun, nounKey: nounKey(row) } : { noun });

/** Text as Rust's `str::parse::<f64>` reads it (no spaces, no hexadecimal, `inf` and `nan` in any case), or null. */
export function parseF64(text) {
  const match = /^([+-]?)(?:(inf|infinity)|(nan)|((?:[0-9]+\.?[0-9]*|\.[0-9]+)(?:[eE][+-]?[0-9]+)?))$/i.exec(text);
  if (!match) return null;
  const magnitude = match[2] ? Infinity : match[3] ? NaN : Number.parseFloat(match[4]);
  return match[1] === '-' ? -magnitude : magnitude;
}

// Rust's `str::trim`: Unicode white space at both ends.
const trim = (text) => String(text).replace(/^\p{White_Space}+|\p{White_Space}+$/gu, '');

// Rust's `to_ascii_lowercase`: A–Z only.
const asciiLower = (text) => text.replace(/[A-Z]/g, (c) => c.toLowerCase());

/**
 * The shortest decimal that reads back as the f32 `x`, the nearest of that length where several do, as
 * Rust writes it (exponent form). The nearest decimal of a length may fall outside the f32's interval
 * where a neighbour does not (below a power of two the interval is half as wide), so the neighbours of
 * the nearest are tried too.
 */
function shortestF32(x) {
  if (x === 0) return Object.is(x, -0) ? '-0' : '0';
  for (let length = 1; length <= 9; length += 1) {
    const [mantissa, power] = x.toExponential(length - 1).split('e');
    const digits = Number(mantissa.replace('.', ''));
    const exponent = Number(power) - (length - 1);
    const candidates = [digits - 1, digits, digits + 1].map((d) => `${d}e${exponent}`)
      .filter((text) => Math.fround(Number(text)) === x);
    if (candidates.length) {
      return candidates.reduce((best, text) => (Math.abs(Number(text) - x) < Math.abs(Number(best) - x) ? text : best));
    }
  }
  return x.toExponential(8);
}

/** A decimal in exponent form written out in full, as Rust's `{}` writes floats. */
function plain(text) {
  const [, sign, whole, fraction = '', exponent = '0'] = /^(-?)([0-9]+)(?:\.([0-9]+))?(?:e([+-]?[0-9]+))?$/.exec(text);
  let digits = whole + fraction;
  let point = whole.length + Number(exponent);
  const leading = digits.length - digits.replace(/^0+/, '').length;
  digits = digits.slice(leading).replace(/0+$/, '');
  point -= leading;
  if (!digits) return `${sign}0`;
  if (point <= 0) return `${sign}0.${'0'.repeat(-point)}${digits}`;
  if (point >= digits.length) return `${sign}${digits}${'0'.repeat(point - digits.length)}`;
  return `${sign}${digits.slice(0, point)}.${digits.slice(point)}`;
}

// What Rust's `{}` writes for a value that is not a finite number.
const notFinite = (x) => (Number.isNaN(x) ? 'NaN' : x > 0 ? 'inf' : '-inf');

/** An f32 as Rust's `{}` writes it. */
export const f32Text = (x) => (Number.isFinite(x) ? plain(shortestF32(Math.fround(x))) : notFinite(x));

/** An f64 as Rust's `{}` writes it. */
export const f64Text = (x) => {
  if (!Number.isFinite(x)) return notFinite(x);
  return Object.is(x, -0) ? '-0' : plain(String(x));
};

// A number in a message: as written, or as Rust's `{:e}` writes it when its digits run long.
function shortNumber(text) {
  const x = parseF64(text);
  return x !== null && text.length > 24 ? x.toExponential().replace('e+', 'e') : text;
}

// Longest part of a given text a message repeats, in characters.
const SHOWN_CHARS = 40;

// Characters Rust's `{:?}` writes as `\u{…}`: controls, formats, separators (but the space), private
// use, unassigned, and marks that extend a grapheme.
const ESCAPED = /[\p{Cc}\p{Cf}\p{Co}\p{Cn}\p{Zl}\p{Zp}\p{Zs}\p{Cs}\p{Grapheme_Extend}]/u;
const SHORT = { '\t': '\\t', '\r': '\\r', '\n': '\\n', '\0': '\\0', '"': '\\"', '\\': '\\\\' };

/** `text` in quotes as Rust's `{:?}` writes it, cut short after 40 characters (with an ellipsis). */
export function quoted(text) {
  const chars = Array.from(String(text));
  const escaped = chars.slice(0, SHOWN_CHARS).map((c) => SHORT[c]
    ?? (c !== ' ' && ESCAPED.test(c) ? `\\u{${c.codePointAt(0).toString(16)}}` : c)).join('');
  return `"${escaped}"${chars.length > SHOWN_CHARS ? '…' : ''}`;
}
