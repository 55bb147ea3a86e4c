// Block pass: bound the field over each block of 4³ cells and keep only the blocks the surface may
// cross. Over a box with centre c and half-diagonal h, a sphere's term r²/|p − cᵢ|² lies between
// r²/(d + h)² and r²/(d − h)² (d = |c − cᵢ|), so the sums of those bound f. A block whose upper bound is
// at most iso is all outside, one whose lower bound is above iso all inside (unless it touches the box's
// faces, which read as outside); either way no cell in it emits a triangle. The others are appended to
// the active list, whose length becomes the indirect dispatch of the per-block passes.

@group(0) @binding(2) var<storage, read_write> counters: Counters;
// Slot → block index, for the active blocks.
@group(0) @binding(3) var<storage, read_write> active_blocks: array<u32>;
// Block index → slot, or INVALID for a skipped block.
@group(0) @binding(4) var<storage, read_write> block_slots: array<u32>;

@compute @workgroup_size(64)
fn classify_blocks(@builtin(global_invocation_id) id: vec3<u32>) {
    let n = blocks_per_axis();
    let block = id.x;
    if (block >= n * n * n) {
        return;
    }
    let first = block_coords(block) * BLOCK_CELLS;
    let last = min(first + vec3<u32>(BLOCK_CELLS), vec3<u32>(grid.cells_per_axis));
    let touches_walls = any(first == vec3<u32>(0u)) || any(last >= vec3<u32>(grid.cells_per_axis));
    var slot = INVALID;
    if (straddles(grid_point(first), grid_point(last), touches_walls)) {
        let s = atomicAdd(&counters.active_blocks, 1u);
        if (s < grid.max_blocks) {
            active_blocks[s] = block;
            slot = s;
        }
    }
    block_slots[block] = slot;
}

@group(0) @binding(5) var<storage, read_write> block_dispatch: DispatchIndirect;

// One invocation: one workgroup per active block (that fits), in rows of DISPATCH_ROW.
@compute @workgroup_size(1)
fn plan_dispatch() {
    let count = min(atomicLoad(&counters.active_blocks), grid.max_blocks);
    block_dispatch = rows(count);
}
