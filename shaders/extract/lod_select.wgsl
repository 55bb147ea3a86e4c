// Level selection on the device (src/extract/lod/walk.rs), by the rule of src/extract/lod/select.rs:
// the octree is walked one level per dispatch, coarsest first, over a queue of candidate blocks. Each
// invocation tests its block against the view frustum and the field's exact bounds (`straddles`), then
// either appends its eight children to the next level's queue or emits itself as a leaf with its
// transition faces. Leaves go where the meshing passes (shaders/extract/lod.wgsl) read them: the
// selection, the kept blocks and the counters. A one-invocation pass between levels writes the next
// level's indirect dispatch. Nothing is read back.
//
// Capacities are fixed: a queue or the leaves running out sets `overflowed`, the frame keeps the mesh
// it had (`finalize_draw` leaves the draw as it was), and from the next frame the finest levels are
// held back (`floor`) until a frame has room again.

struct Walk {
    view_projection: mat4x4<f32>,
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
    // The largest queue of the frame.
    peak: u32,
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
@group(0) @binding(18) var<storage, read_write> walk_state: WalkState;
// Per level, the dispatch of its `select_blocks` (the coarsest is dispatched directly).
@group(0) @binding(19) var<storage, read_write> walk_dispatch: array<DispatchIndirect, 10>;
// The selection the meshing passes read: origin in finest cells (xyz), then level | faces << 8.
@group(0) @binding(21) var<storage, read_write> selection: array<vec4<u32>>;
@group(0) @binding(24) var<storage, read_write> kept_blocks: array<u32>;
@group(0) @binding(14) var<storage, read_write> lod_data: array<u32>;

const LOD_CELLS: u32 = 8u;
// How far below the capacities a frame must stay for a raised floor to come down a level: a level
// finer has about four times the blocks near the surface.
const ROOM_FACTOR: u32 = 4u;

fn split_below(level: u32) -> f32 {
    if (level <= walk_state.floor) {
        return -1.0;
    }
    return walk.split_below[level / 4u][level % 4u];
}

// True when the floor alone keeps the block from splitting.
fn held_back(origin: vec3<u32>, level: u32) -> bool {
    return level <= walk_state.floor && distance_squared(origin, level) < walk.split_below[level / 4u][level % 4u];
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

// False when the box lies wholly outside one plane of the view frustum (`Eye::sees`).
fn sees(low: vec3<f32>, high: vec3<f32>) -> bool {
    var outside = array<bool, 6>(true, true, true, true, true, true);
    for (var i = 0u; i < 8u; i++) {
        let p = select(low, high, vec3<bool>((i & 1u) != 0u, (i & 2u) != 0u, (i & 4u) != 0u));
        let c = walk.view_projection * vec4<f32>(p, 1.0);
        outside[0] = outside[0] && c.x < -c.w;
        outside[1] = outside[1] && c.x > c.w;
        outside[2] = outside[2] && c.y < -c.w;
        outside[3] = outside[3] && c.y > c.w;
        outside[4] = outside[4] && c.z < 0.0;
        outside[5] = outside[5] && c.z > c.w;
    }
    return !(outside[0] || outside[1] || outside[2] || outside[3] || outside[4] || outside[5]);
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
    if (walk_state.overflowed != 0u) {
        walk_state.floor = min(walk_state.floor + 1u, walk.top);
    } else if (walk_state.held == 0u) {
        // The floor changed nothing: the rule alone fits.
        walk_state.floor = 0u;
    } else if (walk_state.floor > 0u && ROOM_FACTOR * walk_state.peak < walk.queue_capacity
        && ROOM_FACTOR * walk_state.leaves < grid.max_blocks) {
        walk_state.floor -= 1u;
    }
    walk_state.held = 0u;
    walk_state.level = walk.top;
    walk_state.overflowed = 0u;
    walk_state.peak = 0u;
    atomicStore(&walk_state.queued[0], 0u);
    atomicStore(&walk_state.queued[1], 0u);
}

fn emit_leaf(origin: vec3<u32>, level: u32) {
    let s = atomicAdd(&counters.active_blocks, 1u);
    atomicAdd(&counters.level_blocks[level], 1u);
    if (s >= grid.max_blocks) {
        walk_state.overflowed = 1u;
        return;
    }
    let packed = vec4<u32>(origin, level | (transitions(origin, level) << 8u));
    selection[s] = packed;
    kept_blocks[s] = s;
    let at = walk.blocks_offset + 4u * s;
    lod_data[at] = packed.x;
    lod_data[at + 1u] = packed.y;
    lod_data[at + 2u] = packed.z;
    lod_data[at + 3u] = packed.w;
}

@compute @workgroup_size(64)
fn select_blocks(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let index = slot_of(workgroup) * 64u + local;
    let level = walk_state.level;
    var origin: vec3<u32>;
    if (level == walk.top) {
        let n = walk.roots_per_axis;
        if (index >= n * n * n) {
            return;
        }
        origin = vec3<u32>(index % n, (index / n) % n, index / (n * n)) * (LOD_CELLS << level);
    } else {
        let queue = level & 1u;
        if (index >= min(atomicLoad(&walk_state.queued[queue]), walk.queue_capacity)) {
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
        if (held_back(origin, level)) {
            walk_state.held = 1u;
        }
        emit_leaf(origin, level);
        return;
    }
    let next = (level - 1u) & 1u;
    let first = atomicAdd(&walk_state.queued[next], 8u);
    if (first + 8u > walk.queue_capacity) {
        walk_state.overflowed = 1u;
        return;
    }
    let half = (LOD_CELLS << level) / 2u;
    for (var c = 0u; c < 8u; c++) {
        let child = origin + vec3<u32>(c & 1u, (c >> 1u) & 1u, c >> 2u) * half;
        queues[next * walk.queue_capacity + first + c] = pack(child);
    }
}

// After level `walk_state.level`: the next level's dispatch, and its children's queue emptied.
@compute @workgroup_size(1)
fn plan_level() {
    let level = walk_state.level;
    if (level == 0u) {
        return;
    }
    let next = level - 1u;
    let count = min(atomicLoad(&walk_state.queued[next & 1u]), walk.queue_capacity);
    walk_state.peak = max(walk_state.peak, atomicLoad(&walk_state.queued[next & 1u]));
    walk_dispatch[next] = rows((count + 63u) / 64u);
    atomicStore(&walk_state.queued[level & 1u], 0u);
    walk_state.level = next;
}

// After the walk: what the frame selected, for the statistics and the next frame's floor. An
// overflowed frame meshes nothing and keeps the mesh it had (`plan_blocks`, `finalize_draw`).
@compute @workgroup_size(1)
fn end_walk() {
    walk_state.leaves = atomicLoad(&counters.active_blocks);
    counters.lod_floor = walk_state.floor;
    counters.lod_overflowed = walk_state.overflowed;
}
