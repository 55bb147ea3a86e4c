// Level selection on the device (src/extract/lod/walk.rs), by the rule of src/extract/lod/select.rs,
// in one module with shaders/extract/lod.wgsl (whose counters, dispatches and `lod_data` it writes):
// the octree is walked one level per dispatch, coarsest first, over a queue of candidate blocks. Each
// invocation tests its block against the view frustum and the field's exact bounds (`straddles`), then
// either appends its eight children to the next level's queue or emits itself as a leaf with its
// transition faces. Leaves go where the meshing passes and the views read them: from `blocks_offset`
// in `lod_data`, origin in finest cells (xyz), then level | transition faces << 8. A one-invocation
// pass after each level writes the next level's indirect dispatch, and after the finest the meshing
// passes'. Nothing is read back.
//
// Capacities are fixed: a queue or the leaves running out sets `overflowed`, the frame keeps the mesh
// it had (`finalize_draw` leaves the draw as it was), and from the next frame the finest levels are
// held back (`floor`) until a frame has room again.

struct Walk {
    // The view frustum's planes: inside where dot(plane.xyz, p) + plane.w >= 0 for each.
    planes: array<vec4<f32>, 6>,
    // The eye in finest cells from the box's low corner; w: 1 to drop the blocks outside the view.
    eye: vec4<f32>,
    // Per level (four to a vector): the squared distance in finest cells below which a block of the
    // level splits, before the floor.
    split_below: array<vec4<f32>, 3>,
    top: u32,
    roots_per_axis: u32,
    // Entries in each of the two queues.
    queue_capacity: u32,
    // Where the kept blocks start in `lod_data`, in words.
    blocks_offset: u32,
}

struct WalkState {
    // The level the next `select_blocks` dispatch walks.
    level: u32,
    // Levels at or below it do not split (0: none held back).
    floor: u32,
    // A queue or the leaves ran out this frame.
    overflowed: u32,
    // Candidates in each queue (level & 1).
    queued: array<atomic<u32>, 2>,
    // The leaves of the last frame.
    leaves: u32,
    // Some block of the last frame would have split but for the floor.
    held: u32,
}

@group(0) @binding(15) var<uniform> walk: Walk;
// Two queues of `queue_capacity` candidates, one per level parity: origin / LOD_CELLS, 10 bits an axis.
@group(0) @binding(16) var<storage, read_write> queues: array<u32>;
@group(0) @binding(18) var<storage, read_write> state: WalkState;
// Per level, the dispatch of its `select_blocks` (the coarsest is dispatched directly).
@group(0) @binding(19) var<storage, read_write> walk_dispatch: array<DispatchIndirect, 10>;

fn split_below(level: u32) -> f32 {
    if (level <= state.floor) {
        return -1.0;
    }
    return walk.split_below[level / 4u][level % 4u];
}


fn distance_squared(origin: vec3<u32>, level: u32) -> f32 {
    let low = vec3<f32>(origin);
    let high = vec3<f32>(origin + vec3<u32>(LOD_CELLS << level));
    let e = walk.eye.xyz;
    let d = clamp(e, low, high) - e;
    return d.x * d.x + d.y * d.y + d.z * d.z;
}

fn splits(origin: vec3<u32>, level: u32) -> bool {
    return distance_squared(origin, level) < split_below(level);
}

fn transitions(origin: vec3<u32>, level: u32) -> u32 {
    let width = LOD_CELLS << level;
    var faces = 0u;
    for (var axis = 0u; axis < 3u; axis++) {
        if (origin[axis] > 0u) {
            var beyond = origin;
            beyond[axis] -= width;
            if (splits(beyond, level)) {
                faces |= 1u << (2u * axis);
            }
        }
        if (origin[axis] + width < grid.cells_per_axis) {
            var beyond = origin;
            beyond[axis] += width;
            if (splits(beyond, level)) {
                faces |= 1u << (2u * axis + 1u);
            }
        }
    }
    return faces;
}

// False when the box lies wholly outside one plane of the view frustum: its corner farthest along the
// plane's normal is outside (`Eye::sees`).
fn sees(low: vec3<f32>, high: vec3<f32>) -> bool {
    for (var i = 0u; i < 6u; i++) {
        let plane = walk.planes[i];
        let n = plane.xyz;
        let farthest = select(low, high, n > vec3<f32>(0.0));
        if (n.x * farthest.x + n.y * farthest.y + n.z * farthest.z + plane.w < 0.0) {
            return false;
        }
    }
    return true;
}

fn pack(origin: vec3<u32>) -> u32 {
    let o = origin / LOD_CELLS;
    return o.x | (o.y << 10u) | (o.z << 20u);
}

fn unpack(entry: u32) -> vec3<u32> {
    return vec3<u32>(entry & 1023u, (entry >> 10u) & 1023u, entry >> 20u) * LOD_CELLS;
}

// Starts a frame's walk: the floor follows the last frame's room, the queues empty.
@compute @workgroup_size(1)
fn begin_walk() {
    if (state.overflowed != 0u) {
        state.floor = min(state.floor + 1u, walk.top);
    } else if (state.held == 0u) {
        // The floor changed nothing: the rule alone fits.
        state.floor = 0u;
    } else if (state.floor > 0u && 8u * state.leaves < grid.max_blocks) {
        // Room for eight times the blocks (and so their candidates): a level finer has about four
        // times as many near the surface, and up to eight.
        state.floor -= 1u;
    }
    state.held = 0u;
    state.level = walk.top;
    state.overflowed = 0u;
    atomicStore(&state.queued[0], 0u);
    atomicStore(&state.queued[1], 0u);
}

fn emit_leaf(origin: vec3<u32>, level: u32) {
    let s = atomicAdd(&counters.active_blocks, 1u);
    atomicAdd(&counters.level_blocks[level], 1u);
    if (s >= grid.max_blocks) {
        state.overflowed = 1u;
        return;
    }
    let at = walk.blocks_offset + 4u * s;
    lod_data[at] = origin.x;
    lod_data[at + 1u] = origin.y;
    lod_data[at + 2u] = origin.z;
    lod_data[at + 3u] = level | (transitions(origin, level) << 8u);
}

@compute @workgroup_size(64)
fn select_blocks(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let index = slot_of(workgroup) * 64u + local;
    let level = state.level;
    var origin: vec3<u32>;
    if (level == walk.top) {
        let n = walk.roots_per_axis;
        if (index >= n * n * n) {
            return;
        }
        origin = vec3<u32>(index % n, (index / n) % n, index / (n * n)) * (LOD_CELLS << level);
    } else {
        let queue = level & 1u;
        if (index >= min(atomicLoad(&state.queued[queue]), walk.queue_capacity)) {
            return;
        }
        origin = unpack(queues[queue * walk.queue_capacity + index]);
    }
    let far = origin + vec3<u32>(LOD_CELLS << level);
    let low = grid_point(origin);
    let high = grid_point(far);
    if (walk.eye.w != 0.0 && !sees(low, high)) {
        return;
    }
    let walls = any(origin == vec3<u32>(0u)) || any(far >= vec3<u32>(grid.cells_per_axis));
    if (!straddles(low, high, walls)) {
        return;
    }
    if (!splits(origin, level)) {
        // Held back by the floor alone?
        if (level <= state.floor && distance_squared(origin, level) < walk.split_below[level / 4u][level % 4u]) {
            state.held = 1u;
        }
        emit_leaf(origin, level);
        return;
    }
    let next = (level - 1u) & 1u;
    let first = atomicAdd(&state.queued[next], 8u);
    if (first + 8u > walk.queue_capacity) {
        state.overflowed = 1u;
        return;
    }
    let half = (LOD_CELLS << level) / 2u;
    for (var c = 0u; c < 8u; c++) {
        let child = origin + vec3<u32>(c & 1u, (c >> 1u) & 1u, c >> 2u) * half;
        queues[next * walk.queue_capacity + first + c] = pack(child);
    }
}

// After level `state.level`: the next level's dispatch, and its children's queue emptied. After
// the finest: what the frame selected (for the statistics and the next frame's floor), and the meshing
// passes' dispatch, empty where the selection ran out of room: that frame keeps the mesh it had
// (`finalize_draw` leaves the draw as it was).
@compute @workgroup_size(1)
fn plan_level() {
    let level = state.level;
    if (level == 0u) {
        let leaves = atomicLoad(&counters.active_blocks);
        state.leaves = leaves;
        counters.lod_floor = state.floor;
        counters.lod_overflowed = state.overflowed;
        lod_dispatch[0] = rows(select(min(leaves, grid.max_blocks), 0u, state.overflowed != 0u));
        // Out of room, the frame asks for half as many blocks again (a queue may have run out first),
        // so that the buffers grow.
        if (state.overflowed != 0u) {
            atomicMax(&counters.active_blocks, grid.max_blocks + grid.max_blocks / 2u + 1u);
        }
        return;
    }
    let next = level - 1u;
    let count = min(atomicLoad(&state.queued[next & 1u]), walk.queue_capacity);
    walk_dispatch[next] = rows((count + 63u) / 64u);
    atomicStore(&state.queued[level & 1u], 0u);
    state.level = next;
}
