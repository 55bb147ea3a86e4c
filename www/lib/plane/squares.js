// Marching squares on circles in the plane: the field's samples, each square's case, the saddle rule
// for the two ambiguous cases, the crossings and the contour as closed rings, and the area each level
// encloses (filled bands are the differences). No DOM: the 2D figure draws from it, and the tests hold
// it to d3-contour's independent implementation and to a fine count of the field.
//
// Conventions, as the 3D figure's (core/src/extract/tables.rs): the box is [-1, 1]², `cells` squares
// per axis, points on the box's edge read 0 (outside), a corner is inside where f > iso, and a vertex
// stays strictly inside its edge (EDGE_MARGIN of the edge from either end), so that a sample equal to
// iso never puts two vertices on one point. The plane computes in f64, so its margin is far below the
// 3D figure's f32 one and moves no vertex by more than a billionth of a square. A square's corners are numbered counter-clockwise from its
// lowest: 0 (x0, y0), 1 (x1, y0), 2 (x1, y1), 3 (x0, y1); its edges 0 (corners 0–1), 1 (1–2), 2 (3–2)
// and 3 (0–3); its case has bit c set where corner c is inside.

/** A vertex stays at least this fraction of its edge from either end. */
export const EDGE_MARGIN = 1e-9;

/** The two corners of each edge, from the corner nearer the origin. */
export const EDGE_CORNERS = [[0, 1], [1, 2], [3, 2], [0, 3]];

/** The two edges that meet at each corner. */
const CORNER_EDGES = [[3, 0], [0, 1], [1, 2], [2, 3]];

/** The ways of joining a saddle square's inside corners, and their words. */
export const SADDLE_RULES = ['table', 'center', 'decider'];

/**
 * The segments of each case, generated from the corners: with one crossing pair the segment joins its
 * two crossed edges; on a saddle (cases 5 and 10, inside corners on a diagonal) two segments each cut
 * off one corner — the inside corners (`apart`, the fixed table's choice, as in the classic 3D table and
 * d3-contour) or the outside ones (`joined`). Each segment runs with the inside on its left.
 */
function generate(joined) {
  return Array.from({ length: 16 }, (_, c) => {
    const inside = (k) => ((c >> k) & 1) === 1;
    const crossed = [0, 1, 2, 3].filter((e) => inside(EDGE_CORNERS[e][0]) !== inside(EDGE_CORNERS[e][1]));
    if (crossed.length === 0) return [];
    // Cut off corner k: a segment between its two edges, oriented by whether k is inside.
    const cut = (k) => {
      const [before, after] = CORNER_EDGES[k];
      return inside(k) ? [after, before] : [before, after];
    };
    if (crossed.length === 4) {
      const saddleInside = inside(0) ? [0, 2] : [1, 3];
      const saddleOutside = inside(0) ? [1, 3] : [0, 2];
      return (joined ? saddleOutside : saddleInside).map(cut);
    }
    // One inside run: walking counter-clockwise round the square, the run ends on one crossed edge
    // (`leaving`) and the segment starts there, with the run on its left.
    const leaving = crossed.find((e) => {
      const [a, b] = EDGE_CORNERS[e];
      // Counter-clockwise, edges 0 and 1 run a → b and edges 2 and 3 run b → a.
      return e < 2 ? inside(a) && !inside(b) : inside(b) && !inside(a);
    });
    const entering = crossed.find((e) => e !== leaving);
    return [[leaving, entering]];
  });
}

/** Segments (edge pairs, inside on the left) of each case with its saddle cut apart, and joined. */
export const SEGMENTS = { apart: generate(false), joined: generate(true) };

/**
 * f = Σ qᵢ kernel(|p − cᵢ|²) at (x, y), for circles `{ x, y, r, charge }` (charge ±1, 1 when absent):
 * by default the inverse square qᵢ rᵢ² / |p − cᵢ|², else `termSize`'s `kernel` with `blobbiness`.
 */
export function fieldAt(circles, x, y, kernel = 'inverse_square', blobbiness = 2) {
  let f = 0;
  for (const c of circles) {
    const d = (x - c.x) ** 2 + (y - c.y) ** 2;
    f += (c.charge ?? 1) * termSize(kernel, c.r * c.r, d, blobbiness);
  }
  return f;
}

/**
 * The field at the (cells + 1)² grid points of [-1, 1]², row by row from y = -1, the edge's points 0,
 * each circle's term shaped by `kernel` (`termSize`).
 */
export function sampleField(circles, cells, kernel = 'inverse_square', blobbiness = 2) {
  if (kernel !== 'inverse_square') return sampleShaped(circles, cells, kernel, blobbiness);
  const n = cells + 1;
  const values = new Float64Array(n * n);
  // Each circle as x, y and q r², and its squared distance in y for the row at hand.
  const k = circles.length;
  const flat = new Float64Array(3 * k);
  circles.forEach((c, m) => flat.set([c.x, c.y, (c.charge ?? 1) * c.r * c.r], 3 * m));
  const dy2 = new Float64Array(k);
  const step = 2 / cells;
  for (let j = 1; j < cells; j += 1) {
    const y = -1 + j * step;
    for (let m = 0; m < k; m += 1) dy2[m] = (y - flat[3 * m + 1]) ** 2;
    for (let i = 1; i < cells; i += 1) {
      const x = -1 + i * step;
      let f = 0;
      for (let m = 0; m < k; m += 1) {
        const dx = x - flat[3 * m];
        const d = dx * dx + dy2[m];
        f += flat[3 * m + 2] / (d > 1e-20 ? d : 1e-20);
      }
      values[j * n + i] = f;
    }
  }
  return values;
}

// `sampleField` with another kernel: each term by `termSize`.
function sampleShaped(circles, cells, kernel, blobbiness) {
  const n = cells + 1;
  const values = new Float64Array(n * n);
  const step = 2 / cells;
  for (let j = 1; j < cells; j += 1) {
    for (let i = 1; i < cells; i += 1) values[j * n + i] = fieldAt(circles, -1 + i * step, -1 + j * step, kernel, blobbiness);
  }
  return values;
}

/**
 * A term's size at squared distance `d2` from a sphere of radius² `r2` with `kernel` (and Blinn's
 * `blobbiness`), as `Terms::size` in core/src/extract/kernel.rs.
 */
export function termSize(kernel, r2, d2, blobbiness = 2) {
  if (kernel === 'blinn') return Math.exp(blobbiness * (1 - d2 / r2));
  if (kernel === 'wyvill') {
    const t = Math.max(1 - d2 / (4 * r2), 0);
    return (2 / 9) * t * t * (5 + 4 * t);
  }
  return r2 / Math.max(d2, 1e-20);
}

/**
 * The samples of a 3D figure's slice plane: the field of `spheres` (`{ center: [x, y, z], radius,
 * charge }`, each term shaped by `kernel` (`termSize`), summed, or with `blend` 'max' the largest
 * adding term less the largest subtracting one) at
 * the grid points of the plane `plane` (0..cells) across `axis` (0 x, 1 y, 2 z) of the figure's grid of
 * `cells` per axis, as `<metaballs-view>` samples them: point (i, j) lies along the next axis after the
 * slice's (i) and the one after that (j); points on the box's faces read 0.
 */
export function sampleSlice(spheres, cells, axis, plane, blend = 'sum', kernel = 'inverse_square', blobbiness = 2) {
  const n = cells + 1;
  const values = new Float64Array(n * n);
  if (plane === 0 || plane === cells) return values;
  const step = 2 / cells;
  const p = [0, 0, 0];
  p[axis] = -1 + plane * step;
  for (let j = 1; j < cells; j += 1) {
    for (let i = 1; i < cells; i += 1) {
      p[(axis + 1) % 3] = -1 + i * step;
      p[(axis + 2) % 3] = -1 + j * step;
      let f = 0;
      let dent = 0;
      for (const s of spheres) {
        const d = (p[0] - s.center[0]) ** 2 + (p[1] - s.center[1]) ** 2 + (p[2] - s.center[2]) ** 2;
        const size = termSize(kernel, s.radius * s.radius, d, blobbiness);
        const subtracting = (s.charge ?? 1) < 0;
        if (blend !== 'max') f += subtracting ? -size : size;
        else if (subtracting) dent = Math.max(dent, size);
        else f = Math.max(f, size);
      }
      values[j * n + i] = f - dent;
    }
  }
  return values;
}

/**
 * The saddle value that decides a saddle square with corner values `f` (corner order) by `rule`:
 * `center` the mean of the four corners, `decider` the bilinear interpolant's saddle,
 * (f0 f2 − f1 f3) / (f0 + f2 − f1 − f3); null for `table`, which decides nothing. The inside corners
 * are joined where this value is above iso.
 */
export function saddleValue(f, rule) {
  if (rule === 'center') return (f[0] + f[1] + f[2] + f[3]) / 4;
  if (rule === 'decider') {
    const d = f[0] + f[2] - f[1] - f[3];
    return d === 0 ? null : (f[0] * f[2] - f[1] * f[3]) / d;
  }
  return null;
}

/**
 * Marching squares over `values` (from `sampleField`) at level `iso`:
 * - `cases`: each square's case (Uint8Array, square (i, j) at j · cells + i);
 * - `saddles`: each saddle square `{ square, case, value, joined }` (the value the rule decided by);
 * - `rings`: the contour, closed rings of points [x, y] in the box, each with the inside on its left
 *   (counter-clockwise round an inside region, clockwise round a hole);
 * - `crossings`: how many edges the contour crosses;
 * - `square(i, j)`: one square as the march saw it (corner values, case, saddle, segments).
 * `placement` is `linear` (where the edge's values interpolate to iso) or `midpoint`.
 */
export function march(values, cells, iso, { placement = 'linear', saddle = 'table' } = {}) {
  const n = cells + 1;
  const cases = new Uint8Array(cells * cells);
  const saddles = [];
  const at = (i, j) => values[j * n + i];
  // Edge ids: the horizontal edge from point (i, j) is 2 (j n + i), the vertical one 2 (j n + i) + 1.
  const edgeId = (i, j, e) => (e === 0 ? 2 * (j * n + i) : e === 1 ? 2 * (j * n + i + 1) + 1
    : e === 2 ? 2 * ((j + 1) * n + i) : 2 * (j * n + i) + 1);
  // For each crossed edge, the edge the contour goes on to (-1 where it crosses none), and the
  // crossed edges in the order found.
  const next = new Int32Array(2 * n * n).fill(-1);
  const crossed = [];
  // A square's case, from the inside bits of its lower and upper rows.
  const row = (j) => {
    const bits = new Uint8Array(n);
    for (let i = 0; i < n; i += 1) bits[i] = values[j * n + i] > iso ? 1 : 0;
    return bits;
  };
  let below = row(0);
  for (let j = 0; j < cells; j += 1) {
    const above = row(j + 1);
    for (let i = 0; i < cells; i += 1) {
      const c = below[i] | below[i + 1] << 1 | above[i + 1] << 2 | above[i] << 3;
      cases[j * cells + i] = c;
      if (c === 0 || c === 15) continue;
      let joined = false;
      if (c === 5 || c === 10) {
        const value = saddleValue([at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)], saddle);
        joined = value !== null && value > iso;
        saddles.push({ square: [i, j], case: c, value, joined });
      }
      for (const [from, to] of (joined ? SEGMENTS.joined : SEGMENTS.apart)[c]) {
        const id = edgeId(i, j, from);
        next[id] = edgeId(i, j, to);
        crossed.push(id);
      }
    }
    below = above;
  }
  const point = (id) => {
    const vertical = id & 1;
    const p = id >> 1;
    const [i, j] = [p % n, Math.floor(p / n)];
    const [a, b] = [at(i, j), vertical ? at(i, j + 1) : at(i + 1, j)];
    let t = placement === 'midpoint' ? 0.5 : (iso - a) / (b - a);
    t = Math.min(Math.max(t, EDGE_MARGIN), 1 - EDGE_MARGIN);
    const step = 2 / cells;
    return vertical ? [-1 + i * step, -1 + (j + t) * step] : [-1 + (i + t) * step, -1 + j * step];
  };
  const rings = [];
  const seen = new Uint8Array(next.length);
  for (const start of crossed) {
    if (seen[start]) continue;
    const ring = [];
    for (let id = start; !seen[id]; id = next[id]) {
      seen[id] = 1;
      ring.push(point(id));
    }
    rings.push(ring);
  }
  // One square as the march saw it: its corner values, case, saddle decision, and segments (points,
  // the inside on the left) with the edges they join.
  const square = (i, j) => {
    const c = cases[j * cells + i];
    const saddleSquare = saddles.find((q) => q.square[0] === i && q.square[1] === j) ?? null;
    const table = saddleSquare?.joined ? SEGMENTS.joined : SEGMENTS.apart;
    return {
      square: [i, j], case: c, corners: [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)], saddle: saddleSquare,
      segments: table[c].map(([from, to]) => ({ edges: [from, to], points: [point(edgeId(i, j, from)), point(edgeId(i, j, to))] })),
    };
  };
  return { cases, saddles, rings, crossings: crossed.length, square };
}

/** A ring's signed area (positive counter-clockwise) and its length. */
export function ringMeasures(ring) {
  let area = 0;
  let length = 0;
  for (let k = 0; k < ring.length; k += 1) {
    const [x0, y0] = ring[k];
    const [x1, y1] = ring[(k + 1) % ring.length];
    area += x0 * y1 - x1 * y0;
    length += Math.hypot(x1 - x0, y1 - y0);
  }
  return { area: area / 2, length };
}

/** The area of { f > iso } as the contour encloses it: the rings' signed areas summed. */
export function enclosedArea(rings) {
  return rings.reduce((sum, ring) => sum + ringMeasures(ring).area, 0);
}

/**
 * Filled bands between `levels` (ascending): for each level, the rings of { f > level }; band k, from
 * levels[k] to levels[k + 1] (the last unbounded), is the first region less the second, and its area
 * the difference of theirs. Below the first level lies the rest of the box (area 4 less the first).
 */
export function bands(values, cells, levels, options) {
  const regions = levels.map((level) => {
    const { rings } = march(values, cells, level, options);
    return { level, rings, area: enclosedArea(rings) };
  });
  return regions.map((region, k) => ({
    from: region.level,
    to: levels[k + 1] ?? Infinity,
    rings: region.rings,
    area: region.area - (regions[k + 1]?.area ?? 0),
  }));
}
