// The 2D figure's circles: the ones a seed gives, read from and written as text (`x,y,r;…`), moved by
// one Euler step between elastic walls, and found under a point.

import { refusal } from '../i18n/words.js';

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

/**
 * Circles from text `x,y,r;…` (a negative r subtracts); throws an Error saying what is accepted (a
 * refusal, i18n/words.js, that a figure words in its reader's language).
 */
export function parseCircles(text) {
  const circles = String(text).split(';').map((s) => s.trim()).filter(Boolean).map((part) => {
    const numbers = part.split(',').map((s) => Number(s.trim()));
    if (numbers.length !== 3 || numbers.some((v) => !Number.isFinite(v)) || numbers[2] === 0) {
      throw refusal(`circles: "${part}" is not x,y,r (three numbers, r not 0)`, 'plane-circle', { part });
    }
    const [x, y, r] = numbers;
    if (Math.abs(x) > 1 || Math.abs(y) > 1) {
      throw refusal(`circles: (${x}, ${y}) is outside the box [-1, 1]²`, 'plane-circle-outside', { x: String(x), y: String(y) });
    }
    return { x, y, r: Math.abs(r), charge: Math.sign(r), vx: 0, vy: 0 };
  });
  if (circles.length === 0) throw refusal('circles: give at least one circle as x,y,r', 'plane-no-circles', {});
  return circles;
}

/** Circles as `circles` reads them (three decimals; a subtracting circle with a negative radius). */
export function circlesText(circles) {
  const n = (v) => String(Math.round(v * 1000) / 1000);
  return circles.map((c) => [c.x, c.y, c.r * (c.charge < 0 ? -1 : 1)].map(n).join(',')).join(';');
}

/** Circles as `circles` reads them back exactly (full precision; a subtracting circle with a negative radius). */
export function circlesExactText(circles) {
  return circles.map((c) => [c.x, c.y, Math.abs(c.r) * ((c.charge ?? Math.sign(c.r)) < 0 ? -1 : 1)].join(',')).join(';');
}

/** One Euler step of `dt` seconds for every circle, the walls elastic. */
export function moveCircles(circles, dt) {
  for (const c of circles) {
    c.x += c.vx * dt;
    c.y += c.vy * dt;
    if (Math.abs(c.x) > 1 - c.r) { c.vx = -Math.sign(c.x) * Math.abs(c.vx); c.x = Math.sign(c.x) * (1 - c.r); }
    if (Math.abs(c.y) > 1 - c.r) { c.vy = -Math.sign(c.y) * Math.abs(c.vy); c.y = Math.sign(c.y) * (1 - c.r); }
  }
}

/** The circle under point (x, y) of the box, or within `near` of a smaller one's centre; or undefined. */
export function circleAt(circles, x, y, near) {
  return circles.find((c) => Math.hypot(c.x - x, c.y - y) < Math.max(c.r, near));
}

/**
 * Removes the circle under (x, y) (see `circleAt`), or adds one of radius 0.2 there where there is
 * none. Returns false, changing nothing, where it would remove the last circle.
 */
export function addOrRemove(circles, x, y, near) {
  const hit = circleAt(circles, x, y, near);
  if (hit && circles.length === 1) return false;
  if (hit) circles.splice(circles.indexOf(hit), 1);
  else circles.push({ x, y, r: 0.2, charge: 1, vx: 0, vy: 0 });
  return true;
}
