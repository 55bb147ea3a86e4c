// Marching-cubes passes over the active cells (those the field pass found the surface crossing), one
// invocation per cell, after cells.wgsl.
//
// `make_vertices`: each cell computes the vertices on the three edges leaving its lowest corner, so every
// surface vertex is computed once (a crossed edge's lowest corner always belongs to an active cell). `make_triangles`: each cell looks up the
// vertices on its twelve edges (in its own block or a neighbour's: an edge the surface crosses on a
// block's face belongs to two blocks the surface crosses, so both are active) and appends its triangles
// as indices. `finalize_draw` (cells.wgsl) turns the index count into the indexed indirect draw, so the
// frame never waits on a readback.

// Every case's triangles under every choice on its ambiguous faces and every join of its interior
// (variant_table in core/src/extract/decider.rs): per case, its first variant; per variant (choices ×
// INTERIOR_CODES + interior code), its first triangle << 8 | its triangle count; per triangle, its three
// edges in 4 bits each. Variant 0 is the classic table's.
@group(0) @binding(17) var<storage, read> triangle_table: array<u32>;

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

// The vertices on the three edges leaving the cell's lowest corner: 0 along x, 3 along y, 8 along z.
@compute @workgroup_size(64)
fn make_vertices(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) index: u32) {
    make_owned_vertices(workgroup, index, 3u, 3u);
}

@compute @workgroup_size(64)
fn make_triangles(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) index: u32) {
    let a = active_at(workgroup, index);
    if (a.reference == INVALID) {
        return;
    }
    // The cell's case and, with the decider, its choices on its ambiguous faces and, with MC33, its
    // interior's join pick its variant.
    let cell_entry = cell_cases[a.reference];
    let chosen = ((cell_entry >> CHOSEN_SHIFT) & 0x3fu) * INTERIOR_CODES + ((cell_entry >> INTERIOR_SHIFT) & 7u);
    let variant = triangle_table[triangle_table[cell_entry & CASE_BITS] + chosen];
    let first_triangle = variant >> 8u;
    let triangle_count = variant & 255u;
    if (triangle_count == 0u) {
        return;
    }
    let cell = a.cell;
    // Part way through the march, the cells not reached yet give no triangles.
    if (!marched(cell)) {
        return;
    }
    let first = atomicAdd(&counters.indices, triangle_count * 3u);
    for (var k = 0u; k < triangle_count; k++) {
        // The table winds clockwise seen from outside; emit counter-clockwise.
        let word = triangle_table[first_triangle + k];
        let edges = vec3<u32>(word & 15u, (word >> 8u) & 15u, (word >> 4u) & 15u);
        var triangle: vec3<u32>;
        for (var j = 0u; j < 3u; j++) {
            let start = edge_start(edges[j]);
            triangle[j] = owned_vertex(cell + start.xyz, start.w, 3u);
        }
        write_triangle(first + 3u * k, triangle);
    }
}
