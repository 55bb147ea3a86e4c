// Marching-cubes passes over the active cells (those the field pass found the surface crossing), one
// invocation per cell.
//
// `make_vertices`: each cell computes the vertices on the three edges leaving its lowest corner, so every
// surface vertex is computed once (a crossed edge's lowest corner always belongs to an active cell). `make_triangles`: each cell looks up the
// vertices on its twelve edges (in its own block or a neighbour's: an edge the surface crosses on a
// block's face belongs to two blocks the surface crosses, so both are active) and appends its triangles
// as indices. `finalize_draw` turns the index count into the indexed indirect draw, so the frame never
// waits on a readback.

@group(0) @binding(2) var<storage, read_write> counters: Counters;
@group(0) @binding(3) var<storage, read> active_blocks: array<u32>;
@group(0) @binding(4) var<storage, read> block_slots: array<u32>;
// The active cells, each as slot * 64 + cell.
@group(0) @binding(8) var<storage, read> active_cells: array<u32>;
@group(0) @binding(6) var<storage, read> block_values: array<f32>;
// Every case's triangles under every choice on its ambiguous faces and every join of its interior
// (variant_table in core/src/extract/decider.rs): per case, its first variant; per variant (choices ×
// INTERIOR_CODES + interior code), its first triangle << 8 | its triangle count; per triangle, its three
// edges in 4 bits each. Variant 0 is the classic table's.
@group(0) @binding(17) var<storage, read> triangle_table: array<u32>;
// Slot s, cell c: the case at s * 64 + c.
@group(0) @binding(7) var<storage, read> cell_cases: array<u32>;
// Slot s, cell c, axis a: the vertex on the edge leaving the cell's lowest corner along a, at
// (s * 64 + c) * 3 + a (INVALID where the budget was full).
@group(0) @binding(10) var<storage, read_write> edge_vertices: array<u32>;
// Per vertex, 6 floats: position, then outward normal.
@group(0) @binding(11) var<storage, read_write> vertices: array<f32>;
@group(0) @binding(12) var<storage, read_write> indices: array<u32>;

// Edge e starts at the corner returned in xyz and runs along axis w (src/extract/tables.rs, EDGE_CORNERS).
fn edge_start(e: u32) -> vec4<u32> {
    switch e {
        case 0u: { return vec4<u32>(0u, 0u, 0u, 0u); }
        case 1u: { return vec4<u32>(1u, 0u, 0u, 1u); }
        case 2u: { return vec4<u32>(0u, 1u, 0u, 0u); }
        case 3u: { return vec4<u32>(0u, 0u, 0u, 1u); }
        case 4u: { return vec4<u32>(0u, 0u, 1u, 0u); }
        case 5u: { return vec4<u32>(1u, 0u, 1u, 1u); }
        case 6u: { return vec4<u32>(0u, 1u, 1u, 0u); }
        case 7u: { return vec4<u32>(0u, 0u, 1u, 1u); }
        case 8u: { return vec4<u32>(0u, 0u, 0u, 2u); }
        case 9u: { return vec4<u32>(1u, 0u, 0u, 2u); }
        case 10u: { return vec4<u32>(1u, 1u, 0u, 2u); }
        default: { return vec4<u32>(0u, 1u, 0u, 2u); }
    }
}

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

fn write_vertex(index: u32, p: vec3<f32>, n: vec3<f32>) {
    let o = index * 6u;
    vertices[o] = p.x;
    vertices[o + 1u] = p.y;
    vertices[o + 2u] = p.z;
    vertices[o + 3u] = n.x;
    vertices[o + 4u] = n.y;
    vertices[o + 5u] = n.z;
}

@compute @workgroup_size(64)
fn make_vertices(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) index: u32) {
    let reference = active_cell(workgroup, index);
    if (reference == INVALID) {
        return;
    }
    let slot = reference / 64u;
    let local = reference % 64u;
    let at = local_cell(local);
    let cell = block_coords(active_blocks[slot]) * BLOCK_CELLS + at;

    // The edges leaving the lowest corner: 0 along x, 3 along y, 8 along z.
    let f0 = value_at(slot, at);
    let inside0 = f0 > grid.iso;
    var crossed = 0u;
    for (var axis = 0u; axis < 3u; axis++) {
        if ((value_at(slot, at + unit(axis)) > grid.iso) != inside0) {
            crossed |= 1u << axis;
        }
    }
    let count = countOneBits(crossed);
    var next = INVALID;
    if (count > 0u) {
        next = atomicAdd(&counters.vertices, count);
    }
    for (var axis = 0u; axis < 3u; axis++) {
        var index = INVALID;
        if ((crossed & (1u << axis)) != 0u) {
            if (next < grid.max_vertices) {
                index = next;
                let v = edge_vertex(cell, cell + unit(axis), f0, value_at(slot, at + unit(axis)));
                write_vertex(index, v.position, v.normal);
            }
            next += 1u;
        }
        edge_vertices[(slot * 64u + local) * 3u + axis] = index;
    }
}

// The vertex on the edge leaving `cell`'s lowest corner along `axis`, wherever its block's slot is.
fn vertex_on_edge(cell: vec3<u32>, axis: u32) -> u32 {
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
    return edge_vertices[(slot * 64u + local) * 3u + axis];
}

@compute @workgroup_size(64)
fn make_triangles(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) index: u32) {
    let reference = active_cell(workgroup, index);
    if (reference == INVALID) {
        return;
    }
    let slot = reference / 64u;
    let local = reference % 64u;
    // The cell's case and, with the decider, its choices on its ambiguous faces and, with MC33, its
    // interior's join pick its variant.
    let cell_entry = cell_cases[reference];
    let chosen = ((cell_entry >> CHOSEN_SHIFT) & 0x3fu) * INTERIOR_CODES + ((cell_entry >> INTERIOR_SHIFT) & 7u);
    let variant = triangle_table[triangle_table[cell_entry & CASE_BITS] + chosen];
    let first_triangle = variant >> 8u;
    let triangle_count = variant & 255u;
    if (triangle_count == 0u) {
        return;
    }
    let cell = block_coords(active_blocks[slot]) * BLOCK_CELLS + local_cell(local);
    // Part way through the march, the cells not reached yet give no triangles.
    if (!marched(cell)) {
        return;
    }
    let first = atomicAdd(&counters.indices, triangle_count * 3u);
    for (var k = 0u; k < triangle_count; k++) {
        let slot_index = first + 3u * k;
        if (slot_index + 3u > grid.max_indices) {
            return;
        }
        // The table winds clockwise seen from outside; emit counter-clockwise.
        let word = triangle_table[first_triangle + k];
        let edges = vec3<u32>(word & 15u, (word >> 8u) & 15u, (word >> 4u) & 15u);
        var triangle = vec3<u32>(0u);
        var complete = true;
        for (var j = 0u; j < 3u; j++) {
            let start = edge_start(edges[j]);
            let index = vertex_on_edge(cell + start.xyz, start.w);
            complete = complete && index != INVALID;
            triangle[j] = index;
        }
        // A vertex lost to a full buffer leaves a degenerate triangle, which draws nothing.
        if (!complete) {
            triangle = vec3<u32>(0u);
        }
        indices[slot_index] = triangle.x;
        indices[slot_index + 1u] = triangle.y;
        indices[slot_index + 2u] = triangle.z;
    }
}

@group(0) @binding(13) var<storage, read_write> draw_args: DrawIndexedIndirect;

// One invocation: the draw covers the indices written, never more than the buffer holds.
@compute @workgroup_size(1)
fn finalize_draw() {
    draw_args = indexed_draw(atomicLoad(&counters.indices));
}
