// The trilinear interpolant of an inspected cell, drawn exactly beside the cell's triangles: the
// surface that marching cubes approximates inside one cell, f(x, y, z) = Σ f_c · (x or 1 − x)(y or
// 1 − y)(z or 1 − z) over the corners c, ray cast from the oblique view the cell drawings use
// (cell-drawing.js). Along a ray the interpolant is a cubic, so each ray's first crossing of the iso
// level is found exactly: the cubic's turning points split the ray into monotone pieces, and the first
// piece whose ends differ in sign is bisected to the float's last bit.

/** The oblique view of the unit cube the cell drawings use: pixel coordinates of p in a `size` box. */
export function project([x, y, z], size) {
  const s = size / 64;
  return [s * (10 + 34 * x + 16 * z), s * (54 - 34 * y - 12 * z)];
}

// Every point p + λ·RAY projects where p does; λ grows away from the eye (the cube's face z = 0 is
// nearest, drawn without offset).
const RAY = [-16 / 34, -12 / 34, 1];

/** The interpolant of corner values `f` (corner c at offset `corners[c]`) at p. */
export function trilinear(f, corners, [x, y, z]) {
  let v = 0;
  for (let c = 0; c < 8; c += 1) {
    const [a, b, d] = corners[c];
    v += f[c] * (a ? x : 1 - x) * (b ? y : 1 - y) * (d ? z : 1 - z);
  }
  return v;
}

/** Its gradient at p. */
export function trilinearGradient(f, corners, [x, y, z]) {
  const g = [0, 0, 0];
  for (let c = 0; c < 8; c += 1) {
    const [a, b, d] = corners[c];
    const [wx, wy, wz] = [a ? x : 1 - x, b ? y : 1 - y, d ? z : 1 - z];
    g[0] += f[c] * (a ? 1 : -1) * wy * wz;
    g[1] += f[c] * wx * (b ? 1 : -1) * wz;
    g[2] += f[c] * wx * wy * (d ? 1 : -1);
  }
  return g;
}

// The span of λ where the ray through (x, y, 0) is inside the unit cube, or null.
function cubeSpan(x, y) {
  let [lo, hi] = [-Infinity, Infinity];
  const start = [x, y, 0];
  for (let i = 0; i < 3; i += 1) {
    const [a, b] = [(0 - start[i]) / RAY[i], (1 - start[i]) / RAY[i]];
    lo = Math.max(lo, Math.min(a, b));
    hi = Math.min(hi, Math.max(a, b));
  }
  return lo < hi ? [lo, hi] : null;
}

// The first s in [0, 3] where the cubic through g(0), g(1), g(2), g(3) (Newton's forward form) crosses
// zero, or null.
function firstRoot([g0, g1, g2, g3]) {
  const [d1, d2, d3] = [g1 - g0, g2 - 2 * g1 + g0, g3 - 3 * g2 + 3 * g1 - g0];
  const g = (s) => g0 + d1 * s + (d2 * s * (s - 1)) / 2 + (d3 * s * (s - 1) * (s - 2)) / 6;
  // g'(s) = a s² + b s + c.
  const [a, b, c] = [d3 / 2, d2 - d3, d1 - d2 / 2 + d3 / 3];
  const turns = [];
  if (Math.abs(a) > 1e-12) {
    const disc = b * b - 4 * a * c;
    if (disc > 0) {
      const q = -(b + Math.sign(b || 1) * Math.sqrt(disc)) / 2;
      turns.push(q / a, c / q);
    }
  } else if (Math.abs(b) > 1e-12) {
    turns.push(-c / b);
  }
  const ends = [0, ...turns.filter((s) => s > 0 && s < 3).sort((p, q) => p - q), 3];
  for (let k = 0; k + 1 < ends.length; k += 1) {
    let [lo, hi] = [ends[k], ends[k + 1]];
    const below = g(lo) <= 0;
    if (below === g(hi) <= 0) continue;
    for (let i = 0; i < 60 && lo < hi; i += 1) {
      const mid = (lo + hi) / 2;
      if (mid === lo || mid === hi) break;
      if ((g(mid) <= 0) === below) lo = mid; else hi = mid;
    }
    return (lo + hi) / 2;
  }
  return null;
}

/**
 * The interpolant's surface f = iso seen in a `size`-pixel drawing: per pixel (rows from the top),
 * `hit` the first point of the surface on its ray (or null), and `front` whether the ray meets it
 * from outside (f ≤ iso before it).
 */
export function castInterpolant(f, iso, corners, size) {
  const s = size / 64;
  const pixels = [];
  for (let row = 0; row < size; row += 1) {
    for (let col = 0; col < size; col += 1) {
      const [x, y] = [((col + 0.5) / s - 10) / 34, (54 - (row + 0.5) / s) / 34];
      const span = cubeSpan(x, y);
      let found = null;
      if (span) {
        const at = (k) => {
          const l = span[0] + ((span[1] - span[0]) * k) / 3;
          return [x + l * RAY[0], y + l * RAY[1], l];
        };
        const root = firstRoot([0, 1, 2, 3].map((k) => trilinear(f, corners, at(k)) - iso));
        if (root !== null) {
          const hit = at(root).map((v) => Math.min(1, Math.max(0, v)));
          found = { hit, front: trilinear(f, corners, at(0)) <= iso };
        }
      }
      pixels.push(found ?? { hit: null, front: false });
    }
  }
  return pixels;
}

/**
 * A canvas of the interpolant of corner values `f` inside the cell, lit from the eye (the outside of
 * the surface in `color`, the mesh's colour; its inside teal), with the cell's edges and corners over
 * it as in the drawing beside it (corners orange inside, blue outside).
 */
export function interpolantDrawing(cube, f, iso, { size = 96, color = [231, 118, 97], label = '' } = {}) {
  const canvas = document.createElement('canvas');
  canvas.width = canvas.height = size;
  canvas.className = 'interpolant';
  canvas.setAttribute('role', 'img');
  if (label) canvas.setAttribute('aria-label', label);
  const context = canvas.getContext('2d');
  if (!context) return canvas;
  const image = context.createImageData(size, size);
  const length = Math.hypot(...RAY);
  castInterpolant(f, iso, cube.corners, size).forEach(({ hit, front }, k) => {
    if (!hit) return;
    const n = trilinearGradient(f, cube.corners, hit);
    const light = Math.abs(n[0] * RAY[0] + n[1] * RAY[1] + n[2] * RAY[2]) / ((Math.hypot(...n) || 1) * length);
    const base = front ? color : [70, 175, 160];
    image.data.set([...base.map((c) => Math.round(c * (0.35 + 0.65 * light))), 255], 4 * k);
  });
  context.putImageData(image, 0, 0);
  context.strokeStyle = 'rgba(160, 160, 170, 0.9)';
  context.lineWidth = 1;
  for (const [a, b] of cube.edges) {
    const [p, q] = [project(cube.corners[a], size), project(cube.corners[b], size)];
    context.beginPath();
    context.moveTo(...p);
    context.lineTo(...q);
    context.stroke();
  }
  for (let c = 0; c < 8; c += 1) {
    const [x, y] = project(cube.corners[c], size);
    context.fillStyle = f[c] > iso ? '#ff9a3d' : '#7aa7ff';
    context.beginPath();
    context.arc(x, y, size / 30, 0, 2 * Math.PI);
    context.fill();
  }
  return canvas;
}
