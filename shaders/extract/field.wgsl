// Field pass: for each active block, f at its 5³ grid points (0 on the box's faces), kept per slot; then
// each of its 4³ cells classifies itself from them, and the cells the surface crosses are appended to the
// active-cell list, so that vertex and triangle work runs only where there is surface. Two dispatches
// rather than one with workgroup memory: software adapters (SwiftShader) run workgroup barriers slowly,
// and this halves mesh generation there.

@group(0) @binding(2) var<storage, read_write> counters: Counters;
@group(0) @binding(3) var<storage, read> active_blocks: array<u32>;
// Slot s holds its block's points at s * 125, x fastest.
@group(0) @binding(6) var<storage, read_write> block_values: array<f32>;
// Slot s, cell c: the case at s * 64 + c.
@group(0) @binding(7) var<storage, read_write> cell_cases: array<u32>;
// The active cells, each as slot * 64 + cell.
@group(0) @binding(8) var<storage, read_write> active_cells: array<u32>;

fn active_slot(workgroup: vec3<u32>) -> u32 {
    let slot = slot_of(workgroup);
    if (slot >= min(atomicLoad(&counters.active_blocks), grid.max_blocks)) {
        return INVALID;
    }
    return slot;
}

@compute @workgroup_size(64)
fn evaluate_field(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let slot = active_slot(workgroup);
    if (slot == INVALID) {
        return;
    }
    let origin = block_coords(active_blocks[slot]) * BLOCK_CELLS;
    for (var i = local; i < BLOCK_POINTS * BLOCK_POINTS * BLOCK_POINTS; i += 64u) {
        let at = vec3<u32>(i % BLOCK_POINTS, (i / BLOCK_POINTS) % BLOCK_POINTS, i / (BLOCK_POINTS * BLOCK_POINTS));
        let id = origin + at;
        var value = 0.0;
        if (!is_boundary(id)) {
            value = field_at(grid_point(id));
        }
        block_values[slot * 125u + i] = value;
    }
}

@compute @workgroup_size(64)
fn classify_cells(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let slot = active_slot(workgroup);
    if (slot == INVALID) {
        return;
    }
    let origin = block_coords(active_blocks[slot]) * BLOCK_CELLS;
    let at = vec3<u32>(local % BLOCK_CELLS, (local / BLOCK_CELLS) % BLOCK_CELLS, local / (BLOCK_CELLS * BLOCK_CELLS));
    var case_index = 0u;
    var values: array<f32, 8>;
    if (all(origin + at < vec3<u32>(grid.cells_per_axis))) {
        for (var c = 0u; c < 8u; c++) {
            let p = at + corner_offset(c);
            let v = block_values[slot * 125u + p.x + BLOCK_POINTS * (p.y + BLOCK_POINTS * p.z)];
            values[c] = v;
            case_index |= select(0u, 1u << c, v > grid.iso);
        }
    }
    var entry = case_index;
    if (has_ambiguous_face(case_index)) {
        let choices = face_choices(slot, at, case_index);
        let decider = (grid.flags & FLAG_DECIDER) != 0u;
        entry |= select(choices & (0x3fu << DECIDED_SHIFT), choices, decider);
    }
    if ((grid.flags & FLAG_MC33) != 0u && case_index != 0u && case_index != 255u) {
        entry |= interior_code(values) << INTERIOR_SHIFT;
    }
    cell_cases[slot * 64u + local] = entry;
    if (case_index != 0u && case_index != 255u) {
        let place = atomicAdd(&counters.active_cells, 1u);
        if (place < grid.max_cells) {
            active_cells[place] = slot * 64u + local;
        }
    }
}

// True when the bilinear interpolant of a face's values (in the face's own corner order) has its saddle
// above iso, joining the face's two inside corners (saddle_above in core/src/extract/decider.rs).
fn saddle_above(f: array<f32, 4>) -> bool {
    let n = f[0] * f[2] - f[1] * f[3];
    let d = (f[0] + f[2]) - (f[1] + f[3]);
    if (d > 0.0) {
        return n > grid.iso * d;
    }
    if (d < 0.0) {
        return n < grid.iso * d;
    }
    return false;
}

// True when corners a and c of a face (in order round it) are on one side and b and d on the other.
fn diagonal(case_index: u32, a: u32, b: u32, c: u32, d: u32) -> bool {
    let s = (vec4<u32>(case_index) >> vec4<u32>(a, b, c, d)) & vec4<u32>(1u);
    return s.x == s.z && s.y == s.w && s.x != s.y;
}

// True when a face of the case is ambiguous: the six faces' corners in order round each (x = 0, x = 1,
// y = 0, y = 1, z = 0, z = 1), tested without reading a value, so that the few cells that have one
// alone (well under 1 % of crossed cells) read their faces.
fn has_ambiguous_face(case_index: u32) -> bool {
    return diagonal(case_index, 0u, 3u, 7u, 4u) || diagonal(case_index, 1u, 2u, 6u, 5u)
        || diagonal(case_index, 0u, 4u, 5u, 1u) || diagonal(case_index, 3u, 7u, 6u, 2u)
        || diagonal(case_index, 0u, 1u, 2u, 3u) || diagonal(case_index, 4u, 5u, 6u, 7u);
}

// The decider's choice on each of the cell's ambiguous faces (face 2 · axis + side, corners (u, v) =
// (0, 0), (1, 0), (1, 1), (0, 1) with u, v the next two axes: FACE_CORNERS in
// core/src/extract/tables.rs), set where its inside corners are joined: from CHOSEN_SHIFT one bit per
// ambiguous face in face order (the variant marching_cubes.wgsl draws), and from DECIDED_SHIFT one bit
// per face.
fn face_choices(slot: u32, at: vec3<u32>, case_index: u32) -> u32 {
    var choices = 0u;
    var ambiguous = 0u;
    for (var face = 0u; face < 6u; face++) {
        let axis = face / 2u;
        // The face's corners as offsets, and which of them are inside (from the case, without a read).
        var offsets: array<vec3<u32>, 4>;
        var inside = 0u;
        for (var k = 0u; k < 4u; k++) {
            var o = vec3<u32>(0u);
            o[axis] = face % 2u;
            o[(axis + 1u) % 3u] = select(0u, 1u, k == 1u || k == 2u);
            o[(axis + 2u) % 3u] = select(0u, 1u, k >= 2u);
            offsets[k] = o;
            let corner = (o.x ^ o.y) | (o.y << 1u) | (o.z << 2u);
            inside |= ((case_index >> corner) & 1u) << k;
        }
        if (inside == 5u || inside == 10u) {
            var f: array<f32, 4>;
            for (var k = 0u; k < 4u; k++) {
                let p = at + offsets[k];
                f[k] = block_values[slot * 125u + p.x + BLOCK_POINTS * (p.y + BLOCK_POINTS * p.z)];
            }
            let joined = saddle_above(f);
            choices |= select(0u, (1u << (ambiguous + CHOSEN_SHIFT)) | (1u << (face + DECIDED_SHIFT)), joined);
            ambiguous += 1u;
        }
    }
    return choices;
}

// The interior's join of a cell with corner values `u` (interior_code in core/src/extract/interior.rs,
// in the same order): 0 for none, else 1 + 2 · pair + side. The slice at the height t* of the vertex
// of A·C − B·D on the vertical edges A (0–4), B (1–5), C (2–6), D (3–7) says which pair of edges the
// body saddle joins, and on which side.
fn interior_code(f: array<f32, 8>) -> u32 {
    var u: array<f32, 8>;
    for (var c = 0u; c < 8u; c++) {
        u[c] = f[c] - grid.iso;
    }
    let da = u[4] - u[0];
    let db = u[5] - u[1];
    let dc = u[6] - u[2];
    let dd = u[7] - u[3];
    let qa = da * dc - db * dd;
    let qb = (u[0] * dc + u[2] * da) - (u[1] * dd + u[3] * db);
    // t* inside (0, 1), decided without the division.
    let w = 2.0 * qa;
    if (!((-qb > 0.0) == (w > 0.0) && qb != 0.0 && abs(qb) < abs(w))) {
        return 0u;
    }
    let t = -qb / w;
    let a = u[0] + da * t;
    let b = u[1] + db * t;
    let c = u[2] + dc * t;
    let d = u[3] + dd * t;
    let ac = a * c;
    let bd = b * d;
    if (ac > bd && ac > 0.0) {
        return 1u + select(0u, 1u, a <= 0.0);
    }
    if (bd > ac && bd > 0.0) {
        return 3u + select(0u, 1u, b <= 0.0);
    }
    return 0u;
}

@group(0) @binding(9) var<storage, read_write> cell_dispatch: DispatchIndirect;

// One invocation: one workgroup per 64 active cells (that fit), in rows of DISPATCH_ROW.
@compute @workgroup_size(1)
fn plan_cell_dispatch() {
    let count = (min(atomicLoad(&counters.active_cells), grid.max_cells) + 63u) / 64u;
    cell_dispatch = rows(count);
}
