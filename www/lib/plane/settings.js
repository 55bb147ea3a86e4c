// The 2D figure's settings read from text, as its rows of the parameter table say (a number in its
// range, a word among its words, a flag), and further levels and what to show. The row is handed in.

import { DEFAULT_SHOWN, SHOWN } from './picture.js';

/** A setting read as the parameter table's `row` reads it: a number in range, a word among the row's, a flag. */
export function readSetting(row, text) {
  const name = row.name;
  if (row.kind === 'number' || row.kind === 'integer') {
    const value = Number(text);
    if (!Number.isFinite(value) || value < row.min || value > row.max || (row.kind === 'integer' && !Number.isInteger(value))) {
      throw new Error(`${name}: "${text}" is not ${row.kind === 'integer' ? 'a whole number' : 'a number'} from ${row.min} to ${row.max}`);
    }
    return value;
  }
  if (row.kind === 'boolean') return text !== 'false' && text !== '0' && text !== 'off';
  if (row.kind === 'choice') {
    const word = String(text).trim().toLowerCase();
    if (!row.words.includes(word)) throw new Error(`${name}: "${text}" is not one of ${row.words.join(', ')}`);
    return word;
  }
  return String(text);
}

/** Words of `show`: `all`, `none`, or a comma list of `SHOWN`; the defaults for an empty text. */
export function readShown(text) {
  const list = String(text).trim().toLowerCase();
  if (list === 'all') return SHOWN;
  if (list === 'none') return [];
  const words = list.split(',').map((s) => s.trim()).filter(Boolean);
  const unknown = words.filter((w) => !SHOWN.includes(w));
  if (unknown.length) throw new Error(`show: ${unknown.join(', ')} is not one of ${SHOWN.join(', ')}`);
  return words.length ? words : DEFAULT_SHOWN;
}

/** Further iso levels (comma list), each in the range of `isoRow` (the iso level's row). */
export function readLevels(text, isoRow) {
  return String(text).split(',').map((s) => s.trim()).filter(Boolean).map((s) => readSetting(isoRow, s));
}

