// The page's pool of mesher workers meshes a large grid in slabs of z and joins them
// (www/lib/engine/slabs.js): run here in Node on the page's own WebAssembly build, the joined mesh is
// the mesh one worker makes of the whole grid (`mesh_job`) number for number — the same vertices in
// the same order, the same triangles, so the same count, closed by position, the same area and volume
// — on seeded scenes (adding and subtracting spheres, both blends, the three case tables and kernels,
// spheres against the walls), cut into two, three and four slabs, seams included; slabs cover the grid in
// whole blocks; slabs that do not fit are refused.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { root } from './helpers.js';
import { joinSlabs, slabRanges } from '../../www/lib/engine/slabs.js';

const wasm = await import(path.join(root, 'pkg/metaballs.js'));
await wasm.default({ module_or_path: readFileSync(path.join(root, 'pkg/metaballs_bg.wasm')) });

// A seeded stream of numbers in [0, 1) (a linear congruential generator).
function random(seed) {
  let state = seed >>> 0;
  return () => {
    state = (Math.imul(state, 1664525) + 1013904223) >>> 0;
    return state / 2 ** 32;
  };
}

// A packed marching-cubes job (`View.cpu_job`): method, iso, cells, interpolation, blend, table,
// kernel, blobbiness, split (marching tetrahedra's alone: 0 here), then centre, radius and charge of
// each sphere.
function job(seed) {
  const next = random(seed);
  const count = 1 + Math.floor(next() * 24);
  const cells = [16, 29, 32, 64, 96, 128][seed % 6];
  const head = [0, 0.5 + next() * 1.5, cells, seed % 2, (seed >> 1) % 2, seed % 3, Math.floor(seed / 3) % 3, 2, 0];
  const spheres = Array.from({ length: count }, (_, i) => [
    next() * 1.8 - 0.9, next() * 1.8 - 0.9, next() * 1.8 - 0.9, 0.1 + next() * 0.35, i % 4 === 3 ? -1 : 1,
  ]);
  return new Float32Array([...head, ...spheres.flat()]);
}

const inSlabs = (packed, pieces) => joinSlabs(packed[2], slabRanges(packed[2], pieces).map(([from, to]) => {
  const [vertices, indices, blocks, cells, keys] = wasm.mesh_slab(packed, from, to);
  return [from, vertices, indices, keys, blocks, cells];
}));

// Area, volume and whether every edge between positions lies on two triangles.
function measures(vertices, indices) {
  const at = (i) => [vertices[6 * i], vertices[6 * i + 1], vertices[6 * i + 2]];
  let area = 0;
  let volume = 0;
  const edges = new Map();
  const name = (p) => p.join(',');
  for (let t = 0; t < indices.length; t += 3) {
    const [a, b, c] = [0, 1, 2].map((k) => at(indices[t + k]));
    const u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    const v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    const cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    area += Math.hypot(...cross) / 2;
    volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
    for (const [p, q] of [[a, b], [b, c], [c, a]]) {
      const key = [name(p), name(q)].sort().join('|');
      edges.set(key, (edges.get(key) ?? 0) + 1);
    }
  }
  return { area, volume, closed: [...edges.values()].every((n) => n === 2) };
}

test('meshes joined from slabs are the whole grid\'s mesh, seams included', () => {
  let withSurface = 0;
  for (let seed = 1; seed <= 36; seed++) {
    const packed = job(seed);
    const whole = wasm.mesh_job(packed);
    const [vertices, indices, blocks, cells] = whole;
    if (indices.length) withSurface += 1;
    const expected = measures(vertices, indices);
    for (const pieces of [2, 3, 4]) {
      const what = `seed ${seed} (${packed[2]}³ cells) in ${pieces} slabs`;
      const joined = inSlabs(packed, pieces);
      assert.equal(joined[1].length, indices.length, `${what}: triangle counts`);
      const seen = measures(joined[0], joined[1]);
      assert.equal(seen.closed, expected.closed, `${what}: closed by position`);
      assert.ok(Math.abs(seen.area - expected.area) <= 1e-6 * Math.max(1, expected.area), `${what}: area`);
      assert.ok(Math.abs(seen.volume - expected.volume) <= 1e-6 * Math.max(1, Math.abs(expected.volume)), `${what}: volume`);
      assert.deepEqual([joined[2], joined[3]], [blocks, cells], `${what}: active blocks and cells`);
      assert.deepEqual(joined[0], vertices, `${what}: vertices`);
      assert.deepEqual(joined[1], indices, `${what}: triangles`);
    }
  }
  assert.ok(withSurface >= 27, `only ${withSurface} of 36 scenes had a surface`);
});

test('slabs cover the grid in whole blocks, as even as blocks allow', () => {
  for (const n of [1, 4, 5, 13, 64, 128, 130]) {
    for (let pieces = 1; pieces <= 5; pieces++) {
      const ranges = slabRanges(n, pieces);
      assert.equal(ranges[0][0], 0);
      assert.equal(ranges.at(-1)[1], n);
      assert.ok(ranges.length <= Math.min(pieces, Math.ceil(n / 4)), `${n} cells in ${pieces}: ${ranges.length}`);
      ranges.forEach(([from, to], k) => {
        assert.ok(from < to && from % 4 === 0, `${n} cells in ${pieces}: ${JSON.stringify(ranges)}`);
        if (k > 0) assert.equal(from, ranges[k - 1][1]);
      });
    }
  }
});

test('slabs that do not fit together are refused with what is wrong', () => {
  const packed = job(4);
  assert.throws(() => wasm.mesh_slab(packed, 8, 4), /not within/);
  const slabs = slabRanges(packed[2], 2).map(([from, to]) => {
    const [vertices, indices, blocks, cells, keys] = wasm.mesh_slab(packed, from, to);
    return [from, vertices, indices, keys, blocks, cells];
  });
  assert.throws(() => joinSlabs(packed[2], [slabs[1], slabs[0]]), /not above/);
  assert.throws(() => joinSlabs(packed[2], [[0, new Float32Array(0), new Uint32Array([0, 1, 2]), new Uint32Array(0), 0, 0]]),
    /triangle on vertex 0/);
});
