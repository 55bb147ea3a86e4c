// The ambiguous faces (ambiguous).

// The corner of a cell at offset o (each 0 or 1), numbered as in src/extract/tables.rs.
fn corner_number(o: vec3<u32>) -> u32 {
    return (o.z << 2u) | (o.y << 1u) | (o.x ^ o.y);
}

// A cross over each ambiguous face of each crossed cell: a face whose two inside corners (or two
// outside corners) sit on a diagonal. 6 faces × 2 diagonals × 2 ends.
@vertex
fn ambiguous_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let reference = active_cells[i];
    let case_index = cell_cases[reference] & CASE_BITS;
    let face = v / 4u;
    let axis = face / 2u;
    // The face's corners in order around it.
    var q: array<vec3<u32>, 4>;
    for (var k = 0u; k < 4u; k++) {
        var o = vec3<u32>(0u);
        o[axis] = face & 1u;
        o[(axis + 1u) % 3u] = ((k >> 1u) ^ k) & 1u;
        o[(axis + 2u) % 3u] = (k >> 1u) & 1u;
        q[k] = o;
    }
    var inside: array<bool, 4>;
    for (var k = 0u; k < 4u; k++) {
        inside[k] = ((case_index >> corner_number(q[k])) & 1u) == 1u;
    }
    let ambiguous = inside[0] == inside[2] && inside[1] == inside[3] && inside[0] != inside[1];
    if (!ambiguous) {
        return mark(HIDDEN, vec3<f32>(0.0), 0.0);
    }
    let diagonal = (v / 2u) & 1u;
    let corner = q[diagonal + 2u * (v & 1u)];
    let cell = vec3<f32>(cell_of_block_cell(reference));
    let p = grid.box_min + (cell + vec3<f32>(corner)) * grid.cell_size;
    return mark(clip_of(p), vec3<f32>(1.0, 0.2, 0.85), 1.0);
}
