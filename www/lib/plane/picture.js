// The 2D figure's picture as a list of shapes — filled bands, the grid, the contour, each square's case,
// the samples' values and signs, the crossings, the saddle squares with the value that decided them —
// painted on a canvas or written as SVG from the same list, so the vector export is the picture.
// No DOM: a canvas context is handed in. Its numbers and words are the reader's language; the picture
// itself runs left to right in any.

import { PLANE_TABLE } from '../attributes.js';
import { ENGLISH } from '../i18n/words.js';
import { bands, march } from './squares.js';
import { segmentsBefore, squareAt } from './stepper.js';

/** Everything the picture can show (the `show` attribute's words), and what it shows by default. */
// What the figure can show, and what it shows unless told (the table's `show` row).
const SHOW_ROW = PLANE_TABLE.find((row) => row.name === 'show');
export const SHOWN = SHOW_ROW.words;
export const DEFAULT_SHOWN = SHOW_ROW.default.split(',');

// The smallest square, in pixels, at which each kind of label is drawn.
const MIN_PIXELS = { grid: 4, corners: 7, crossings: 5, cases: 16, values: 34, saddles: 12 };

/** Colours of the two themes (the 3D figure's, written for a flat picture). */
export const THEMES = {
  dark: {
    background: '#14171f', grid: '#3a4152', text: '#d7dbe4', muted: '#8e96a8', inside: '#ff8c1a',
    outside: '#6f7c99', contour: '#ffffff', crossing: '#ffd166', joined: '#4cc9f0', apart: '#ef476f',
    bands: ['#1d2a44', '#22406b', '#2b5d8f', '#3c7fb1', '#58a4cc', '#85c7de'], circle: '#c3cad8',
    step: 'rgba(255, 209, 102, 0.18)',
  },
  light: {
    background: '#f7f7f4', grid: '#c9ccd3', text: '#1f2430', muted: '#5d6577', inside: '#d9480f',
    outside: '#7d8799', contour: '#11141b', crossing: '#b7791f', joined: '#0b7285', apart: '#c2255c',
    bands: ['#eef3f8', '#d6e4f0', '#b7cfe4', '#93b6d6', '#6c9bc6', '#4a80b4'], circle: '#3b4252',
    step: 'rgba(183, 121, 31, 0.2)',
  },
};

const format = (v) => (Math.abs(v) >= 100 ? v.toFixed(0) : Math.abs(v) >= 10 ? v.toFixed(1) : v.toFixed(2));

/** English words, for what is drawn or written without a figure's (tests, tools). */
export { ENGLISH };

// The glyphs a language writes numbers with (decimal sign, minus, digits), by language tag.
const GLYPHS = new Map();

function glyphsOf(lang) {
  if (!GLYPHS.has(lang)) {
    const decimal = new Intl.NumberFormat(lang, { useGrouping: false, minimumFractionDigits: 1 }).formatToParts(-1.5);
    const part = (type, english) => decimal.find((p) => p.type === type)?.value ?? english;
    const digit = new Intl.NumberFormat(lang, { useGrouping: false });
    const glyphs = { '.': part('decimal', '.'), '-': part('minusSign', '-') };
    for (let d = 0; d <= 9; d += 1) glyphs[d] = digit.format(d);
    GLYPHS.set(lang, Object.entries(glyphs).every(([c, g]) => c === g) ? null : glyphs);
  }
  return GLYPHS.get(lang);
}

/**
 * A number as JavaScript writes it (`toFixed`, `String`), in `words`' language: its digits, decimal
 * sign and minus as the language writes them, rounded and as long as written (English as written).
 */
export function numeral(words, text) {
  const glyphs = glyphsOf(words.chain[0]);
  return glyphs ? String(text).replace(/[0-9.-]/g, (c) => glyphs[c]) : String(text);
}

/**
 * The shapes of one frame: `values` sampled on `cells` squares per axis, contoured at `iso` (and at
 * each of `levels`, as lines, and as filled bands between them where `bands` is shown), in a square
 * picture of `size` pixels. `options` are march's (`placement`, `saddle`). With `step` (a step of the
 * stepper, `stepper.js`), the contour is drawn only as far as the march has gone, and the square at
 * that step is lit with its segments and crossings. Its labels are in `words`' language. Returns
 * `{ shapes, result }`, `result` being march's at `iso`.
 */
export function picture({
  values, cells, iso, levels = [], circles = [], shown, options, size, theme = 'dark', step = null, words = ENGLISH,
}) {
  const colors = THEMES[theme] ?? THEMES.dark;
  const written = (v) => numeral(words, format(v));
  const show = new Set(shown);
  // The box [-1, 1]² inside a margin, so the labels of its edge's samples show.
  const margin = Math.round(size * 0.03);
  const inner = size - 2 * margin;
  const px = inner / cells;
  const X = (x) => margin + ((x + 1) / 2) * inner;
  const Y = (y) => margin + ((1 - y) / 2) * inner;
  // Grid point (i, j) on the picture.
  const gx = (i) => margin + i * px;
  const gy = (j) => margin + inner - j * px;
  const shapes = [{ kind: 'rect', x: 0, y: 0, w: size, h: size, fill: colors.background }];
  const ringPath = (rings) => rings.map((ring) => `M${ring.map(([x, y]) => `${X(x).toFixed(2)},${Y(y).toFixed(2)}`).join('L')}Z`).join('');
  const all = [...new Set([...levels, iso])].sort((a, b) => a - b);
  if (show.has('bands') && all.length > 1) {
    for (const [k, band] of bands(values, cells, all, options).entries()) {
      shapes.push({ kind: 'path', d: ringPath(band.rings), fill: colors.bands[Math.min(k, colors.bands.length - 1)], role: 'band', level: band.from });
    }
  }
  const n = cells + 1;
  const at = (i, j) => values[j * n + i];
  if (show.has('grid') && px >= MIN_PIXELS.grid) {
    for (let k = 0; k <= cells; k += 1) {
      shapes.push({ kind: 'line', x1: gx(k), y1: gy(0), x2: gx(k), y2: gy(cells), stroke: colors.grid, width: 1 });
      shapes.push({ kind: 'line', x1: gx(0), y1: gy(k), x2: gx(cells), y2: gy(k), stroke: colors.grid, width: 1 });
    }
  }
  const result = march(values, cells, iso, options);
  if (show.has('contour')) {
    for (const level of all.filter((l) => l !== iso)) {
      shapes.push({ kind: 'path', d: ringPath(march(values, cells, level, options).rings), stroke: colors.muted, width: 1, role: 'level', level });
    }
    const d = step === null ? ringPath(result.rings)
      : segmentsBefore(result, cells, step).map(([p, q]) => `M${X(p[0]).toFixed(2)},${Y(p[1]).toFixed(2)}L${X(q[0]).toFixed(2)},${Y(q[1]).toFixed(2)}`).join('');
    shapes.push({ kind: 'path', d, stroke: colors.contour, width: Math.max(1.5, Math.min(3, px / 8)), role: 'contour', level: iso });
  }
  if (step !== null && step < cells * cells) {
    const [i, j] = squareAt(step, cells);
    const here = result.square(i, j);
    shapes.push({ kind: 'rect', x: gx(i), y: gy(j + 1), w: px, h: px, fill: colors.step, stroke: colors.crossing, width: 2, role: 'step' });
    for (const { points: [p, q] } of here.segments) {
      shapes.push({ kind: 'line', x1: X(p[0]), y1: Y(p[1]), x2: X(q[0]), y2: Y(q[1]), stroke: colors.crossing, width: 3, role: 'step-segment' });
      for (const [x, y] of [p, q]) shapes.push({ kind: 'circle', cx: X(x), cy: Y(y), r: 4, fill: colors.crossing, stroke: 'none', width: 0 });
    }
  }
  if (show.has('cases') && px >= MIN_PIXELS.cases) {
    for (let j = 0; j < cells; j += 1) {
      for (let i = 0; i < cells; i += 1) {
        const c = result.cases[j * cells + i];
        if (c === 0 || c === 15) continue;
        shapes.push({ kind: 'text', x: gx(i + 0.5), y: gy(j + 0.5), text: String(c), fill: colors.muted, size: Math.min(14, px / 3), anchor: 'middle' });
      }
    }
  }
  if (show.has('saddles') && px >= MIN_PIXELS.saddles) {
    for (const s of result.saddles) {
      const [i, j] = s.square;
      const color = s.joined ? colors.joined : colors.apart;
      shapes.push({ kind: 'rect', x: gx(i) + 1.5, y: gy(j + 1) + 1.5, w: px - 3, h: px - 3, stroke: color, width: 1.5, role: 'saddle' });
      const label = s.value === null ? words.t(s.joined ? 'plane.picture.joined' : 'plane.picture.apart')
        : `${written(s.value)} ${s.joined ? '>' : '≤'} ${written(iso)}`;
      if (px >= MIN_PIXELS.values) {
        shapes.push({ kind: 'text', x: gx(i + 0.5), y: gy(j + 0.5) + Math.min(14, px / 3), text: label, fill: color, size: Math.min(12, px / 5), anchor: 'middle' });
      }
    }
  }
  if (show.has('corners') && px >= MIN_PIXELS.corners) {
    const r = Math.min(5, px / 7);
    for (let j = 0; j <= cells; j += 1) {
      for (let i = 0; i <= cells; i += 1) {
        const inside = at(i, j) > iso;
        shapes.push({ kind: 'circle', cx: gx(i), cy: gy(j), r, fill: inside ? colors.inside : 'none', stroke: inside ? colors.inside : colors.outside, width: 1 });
      }
    }
  }
  if (show.has('values') && px >= MIN_PIXELS.values) {
    for (let j = 0; j <= cells; j += 1) {
      for (let i = 0; i <= cells; i += 1) {
        const v = at(i, j);
        shapes.push({ kind: 'text', x: gx(i) + 4, y: gy(j) - 6, text: written(v), fill: v > iso ? colors.inside : colors.text, size: Math.min(12, px / 4.5), anchor: 'start' });
      }
    }
  }
  if (show.has('crossings') && px >= MIN_PIXELS.crossings) {
    const r = Math.min(3.5, px / 10);
    // With the stepper, only the crossings the march has reached.
    const points = step === null ? result.rings.flat() : segmentsBefore(result, cells, step).flat();
    for (const [x, y] of points) shapes.push({ kind: 'circle', cx: X(x), cy: Y(y), r, fill: colors.crossing, stroke: 'none', width: 0 });
  }
  if (show.has('circles')) {
    for (const c of circles) {
      shapes.push({ kind: 'circle', cx: X(c.x), cy: Y(c.y), r: (c.r / 2) * inner, fill: 'none', stroke: colors.circle, width: 1, dash: (c.charge ?? 1) < 0 });
    }
  }
  return { shapes, result };
}

/** Paints `shapes` on a 2D canvas context, scaled by `scale` (device pixels per picture pixel). */
export function paint(context, shapes, scale = 1) {
  context.save();
  context.scale(scale, scale);
  // Numbers and the picture run left to right, whatever the page's direction.
  context.direction = 'ltr';
  for (const s of shapes) {
    context.setLineDash(s.dash ? [4, 3] : []);
    if (s.kind === 'rect') {
      if (s.fill) { context.fillStyle = s.fill; context.fillRect(s.x, s.y, s.w, s.h); }
      if (s.stroke) { context.strokeStyle = s.stroke; context.lineWidth = s.width; context.strokeRect(s.x, s.y, s.w, s.h); }
    } else if (s.kind === 'line') {
      context.strokeStyle = s.stroke;
      context.lineWidth = s.width;
      context.beginPath();
      context.moveTo(s.x1, s.y1);
      context.lineTo(s.x2, s.y2);
      context.stroke();
    } else if (s.kind === 'path') {
      const path = new Path2D(s.d);
      if (s.fill) { context.fillStyle = s.fill; context.fill(path, 'evenodd'); }
      if (s.stroke) { context.strokeStyle = s.stroke; context.lineWidth = s.width; context.lineJoin = 'round'; context.stroke(path); }
    } else if (s.kind === 'circle') {
      context.beginPath();
      context.arc(s.cx, s.cy, s.r, 0, 2 * Math.PI);
      if (s.fill !== 'none') { context.fillStyle = s.fill; context.fill(); }
      if (s.stroke !== 'none' && s.width > 0) { context.strokeStyle = s.stroke; context.lineWidth = s.width; context.stroke(); }
    } else if (s.kind === 'text') {
      context.fillStyle = s.fill;
      context.font = `${s.size.toFixed(1)}px system-ui, sans-serif`;
      context.textAlign = s.anchor === 'middle' ? 'center' : 'left';
      context.textBaseline = 'middle';
      context.fillText(s.text, s.x, s.y);
    }
  }
  context.restore();
}

const escape = (text) => String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);

/** `shapes` as an SVG document of `size` × `size` units, titled `title`. */
export function toSvg(shapes, size, title = '') {
  const attrs = (o) => Object.entries(o).filter(([, v]) => v !== undefined && v !== null).map(([k, v]) => `${k}="${escape(v)}"`).join(' ');
  const paintAttrs = (s) => ({
    fill: s.fill ?? 'none', stroke: s.stroke ?? 'none', 'stroke-width': s.stroke ? s.width : undefined,
    'stroke-dasharray': s.dash ? '4 3' : undefined,
  });
  const body = shapes.map((s) => {
    if (s.kind === 'rect') return `<rect ${attrs({ x: s.x, y: s.y, width: s.w, height: s.h, ...paintAttrs(s), class: s.role })}/>`;
    if (s.kind === 'line') return `<line ${attrs({ x1: s.x1, y1: s.y1, x2: s.x2, y2: s.y2, stroke: s.stroke, 'stroke-width': s.width })}/>`;
    if (s.kind === 'path') {
      return `<path ${attrs({ d: s.d, ...paintAttrs(s), 'fill-rule': s.fill ? 'evenodd' : undefined, 'stroke-linejoin': 'round', class: s.role, 'data-level': s.level })}/>`;
    }
    if (s.kind === 'circle') return `<circle ${attrs({ cx: s.cx.toFixed(2), cy: s.cy.toFixed(2), r: s.r.toFixed(2), ...paintAttrs(s) })}/>`;
    return `<text ${attrs({ x: s.x.toFixed(1), y: s.y.toFixed(1), fill: s.fill, 'font-size': s.size.toFixed(1), 'font-family': 'system-ui, sans-serif', 'text-anchor': s.anchor, 'dominant-baseline': 'middle' })}>${escape(s.text)}</text>`;
  });
  return `<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 ${size} ${size}" width="${size}" height="${size}">`
    + `${title ? `<title>${escape(title)}</title>` : ''}${body.join('')}</svg>`;
}
