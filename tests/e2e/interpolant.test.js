// The cell inspector's picture of the trilinear interpolant (www/lib/features/interpolant.js), held to
// the interpolant itself: every hit lies on the iso level, a linear field is drawn as its plane, and on
// random cells each ray's first crossing is the one a brute-force march of 20,000 steps finds.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { castInterpolant, project } from '../../www/lib/features/interpolant.js';

// Corner c at offset (x, y, z) as core/src/extract/tables.rs numbers them.
const CORNERS = [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]];
const SIZE = 64;

// The trilinear interpolant in its polynomial form, a + bx + cy + dz + exy + fyz + gxz + hxyz, written
// apart from the module's weighted sum.
function trilinear(v, _corners, [x, y, z]) {
  const [f000, f100, f110, f010, f001, f101, f111, f011] = v;
  const a = f000;
  const [b, c, d] = [f100 - f000, f010 - f000, f001 - f000];
  const e = f110 - f100 - f010 + f000;
  const f = f011 - f010 - f001 + f000;
  const g = f101 - f100 - f001 + f000;
  const h = f111 - f110 - f101 - f011 + f100 + f010 + f001 - f000;
  return a + b * x + c * y + d * z + e * x * y + f * y * z + g * x * z + h * x * y * z;
}
const RAY = [-16 / 34, -12 / 34, 1];

function random(seed) {
  let s = seed >>> 0;
  return () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

// The first crossing of `iso` along the ray through pixel k, marched in tiny steps: its point or null.
function marched(f, iso, k) {
  const s = SIZE / 64;
  const [x, y] = [((k % SIZE) + 0.5) / s - 10, 54 - (Math.floor(k / SIZE) + 0.5) / s].map((v) => v / 34);
  const inside = (p) => p.every((v) => v >= -1e-12 && v <= 1 + 1e-12);
  const at = (l) => [x + l * RAY[0], y + l * RAY[1], l];
  let before = null;
  for (let i = 0; i <= 20000; i += 1) {
    const p = at(-3 + (5 * i) / 20000);
    if (!inside(p)) {
      if (before !== null) return null;
      continue;
    }
    const above = trilinear(f, CORNERS, p) > iso;
    if (before !== null && above !== before) return p;
    before = above;
  }
  return null;
}

test('a linear field is drawn as its plane, and every hit lies on the iso level', () => {
  // f = x: the surface f = 0.5 is the plane x = 0.5.
  const f = CORNERS.map(([x]) => x);
  const pixels = castInterpolant(f, 0.5, CORNERS, SIZE);
  const hits = pixels.filter((p) => p.hit);
  assert.ok(hits.length > 0.1 * SIZE * SIZE, `${hits.length} pixels show the plane`);
  for (const { hit, front } of hits) {
    assert.ok(Math.abs(hit[0] - 0.5) < 1e-9, `hit at x = ${hit[0]}`);
    // The eye looks along −x as it goes deeper (RAY.x < 0): it meets the plane from x > 0.5, inside.
    assert.equal(front, false);
  }
  // The plane's quad, projected, is what is covered (to a pixel along its border).
  const quad = [[0.5, 0, 0], [0.5, 1, 0], [0.5, 1, 1], [0.5, 0, 1]].map((p) => project(p, SIZE));
  const within = (u, v) => {
    let sign = 0;
    for (let i = 0; i < 4; i += 1) {
      const [a, b] = [quad[i], quad[(i + 1) % 4]];
      const cross = (b[0] - a[0]) * (v - a[1]) - (b[1] - a[1]) * (u - a[0]);
      if (Math.abs(cross) < 1.5 * Math.hypot(b[0] - a[0], b[1] - a[1])) return null;
      if (sign && Math.sign(cross) !== sign) return false;
      sign = Math.sign(cross);
    }
    return true;
  };
  pixels.forEach(({ hit }, k) => {
    const expected = within((k % SIZE) + 0.5, Math.floor(k / SIZE) + 0.5);
    if (expected !== null) assert.equal(Boolean(hit), expected, `pixel ${k}`);
  });
});

test('on random cells, each ray meets the surface where a fine march along it does', () => {
  const next = random(7);
  let compared = 0;
  let differing = 0;
  for (let cell = 0; cell < 12; cell += 1) {
    const f = CORNERS.map(() => next() * 2);
    const iso = 1;
    const pixels = castInterpolant(f, iso, CORNERS, SIZE);
    for (let k = 0; k < pixels.length; k += 3) {
      const want = marched(f, iso, k);
      const got = pixels[k].hit;
      compared += 1;
      if (Boolean(want) !== Boolean(got)) {
        differing += 1;
        continue;
      }
      if (got) {
        assert.ok(Math.abs(trilinear(f, CORNERS, got) - iso) < 1e-9, `cell ${cell}, pixel ${k}: f = iso at the hit`);
        const gap = Math.hypot(...got.map((v, i) => v - want[i]));
        assert.ok(gap < 1e-3, `cell ${cell}, pixel ${k}: hit ${got} against ${want}`);
      }
    }
  }
  // Only rays that graze the surface (two crossings within a march step) may differ.
  assert.ok(differing <= 0.002 * compared, `${differing} of ${compared} rays differ`);
});
