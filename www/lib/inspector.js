// The cell inspector's box (what marching cubes decided in the selected cell, live as the spheres
// move) and the gallery of the 15 case classes, both with small drawings of a cell: corners inside
// filled, triangles where the case puts them.

import { classColor } from './legends.js';

const SVG = 'http://www.w3.org/2000/svg';

// An oblique view of the unit cube, `size` pixels square.
function project([x, y, z], size) {
  const s = size / 64;
  return [s * (10 + 34 * x + 16 * z), s * (54 - 34 * y - 12 * z)];
}

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

/** The gallery: one drawing per class, with its number, name and how many of the 256 cases it holds. */
export function buildGallery({ classes, cube }) {
  const list = document.createElement('div');
  list.className = 'gallery';
  for (const k of classes) {
    const figure = document.createElement('figure');
    figure.dataset.class = String(k.class);
    const caption = document.createElement('figcaption');
    caption.textContent = `${k.class} · ${k.name} (${k.cases} cases, ${k.triangleCount} △)`;
    figure.append(
      cellDrawing(cube, k.inside, k.triangles, () => 0.5, {
        color: classColor(k.class), label: `class ${k.class}: ${k.name}`,
      }),
      caption,
    );
    list.append(figure);
  }
  return list;
}

// How often the inspector's figures are refreshed while the spheres move, in ms.
const REFRESH_MS = 200;

const format = (v, digits = 3) => (Math.abs(v) >= 1000 ? v.toExponential(2) : v.toFixed(digits));

/**
 * The cell inspector of one figure: selects cells in its wasm view and shows their reports in the box
 * `#inspector` of `root`.
 */
export class Inspector {
  #box;
  #cube;
  #host;
  #report = null;
  #shownAt = 0;

  /**
   * `host` has view() (the wasm view or null), iso(), onShow(report) after each change or refresh,
   * and onClass(k) to mark class k in the gallery (null for none).
   */
  constructor(root, cube, host) {
    this.#box = root.getElementById('inspector');
    this.#cube = cube;
    this.#host = host;
    this.#box.addEventListener('click', (e) => {
      if (e.target.closest('.close')) this.deselect();
    });
  }

  /** Selects the cell under canvas pixel (x, y) (device pixels), or nothing over the background. */
  pick(x, y) {
    const view = this.#host.view();
    if (view) this.#update(view.pick_cell(x, y));
  }

  /** Selects cell (x, y, z); returns its report (null outside the grid or before the view starts). */
  select(x, y, z) {
    const view = this.#host.view();
    if (view) this.#update(view.select_cell(x, y, z));
    return this.#report;
  }

  /** Lets go of the cell. */
  deselect() {
    this.#host.view()?.clear_selection();
    if (this.#report) this.#update(null);
  }

  /** Refreshes the shown figures while the spheres move (a few times a second). */
  follow(now) {
    const view = this.#host.view();
    if (view && this.#report !== null && now - this.#shownAt > REFRESH_MS) this.#update(view.inspect());
  }

  #update(report) {
    this.show(report ?? null, this.#host.iso());
    this.#host.onShow(this.#report);
  }

  /** The report shown, or null. */
  get report() {
    return this.#report;
  }

  /** Shows `report` (from `View.inspect`), or hides the box for null. */
  show(report, iso) {
    this.#report = report;
    this.#shownAt = performance.now();
    if (!report) {
      this.#box.hidden = true;
      this.#host.onClass(null);
      return;
    }
    const [x, y, z] = report.cell;
    const inside = [...report.corners.keys()].filter((c) => report.corners[c] > iso);
    const t = new Map(report.edges.map((e) => [e.edge, e.t]));
    const rows = report.corners.map((v, c) => {
      const sign = v > iso ? '<b class="in">in</b>' : '<span class="out">out</span>';
      return `<tr><td>${c}</td><td>${format(v)}</td><td>${sign}</td></tr>`;
    }).join('');
    const edges = report.edges.map((e) => {
      const [a, b] = this.#cube().edges[e.edge];
      const p = e.vertex.map((v) => v.toFixed(3)).join(', ');
      return `<tr><td>${e.edge} (${a}–${b})</td><td>${e.t.toFixed(3)}</td><td>(${p})</td></tr>`;
    }).join('');
    const triangles = report.triangles.map((tri) => tri.join('–')).join(', ') || 'none';
    this.#box.innerHTML = `
      <header><h3>Cell (${x}, ${y}, ${z})</h3>
        <button type="button" class="close" aria-label="Deselect the cell (Esc)">×</button></header>
      <p>Case <b id="inspector-case">${report.case}</b> = <code>${report.bits}</code> (bit c: corner c inside)
        · class <b id="inspector-class">${report.class}</b>, ${report.className}</p>
      <div class="inspector-body">
        <table class="corners"><thead><tr><th>corner</th><th>f</th><th>f &gt; ${format(iso, 2)}?</th></tr></thead>
          <tbody>${rows}</tbody></table>
        <div class="drawing"></div>
      </div>
      <p>Triangles (edges): ${triangles}</p>
      <table class="crossings"><thead><tr><th>edge</th><th>t</th><th>vertex</th></tr></thead>
        <tbody>${edges}</tbody></table>`;
    this.#box.querySelector('.drawing').append(cellDrawing(this.#cube(), inside, report.triangles,
      (e) => t.get(e) ?? 0.5, { size: 96, color: classColor(report.class), label: `case ${report.case}` }));
    this.#box.hidden = false;
    this.#host.onClass(report.class);
  }
}
