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
    if (all(origin + at < vec3<u32>(grid.cells_per_axis))) {
        for (var c = 0u; c < 8u; c++) {
            let p = at + corner_offset(c);
            let v = block_values[slot * 125u + p.x + BLOCK_POINTS * (p.y + BLOCK_POINTS * p.z)];
            case_index |= select(0u, 1u << c, v > grid.iso);
        }
    }
    cell_cases[slot * 64u + local] = case_index;
    if (case_index != 0u && case_index != 255u) {
        let place = atomicAdd(&counters.active_cells, 1u);
        if (place < grid.max_cells) {
            active_cells[place] = slot * 64u + local;
        }
    }
}

struct DispatchIndirect {
    x: u32,
    y: u32,
    z: u32,
}

@group(0) @binding(9) var<storage, read_write> cell_dispatch: DispatchIndirect;

// One invocation: one workgroup per 64 active cells (that fit), in rows of DISPATCH_ROW.
@compute @workgroup_size(1)
fn plan_cell_dispatch() {
    let count = (min(atomicLoad(&counters.active_cells), grid.max_cells) + 63u) / 64u;
    cell_dispatch.x = min(count, DISPATCH_ROW);
    cell_dispatch.y = (count + DISPATCH_ROW - 1u) / DISPATCH_ROW;
    cell_dispatch.z = 1u;
}
