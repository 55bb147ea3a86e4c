// Field pass: for each active block, f at its 5³ grid points (0 on the box's faces), stored per slot.

@group(0) @binding(2) var<storage, read> totals: Totals;
@group(0) @binding(3) var<storage, read> active_blocks: array<u32>;
// Slot s holds its block's points at s * 125, x fastest.
@group(0) @binding(4) var<storage, read_write> block_values: array<f32>;

@compute @workgroup_size(64)
fn evaluate_field(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let slot = slot_of(workgroup);
    if (slot >= min(totals.active_blocks, grid.max_blocks)) {
        return;
    }
    let origin = block_coords(active_blocks[slot]) * BLOCK_CELLS;
    for (var i = local; i < BLOCK_POINTS * BLOCK_POINTS * BLOCK_POINTS; i += 64u) {
        let id = origin + vec3<u32>(i % BLOCK_POINTS, (i / BLOCK_POINTS) % BLOCK_POINTS, i / (BLOCK_POINTS * BLOCK_POINTS));
        var value = 0.0;
        if (!is_boundary(id)) {
            value = field_at(grid_point(id));
        }
        block_values[slot * 125u + i] = value;
    }
}
