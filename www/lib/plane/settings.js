// The 2D figure's settings read from text, as the parameter table reads them where the 2D and 3D
// figures share a setting (a number in its range, a word among its words, a flag), and the figure's
// own: circles, further levels, what to show; and the circles a seed gives. The table's row is handed
// in, so nothing here imports the table.

import { DEFAULT_SHOWN, SHOWN } from './picture.js';

// A small seeded generator (xorshift), so a seed gives the same circles.
function random(seed) {
  let s = (seed >>> 0) || 1;
  return () => {
    s ^= s << 13; s >>>= 0;
    s ^= s >>> 17;
    s ^= s << 5; s >>>= 0;
    return s / 2 ** 32;
  };
}

/** `count` circles from `seed`, inside the box, each with a velocity. */
export function seededCircles(seed, count) {
  const rng = random(seed * 2654435761 + 1);
  return Array.from({ length: count }, () => {
    const r = 0.1 + rng() * 0.14;
    return {
      x: (rng() * 2 - 1) * (0.9 - r), y: (rng() * 2 - 1) * (0.9 - r), r, charge: 1,
      vx: (rng() - 0.5) * 0.5, vy: (rng() - 0.5) * 0.5,
    };
  });
}

/** Circles from text `x,y,r;…` (a negative r subtracts); throws an Error saying what is accepted. */
export function parseCircles(text) {
  const circles = String(text).split(';').map((s) => s.trim()).filter(Boolean).map((part) => {
    const numbers = part.split(',').map((s) => Number(s.trim()));
    if (numbers.length !== 3 || numbers.some((v) => !Number.isFinite(v)) || numbers[2] === 0) {
      throw new Error(`circles: "${part}" is not x,y,r (three numbers, r not 0)`);
    }
    const [x, y, r] = numbers;
    if (Math.abs(x) > 1 || Math.abs(y) > 1) throw new Error(`circles: (${x}, ${y}) is outside the box [-1, 1]²`);
    return { x, y, r: Math.abs(r), charge: Math.sign(r), vx: 0, vy: 0 };
  });
  if (circles.length === 0) throw new Error('circles: give at least one circle as x,y,r');
  return circles;
}

/** Circles as `circles` reads them (three decimals; a subtracting circle with a negative radius). */
export function circlesText(circles) {
  const n = (v) => String(Math.round(v * 1000) / 1000);
  return circles.map((c) => [c.x, c.y, c.r * (c.charge < 0 ? -1 : 1)].map(n).join(',')).join(';');
}

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

/** Words of `show` (comma list of `SHOWN`), or the defaults for an empty text. */
export function readShown(text) {
  const words = String(text).split(',').map((s) => s.trim()).filter(Boolean);
  const unknown = words.filter((w) => !SHOWN.includes(w));
  if (unknown.length) throw new Error(`show: ${unknown.join(', ')} is not one of ${SHOWN.join(', ')}`);
  return words.length ? words : DEFAULT_SHOWN;
}

/** Further iso levels (comma list), each in the range of `isoRow` (the iso level's row). */
export function readLevels(text, isoRow) {
  return String(text).split(',').map((s) => s.trim()).filter(Boolean).map((s) => readSetting(isoRow, s));
}

