// Marching tetrahedra over the active cells, one invocation per cell, after cells.wgsl, with the splits
// and cases of core/src/extract/tetra.rs.
//
// `make_tetra_vertices`: each cell computes the vertices on the segments it owns (cells.wgsl): the
// three edges leaving its lowest corner, the diagonal the split draws on each of the three faces
// through that corner, and with six tetrahedra the diagonal through the cell, so every vertex is
// computed once (a crossed segment's lowest corner is an active cell's). `make_tetra_triangles`: each cell cuts its
// tetrahedra and appends their triangles as indices into the vertices of the segments they cross (in
// its own block or a neighbour's).

// The tables (`tetra_table` in src/extract/gpu/marching.rs): at row * 6 + k, the k-th tetrahedron
// of a split's row (0 six-way, 1 and 2 five-way in a cell whose lowest corner's coordinates sum to an
// even or odd number) as four corners of 3 bits; at CASES + case, the case's triangle count in bits 0
// and 1, then from bit 2 its triangles, 12 bits each: three vertices, each on the edge between two of
// the tetrahedron's corners, 2 bits each.
@group(0) @binding(21) var<storage, read> tetra_table: array<u32>;

const CASES: u32 = 18u;

@compute @workgroup_size(64)
fn make_tetra_vertices(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) index: u32) {
    make_owned_vertices(workgroup, index, select(SEGMENTS, SEGMENTS - 1u, five_way()), SEGMENTS);
}

// The vertex on the segment between corners `c` and `d` of `cell`: owned by the cell at the segment's
// lowest corner, in the slot its direction gives.
fn segment_vertex(cell: vec3<u32>, c: u32, d: u32) -> u32 {
    let a = corner_offset(c);
    let b = corner_offset(d);
    let along = vec3<u32>(a != b);
    let axes = along.x + along.y + along.z;
    var k = 6u;
    if (axes == 1u) {
        k = along.y + 2u * along.z;
    } else if (axes == 2u) {
        k = 4u - along.y + 2u * (1u - along.z);
    }
    return owned_vertex(cell + min(a, b), k, SEGMENTS);
}

@compute @workgroup_size(64)
fn make_tetra_triangles(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) index: u32) {
    let a = active_at(workgroup, index);
    if (a.reference == INVALID) {
        return;
    }
    let cell = a.cell;
    let inside = cell_cases[a.reference] & CASE_BITS;
    let row = select(0u, 1u + u32(odd(cell)), five_way());
    let count = select(6u, 5u, five_way());
    var cases: array<u32, 6>;
    var triangles = 0u;
    for (var t = 0u; t < count; t++) {
        let corners = tetra_table[row * 6u + t];
        var code = 0u;
        for (var i = 0u; i < 4u; i++) {
            code |= ((inside >> ((corners >> (3u * i)) & 7u)) & 1u) << i;
        }
        cases[t] = tetra_table[CASES + code];
        triangles += cases[t] & 3u;
    }
    var next = atomicAdd(&counters.indices, triangles * 3u);
    for (var t = 0u; t < count; t++) {
        let corners = tetra_table[row * 6u + t];
        for (var j = 0u; j < (cases[t] & 3u); j++) {
            let word = cases[t] >> (2u + 12u * j);
            var triangle: vec3<u32>;
            for (var i = 0u; i < 3u; i++) {
                let edge = word >> (4u * i);
                let c = (corners >> (3u * (edge & 3u))) & 7u;
                let d = (corners >> (3u * ((edge >> 2u) & 3u))) & 7u;
                triangle[i] = segment_vertex(cell, c, d);
            }
            write_triangle(next, triangle);
            next += 3u;
        }
    }
}
