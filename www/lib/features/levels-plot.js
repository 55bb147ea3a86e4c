// The drawings of the "Along the iso level" panel: the surface's blobs, genus, area and volume against
// the iso level (log axis) with every critical level marked and the current level a cursor that can be
// dragged, and the merge tree of the blobs (leaves the spheres, joins at their saddles' levels), each
// join a button. SVG, from a search's result (lib/engine/levels.js); no state of their own.

import { rowOf } from '../core/table.js';

const SVG = 'http://www.w3.org/2000/svg';

/** The iso level the table accepts nearest to `value`, to four significant digits. */
export function isoWithin(value) {
  const { min, max } = rowOf('iso');
  return Number(Math.min(max, Math.max(min, value)).toPrecision(4));
}

/** Colours of the critical points by what they do, as the markers in the figure show them. */
export const ROLE_COLORS = {
  join: '#ff9f43', loop: '#f368e0', hole: '#4aa3ff', cavity: '#54a0ff', fill: '#10ac84', birth: '#feca57', unresolved: '#8395a7',
};

/** What critical point `p` does as the iso level falls past it, with its level: "f = 0.7812: two blobs join". */
export const criticalLevel = (words, p) => words.t('critical.level', {
  value: writeLevel(words, p.value), what: words.t(`critical.role.${p.role}`),
});

function node(tag, attributes = {}, text = '') {
  const element = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attributes)) element.setAttribute(k, String(v));
  if (text) element.textContent = text;
  return element;
}

/** The iso range the plot spans: a little beyond the critical levels above zero. */
export function plotRange(result, iso) {
  const { min, max } = rowOf('iso');
  const levels = result.points.map((p) => p.value).filter((v) => v > 0);
  const low = Math.min(iso, ...levels, result.wallLevel > 0 ? result.wallLevel : Infinity);
  const high = Math.max(iso, ...levels);
  return [Math.max(min, low / 2), Math.min(max, Math.max(high * 2, low * 4))];
}

/** Sphere numbers as a list: "0, 1, 2". */
export const spheres = (words, list) => words.list(list.map((k) => words.number(k)), 'unit');

/** Round to four significant digits, as the iso level is written. */
export const round4 = (v) => Number(v.toPrecision(4));

/** `v` to four significant digits, written for the reader. */
export const writeLevel = (words, v) => words.number(round4(v), 12);

/**
 * The plot: `{ svg, xToIso }`. `measures` (optional) gives `[[area, volume], …]` at `levels`.
 * `onIso(value)` is called as the cursor is dragged or moved with the keys. Its words are `words`'.
 */
export function drawPlot(result, iso, { measures = null, levels = [], onIso, onDrag = () => {}, words }) {
  const [w, h, left, right, top, bottom] = [280, 150, 26, 8, 8, 24];
  const [low, high] = plotRange(result, iso);
  const x = (v) => left + ((Math.log10(v) - Math.log10(low)) / (Math.log10(high) - Math.log10(low))) * (w - left - right);
  const xToIso = (px) => 10 ** (Math.log10(low) + ((px - left) / (w - left - right)) * (Math.log10(high) - Math.log10(low)));
  const bands = result.bands;
  const most = Math.max(1, ...bands.map((b) => Math.max(b.surfaces, b.genus)));
  const y = (count) => top + (1 - count / most) * (h - top - bottom);
  // The plot does not mirror where the words run right to left.
  const svg = node('svg', { viewBox: `0 0 ${w} ${h}`, class: 'levels-plot', direction: 'ltr' });
  if (result.wallLevel > low) {
    svg.append(node('rect', { x: left, y: top, width: Math.max(0, x(Math.min(result.wallLevel, high)) - left), height: h - top - bottom, class: 'walls' }));
  }
  for (let c = 0; c <= most; c += Math.max(1, Math.ceil(most / 4))) {
    svg.append(node('line', { x1: left, x2: w - right, y1: y(c), y2: y(c), class: 'grid' }));
    svg.append(node('text', { x: left - 4, y: y(c) + 3, 'text-anchor': 'end' }, words.number(c)));
  }
  for (let e = Math.ceil(Math.log10(low)); e <= Math.floor(Math.log10(high)); e += 1) {
    svg.append(node('text', { x: x(10 ** e), y: h - bottom + 11, 'text-anchor': 'middle' }, words.number(10 ** e, 12)));
  }
  svg.append(node('text', { x: (left + w) / 2, y: h - 2, 'text-anchor': 'middle', direction: words.dir }, words.t('levels.axis')));
  // Area and volume, each scaled to the plot's height.
  if (measures && levels.length) {
    for (const [k, color] of [[0, '#5ec962'], [1, '#21918c']]) {
      const largest = Math.max(...measures.map((m) => m[k]), 1e-9);
      const d = levels.filter((v) => v > low && v < high)
        .map((v, i) => `${i ? 'L' : 'M'}${x(v).toFixed(1)},${y((measures[levels.indexOf(v)][k] / largest) * most).toFixed(1)}`).join('');
      svg.append(node('path', { d, stroke: color, fill: 'none', 'stroke-width': 1, 'stroke-dasharray': k ? '2 2' : '' }));
    }
  }
  // Blobs (surfaces) and genus: steps between the critical levels.
  for (const [key, color, dash] of [['surfaces', '#e77661', ''], ['genus', '#4aa3ff', '4 3']]) {
    let d = '';
    for (const b of bands) {
      const [a, c] = [Math.min(high, b.above ?? high), Math.max(low, b.below)];
      if (a <= low || c >= high) continue;
      d += `${d ? 'L' : 'M'}${x(a).toFixed(1)},${y(b[key]).toFixed(1)}L${x(c).toFixed(1)},${y(b[key]).toFixed(1)}`;
    }
    svg.append(node('path', { d, stroke: color, fill: 'none', 'stroke-width': 1.8, 'stroke-dasharray': dash }));
  }
  for (const p of result.points) {
    if (p.value <= low || p.value >= high) continue;
    const tick = node('line', { x1: x(p.value), x2: x(p.value), y1: top, y2: h - bottom, stroke: ROLE_COLORS[p.role], 'stroke-width': 1, opacity: 0.8 });
    tick.append(node('title', {}, criticalLevel(words, p)));
    svg.append(tick);
  }
  const cursor = node('g', {
    class: 'cursor', tabindex: 0, role: 'slider', 'aria-label': words.t('setting.iso'), 'aria-valuenow': iso,
    'aria-valuemin': round4(low), 'aria-valuemax': round4(high), 'aria-valuetext': words.t('levels.cursor', { iso: writeLevel(words, iso) }),
  });
  // A finger's target: 26 units wide (at least 24 CSS px as the plot is drawn), the whole plot high.
  cursor.append(node('rect', { x: x(iso) - 13, y: top - 6, width: 26, height: h - bottom - top + 6, class: 'hit' }));
  cursor.append(node('line', { x1: x(iso), x2: x(iso), y1: top - 4, y2: h - bottom, class: 'cursor-line' }));
  cursor.append(node('rect', { x: x(iso) - 5, y: top - 6, width: 10, height: 8, rx: 2, class: 'cursor-grip' }));
  svg.append(cursor);
  const toIso = (event) => {
    const box = svg.getBoundingClientRect();
    return isoWithin(Math.min(high, Math.max(low, xToIso(((event.clientX - box.left) / box.width) * w))));
  };
  svg.addEventListener('pointerdown', (event) => {
    if (event.button !== 0) return;
    svg.setPointerCapture?.(event.pointerId);
    onDrag(true);
    onIso(toIso(event));
    const move = (e) => onIso(toIso(e));
    const end = () => {
      for (const [type, f] of [['pointermove', move], ['pointerup', end], ['pointercancel', end], ['lostpointercapture', end]]) {
        svg.removeEventListener(type, f);
      }
      onDrag(false);
    };
    svg.addEventListener('pointermove', move);
    for (const type of ['pointerup', 'pointercancel', 'lostpointercapture']) svg.addEventListener(type, end);
  });
  // Arrows move 2 %; Page Up and Page Down jump past the next critical level.
  cursor.addEventListener('keydown', (event) => {
    const levels = result.points.map((p) => p.value).filter((v) => v > 0);
    const levelsAbove = levels.filter((v) => v > iso * 1.0001).sort((a, b) => a - b);
    const levelsBelow = levels.filter((v) => v < iso * 0.9999).sort((a, b) => b - a);
    const moves = {
      ArrowRight: iso * 1.02, ArrowUp: iso * 1.02, ArrowLeft: iso / 1.02, ArrowDown: iso / 1.02,
      PageUp: levelsAbove.length ? levelsAbove[0] * 1.01 : null, PageDown: levelsBelow.length ? levelsBelow[0] * 0.99 : null,
    };
    if (!(event.key in moves) || moves[event.key] === null) return;
    event.preventDefault();
    onIso(isoWithin(moves[event.key]));
  });
  // Moves the cursor to `value` without drawing the plot again (while it is dragged).
  const moveCursor = (value) => {
    cursor.setAttribute('transform', `translate(${(x(value) - x(iso)).toFixed(1)} 0)`);
    cursor.setAttribute('aria-valuenow', value);
    cursor.setAttribute('aria-valuetext', words.t('levels.cursor', { iso: writeLevel(words, value) }));
  };
  return { svg, xToIso, moveCursor };
}

/**
 * The merge tree: leaves (the adding spheres) on top, each join at its saddle's level, a button. Its
 * words are `words`'.
 */
export function drawTree(result, iso, onJoin, words) {
  const [w, h, top, bottom, left] = [280, 130, 14, 16, 26];
  const tree = result.tree;
  if (!tree.length) return node('svg', { viewBox: `0 0 ${w} 20` });
  const roots = tree.map((_, k) => k).filter((k) => !tree.some((n) => n.children.includes(k)));
  const order = [];
  const visit = (k) => (tree[k].children.length ? tree[k].children.forEach(visit) : order.push(k));
  roots.forEach(visit);
  const joins = tree.filter((n) => n.value !== null && n.value > 0).map((n) => n.value);
  const [low, high] = joins.length ? [Math.min(...joins, iso) / 1.5, Math.max(...joins, iso) * 1.5] : [iso / 2, iso * 2];
  const y = (v) => (v === null ? top
    : top + 6 + ((Math.log10(high) - Math.log10(Math.min(high, Math.max(low, v)))) / (Math.log10(high) - Math.log10(low))) * (h - top - bottom - 6));
  const xOf = new Map();
  order.forEach((k, i) => xOf.set(k, left + ((i + 0.5) / order.length) * (w - left - 8)));
  const x = (k) => {
    if (!xOf.has(k)) xOf.set(k, tree[k].children.reduce((s, c) => s + x(c), 0) / tree[k].children.length);
    return xOf.get(k);
  };
  const svg = node('svg', {
    viewBox: `0 0 ${w} ${h}`, class: 'merge-tree', role: 'group', 'aria-label': words.t('levels.merge-tree'), direction: 'ltr',
  });
  svg.append(node('line', { x1: left, x2: w - 8, y1: y(iso), y2: y(iso), class: 'cursor-line' }));
  svg.append(node('text', { x: 2, y: y(iso) + 3 }, words.t('levels.tree-iso')));
  tree.forEach((n, k) => {
    if (!n.children.length) {
      svg.append(node('text', { x: x(k), y: top - 4, 'text-anchor': 'middle' }, n.spheres.length ? words.number(n.spheres[0]) : '·'));
      return;
    }
    const [a, b] = n.children;
    const level = y(n.value);
    for (const c of [a, b]) svg.append(node('path', { d: `M${x(c)},${y(tree[c].value)}V${level}`, class: 'branch' }));
    svg.append(node('line', { x1: x(a), x2: x(b), y1: level, y2: level, class: 'branch' }));
    const [left, right] = [tree[a].spheres, tree[b].spheres];
    const fields = { a: spheres(words, left), b: spheres(words, right), value: writeLevel(words, n.value) };
    const label = words.t('critical.join', fields);
    const button = node('g', { class: 'join', tabindex: 0, role: 'button', 'aria-label': label, 'data-node': k });
    button.append(node('circle', { cx: x(k), cy: level, r: 13, class: 'hit' }));
    button.append(node('circle', { cx: x(k), cy: level, r: 4.5, fill: ROLE_COLORS.join }));
    button.append(node('title', {}, words.t('critical.join-title', fields)));
    const choose = (event) => { event.preventDefault(); onJoin(k); };
    button.addEventListener('click', choose);
    button.addEventListener('keydown', (event) => (event.key === 'Enter' || event.key === ' ') && choose(event));
    svg.append(button);
  });
  return svg;
}
