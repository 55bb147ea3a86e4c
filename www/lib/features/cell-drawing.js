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

/**
 * The gallery: one drawing per configuration of each class (MC33's 33: the 15 classes, those with
 * ambiguous faces or an ambiguous inside split by how they are joined), with its name and triangles.
 * `count` drawings are made now (all by default); `more()` makes the next one and says whether any is
 * left, so that a page can draw them a few at a time.
 */
export function buildGallery({ classes, cube }, count = Infinity) {
  const list = document.createElement('div');
  list.className = 'gallery';
  const all = classes.flatMap((k) => k.subcases.map((s) => ({ k, s, only: k.subcases.length === 1 })));
  let next = 0;
  list.more = () => {
    const { k, s, only } = all[next++] ?? {};
    if (!k) return false;
    const figure = document.createElement('figure');
    figure.dataset.class = String(k.class);
    figure.dataset.subcase = s.name;
    const triangles = `${s.triangles.length} △`;
    // The faces it joins, and the tunnel where the interior decides between configurations.
    const interior = k.subcases.some((o) => o.tunnel && o.joined === s.joined);
    const inside = s.tunnel ? 'a tunnel inside' : interior ? 'no tunnel' : '';
    const faces = s.ambiguous ? `${s.joined} of ${s.ambiguous} ambiguous faces joined` : '';
    const how = [faces, inside].filter(Boolean).join(', ');
    const short = [s.ambiguous ? `${s.joined}/${s.ambiguous} joined` : '', inside.replace('a tunnel inside', 'tunnel')]
      .filter(Boolean).join(', ');
    const caption = document.createElement('figcaption');
    caption.textContent = only ? `${k.class} · ${k.name} (${k.cases} cases, ${triangles})` : `${s.name} · ${short} (${triangles})`;
    figure.title = `Class ${k.class}, ${k.name} (${k.cases} of the 256 cases)${only ? '' : `: configuration ${s.name}, ${how}`}`;
    figure.append(
      cellDrawing(cube, k.inside, s.triangles, () => 0.5, {
        color: classColor(k.class), label: only ? `class ${k.class}: ${k.name}` : `configuration ${s.name}: ${k.name}, ${how}`,
      }),
      caption,
    );
    list.append(figure);
    return next < all.length;
  };
  while (next < count && list.more());
  return list;
}
