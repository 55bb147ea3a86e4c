// When the case table changes, a notice names the cells whose triangles changed and says how the blob
// count went. Those cells are the ones with an ambiguous face that the asymptotic decider joins (the
// classic table cuts every such face apart) and, to or from MC33, those with a tunnel through their
// inside, found for the first frame drawn under the new table by the CPU's marching cubes on the
// page's mesher worker, whichever mesher draws; up to LISTED_CELLS cells per axis, and only off the
// page's thread (else the notice gives the blob counts alone).

import { decidedCells, meshShape } from '../engine/meshers.js';

// Cells named in the notice; the rest are counted.
const NAMED = 4;
// The finest grid whose changed cells are listed (a CPU mesh of it on the worker).
const LISTED_CELLS = 256;

const plural = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;

// What each table changes from the classic one, as the kinds of `decidedCells`: faces the decider
// joins (bit 0), tunnels (bit 1).
const KINDS = { classic: 0, decider: 1, mc33: 3 };
const CHANGES = {
  1: 'each with a face the decider joins and the classic table cuts',
  2: 'each with a tunnel through its inside that MC33 draws',
  3: 'each with a face the decider joins and the classic table cuts, or a tunnel MC33 draws',
};

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
    if (lod || method === 'surface_nets') {
      this.#pending = null;
      this.#ctx.notice(`table=${value}: ${lod ? 'level of detail' : 'surface nets'} keeps the classic table; the mesh is unchanged`);
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
      this.#ctx.notice(tableNotice(pending.value, changed, before, after, pending.kinds), 12000);
    });
  }
}

/**
 * The notice for a change to `table` where `cells` differ (null where they were not listed), with the
 * blob counts before and after (null where unknown); `kinds` (bits of `KINDS`) say what differs.
 */
export function tableNotice(table, cells, before, after, kinds = 1) {
  const blobs = before !== null && after !== null ? `blobs ${before} → ${after}` : '';
  if (cells === null) return `table=${table}${blobs ? `: ${blobs}` : ''}`;
  if (cells.length === 0) {
    const what = { 2: 'a tunnel MC33 draws', 3: 'a face the asymptotic decider joins or a tunnel MC33 draws' }[kinds]
      ?? 'a face the asymptotic decider joins';
    return `table=${table}: no cell here has ${what}; both tables give this mesh`;
  }
  const named = cells.slice(0, NAMED).map((c) => `(${c.join(', ')})`).join(', ');
  const more = cells.length > NAMED ? ` and ${cells.length - NAMED} more` : '';
  return `table=${table}: ${plural(cells.length, 'cell')} changed, ${CHANGES[kinds] ?? CHANGES[3]}: ${named}${more}${blobs ? `; ${blobs}` : ''}`;
}
