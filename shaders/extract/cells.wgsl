// What the per-cell passes share (marching_cubes.wgsl, marching_tetrahedra.wgsl or dual.wgsl follows it
// in one module): the mesh buffers, the active cell an invocation works on, the vertices the cells own,
// and the indexed indirect draw.

@group(0) @binding(2) var<storage, read_write> counters: Counters;
@group(0) @binding(3) var<storage, read> active_blocks: array<u32>;
@group(0) @binding(4) var<storage, read> block_slots: array<u32>;
// The active cells, each as slot * 64 + cell.
@group(0) @binding(8) var<storage, read> active_cells: array<u32>;
@group(0) @binding(6) var<storage, read> block_values: array<f32>;
// Slot s, cell c: the case at s * 64 + c.
@group(0) @binding(7) var<storage, read> cell_cases: array<u32>;
// Slot s, cell c, the k-th of the PER_CELL vertices a cell owns: the vertex at (s * 64 + c) * PER_CELL + k
// (INVALID where the budget was full). The dual methods keep each cell's one vertex in slot 0 and its
// QEF's mark in slot 1.
@group(0) @binding(10) var<storage, read_write> edge_vertices: array<u32>;
// Per vertex, 6 floats: position, then outward normal.
@group(0) @binding(11) var<storage, read_write> vertices: array<f32>;
@group(0) @binding(12) var<storage, read_write> indices: array<u32>;

fn unit(axis: u32) -> vec3<u32> {
    return vec3<u32>(u32(axis == 0u), u32(axis == 1u), u32(axis == 2u));
}

fn local_cell(local: u32) -> vec3<u32> {
    return vec3<u32>(local % BLOCK_CELLS, (local / BLOCK_CELLS) % BLOCK_CELLS, local / (BLOCK_CELLS * BLOCK_CELLS));
}

fn value_at(slot: u32, point: vec3<u32>) -> f32 {
    return block_values[slot * 125u + point.x + BLOCK_POINTS * (point.y + BLOCK_POINTS * point.z)];
}

// The active cell invocation `id` of a per-cell pass works on, as slot * 64 + cell, or INVALID.
fn active_cell(workgroup: vec3<u32>, local: u32) -> u32 {
    let id = slot_of(workgroup) * 64u + local;
    if (id >= min(atomicLoad(&counters.active_cells), grid.max_cells)) {
        return INVALID;
    }
    return active_cells[id];
}

// An active cell as the per-cell passes read it: `reference` as in active_cells (INVALID for an
// invocation past the last, whose other fields mean nothing), its block's slot, its place in its block
// and in the grid.
struct Active {
    reference: u32,
    slot: u32,
    at: vec3<u32>,
    cell: vec3<u32>,
}

fn active_at(workgroup: vec3<u32>, local: u32) -> Active {
    let reference = active_cell(workgroup, local);
    let slot = select(reference / 64u, 0u, reference == INVALID);
    let at = local_cell(reference % 64u);
    return Active(reference, slot, at, block_coords(active_blocks[slot]) * BLOCK_CELLS + at);
}

fn write_vertex(index: u32, p: vec3<f32>, n: vec3<f32>) {
    let o = index * 6u;
    vertices[o] = p.x;
    vertices[o + 1u] = p.y;
    vertices[o + 2u] = p.z;
    vertices[o + 3u] = n.x;
    vertices[o + 4u] = n.y;
    vertices[o + 5u] = n.z;
}

// Segments a cell may own: three edges, three face diagonals, one body diagonal.
const SEGMENTS: u32 = 7u;
// In grid.flags: marching tetrahedra cuts cells into five tetrahedra, else six.
const FLAG_FIVE: u32 = 64u;

// A segment, as its ends' offsets from a cell's lowest corner, the end first in grid order first.
struct Segment {
    a: vec3<u32>,
    b: vec3<u32>,
}

fn five_way() -> bool {
    return (grid.flags & FLAG_FIVE) != 0u;
}

fn odd(cell: vec3<u32>) -> bool {
    return ((cell.x + cell.y + cell.z) & 1u) == 1u;
}

// The k-th segment `cell` owns: k < 3 the edge along axis k (all marching cubes' cells own); 3 + a the
// diagonal of the face across axis a (with five tetrahedra, the one between the face's corners whose
// coordinates sum to an even number); 6 the body diagonal.
fn owned_segment(cell: vec3<u32>, k: u32) -> Segment {
    if (k < 3u) {
        return Segment(vec3<u32>(0u), unit(k));
    }
    if (k == 6u) {
        return Segment(vec3<u32>(0u), vec3<u32>(1u));
    }
    let u = unit(select(0u, 1u, k == 3u));
    let v = unit(select(2u, 1u, k == 5u));
    if (five_way() && odd(cell)) {
        return Segment(u, v);
    }
    return Segment(vec3<u32>(0u), u + v);
}

// The vertices on the first `count` segments the active cell of invocation `index` owns, at `per_cell`
// slots a cell (INVALID where a segment is not crossed or the budget was full). A crossed segment's
// lowest corner is always an active cell's, so every vertex is made once.
fn make_owned_vertices(workgroup: vec3<u32>, index: u32, count: u32, per_cell: u32) {
    let a = active_at(workgroup, index);
    let slot = a.slot;
    let at = a.at;
    let cell = a.cell;
    // The segments' vertices of a block past the buffer's room are not made.
    if (a.reference == INVALID || (a.reference + 1u) * per_cell > arrayLength(&edge_vertices)) {
        return;
    }
    var crossed = 0u;
    for (var k = 0u; k < count; k++) {
        let s = owned_segment(cell, k);
        if ((value_at(slot, at + s.a) > grid.iso) != (value_at(slot, at + s.b) > grid.iso)) {
            crossed |= 1u << k;
        }
    }
    var next = INVALID;
    if (crossed != 0u) {
        next = atomicAdd(&counters.vertices, countOneBits(crossed));
    }
    for (var k = 0u; k < per_cell; k++) {
        var index = INVALID;
        if ((crossed & (1u << k)) != 0u) {
            if (next < grid.max_vertices) {
                index = next;
                let s = owned_segment(cell, k);
                let v = edge_vertex(cell + s.a, cell + s.b, value_at(slot, at + s.a), value_at(slot, at + s.b));
                write_vertex(index, v.position, v.normal);
            }
            next += 1u;
        }
        edge_vertices[a.reference * per_cell + k] = index;
    }
}

// The `k`-th of the `per_cell` vertices `cell` owns, wherever its block's slot is.
fn owned_vertex(cell: vec3<u32>, k: u32, per_cell: u32) -> u32 {
    // A crossed edge never starts on the box's far faces (both its ends would read as outside).
    if (any(cell >= vec3<u32>(grid.cells_per_axis))) {
        return INVALID;
    }
    let slot = block_slots[block_index(cell / BLOCK_CELLS)];
    if (slot >= grid.max_blocks) {
        return INVALID;
    }
    let at = cell % BLOCK_CELLS;
    let local = at.x + BLOCK_CELLS * (at.y + BLOCK_CELLS * at.z);
    let index = (slot * 64u + local) * per_cell + k;
    // Past the end of a buffer too small for every active block (marching tetrahedra's, at the largest
    // grids): no vertex.
    if (index >= arrayLength(&edge_vertices)) {
        return INVALID;
    }
    return edge_vertices[index];
}

// Appends a triangle at `slot_index` of the indices, or a degenerate one (which draws nothing) where a
// vertex was lost to a full buffer; nothing past the buffer's end.
fn write_triangle(slot_index: u32, t: vec3<u32>) {
    if (slot_index + 3u > grid.max_indices) {
        return;
    }
    let triangle = select(vec3<u32>(0u), t, all(t != vec3<u32>(INVALID)));
    indices[slot_index] = triangle.x;
    indices[slot_index + 1u] = triangle.y;
    indices[slot_index + 2u] = triangle.z;
}

@group(0) @binding(13) var<storage, read_write> draw_args: DrawIndexedIndirect;

// One invocation: the draw covers the indices written, never more than the buffer holds.
@compute @workgroup_size(1)
fn finalize_draw() {
    draw_args = indexed_draw(atomicLoad(&counters.indices));
}
