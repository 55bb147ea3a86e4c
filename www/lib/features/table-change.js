// When the case table changes, a notice names the cells whose triangles changed and says how the blob
// count went. Those cells are the ones with an ambiguous face that the asymptotic decider joins (the
// classic table cuts every such face apart), found by the CPU's marching cubes on the mesher worker
// for the frame's spheres, whichever mesher draws.

import { decidedCells, meshShape } from '../engine/meshers.js';

// Cells named in the notice; the rest are counted.
const NAMED = 4;

const plural = (n, word) => `${n} ${word}${n === 1 ? '' : 's'}`;

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
    if (!view) return;
    // The blobs under the table left (the mesh on screen), and the cells that differ.
    this.#pending = { value, before: blobsOf(view), cells: decidedCells(view.cpu_job(true)) };
  }

  // The first frame drawn under the new table: its blobs, then the notice.
  frameDrawn() {
    const pending = this.#pending;
    const view = this.#ctx.view;
    if (!pending || !view) return;
    this.#pending = null;
    Promise.all([pending.cells, pending.before, blobsOf(view)]).then(([cells, before, after]) => {
      if (this.#ctx.state.table !== pending.value) return;
      this.#ctx.notice(tableNotice(pending.value, cells, before, after), 12000);
    }, (error) => this.#ctx.notice(`table=${pending.value}: ${error?.message ?? error}`));
  }
}

/** The notice for a change to `table` where `cells` differ, with the blob counts before and after. */
export function tableNotice(table, cells, before, after) {
  if (cells.length === 0) {
    return `table=${table}: no cell here has a face the asymptotic decider joins; both tables give this mesh`;
  }
  const named = cells.slice(0, NAMED).map((c) => `(${c.join(', ')})`).join(', ');
  const more = cells.length > NAMED ? ` and ${cells.length - NAMED} more` : '';
  const blobs = before !== null && after !== null ? `; blobs ${before} → ${after}` : '';
  return `table=${table}: ${plural(cells.length, 'cell')} changed, each with a face the decider joins and the classic table cuts: ${named}${more}${blobs}`;
}
