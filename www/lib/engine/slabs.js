// A figure's grid cut across z into slabs that several mesher workers mesh at once, and the slabs'
// meshes joined into the mesh one worker makes of the whole grid (`mesh_job`), vertex for vertex.
//
// Each slab is a whole number of blocks of cells thick (`mesh_slab` meshes its layers and says which
// grid edge each of its vertices lies on). A slab's mesher makes the vertices its cells use in the order
// the whole grid's does; the vertices on the x and y edges of the plane where two slabs meet are used
// by the cells on both sides, so both make them: the lower slab's are kept and the upper slab's
// triangles are pointed at them. Every other vertex follows in the order its slab made it, and the
// triangles slab by slab, so the joined mesh is the whole grid's.

/** Cells per side of a block (`BLOCK_CELLS`): slabs start on block boundaries. */
const BLOCK = 4;

/**
 * The slabs of a grid of `n` cells per axis for up to `pieces` meshers: `[[first layer, end], …]`, each a
 * whole number of blocks thick, as even as blocks allow; fewer where the grid has fewer blocks.
 */
export function slabRanges(n, pieces) {
  const blocks = Math.ceil(n / BLOCK);
  const count = Math.max(1, Math.min(pieces, blocks));
  const at = (k) => Math.min(Math.floor((blocks * k) / count) * BLOCK, n);
  return Array.from({ length: count }, (_, k) => [at(k), at(k + 1)]);
}

/**
 * Joins the meshes of the slabs of a grid of `n` cells per axis, each `[first layer, vertices
 * (Float32Array, 6 numbers a vertex), indices (Uint32Array), edges (Uint32Array, one a vertex:
 * point index × 3 + axis), active blocks, active cells]`, in z order: `[vertices, indices, active
 * blocks, active cells]` as `mesh_job` gives them. Throws on slabs that do not fit together.
 */
export function joinSlabs(n, slabs) {
  const side = n + 1;
  const plane = side * side;
  let vertexCount = 0;
  let indexCount = 0;
  for (const [, vertices, indices] of slabs) {
    vertexCount += vertices.length / 6;
    indexCount += indices.length;
  }
  const vertices = new Float32Array(6 * vertexCount);
  const indices = new Uint32Array(indexCount);
  // The joined index of the vertex on each x and y edge of the plane where the next slab starts.
  let seam = null;
  let made = 0;
  let written = 0;
  let [blocks, cells] = [0, 0];
  slabs.forEach(([from, slabVertices, slabIndices, keys, slabBlocks, slabCells], k) => {
    if (k > 0 && from <= slabs[k - 1][0]) throw new Error(`slab ${k} starts at layer ${from}, not above the one before it`);
    if (slabVertices.length !== 6 * keys.length) throw new Error(`slab ${k} has ${keys.length} edges for ${slabVertices.length / 6} vertices`);
    const next = slabs[k + 1]?.[0];
    const nextSeam = next === undefined ? null : new Uint32Array(2 * plane).fill(0xffffffff);
    const remap = new Uint32Array(keys.length);
    for (let i = 0; i < keys.length; i++) {
      const key = keys[i];
      const axis = key % 3;
      const point = (key - axis) / 3;
      const z = Math.floor(point / plane);
      const slot = 2 * (point - z * plane) + axis;
      let joined;
      if (axis < 2 && z === from && seam && seam[slot] !== 0xffffffff) {
        joined = seam[slot];
      } else {
        joined = made;
        vertices.set(slabVertices.subarray(6 * i, 6 * i + 6), 6 * made);
        made += 1;
      }
      if (axis < 2 && z === next) nextSeam[slot] = joined;
      remap[i] = joined;
    }
    for (let t = 0; t < slabIndices.length; t++) {
      const index = slabIndices[t];
      if (index >= keys.length) throw new Error(`slab ${k} has a triangle on vertex ${index} of ${keys.length}`);
      indices[written + t] = remap[index];
    }
    written += slabIndices.length;
    blocks += slabBlocks;
    cells += slabCells;
    seam = nextSeam;
  });
  return [vertices.subarray(0, 6 * made), indices, blocks, cells];
}
