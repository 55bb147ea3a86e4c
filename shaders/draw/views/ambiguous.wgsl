// The ambiguous faces (ambiguous): on each face whose two inside corners (or two outside corners) sit
// on a diagonal, a cross over the face and its two possible joinings, drawn through the midpoints of
// the face's edges. The joining the cell's triangles follow is solid: amber where the asymptotic
// decider would join the face the same way, red where it would not (the classic table's fixed choice
// disagreeing with the face's values); the other joining is faint.

// The corner of a cell at offset o (each 0 or 1), numbered as in src/extract/tables.rs.
fn corner_number(o: vec3<u32>) -> u32 {
    return (o.z << 2u) | (o.y << 1u) | (o.x ^ o.y);
}

// Per face, 12 vertices: the cross (2 diagonals × 2 ends), then the chosen joining, then the other
// (each 2 segments × 2 ends; a segment cuts one corner off, from the midpoint of the edge before it
// to the midpoint of the edge after it, walking the face's corners in order).
@vertex
fn ambiguous_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let reference = active_cells[i];
    let entry = cell_cases[reference];
    let face = v / 12u;
    let w = v % 12u;
    let axis = face / 2u;
    // The face's corners in order around it.
    var q: array<vec3<u32>, 4>;
    var inside = 0u;
    for (var k = 0u; k < 4u; k++) {
        var o = vec3<u32>(0u);
        o[axis] = face & 1u;
        o[(axis + 1u) % 3u] = ((k >> 1u) ^ k) & 1u;
        o[(axis + 2u) % 3u] = (k >> 1u) & 1u;
        q[k] = o;
        inside |= ((entry >> corner_number(o)) & 1u) << k;
    }
    // Inside corners on a diagonal: 0 and 2 (0b0101) or 1 and 3 (0b1010).
    if (inside != 5u && inside != 10u) {
        return mark(HIDDEN, vec3<f32>(0.0), 0.0);
    }
    var p = vec3<f32>(q[(w & 2u) / 2u + 2u * (w & 1u)]);
    var color = vec3<f32>(1.0, 0.2, 0.85);
    var alpha = 1.0;
    if (w >= 4u) {
        let decided = ((entry >> (DECIDED_SHIFT + face)) & 1u) == 1u;
        let chosen = decided && (grid.flags & FLAG_DECIDER) != 0u;
        // Joined, the segments cut the outside corners off; apart, the inside ones.
        let cut = ((inside >> 1u) & 1u) + u32(chosen != (w >= 8u)) + (w & 2u);
        let end = select(q[(cut + 3u) % 4u], q[(cut + 1u) % 4u], (w & 1u) == 1u);
        p = vec3<f32>(q[cut % 4u] + end) * 0.5;
        // Amber where the decider agrees, red where it does not; the other joining faint.
        color = select(vec3<f32>(1.0, f32(chosen == decided) * 0.45, 0.0), vec3<f32>(0.85), w >= 8u);
        alpha = select(1.0, 0.45, w >= 8u);
    }
    let cell = vec3<f32>(cell_of_block_cell(reference));
    return mark(clip_of(grid.box_min + (cell + p) * grid.cell_size), color, alpha);
}
