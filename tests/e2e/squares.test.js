// Marching squares in the plane (www/lib/plane/squares.js), node only: the generated table, a circle's
// area, the contour against d3-contour's independent implementation on the same samples, filled bands
// against a fine count of the field, and the saddle rules against the bilinear interpolant.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { contours } from 'd3-contour';
import {
  EDGE_CORNERS, SEGMENTS, bands, enclosedArea, fieldAt, march, ringMeasures, sampleField, saddleValue,
} from '../../www/lib/plane/squares.js';

// A small seeded generator (xorshift), so runs repeat.
function random(seed) {
  let s = seed >>> 0 || 1;
  return () => {
    s ^= s << 13; s >>>= 0;
    s ^= s >>> 17;
    s ^= s << 5; s >>>= 0;
    return s / 2 ** 32;
  };
}

function circles(rng, count, { charges = false } = {}) {
  return Array.from({ length: count }, () => ({
    x: rng() * 1.2 - 0.6, y: rng() * 1.2 - 0.6, r: 0.05 + rng() * 0.15,
    charge: charges && rng() < 0.25 ? -1 : 1,
  }));
}

test('each case joins exactly its crossed edges, each once, with the inside on the left', () => {
  for (const [name, table] of Object.entries(SEGMENTS)) {
    for (let c = 0; c < 16; c += 1) {
      const inside = (k) => ((c >> k) & 1) === 1;
      const crossed = [0, 1, 2, 3].filter((e) => inside(EDGE_CORNERS[e][0]) !== inside(EDGE_CORNERS[e][1]));
      const used = table[c].flat().sort();
      assert.deepEqual(used, [...crossed].sort(), `${name} case ${c}`);
      // The inside on the left of each segment between edge midpoints, seen from the square's centre.
      const mid = [[0.5, 0], [1, 0.5], [0.5, 1], [0, 0.5]];
      const corner = [[0, 0], [1, 0], [1, 1], [0, 1]];
      for (const [a, b] of table[c]) {
        const [p, q] = [mid[a], mid[b]];
        const left = (k) => (q[0] - p[0]) * (corner[k][1] - p[1]) - (q[1] - p[1]) * (corner[k][0] - p[0]) > 0;
        // The corner the segment cuts off is on its left exactly when it is inside.
        const cut = [0, 1, 2, 3].find((k) => [a, b].every((e) => EDGE_CORNERS[e].includes(k)));
        if (cut !== undefined) assert.equal(left(cut), inside(cut), `${name} case ${c}, segment ${a}→${b}`);
      }
    }
  }
  assert.equal(SEGMENTS.apart[5].length, 2);
  assert.notDeepEqual(SEGMENTS.apart[5], SEGMENTS.joined[5]);
});

test('one circle encloses its disk: one ring, counter-clockwise, of area π r² within the squares\' error', () => {
  const r = 0.4;
  for (const cells of [16, 64, 256]) {
    const { rings } = march(sampleField([{ x: 0.03, y: -0.02, r }], cells), cells, 1);
    assert.equal(rings.length, 1);
    const { area, length } = ringMeasures(rings[0]);
    const h = 2 / cells;
    assert.ok(Math.abs(area - Math.PI * r * r) < 2 * Math.PI * r * h * h, `${cells}: area ${area}`);
    assert.ok(Math.abs(length - 2 * Math.PI * r) < 2 * Math.PI * r * h, `${cells}: length ${length}`);
  }
});

// d3-contour on the same samples: its points sit at pixel centres (i + 0.5, j + 0.5), and its regions
// are f ≥ level (ours f > level: the same for values that never equal the level).
function d3Rings(values, cells, level) {
  const n = cells + 1;
  const [multi] = contours().size([n, n]).thresholds([level])(Array.from(values));
  const step = 2 / cells;
  return multi.coordinates.flat().map((ring) => ring.slice(0, -1).map(([x, y]) => [-1 + (x - 0.5) * step, -1 + (y - 0.5) * step]));
}

test('the contour equals d3-contour\'s on the same samples: as many rings, the same lengths and areas', () => {
  const rng = random(20261126);
  let compared = 0;
  for (let scene = 0; scene < 12; scene += 1) {
    const cells = [32, 64, 128, 200][scene % 4];
    const values = sampleField(circles(rng, 2 + (scene % 5) * 3, { charges: scene % 3 === 2 }), cells);
    for (const level of [0.5, 1, 1.7]) {
      const ours = march(values, cells, level).rings;
      const theirs = d3Rings(values, cells, level);
      assert.equal(ours.length, theirs.length, `scene ${scene}, level ${level}: rings`);
      const lengths = (rings) => rings.map((r) => ringMeasures(r).length).sort((a, b) => a - b);
      const [a, b] = [lengths(ours), lengths(theirs)];
      for (let k = 0; k < a.length; k += 1) assert.ok(Math.abs(a[k] - b[k]) < 2e-6, `scene ${scene}, level ${level}: ${a[k]} vs ${b[k]}`);
      // d3 winds its rings the other way (its y axis points down): compare magnitudes.
      const areas = (rings) => rings.map((r) => Math.abs(ringMeasures(r).area)).sort((x, y) => x - y);
      const [p, q] = [areas(ours), areas(theirs)];
      for (let k = 0; k < p.length; k += 1) assert.ok(Math.abs(p[k] - q[k]) < 4e-6, `scene ${scene}: area ${p[k]} vs ${q[k]}`);
      compared += ours.length;
    }
  }
  assert.ok(compared > 50, `${compared} rings compared`);
});

test('filled bands sum to the box and each holds the area of { a < f ≤ b } within the squares\' error', () => {
  const rng = random(7);
  const list = circles(rng, 16, { charges: true });
  const cells = 128;
  const levels = [0.3, 0.6, 1, 1.5, 2.5];
  const found = bands(sampleField(list, cells), cells, levels);
  // Below the first level: the rest of the box.
  const below = 4 - found.reduce((sum, band) => sum + band.area, 0);
  assert.ok(below > 0 && below < 4);
  // A fine midpoint count of the field itself.
  const fine = 1200;
  const counts = new Array(levels.length).fill(0);
  for (let j = 0; j < fine; j += 1) {
    for (let i = 0; i < fine; i += 1) {
      const f = fieldAt(list, -1 + (2 * (i + 0.5)) / fine, -1 + (2 * (j + 0.5)) / fine);
      for (let k = levels.length - 1; k >= 0; k -= 1) {
        if (f > levels[k]) { counts[k] += 1; break; }
      }
    }
  }
  const h = 2 / cells;
  found.forEach((band, k) => {
    const exact = (counts[k] * 4) / (fine * fine);
    // The error of a contour at spacing h is of order its length times h².
    const length = band.rings.reduce((sum, r) => sum + ringMeasures(r).length, 0)
      + (found[k + 1]?.rings ?? []).reduce((sum, r) => sum + ringMeasures(r).length, 0);
    const tolerance = length * h * 0.5 + (length * 2) / fine;
    assert.ok(Math.abs(band.area - exact) < tolerance, `band ${band.from}–${band.to}: ${band.area} vs ${exact} (±${tolerance})`);
  });
});

// One saddle square in the middle of a 3 × 3 grid whose edge reads 0: corners 0 and 2 inside.
function saddleGrid(f) {
  const values = new Float64Array(16);
  [values[5], values[6], values[10], values[9]] = f;
  return values;
}

// Whether the bilinear interpolant of `f` joins corners 0 and 2 inside the square at `iso`: a flood
// fill of a fine sampling of it, written apart from the rules.
function bilinearJoins(f, iso, m = 300) {
  const value = (u, v) => f[0] * (1 - u) * (1 - v) + f[1] * u * (1 - v) + f[2] * u * v + f[3] * (1 - u) * v;
  const inside = (i, j) => value(i / (m - 1), j / (m - 1)) > iso;
  const seen = new Uint8Array(m * m);
  const stack = [[0, 0]];
  seen[0] = 1;
  while (stack.length) {
    const [i, j] = stack.pop();
    if (i === m - 1 && j === m - 1) return true;
    for (const [a, b] of [[i + 1, j], [i - 1, j], [i, j + 1], [i, j - 1]]) {
      if (a >= 0 && b >= 0 && a < m && b < m && !seen[b * m + a] && inside(a, b)) {
        seen[b * m + a] = 1;
        stack.push([a, b]);
      }
    }
  }
  return false;
}

test('the saddle rules: the table cuts apart, the centre value and the decider join by their values', () => {
  // Centre value above the level, the interpolant's saddle below: the two rules disagree.
  const f = [3.5, 0.2, 1.01, 0.2];
  assert.ok(saddleValue(f, 'center') > 1 && saddleValue(f, 'decider') < 1);
  const rings = (saddle) => march(saddleGrid(f), 3, 1, { saddle });
  assert.equal(rings('table').rings.length, 2);
  assert.equal(rings('center').rings.length, 1);
  assert.equal(rings('decider').rings.length, 2);
  assert.deepEqual(rings('center').saddles, [{ square: [1, 1], case: 5, value: 1.2275, joined: true }]);
  // The decider joins exactly where the bilinear interpolant does, on random saddle squares.
  const rng = random(99);
  let joined = 0;
  for (let k = 0; k < 300; k += 1) {
    const g = [1 + rng() * 2, rng(), 1 + rng() * 2, rng()];
    const decided = march(saddleGrid(g), 3, 1, { saddle: 'decider' });
    const [square] = decided.saddles;
    if (Math.abs(square.value - 1) < 2e-3) continue;
    assert.equal(square.joined, bilinearJoins(g, 1), `corners ${g}`);
    assert.equal(decided.rings.length, square.joined ? 1 : 2);
    joined += square.joined;
  }
  assert.ok(joined > 20 && joined < 280, `${joined} joined`);
});

test('a sample equal to the level puts no two vertices on one point', () => {
  // Circles of radius 0.5 centred on a grid point: the points at distance 0.5 read exactly 1.
  const cells = 16;
  const { rings } = march(sampleField([{ x: 0, y: 0, r: 0.5 }], cells), cells, 1);
  const points = rings.flat().map(([x, y]) => `${x},${y}`);
  assert.equal(new Set(points).size, points.length);
  assert.ok(enclosedArea(rings) > 0);
});

test('stepping through every square builds exactly the contour, segment for segment', async () => {
  const { segmentsBefore, nextCrossed, caseBits } = await import('../../www/lib/plane/stepper.js');
  const rng = random(5);
  for (const cells of [6, 12, 30]) {
    const values = sampleField(circles(rng, 4), cells);
    const result = march(values, cells, 1, { saddle: 'decider' });
    const key = ([p, q]) => `${p[0]},${p[1]}→${q[0]},${q[1]}`;
    const fromRings = result.rings.flatMap((ring) => ring.map((p, k) => key([p, ring[(k + 1) % ring.length]]))).sort();
    const stepped = segmentsBefore(result, cells, cells * cells).map(key).sort();
    assert.deepEqual(stepped, fromRings, `${cells}²`);
    // Each step adds its square's segments, and builds its case from its corners.
    let count = 0;
    for (let k = 0; k < cells * cells; k += 1) {
      const square = result.square(k % cells, Math.floor(k / cells));
      assert.equal(caseBits(square.corners, 1).case, result.cases[k]);
      assert.equal(segmentsBefore(result, cells, k + 1).length, count + square.segments.length);
      count += square.segments.length;
    }
    // "Next crossed" stops exactly at the squares the contour crosses.
    const crossed = [];
    for (let k = nextCrossed(result.cases, -1); k >= 0; k = nextCrossed(result.cases, k)) crossed.push(k);
    assert.deepEqual(crossed, [...result.cases.keys()].filter((k) => result.cases[k] % 15 !== 0));
  }
});
