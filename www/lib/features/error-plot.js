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
 * Sweeps the resolutions with `view()`'s `error_at`, writing progress into `status` worded by
 * `words.t(key, fields)`; resolves to { linear: [{ n, rms, max, triangles }], midpoint: […],
 * slopes: { linear: { rms, max }, … } }.
 */
export async function sweepErrors(view, status, words) {
  const result = { slopes: {} };
  const total = RESOLUTIONS.length * PLACEMENTS.length;
  let done = 0;
  for (const placement of PLACEMENTS) {
    const points = [];
    for (const n of RESOLUTIONS) {
      status(words.t(`error-plot.meshing-${placement.name}`, { n, step: done + 1, steps: total }), done / total);
      await idle();
      const v = view();
      if (!v) throw Object.assign(new Error('the figure is not drawing'), { code: 'not-drawing' });
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

/** A fitted slope written for the reader. */
const slope = (words, value) => (value === null || value === undefined ? words.t('error-plot.no-slope') : words.fixed(value, 2));

function node(tag, attributes = {}, text = '') {
  const element = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attributes)) element.setAttribute(k, String(v));
  if (text) element.textContent = text;
  return element;
}

/** The log-log plot of a sweep in `words`, as an SVG element with a text description. */
export function plotErrors(result, words) {
  const [w, h, left, right, top, bottom] = [260, 170, 40, 8, 8, 26];
  const all = PLACEMENTS.flatMap((p) => result[p.name].flatMap((q) => [q.rms, q.max])).filter((v) => v > 0);
  const [yLow, yHigh] = [Math.log10(Math.min(...all)), Math.log10(Math.max(...all))];
  const [xLow, xHigh] = [Math.log10(RESOLUTIONS[0]), Math.log10(RESOLUTIONS.at(-1))];
  const x = (n) => left + ((Math.log10(n) - xLow) / (xHigh - xLow)) * (w - left - right);
  const y = (v) => top + (1 - (Math.log10(v) - Math.floor(yLow)) / (Math.ceil(yHigh) - Math.floor(yLow))) * (h - top - bottom);
  // The plot does not mirror where the words run right to left.
  const svg = node('svg', { viewBox: `0 0 ${w} ${h}`, role: 'img', direction: 'ltr' });
  const lines = [];
  for (let e = Math.floor(yLow); e <= Math.ceil(yHigh); e += 1) {
    svg.append(node('line', { x1: left, x2: w - right, y1: y(10 ** e), y2: y(10 ** e), class: 'grid' }));
    svg.append(node('text', { x: left - 4, y: y(10 ** e) + 3, 'text-anchor': 'end' }, words.t('error-plot.tick', { exponent: e })));
  }
  for (const n of RESOLUTIONS) {
    svg.append(node('text', { x: x(n), y: h - bottom + 12, 'text-anchor': 'middle' }, words.number(n)));
  }
  svg.append(node('text', { x: (left + w) / 2, y: h - 2, 'text-anchor': 'middle', direction: words.dir }, words.t('error-plot.axis')));
  for (const p of PLACEMENTS) {
    for (const [key, dash] of [['rms', ''], ['max', '4 3']]) {
      const path = result[p.name].filter((q) => q[key] > 0).map((q, i) => `${i ? 'L' : 'M'}${x(q.n).toFixed(1)},${y(q[key]).toFixed(1)}`).join('');
      svg.append(node('path', { d: path, stroke: p.color, 'stroke-dasharray': dash, fill: 'none', 'stroke-width': 1.6 }));
    }
    const s = result.slopes[p.name];
    lines.push(words.t(`error-plot.slopes-${p.name}`, { rms: slope(words, s.rms), max: slope(words, s.max) }));
  }
  const description = words.t('error-plot.description', { slopes: lines.join('; '), slope: slope(words, result.slopes.triangles) });
  svg.setAttribute('aria-label', description);
  return { svg, description, lines };
}

/** The feature: the panel's "Error vs resolution" button and its plot. */
export class ErrorPlot {
  #ctx;
  // The plot's box and its status, the sweep it shows, or the error that stopped it.
  #shown = null;

  constructor(ctx) {
    this.#ctx = ctx;
  }

  // The plot and its caption in the reader's language.
  language() {
    if (!this.#shown?.plot.isConnected) return;
    const { plot, status, result, error } = this.#shown;
    if (result) this.#draw(plot, result);
    if (error) status.textContent = this.#stopped(error);
  }

  // What the status says when the sweep stopped.
  #stopped(error) {
    const reason = error?.code === 'not-drawing' ? this.#ctx.t('error-plot.not-drawing') : this.#ctx.words.refusal(error);
    return this.#ctx.t('error-plot.stopped', { reason });
  }

  #draw(plot, result) {
    const words = this.#ctx.words;
    const { svg, lines } = plotErrors(result, words);
    const caption = document.createElement('figcaption');
    const square = (color) => {
      const span = document.createElement('span');
      span.style.color = color;
      span.textContent = '■';
      return span;
    };
    caption.append(square('#4aa3ff'), ` ${words.t('error-plot.linear')} · `, square('#ff9f43'),
      ` ${words.t('error-plot.midpoint')} · ${words.t('error-plot.styles')}`, document.createElement('br'),
      lines.join(' · '), ` · ${words.t('error-plot.triangles', { slope: slope(words, result.slopes.triangles) })}`);
    plot.replaceChildren(svg, caption);
  }

  controls() {
    return { 'error-plot': (panel) => this.#control(panel) };
  }

  #control({ element, makeButton }) {
    const status = element('p', { className: 'hint', role: 'status' });
    const plot = element('figure', { className: 'error-plot' });
    const button = makeButton('error-plot', this.#ctx.t('action.error-plot'), this.#ctx.t('error-plot.title'), async () => {
      button.disabled = true;
      const shown = this.#shown = { plot, status, result: null, error: null };
      try {
        shown.result = await sweepErrors(() => this.#ctx.view, (text) => { status.textContent = text; }, this.#ctx);
        this.#draw(plot, shown.result);
      } catch (error) {
        shown.error = error;
        status.textContent = this.#stopped(error);
      } finally {
        button.disabled = false;
      }
    });
    button.dataset.t = 'action.error-plot';
    button.dataset.tTitle = 'error-plot.title';
    return [element('div', { className: 'buttons' }, button), status, plot];
  }
}
