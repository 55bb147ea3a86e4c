// The cell inspector's box: what marching cubes decided in the selected cell, live as the spheres
// move, with a drawing of the cell; and the gallery of the case classes and their configurations.

import { PICTURE_FRAMES } from '../core/redraw.js';
import { caseGallery } from '../engine/wasm.js';
import { buildGallery, cellDrawing } from './cell-drawing.js';
import { interpolantDrawing } from './interpolant.js';
import { classColor } from './legends.js';

// How often the inspector's figures are refreshed while the spheres move, in ms.
const REFRESH_MS = 200;

const format = (v, digits = 3) => (Math.abs(v) >= 1000 ? v.toExponential(2) : v.toFixed(digits));

/**
 * The cell inspector of one figure: selects cells in its wasm view and shows their reports in the box
 * `#inspector`, with the gallery of configurations in the panel marking the inspected one.
 */
export class Inspector {
  static attributes = ['edit'];
  #ctx;
  #box;
  #report = null;
  #shownAt = 0;
  #gallery = null;
  #shownSubcase = null;

  constructor(ctx) {
    this.#ctx = ctx;
    this.#box = ctx.$('inspector');
    this.#box.addEventListener('click', (e) => {
      if (e.target.closest('.close')) this.deselect();
    });
  }

  #cube() { return caseGallery().cube; }

  // Entering or leaving edit mode lets go of the cell.
  changed() { this.deselect(); }

  afterTick(now) { this.follow(now); }

  panelBuilt() { this.#gallery = null; }

  controls() {
    return { inspector: (panel) => this.#control(panel) };
  }

  // The hint, and the gallery of the cases' configurations, drawn one at a time while the page is idle (all
  // that are left when it is opened), not before the figure's first frame.
  #control({ element, gallery }) {
    const hint = element('p', { className: 'hint', textContent: 'Click the surface to inspect a cell (Esc to let go).' });
    const cases = element('details', { className: 'cases' }, element('summary', { textContent: 'The 15 cases and their 33 configurations' }));
    const idle = (draw) => (globalThis.requestIdleCallback
      ? requestIdleCallback(draw, { timeout: 1000 }) : setTimeout(draw, 0));
    let drawing = null;
    const fill = (all) => {
      if (!cases.isConnected || (drawing && drawing !== this.#gallery)) return;
      if (!drawing) {
        drawing = this.#gallery = buildGallery(gallery, 0);
        cases.append(drawing);
      }
      let more = drawing.more();
      while (all && more) more = drawing.more();
      this.#markClass();
      if (more) idle(() => fill(false));
    };
    cases.addEventListener('toggle', () => fill(true), { once: true });
    idle(() => fill(false));
    return [hint, cases];
  }

  // Marks the inspected cell's configuration in the gallery.
  #markClass() {
    for (const figure of this.#gallery?.children ?? []) {
      figure.classList.toggle('current', figure.dataset.subcase === this.#shownSubcase);
    }
  }

  #onSubcase(name) {
    this.#shownSubcase = name;
    this.#markClass();
  }

  /** Selects the cell under canvas pixel (x, y) (device pixels), or nothing over the background. */
  pick(x, y) {
    const view = this.#ctx.view;
    if (view) this.#update(view.pick_cell(x, y));
  }

  /** Selects cell (x, y, z); returns its report (null outside the grid or before the view starts). */
  select(x, y, z) {
    const view = this.#ctx.view;
    if (view) this.#update(view.select_cell(x, y, z));
    return this.#report;
  }

  /** Lets go of the cell. */
  deselect() {
    this.#ctx.view?.clear_selection();
    if (this.#report) this.#update(null);
  }

  /** Refreshes the shown figures while the spheres move (a few times a second). */
  follow(now) {
    const view = this.#ctx.view;
    if (view && this.#report !== null && now - this.#shownAt > REFRESH_MS) this.#update(view.inspect());
  }

  #update(report) {
    this.show(report ?? null, this.#ctx.state.iso);
    this.#ctx.redraw(PICTURE_FRAMES);
    this.#ctx.emit('metaballs-inspect', { cell: this.#report });
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
      this.#onSubcase(null);
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
    const faces = (report.faces ?? []).map((f) => {
      const plane = `${'xyz'[f.face >> 1]} = ${f.face & 1}`;
      const saddle = f.saddle === null ? 'no saddle' : `saddle ${format(f.saddle)} ${f.deciderJoins ? '&gt;' : '≤'} ${format(iso, 2)}`;
      const decider = f.deciderJoins ? 'the decider joins its inside corners' : 'the decider cuts them apart';
      const drawn = f.joined ? 'joined' : 'cut apart';
      const agree = f.joined === f.deciderJoins;
      const mark = agree ? '' : ' (against the decider)';
      return `<li${agree ? '' : ' class="disagrees"'} data-face="${f.face}">Face ${plane}: ${saddle}: ${decider}; drawn ${drawn}${mark}</li>`;
    }).join('');
    const ambiguous = faces ? `<p>Ambiguous faces (inside corners on a diagonal):</p><ul class="faces">${faces}</ul>` : '';
    // The interior test (MC33): a tunnel joining two loops the faces leave apart.
    const corners = (report.interior ?? []).join(' and ');
    const through = corners
      ? `<p class="interior">Inside the cell: the trilinear interpolant joins corners ${corners} through a saddle; ${report.tunnel
        ? 'drawn as a tunnel (table=mc33)' : 'drawn apart (only table=mc33 draws the tunnel)'}</p>`
      : '';
    this.#box.innerHTML = `
      <header><h3>Cell (${x}, ${y}, ${z})</h3>
        <button type="button" class="close" aria-label="Deselect the cell (Esc)">×</button></header>
      <p>Case <b id="inspector-case">${report.case}</b> = <code>${report.bits}</code> (bit c: corner c inside)
        · class <b id="inspector-class">${report.class}</b>, ${report.className}
        · configuration <b id="inspector-subcase">${report.subcase}</b>${report.drawnSubcase === report.subcase ? ''
          : ` <span class="drawn-subcase">(the table in use draws ${report.drawnSubcase})</span>`}</p>
      <div class="inspector-body">
        <table class="corners"><thead><tr><th>corner</th><th>f</th><th>f &gt; ${format(iso, 2)}?</th></tr></thead>
          <tbody>${rows}</tbody></table>
        <div class="drawing"></div>
      </div>
      <p>Triangles (edges): ${triangles}</p>${ambiguous}${through}
      <table class="crossings"><thead><tr><th>edge</th><th>t</th><th>vertex</th></tr></thead>
        <tbody>${edges}</tbody></table>`;
    this.#box.querySelector('.drawing').append(
      cellDrawing(this.#cube(), inside, report.triangles, (e) => t.get(e) ?? 0.5,
        { size: 96, color: classColor(report.class), label: `case ${report.case}: its triangles` }),
      interpolantDrawing(this.#cube(), report.corners, iso,
        { size: 96, label: `case ${report.case}: the trilinear interpolant of its corner values, ray cast` }));
    this.#box.hidden = false;
    this.#onSubcase(report.subcase);
  }
}
