// The ambiguous faces (ambiguous): on each face whose two inside corners (or two outside corners) sit
// on a diagonal, a cross over the face and its two possible joinings, drawn through the midpoints of
// the face's edges. The joining the cell's triangles follow is solid: amber where the asymptotic
// decider would join the face the same way, red where it would not (the classic table's fixed choice
// disagreeing with the face's values); the other joining is faint.

// The corner of a cell at offset o (each 0 or 1), numbered as in src/extract/tables.rs.
fn corner_number(o: vec3<u32>) -> u32 {
    return (o.z << 2u) | (o.y << 1u) | (o.x ^ o.y);
}

const FACE_VERTICES: u32 = 12u;
const CROSS_COLOR: vec3<f32> = vec3<f32>(1.0, 0.2, 0.85);
const AGREED_COLOR: vec3<f32> = vec3<f32>(1.0, 0.45, 0.0);
const DISAGREED_COLOR: vec3<f32> = vec3<f32>(1.0, 0.0, 0.0);
const OTHER_COLOR: vec3<f32> = vec3<f32>(0.85, 0.85, 0.85);

// Per face, 12 vertices: the cross (2 diagonals × 2 ends), then the chosen joining, then the other
// (each 2 segments × 2 ends; a segment cuts one corner off, from the midpoint of the edge before it
// to the midpoint of the edge after it, walking the face's corners in order).
@vertex
fn ambiguous_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let reference = active_cells[i];
    let entry = cell_cases[reference];
    let case_index = entry & CASE_BITS;
    let face = v / FACE_VERTICES;
    let w = v % FACE_VERTICES;
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
    let cell = vec3<f32>(cell_of_block_cell(reference));
    let at = grid.box_min + cell * grid.cell_size;
    if (w < 4u) {
        let diagonal = (w / 2u) & 1u;
        let corner = q[diagonal + 2u * (w & 1u)];
        return mark(clip_of(at + vec3<f32>(corner) * grid.cell_size), CROSS_COLOR, 1.0);
    }
    let decided = ((entry >> (DECIDED_SHIFT + face)) & 1u) == 1u;
    let chosen = decided && (grid.flags & FLAG_DECIDER) != 0u;
    let first_inside = select(1u, 0u, inside[0]);
    // Joined, the segments cut the outside corners off; apart, the inside ones.
    let drawn_joined = select(chosen, !chosen, w >= 8u);
    let cut = select(first_inside, first_inside + 1u, drawn_joined) + 2u * ((w / 2u) & 1u);
    let start = vec3<f32>(q[(cut + 3u) % 4u] + q[cut % 4u]) * 0.5;
    let end = vec3<f32>(q[cut % 4u] + q[(cut + 1u) % 4u]) * 0.5;
    let p = select(start, end, (w & 1u) == 1u);
    var color = OTHER_COLOR;
    var alpha = 0.45;
    if (w < 8u) {
        color = select(DISAGREED_COLOR, AGREED_COLOR, chosen == decided);
        alpha = 1.0;
    }
    return mark(clip_of(at + p * grid.cell_size), color, alpha);
}
