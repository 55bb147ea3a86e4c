// The cell inspector's box: what marching cubes decided in the selected cell, live as the spheres
// move, with a drawing of the cell; and the gallery of the case classes and their configurations.

import { PICTURE_FRAMES } from '../core/redraw.js';
import { caseGallery } from '../engine/wasm.js';
import { buildGallery, cellDrawing, className } from './cell-drawing.js';
import { interpolantDrawing } from './interpolant.js';
import { classColor } from './legends.js';

// How often the inspector's figures are refreshed while the spheres move, in ms.
const REFRESH_MS = 200;

/** `v` written for the reader with `digits` decimals, as 1.23e+4 from a thousand on. */
function format(words, v, digits = 3) {
  if (Math.abs(v) < 1000) return words.fixed(v, digits);
  const [mantissa, exponent] = v.toExponential(2).split('e');
  return `${words.fixed(Number(mantissa), 2)}e${exponent}`;
}

const ESCAPES = { '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' };
/** `text` safe inside HTML. */
export const escape = (text) => String(text).replace(/[&<>"]/g, (c) => ESCAPES[c]);

/**
 * Message `key` as HTML: its words escaped, each text field put in as the markup given (this file's
 * own, or escaped by the caller), number fields written for the language.
 */
export function markup(words, key, fields = {}) {
  const marked = Object.keys(fields).filter((name) => typeof fields[name] !== 'number');
  const tokens = Object.fromEntries(marked.map((name, i) => [name, `\u0001${i}\u0001`]));
  return escape(words.t(key, { ...fields, ...tokens })).replace(/\u0001(\d+)\u0001/g, (_, i) => fields[marked[i]]);
}

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
    const hint = element('p', { className: 'hint', textContent: this.#ctx.t('inspector.hint') });
    hint.dataset.t = 'inspector.hint';
    const summary = element('summary', { textContent: this.#ctx.t('inspector.cases') });
    summary.dataset.t = 'inspector.cases';
    const cases = element('details', { className: 'cases' }, summary);
    const idle = (draw) => (globalThis.requestIdleCallback
      ? requestIdleCallback(draw, { timeout: 1000 }) : setTimeout(draw, 0));
    let drawing = null;
    const fill = (all) => {
      if (!cases.isConnected || (drawing && drawing !== this.#gallery)) return;
      if (!drawing) {
        drawing = this.#gallery = buildGallery(gallery, 0, this.#ctx.words);
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

  // The box and the gallery in the reader's language.
  language(words) {
    this.#gallery?.language(words);
    if (this.#report) this.show(this.#report, this.#ctx.state.iso);
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
    const words = this.#ctx.words;
    const t = (key, fields) => markup(words, key, fields);
    const number = (v, digits) => format(words, v, digits);
    const [x, y, z] = report.cell;
    const inside = [...report.corners.keys()].filter((c) => report.corners[c] > iso);
    const along = new Map(report.edges.map((e) => [e.edge, e.t]));
    const rows = report.corners.map((v, c) => {
      const sign = v > iso ? `<b class="in">${t('inspector.in')}</b>` : `<span class="out">${t('inspector.out')}</span>`;
      return `<tr><td>${c}</td><td>${number(v)}</td><td>${sign}</td></tr>`;
    }).join('');
    const edges = report.edges.map((e) => {
      const [a, b] = this.#cube().edges[e.edge];
      const [px, py, pz] = e.vertex.map((v) => words.fixed(v, 3));
      return `<tr><td>${e.edge} (${a}–${b})</td><td>${words.fixed(e.t, 3)}</td><td>${t('inspector.point', { x: px, y: py, z: pz })}</td></tr>`;
    }).join('');
    const triangles = report.triangles.map((tri) => tri.join('–')).join(', ') || t('inspector.none');
    const faces = (report.faces ?? []).map((f) => {
      const plane = `${'xyz'[f.face >> 1]} = ${f.face & 1}`;
      const saddle = f.saddle === null ? t('inspector.face-no-saddle')
        : t(`inspector.face-saddle-${f.deciderJoins ? 'joins' : 'cuts'}`, { value: number(f.saddle), iso: number(iso, 2) });
      const agree = f.joined === f.deciderJoins;
      const key = `inspector.face-${f.deciderJoins ? 'joins' : 'cuts'}-${f.joined ? 'joined' : 'cut'}`;
      return `<li${agree ? '' : ' class="disagrees"'} data-face="${f.face}">${t(key, { plane, saddle })}</li>`;
    }).join('');
    const ambiguous = faces ? `<p>${t('inspector.ambiguous')}</p><ul class="faces">${faces}</ul>` : '';
    // The interior test (MC33): a tunnel joining two loops the faces leave apart.
    const corners = report.interior ?? [];
    const through = corners.length
      ? `<p class="interior">${t(report.tunnel ? 'inspector.interior-tunnel' : 'inspector.interior-apart', { corners: escape(words.field(corners)) })}</p>`
      : '';
    const drawn = report.drawnSubcase === report.subcase ? ''
      : ` <span class="drawn-subcase">${t('inspector.drawn-subcase', { configuration: escape(report.drawnSubcase) })}</span>`;
    const account = t('inspector.case', {
      case: `<b id="inspector-case">${report.case}</b>`,
      bits: `<code>${report.bits}</code>`,
      class: `<b id="inspector-class">${report.class}</b>`,
      name: escape(className(words, report.class)),
      configuration: `<b id="inspector-subcase">${escape(report.subcase)}</b>`,
    });
    this.#box.innerHTML = `
      <header><h3>${t('inspector.cell', { x, y, z })}</h3>
        <button type="button" class="close" aria-label="${t('inspector.close')}">×</button></header>
      <p>${account}${drawn}</p>
      <div class="inspector-body">
        <table class="corners"><thead><tr><th>${t('inspector.corner')}</th><th>f</th><th>${t('inspector.above', { iso: number(iso, 2) })}</th></tr></thead>
          <tbody>${rows}</tbody></table>
        <div class="drawing"></div>
      </div>
      <p>${t('inspector.triangles', { triangles })}</p>${ambiguous}${through}
      <table class="crossings"><thead><tr><th>${t('inspector.edge')}</th><th>t</th><th>${t('inspector.vertex')}</th></tr></thead>
        <tbody>${edges}</tbody></table>`;
    this.#box.querySelector('.drawing').append(
      cellDrawing(this.#cube(), inside, report.triangles, (e) => along.get(e) ?? 0.5,
        { size: 96, color: classColor(report.class), label: words.t('inspector.drawing', { case: report.case }) }),
      interpolantDrawing(this.#cube(), report.corners, iso,
        { size: 96, label: words.t('inspector.interpolant', { case: report.case }) }));
    this.#box.hidden = false;
    this.#onSubcase(report.subcase);
  }
}
