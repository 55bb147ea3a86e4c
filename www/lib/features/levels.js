// Topology along the iso level, from the field itself: the critical points of the current spheres
// (found with proof on the topology worker, lib/engine/levels.js), searched again as the spheres move
// while anything shows them. What shows them:
//   - `levels` ("Along the iso level", a box in the figure's lower left): the plot of blobs, genus,
//     area and volume against the iso level with a cursor, the merge tree whose joins set the iso level
//     just below them, and the critical levels in words;
//   - `critical` (markers over the figure, by kind, with their values);
//   - `pause-on=merge`: the animation waits for each frame's search, and stops at the frame the field's
//     blobs join (not when a mesh notices);
//   - the HUD's "Field" line, and where the mesh disagrees, what the field does there and why the mesh
//     misses it (a neck thinner than a cell, a tunnel the table does not draw).
// `criticalPoints()` gives the same result to scripts.

import { relabel } from '../i18n/words.js';
import { countsAt, criticalPoints, measuresAlong, packSpheres } from '../engine/levels.js';
import { criticalLevel, drawPlot, drawTree, isoWithin, plotRange, ROLE_COLORS, spheres, writeLevel } from './levels-plot.js';
import { TopologyWatch } from './topology.js';

const EVERY_MS = 300;
const MARK = { 3: '▲', 2: '◆', 1: '●', 0: '▼' };

export class IsoLevels {
  static attributes = ['critical', 'levels', 'kernel', 'blend'];
  #ctx;
  #result = null;
  #packed = null;
  #pending = null;
  #askedAt = -Infinity;
  #panel = null;
  #marks = null;
  #measures = null;
  // The plot drawn last, and whether its cursor is being dragged (it is then moved, not drawn again).
  #plot = null;
  #dragging = false;
  // What the box says before a search's result is in: [key, fields].
  #said = null;

  constructor(ctx) {
    this.#ctx = ctx;
  }

  /** The newest search's result, or null. */
  get latest() { return this.#result; }

  changed(name) {
    if (name === 'levels' || (this.#open && (name === 'kernel' || name === 'blend'))) this.#showBox();
    if (!this.#serves()) this.#showHud();
    this.#ctx.redraw(2);
  }

  /**
   * The search proves the critical points of the sum of inverse squares only: another kernel or the
   * blend by max is said so rather than shown with that field's points.
   */
  #serves() {
    const s = this.#ctx.state;
    return (s.kernel ?? 'inverse_square') === 'inverse_square' && s.blend !== 'max';
  }

  connected() { this.#showBox(); }

  get #open() { return on(this.#ctx.state.levels); }

  #wanted() {
    const s = this.#ctx.state;
    return this.#serves() && (this.#open || on(s.critical) || (s['pause-on'] === 'merge' && !s.paused));
  }

  holds() {
    return this.#pending !== null && this.#ctx.state['pause-on'] === 'merge' && !this.#ctx.state.paused;
  }

  /** Spheres as the search reads them, from the view. */
  #spheres() {
    const packed = this.#ctx.view?.spheres();
    if (!packed) return null;
    const out = new Float32Array((packed.length / 7) * 4);
    for (let i = 0, j = 0; i + 7 <= packed.length; i += 7, j += 4) out.set(packed.slice(i, i + 4), j);
    return out;
  }

  frameDrawn(now) {
    if (!this.#wanted() || this.#pending) return;
    const merge = this.#ctx.state['pause-on'] === 'merge' && !this.#ctx.state.paused;
    if (!merge && now - this.#askedAt < EVERY_MS) return;
    const packed = this.#spheres();
    if (!packed || (this.#packed && !merge && same(packed, this.#packed) && this.#result)) return;
    this.#askedAt = now;
    this.#search(packed).catch(() => {});
  }

  /** Searches `packed` spheres; the figure's iso level at the time decides what is news. */
  #search(packed) {
    const asked = criticalPoints(packed).then((result) => {
      // The blobs before and after, both at the iso level now (a change of level is not a merge).
      const iso = Number(this.#ctx.state.iso);
      const before = this.#result ? countsAt(this.#result, iso) : null;
      this.#packed = packed;
      this.#result = result;
      this.#take(result, before, iso);
      return result;
    }).finally(() => {
      if (this.#pending === asked) this.#pending = null;
    });
    this.#pending = asked;
    return asked;
  }

  #take(result, before, iso) {
    const now = countsAt(result, iso);
    if (before && now && now.blobs < before.blobs && this.#ctx.state['pause-on'] === 'merge' && !this.#ctx.state.paused) {
      this.#ctx.set('paused', true);
      const join = result.points.filter((p) => p.role === 'join' && p.value > iso).sort((a, b) => a.value - b.value)[0];
      const words = this.#ctx.words;
      const fields = { count: before.blobs, blobs: now.blobs, value: join ? writeLevel(words, join.value) : '' };
      this.#ctx.each('announce', words.t(join ? 'critical.merge-paused-at' : 'critical.merge-paused', fields));
    }
    this.#showHud();
    if (this.#open && this.#serves()) this.#drawPanel();
    this.#ctx.redraw(1);
  }

  /** For scripts: resolves to the search's result for the spheres now, with the counts at the iso level. */
  async result() {
    const packed = this.#spheres();
    if (!packed) throw new Error('the figure is not drawing');
    if (!this.#serves()) throw new Error(this.#ctx.words.t('levels.unserved'));
    const result = await this.#search(packed);
    return { ...result, iso: Number(this.#ctx.state.iso), counts: countsAt(result, Number(this.#ctx.state.iso)) };
  }

  // ------------------------------------------------------------------ the HUD

  #showHud() {
    const $ = (id) => this.#ctx.$(id);
    if (!$('hud-field')) return;
    const iso = Number(this.#ctx.state.iso);
    const s = this.#ctx.state;
    if (!this.#serves() && (this.#open || on(s.critical))) {
      $('hud-field').hidden = false;
      $('hud-field-warning').hidden = true;
      $('hud-field-text').textContent = this.#ctx.words.t('levels.unserved');
      return;
    }
    // Only while a search follows the spheres (an older result is of spheres that have moved on).
    const counts = this.#result && this.#wanted() ? countsAt(this.#result, iso) : null;
    if (!counts) {
      $('hud-field').hidden = $('hud-field-warning').hidden = true;
      return;
    }
    $('hud-field').hidden = false;
    const words = this.#ctx.words;
    const walls = iso <= this.#result.wallLevel;
    $('hud-field-text').textContent = words.t(walls ? 'levels.field-walls' : 'levels.field', { count: counts.surfaces, genus: counts.genus });
    const mesh = this.#ctx.get(TopologyWatch)?.latest;
    const text = mesh && !walls ? disagreement(this.#result, counts, mesh, iso, Number(this.#ctx.state.resolution), words) : '';
    $('hud-field-warning').hidden = !text;
    $('hud-field-warning').textContent = text;
  }

  shape() { this.#showHud(); }

  // The HUD's line and the box in the reader's language (the markers are written every frame).
  language(words) {
    this.#showHud();
    if (this.#said && this.#panel) this.#panel.textContent = words.t(...this.#said);
    if (this.#open && this.#result && this.#serves()) {
      this.#plot = null;
      this.#drawPanel();
    }
  }

  // ------------------------------------------------------------------ markers over the figure

  afterTick() {
    if (!on(this.#ctx.state.critical) || !this.#result || !this.#ctx.view || !this.#serves()) {
      if (this.#marks) this.#marks.hidden = true;
      return;
    }
    if (!this.#marks) {
      this.#marks = document.createElement('div');
      this.#marks.id = 'critical-marks';
      this.#marks.setAttribute('aria-hidden', 'true');
      // Over the canvas, which does not mirror where the words run right to left.
      this.#marks.dir = 'ltr';
      this.#ctx.canvas.after(this.#marks);
    }
    this.#marks.hidden = false;
    const points = this.#result.points.filter((p) => p.inBox);
    const at = this.#ctx.view.points_on_screen(Float32Array.from(points.flatMap((p) => p.position)));
    const scale = this.#ctx.canvas.width / Math.max(1, this.#ctx.canvas.clientWidth);
    while (this.#marks.children.length > points.length) this.#marks.lastChild.remove();
    // A value is written beside a mark only where it keeps clear of the values already written.
    const labelled = [];
    const words = this.#ctx.words;
    points.forEach((p, k) => {
      let mark = this.#marks.children[k];
      if (!mark) {
        mark = document.createElement('span');
        this.#marks.append(mark);
      }
      const [x, y] = [at[2 * k] / scale, at[2 * k + 1] / scale];
      mark.hidden = !Number.isFinite(x);
      mark.style.transform = `translate(${x}px, ${y}px)`;
      mark.style.color = ROLE_COLORS[p.role];
      const clear = labelled.every(([lx, ly]) => Math.abs(lx - x) > 48 || Math.abs(ly - y) > 13);
      if (clear) labelled.push([x, y]);
      mark.textContent = clear ? `${MARK[p.index]} ${words.number(Number(p.value.toPrecision(3)), 12)}` : MARK[p.index];
      mark.title = criticalLevel(words, p);
    });
  }

  // ------------------------------------------------------------------ the panel

  /** Shows or hides the box as `levels` says, searching when it opens. */
  #showBox() {
    const box = this.#ctx.$('levels-box');
    if (!box) return;
    if (!this.#open) {
      box.hidden = true;
      return;
    }
    if (!this.#panel) {
      const close = document.createElement('button');
      close.className = 'close';
      close.textContent = '×';
      close.dataset.tTitle = 'levels.close-title';
      close.dataset.tLabel = 'levels.close';
      close.addEventListener('click', () => this.#ctx.set('levels', false));
      const title = document.createElement('h3');
      title.dataset.t = 'setting.levels';
      this.#panel = document.createElement('div');
      this.#panel.className = 'levels';
      box.replaceChildren(close, title, this.#panel);
      relabel(box, this.#ctx.words);
      this.#say('levels.finding');
    }
    // (The panel behind the box takes no focus while the box covers it: FigureSheets.)
    box.hidden = false;
    this.#measures = null;
    if (!this.#serves()) {
      this.#plot = null;
      this.#say('levels.unserved');
      return;
    }
    const packed = this.#spheres();
    if (packed) {
      this.#search(packed).catch((error) => this.#say('levels.stopped', { reason: error?.message ?? String(error) }));
    }
  }

  started() { if (this.#open) this.#showBox(); }

  // Says message `key` in the box, in place of its plot.
  #say(key, fields = {}) {
    this.#said = [key, fields];
    this.#panel.textContent = this.#ctx.t(key, fields);
  }

  refresh() {
    if (this.#open && this.#result && this.#serves()) this.#drawPanel();
    this.#showHud();
  }

  #setIso(value) {
    this.#ctx.set('iso', isoWithin(value));
  }

  /** Sets the iso level just below join `k` of `result`'s tree: where the neck is a cell and a half across. */
  #chooseJoin(result, k) {
    const join = result.points[result.tree[k].point];
    const cell = 2 / Number(this.#ctx.state.resolution);
    const drop = Math.abs(join.eigenvalues[0]) * (0.75 * cell) ** 2 / 2;
    const lower = result.points.map((p) => p.value).filter((v) => v < join.value * 0.9999 && v > 0).sort((a, b) => b - a)[0];
    const floor = lower ? Math.sqrt(lower * join.value) : join.value * 0.5;
    const iso = isoWithin(Math.max(floor, Math.min(join.value - drop, join.value * 0.999)));
    this.#setIso(iso);
    const words = this.#ctx.words;
    const [a, b] = result.tree[k].children.map((c) => spheres(words, result.tree[c].spheres));
    this.#ctx.each('announce', words.t('critical.join-chosen', { a, b, iso: words.number(iso, 12), value: writeLevel(words, join.value) }));
  }

  #drawPanel() {
    const body = this.#panel;
    const result = this.#result;
    if (!body || !result) return;
    const iso = Number(this.#ctx.state.iso);
    if (this.#dragging && this.#plot) {
      this.#plot.moveCursor(iso);
      return;
    }
    const [low, high] = plotRange(result, iso);
    const levels = Array.from({ length: 24 }, (_, i) => low * (high / low) ** ((i + 0.5) / 24));
    if (!this.#measures || this.#measures.packed !== this.#packed) {
      const packed = this.#packed;
      this.#measures = { packed, values: null };
      measuresAlong(packed, levels, 32).then((values) => {
        if (this.#measures?.packed !== packed) return;
        this.#measures.values = values;
        this.#measures.levels = levels;
        this.#drawPanel();
      }, () => {});
    }
    const counts = countsAt(result, iso);
    const words = this.#ctx.words;
    this.#said = null;
    const status = document.createElement('p');
    status.className = 'hint';
    status.setAttribute('role', 'status');
    const proved = result.complete && result.undecided === 0;
    const found = { count: result.points.length, ms: words.fixed(result.milliseconds, 0) };
    status.textContent = `${words.t(proved ? 'levels.points-proved' : 'levels.points-unproved', found)} `
      + (counts ? words.t('levels.at-iso', {
        iso: writeLevel(words, iso),
        blobs: words.t('levels.blobs', { count: counts.blobs }),
        cavities: words.t('levels.cavities', { count: counts.cavities }),
        genus: counts.genus,
      }) : '')
      + (result.countsUnknown ? words.t('levels.counts-unknown', { reason: result.countsUnknown }) : '');
    this.#plot = drawPlot(result, iso, {
      measures: this.#measures?.values,
      levels: this.#measures?.levels ?? [],
      onIso: (v) => this.#setIso(v),
      onDrag: (on) => {
        this.#dragging = on;
        if (!on) this.#drawPanel();
      },
      words,
    });
    const { svg } = this.#plot;
    const key = document.createElement('p');
    key.className = 'hint';
    // The swatches are samples of the plot's lines (graphics, not text).
    const swatch = (color, line) => {
      const span = document.createElement('span');
      span.setAttribute('aria-hidden', 'true');
      span.className = 'swatch';
      span.style.color = color;
      span.textContent = line;
      return span;
    };
    const entries = [['#e77661', '━', 'surfaces'], ['#4aa3ff', '╍', 'genus'], ['#5ec962', '━', 'area'], ['#21918c', '╍', 'volume']];
    entries.forEach(([color, line, name], i) => key.append(...(i ? [' · '] : []), swatch(color, line), ` ${words.t(`levels.key-${name}`)}`));
    key.append(` · ${words.t('levels.key-walls')}`);
    const tree = drawTree(result, iso, (k) => this.#chooseJoin(result, k), words);
    const list = document.createElement('ol');
    list.className = 'critical-levels';
    list.tabIndex = 0;
    list.setAttribute('aria-label', words.t('levels.list'));
    for (const p of result.points.filter((q) => q.value > 0).slice(0, 24)) {
      const item = document.createElement('li');
      const mark = document.createElement('i');
      mark.setAttribute('aria-hidden', 'true');
      mark.style.color = ROLE_COLORS[p.role];
      mark.textContent = MARK[p.index];
      item.append(mark, ` ${criticalLevel(words, p)}`);
      list.append(item);
    }
    // Focus stays where it was across the redraw: the cursor, a join of the tree, or the list.
    const active = this.#ctx.root.activeElement;
    const focused = active && body.contains(active)
      ? (active.dataset?.node !== undefined ? `g.join[data-node="${active.dataset.node}"]` : active.matches('.cursor') ? '.cursor'
        : active.matches('ol') ? 'ol' : null)
      : null;
    const scrolled = body.querySelector('ol')?.scrollTop ?? 0;
    body.replaceChildren(status, svg, key, tree, list);
    list.scrollTop = scrolled;
    if (focused) body.querySelector(focused)?.focus();
  }
}

/** A flag's value in the state (a boolean, or its text). */
const on = (value) => value === true || value === 'true';

function same(a, b) {
  return a.length === b.length && a.every((v, i) => v === b[i]);
}

/**
 * Where the mesh's shape differs from the field's at `iso`: what the field does near there and why a
 * mesh at `n`³ misses it, in `words`, or ''.
 */
export function disagreement(result, counts, mesh, iso, n, words) {
  const cell = 2 / n;
  if (mesh.components > counts.surfaces) {
    const join = result.points.filter((p) => p.role === 'join' && p.value > iso).sort((a, b) => a.value - b.value)[0];
    if (!join) return words.t('levels.more-pieces', { count: mesh.components, surfaces: counts.surfaces });
    const joined = join.ends.map((e) => e?.sphere).filter((s) => s !== undefined);
    const width = 2 * Math.sqrt((2 * (join.value - iso)) / Math.abs(join.eigenvalues[0]));
    return words.t('levels.neck', { spheres: joined, value: writeLevel(words, join.value), width: words.fixed(width / cell, 1), n });
  }
  if (mesh.components < counts.surfaces) {
    const join = result.points.filter((p) => p.role === 'join' && p.value < iso).sort((a, b) => b.value - a.value)[0];
    const fields = { count: counts.surfaces, pieces: mesh.components, value: join ? writeLevel(words, join.value) : '' };
    return words.t(join ? 'levels.fewer-pieces-below' : 'levels.fewer-pieces', fields);
  }
  if (mesh.genus !== counts.genus) return words.t('levels.genus', { mesh: mesh.genus, field: counts.genus });
  return '';
}
