// The "error vs resolution" plot of the Teaching group: the current spheres meshed on the CPU at a sweep
// of resolutions, with linear and midpoint placement, one resolution per idle moment (the figure keeps
// drawing), then RMS and largest distance to the exact surface and the triangle count against cells
// per axis, log-log, with the fitted slopes. Linear placement falls about as h², midpoints as h.

import { wasmModule } from '../engine/wasm.js';

const RESOLUTIONS = [8, 12, 16, 24, 32, 48, 64];
const PLACEMENTS = [
  { name: 'linear', midpoint: false, color: '#4aa3ff' },
  { name: 'midpoint', midpoint: true, color: '#ff9f43' },
];
const SVG = 'http://www.w3.org/2000/svg';

/** Least-squares slope of log y against log x, as the crate fits it (null with fewer than two usable points). */
const fittedSlope = (points) => wasmModule().fitted_slope(points.map((p) => p[0]), points.map((p) => p[1])) ?? null;

const idle = () => new Promise((resolve) => (globalThis.requestIdleCallback ?? setTimeout)(resolve, { timeout: 200 }));

/**
 * Sweeps the resolutions with `view()`'s `error_at`, writing progress into `status`; resolves to
 * { linear: [{ n, rms, max, triangles }], midpoint: […], slopes: { linear: { rms, max }, … } }.
 */
export async function sweepErrors(view, status) {
  const result = { slopes: {} };
  const total = RESOLUTIONS.length * PLACEMENTS.length;
  let done = 0;
  for (const placement of PLACEMENTS) {
    const points = [];
    for (const n of RESOLUTIONS) {
      status(`Meshing ${n}³ with ${placement.name} placement (${done + 1} of ${total})…`, done / total);
      await idle();
      const v = view();
      if (!v) throw new Error('the figure is not drawing');
      const [rms, max, triangles] = v.error_at(n, placement.midpoint);
      points.push({ n, rms, max, triangles });
      done += 1;
    }
    result[placement.name] = points;
    result.slopes[placement.name] = {
      rms: fittedSlope(points.map((p) => [p.n, p.rms])),
      max: fittedSlope(points.map((p) => [p.n, p.max])),
    };
  }
  result.slopes.triangles = fittedSlope(result.linear.map((p) => [p.n, p.triangles]));
  status('', 1);
  return result;
}

function node(tag, attributes = {}, text = '') {
  const element = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attributes)) element.setAttribute(k, String(v));
  if (text) element.textContent = text;
  return element;
}

/** The log-log plot of a sweep, as an SVG element with a text description. */
export function plotErrors(result) {
  const [w, h, left, right, top, bottom] = [260, 170, 40, 8, 8, 26];
  const all = PLACEMENTS.flatMap((p) => result[p.name].flatMap((q) => [q.rms, q.max])).filter((v) => v > 0);
  const [yLow, yHigh] = [Math.log10(Math.min(...all)), Math.log10(Math.max(...all))];
  const [xLow, xHigh] = [Math.log10(RESOLUTIONS[0]), Math.log10(RESOLUTIONS.at(-1))];
  const x = (n) => left + ((Math.log10(n) - xLow) / (xHigh - xLow)) * (w - left - right);
  const y = (v) => top + (1 - (Math.log10(v) - Math.floor(yLow)) / (Math.ceil(yHigh) - Math.floor(yLow))) * (h - top - bottom);
  const svg = node('svg', { viewBox: `0 0 ${w} ${h}`, role: 'img' });
  const lines = [];
  for (let e = Math.floor(yLow); e <= Math.ceil(yHigh); e += 1) {
    svg.append(node('line', { x1: left, x2: w - right, y1: y(10 ** e), y2: y(10 ** e), class: 'grid' }));
    svg.append(node('text', { x: left - 4, y: y(10 ** e) + 3, 'text-anchor': 'end' }, `1e${e}`));
  }
  for (const n of RESOLUTIONS) {
    svg.append(node('text', { x: x(n), y: h - bottom + 12, 'text-anchor': 'middle' }, String(n)));
  }
  svg.append(node('text', { x: (left + w) / 2, y: h - 2, 'text-anchor': 'middle' }, 'cells per axis'));
  for (const p of PLACEMENTS) {
    for (const [key, dash] of [['rms', ''], ['max', '4 3']]) {
      const path = result[p.name].filter((q) => q[key] > 0).map((q, i) => `${i ? 'L' : 'M'}${x(q.n).toFixed(1)},${y(q[key]).toFixed(1)}`).join('');
      svg.append(node('path', { d: path, stroke: p.color, 'stroke-dasharray': dash, fill: 'none', 'stroke-width': 1.6 }));
    }
    const s = result.slopes[p.name];
    lines.push(`${p.name}: RMS slope ${s.rms?.toFixed(2)}, max slope ${s.max?.toFixed(2)}`);
  }
  const description = `Error against cells per axis, log-log. ${lines.join('; ')}; triangles grow with slope ${result.slopes.triangles?.toFixed(2)}.`;
  svg.setAttribute('aria-label', description);
  return { svg, description, lines };
}

/** The feature: the panel's "Error vs resolution" button and its plot. */
export class ErrorPlot {
  #ctx;

  constructor(ctx) {
    this.#ctx = ctx;
  }

  controls() {
    return { 'error-plot': (panel) => this.#control(panel) };
  }

  #control({ element, makeButton }) {
    const status = element('p', { className: 'hint', role: 'status' });
    const plot = element('figure', { className: 'error-plot' });
    const button = makeButton('error-plot', 'Error vs resolution',
      'Mesh these spheres at 8³ to 64³ on the CPU and plot the distance to the exact surface', async () => {
        button.disabled = true;
        try {
          const result = await sweepErrors(() => this.#ctx.view, (text) => { status.textContent = text; });
          const { svg, lines } = plotErrors(result);
          const caption = element('figcaption', {});
          caption.innerHTML = '<span style="color:#4aa3ff">■</span> linear · <span style="color:#ff9f43">■</span> midpoint · solid RMS, dashed max<br>';
          caption.append(lines.join(' · '), ` · triangles ∝ n^${result.slopes.triangles?.toFixed(2)}`);
          plot.replaceChildren(svg, caption);
        } catch (error) {
          status.textContent = `The plot stopped: ${error?.message ?? error}`;
        } finally {
          button.disabled = false;
        }
      });
    return [element('div', { className: 'buttons' }, button), status, plot];
  }
}
