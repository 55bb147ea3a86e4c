// When the case table changes, a notice names the cells whose triangles changed and says how the blob
// count went. Those cells are the ones with an ambiguous face that the asymptotic decider joins (the
// classic table cuts every such face apart) and, to or from MC33, those with a tunnel through their
// inside, found for the first frame drawn under the new table by the CPU's marching cubes on the
// page's mesher worker, whichever mesher draws; up to LISTED_CELLS cells per axis, and only off the
// page's thread (else the notice gives the blob counts alone).

import { ENGLISH } from '../i18n/words.js';
import { decidedCells, meshShape } from '../engine/meshers.js';

// Cells named in the notice; the rest are counted.
const NAMED = 4;
// The finest grid whose changed cells are listed (a CPU mesh of it on the worker).
const LISTED_CELLS = 256;

// What each table changes from the classic one, as the kinds of `decidedCells`: faces the decider
// joins (bit 0), tunnels (bit 1). The notices' words name the kinds: `face`, `tunnel`, `both`.
const KINDS = { classic: 0, decider: 1, mc33: 3 };
const KIND_WORDS = { 1: 'face', 2: 'tunnel', 3: 'both' };

// The number of blobs of the view's mesh now (null where it cannot be read).
const blobsOf = (view) => view.mesh_triangles().then(([vertices, triangles]) => meshShape(vertices, triangles))
  .then(([components]) => components, () => null);

export class TableChange {
  static attributes = ['table'];
  #ctx;
  #pending = null;

  constructor(ctx) {
    this.#ctx = ctx;
  }

  changed(name, value) {
    const view = this.#ctx.view;
    const { lod, method } = this.#ctx.state;
    if (!view) return;
    if (lod || method !== 'marching_cubes') {
      this.#pending = null;
      const kept = lod ? 'lod' : { surface_nets: 'nets', dual_contouring: 'dual', marching_tetrahedra: 'tetra' }[method];
      this.#ctx.notice(this.#ctx.t(`notice.table-kept-${kept}`, { table: value }));
      return;
    }
    // The blobs under the table left (the mesh on screen), and which kinds of cell change.
    const from = this.#ctx.settings.applied?.table ?? 'classic';
    this.#pending = { value, before: blobsOf(view), kinds: (KINDS[from] ?? 0) ^ (KINDS[value] ?? 0) };
  }

  // The first frame drawn under the new table: its changed cells and blobs, then the notice.
  frameDrawn() {
    const pending = this.#pending;
    const view = this.#ctx.view;
    if (!pending || !view) return;
    this.#pending = null;
    const listed = this.#ctx.state.resolution <= LISTED_CELLS;
    const cells = listed ? decidedCells(view.cpu_job(true)).catch(() => null) : Promise.resolve(null);
    Promise.all([cells, pending.before, blobsOf(view)]).then(([all, before, after]) => {
      if (this.#ctx.state.table !== pending.value) return;
      const changed = all && all.filter((c) => c[3] & pending.kinds).map((c) => c.slice(0, 3));
      this.#ctx.notice(tableNotice(pending.value, changed, before, after, pending.kinds, this.#ctx.words), 12000);
    });
  }
}

/**
 * The notice for a change to `table` where `cells` differ (null where they were not listed), with the
 * blob counts before and after (null where unknown); `kinds` (bits of `KINDS`) say what differs;
 * worded with `words` (English by default).
 */
export function tableNotice(table, cells, before, after, kinds = 1, words = ENGLISH) {
  const blobs = before !== null && after !== null;
  if (cells === null) return blobs ? words.t('notice.table-blobs', { table, before, after }) : words.t('notice.table', { table });
  if (cells.length === 0) return words.t(`notice.table-none-${KIND_WORDS[kinds] ?? 'face'}`, { table });
  // The cells as the grid numbers them (x, y, z), the first few named.
  const named = cells.slice(0, NAMED).map((c) => `(${c.join(', ')})`).join(', ');
  const listed = cells.length > NAMED ? words.t('notice.cells-more', { cells: named, count: cells.length - NAMED }) : named;
  const changed = words.t(`notice.table-changed-${KIND_WORDS[kinds] ?? 'both'}`, { table, count: cells.length, cells: listed });
  return blobs ? words.t('notice.with-blobs', { notice: changed, before, after }) : changed;
}
