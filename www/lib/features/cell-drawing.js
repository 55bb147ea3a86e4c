// Small drawings of a cell (corners inside filled, triangles where the case puts them), for the cell
// inspector's box and the gallery of the case classes and their configurations.

import { project } from './interpolant.js';
import { classColor } from './legends.js';

const SVG = 'http://www.w3.org/2000/svg';

/**
 * A drawing of a cell: its edges, the triangles (edge-number triples) with vertex `t` along each edge
 * (`t(e)`, 0.5 for the gallery), and its corners filled when inside.
 */
export function cellDrawing(cube, inside, triangles, t, { size = 64, color = '#e77661', label = '' } = {}) {
  const svg = document.createElementNS(SVG, 'svg');
  svg.setAttribute('viewBox', `0 0 ${size} ${size}`);
  svg.setAttribute('width', String(size));
  svg.setAttribute('height', String(size));
  svg.setAttribute('role', 'img');
  // The drawing does not mirror where the words run right to left.
  svg.setAttribute('direction', 'ltr');
  if (label) svg.setAttribute('aria-label', label);
  const add = (name, attributes) => {
    const node = document.createElementNS(SVG, name);
    for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, String(value));
    svg.append(node);
    return node;
  };
  const corner = (c) => project(cube.corners[c], size);
  for (const [a, b] of cube.edges) {
    const [p, q] = [corner(a), corner(b)];
    add('line', { x1: p[0], y1: p[1], x2: q[0], y2: q[1], class: 'edge' });
  }
  const vertex = (e) => {
    const [a, b] = cube.edges[e];
    const [p, q] = [cube.corners[a], cube.corners[b]];
    const f = t(e);
    return project(p.map((v, i) => v + (q[i] - v) * f), size);
  };
  for (const triangle of triangles) {
    const points = triangle.map((e) => vertex(e).map((v) => v.toFixed(1)).join(',')).join(' ');
    add('polygon', { points, fill: color, class: 'triangle' });
  }
  for (let c = 0; c < 8; c += 1) {
    const [x, y] = corner(c);
    add('circle', { cx: x, cy: y, r: size / 18, class: inside.includes(c) ? 'inside' : 'outside' });
    if (size >= 90) add('text', { x: x + 5, y: y - 4, class: 'corner-number' }).textContent = String(c);
  }
  return svg;
}

/** The name of class `k` of the cases, in the reader's language. */
export const className = (words, k) => words.t(`inspector.class.${k}`);

/**
 * The gallery: one drawing per configuration of each class (MC33's 33: the 15 classes, those with
 * ambiguous faces or an ambiguous inside split by how they are joined), with its name and triangles.
 * `count` drawings are made now (all by default); `more()` makes the next one and says whether any is
 * left, so that a page can draw them a few at a time. Its words are `words`'; `language(words)`
 * rewords the drawings made and those to come.
 */
export function buildGallery({ classes, cube }, count = Infinity, words) {
  const list = document.createElement('div');
  list.className = 'gallery';
  const all = classes.flatMap((k) => k.subcases.map((s) => ({ k, s, only: k.subcases.length === 1 })));
  const worded = [];
  let next = 0;
  list.more = () => {
    const { k, s, only } = all[next++] ?? {};
    if (!k) return false;
    const figure = document.createElement('figure');
    figure.dataset.class = String(k.class);
    figure.dataset.subcase = s.name;
    const caption = document.createElement('figcaption');
    const drawing = cellDrawing(cube, k.inside, s.triangles, () => 0.5, { color: classColor(k.class) });
    figure.append(drawing, caption);
    const word = (w) => {
      const fields = { class: k.class, name: className(w, k.class), count: k.cases, configuration: s.name, triangles: s.triangles.length };
      if (only) {
        caption.textContent = w.t('inspector.gallery-class', fields);
        figure.title = w.t('inspector.gallery-class-title', fields);
        drawing.setAttribute('aria-label', w.t('inspector.gallery-class-label', fields));
        return;
      }
      // The faces it joins, and the tunnel where the interior decides between configurations.
      const interior = k.subcases.some((o) => o.tunnel && o.joined === s.joined);
      const inside = s.tunnel ? 'tunnel' : interior ? 'no-tunnel' : '';
      const faces = { joined: s.joined, ambiguous: s.ambiguous, count: s.ambiguous };
      const short = [s.ambiguous ? w.t('inspector.gallery-joined-short', faces) : '',
        inside ? w.t(`inspector.gallery-${inside === 'tunnel' ? 'tunnel-short' : inside}`) : ''].filter(Boolean);
      const how = w.list([s.ambiguous ? w.t('inspector.gallery-joined', faces) : '',
        inside ? w.t(`inspector.gallery-${inside}`) : ''].filter(Boolean), 'unit');
      caption.textContent = w.t('inspector.gallery-configuration', { ...fields, how: w.list(short, 'unit') });
      figure.title = w.t('inspector.gallery-configuration-title', { ...fields, how });
      drawing.setAttribute('aria-label', w.t('inspector.gallery-configuration-label', { ...fields, how }));
    };
    word(words);
    worded.push(word);
    list.append(figure);
    return next < all.length;
  };
  list.language = (w) => {
    words = w;
    for (const word of worded) word(w);
  };
  while (next < count && list.more());
  return list;
}
