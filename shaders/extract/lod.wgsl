// Level of detail on the device (src/extract/lod/gpu.rs): the frame's blocks come from the selection
// passes (shaders/extract/lod_select.wgsl, in the same module), which keep those the surface may
// cross; these passes mesh them as src/extract/lod/mesher.rs does.
//
// `find_cells`: one workgroup per kept block samples the block at its level (and each transition face
// at the level below) into workgroup memory, lists the crossed cells and transition cells, and makes
// the vertex on each crossed edge once, through a hash table keyed by the edge (its lower end in
// finest cells, its axis and its level): a fine block and the transition cells of its coarse neighbour
// name a shared edge alike. `make_triangles`: each listed cell looks its vertices up and appends its
// triangles. `finalize_draw`: the indexed indirect draw. Nothing is read back.

// The counters; from word 64 (byte 256, LEVEL_COUNTS_OFFSET) the triangles of each level, then the
// leaves of each level.
struct LodCounters {
    active_blocks: atomic<u32>,
    vertices: atomic<u32>,
    indices: atomic<u32>,
    active_cells: atomic<u32>,
    // The selection ran out of room: this frame meshes nothing and keeps the mesh it had.
    lod_overflowed: u32,
    // Levels at or below it were held back from splitting.
    lod_floor: u32,
    // Dual contouring's crossings (Counters in common.wgsl).
    crossings: u32,
    _pad: array<u32, 57>,
    level_triangles: array<atomic<u32>, 12>,
    level_blocks: array<atomic<u32>, 12>,
}

@group(0) @binding(2) var<storage, read_write> counters: LodCounters;

// The meshing passes' dispatches: [0] one workgroup per kept block (written after the selection), [1]
// one invocation per listed cell.
@group(0) @binding(26) var<storage, read_write> lod_dispatch: array<DispatchIndirect, 2>;

struct Lod {
    _unused: u32,
    // Slots in each of the hash table's PARTITIONS partitions (a power of two).
    partition_slots: u32,
    // Where the kept blocks start in `lod_data`, in words.
    blocks_offset: u32,
    _pad: u32,
}

// The tables, in one buffer (WebGPU lets a stage bind only 8 storage buffers): from CASES, per case
// bits 0..11 the crossed edges and bits 16.. the triangle count; from TRIANGLES, per case 16 edge
// numbers of the triangles (0xffffffff after the last); from TRANSITIONS, per transition case 13
// words: the triangle count, then each triangle's three edges (a byte each, the edge's two samples as
// nibbles), wound for a right-handed (u, v, w) frame.
@group(0) @binding(25) var<storage, read> lod_tables: array<u32>;
const CASES: u32 = 0u;
const TRIANGLES: u32 = 256u;
const TRANSITIONS: u32 = 4352u;
// Per vertex, 6 floats: position, then outward normal.
@group(0) @binding(11) var<storage, read_write> vertices: array<f32>;
@group(0) @binding(12) var<storage, read_write> indices: array<u32>;
@group(0) @binding(20) var<uniform> lod: Lod;
// The listed cells: kept block's slot, then cell | case << 10 (cells 0..511 regular, 512.. transition).
@group(0) @binding(22) var<storage, read_write> cells: array<vec2<u32>>;
// The hash table: per slot, the edge key (0 for an empty slot) and the vertex made for it.
@group(0) @binding(23) var<storage, read_write> hash: array<atomic<u32>>;
// Per triangle, its level (with TRANSITION added for a transition cell's); then from
// lod.blocks_offset the kept blocks as the views draw them (grid=blocks), four words each.
@group(0) @binding(14) var<storage, read_write> lod_data: array<u32>;

const LOD_CELLS: u32 = 8u;
const LOD_POINTS: u32 = 9u;
const FACE_POINTS: u32 = 17u;
const REGULAR_CELLS: u32 = 512u;
const PARTITIONS: u32 = 1024u;
const TRANSITION: u32 = 128u;

// Edge e of a cell joins corners (low nibble, high nibble), the lower first (EDGE_CORNERS).
var<private> EDGE_CORNERS: array<u32, 12> = array<u32, 12>(0x10u, 0x21u, 0x23u, 0x30u, 0x54u, 0x65u, 0x67u, 0x74u, 0x40u, 0x51u, 0x62u, 0x73u);

var<workgroup> block_values: array<f32, 729>;
var<workgroup> face_values: array<f32, 1734>;

struct Block {
    origin: vec3<u32>,
    level: u32,
    transitions: u32,
}

// The kept block in slot `index`, where the selection passes left it in `lod_data`.
fn block_at(index: u32) -> Block {
    let at = lod.blocks_offset + 4u * index;
    let b = vec4<u32>(lod_data[at], lod_data[at + 1u], lod_data[at + 2u], lod_data[at + 3u]);
    return Block(b.xyz, b.w & 0xffu, (b.w >> 8u) & 0x3fu);
}

fn block_width(b: Block) -> u32 {
    return LOD_CELLS << b.level;
}

fn unit(axis: u32) -> vec3<u32> {
    return vec3<u32>(u32(axis == 0u), u32(axis == 1u), u32(axis == 2u));
}

// The field at finest grid point `id`, as the oracle samples it.
fn sample(id: vec3<u32>) -> f32 {
    if (is_boundary(id)) {
        return 0.0;
    }
    return field_at(grid_point(id));
}

@compute @workgroup_size(1)
fn plan_cells() {
    lod_dispatch[1] = rows((min(atomicLoad(&counters.active_cells), grid.max_cells) + 63u) / 64u);
}

// The table slot holding `key` in its part; with `insert`, claims a free one for it (the claim
// is flagged in bit 31 of the result). INVALID when the part is full.
fn find_slot(part: u32, key: u32, insert: bool) -> u32 {
    let mask = lod.partition_slots - 1u;
    let base = part * lod.partition_slots;
    var at = (key * 0x9e3779b1u) >> 7u;
    for (var probe = 0u; probe <= mask; probe++) {
        let s = base + (at & mask);
        if (insert) {
            let r = atomicCompareExchangeWeak(&hash[2u * s], 0u, key);
            if (r.exchanged) {
                return s | 0x80000000u;
            }
            if (r.old_value == key) {
                return s;
            }
            if (r.old_value == 0u) {
                // A weak exchange may fail spuriously: try this slot again.
                probe--;
                continue;
            }
        } else {
            let k = atomicLoad(&hash[2u * s]);
            if (k == key) {
                return s;
            }
            if (k == 0u) {
                return INVALID;
            }
        }
        at++;
    }
    return INVALID;
}

// The table slot of the edge of `level` from finest point `start` along `axis`.
fn edge_slot(start: vec3<u32>, axis: u32, level: u32, insert: bool) -> u32 {
    let s = start >> vec3<u32>(level);
    let part = (s.x & 31u) | ((s.y & 31u) << 5u);
    let key = ((s.x >> 5u) | ((s.y >> 5u) << 7u) | (s.z << 14u) | (axis << 26u) | (level << 28u)) + 1u;
    return find_slot(part, key, insert);
}

fn write_vertex(index: u32, p: vec3<f32>, n: vec3<f32>) {
    let o = index * 6u;
    vertices[o] = p.x;
    vertices[o + 1u] = p.y;
    vertices[o + 2u] = p.z;
    vertices[o + 3u] = n.x;
    vertices[o + 4u] = n.y;
    vertices[o + 5u] = n.z;
}

// Makes the vertex on the edge from finest point `start` along `axis` at `level`, whose ends read
// `fa` and `fb`, unless another invocation has.
fn make_vertex(start: vec3<u32>, axis: u32, level: u32, fa: f32, fb: f32) {
    let claimed = edge_slot(start, axis, level, true);
    if (claimed == INVALID || (claimed & 0x80000000u) == 0u) {
        return;
    }
    let slot = claimed & 0x7fffffffu;
    let index = atomicAdd(&counters.vertices, 1u);
    if (index >= grid.max_vertices) {
        atomicStore(&hash[2u * slot + 1u], INVALID);
        return;
    }
    let v = edge_vertex(start, start + unit(axis) * (1u << level), fa, fb);
    write_vertex(index, v.position, v.normal);
    atomicStore(&hash[2u * slot + 1u], index);
}

fn point_index(c: vec3<u32>) -> u32 {
    return c.x + LOD_POINTS * (c.y + LOD_POINTS * c.z);
}

// A transition face's axes: w across it, u and v along it (u = w + 1, v = w + 2, cyclically).
fn face_axes(face: u32) -> vec3<u32> {
    let w = face / 2u;
    return vec3<u32>((w + 1u) % 3u, (w + 2u) % 3u, w);
}

// The finest point of sample (i, j) (in half cells of the block's level) on transition face `face`.
fn face_point(b: Block, face: u32, i: u32, j: u32) -> vec3<u32> {
    let axes = face_axes(face);
    let fine = (1u << b.level) / 2u;
    var p = b.origin;
    p[axes.z] += (face % 2u) * block_width(b);
    p[axes.x] += i * fine;
    p[axes.y] += j * fine;
    return p;
}

// Sample s (0..12) of transition cell (ci, cj): its (i, j) on the face grid.
fn transition_sample(s: u32, ci: u32, cj: u32) -> vec2<u32> {
    var t = s;
    if (s >= 9u) {
        t = 2u * ((s - 9u) & 1u) + 6u * ((s - 9u) >> 1u);
    }
    return vec2<u32>(2u * ci + t % 3u, 2u * cj + t / 3u);
}

fn face_value(face: u32, ij: vec2<u32>) -> f32 {
    return face_values[face * FACE_POINTS * FACE_POINTS + ij.x + FACE_POINTS * ij.y];
}

// The case of transition cell (ci, cj) on `face` (bits as src/extract/lod/transition.rs orders them).
fn transition_case(face: u32, ci: u32, cj: u32) -> u32 {
    var bits = array<u32, 9>(0x001u, 0x002u, 0x004u, 0x080u, 0x100u, 0x008u, 0x040u, 0x020u, 0x010u);
    var case_index = 0u;
    for (var s = 0u; s < 9u; s++) {
        if (face_value(face, transition_sample(s, ci, cj)) > grid.iso) {
            case_index |= bits[s];
        }
    }
    return case_index;
}

// Transition edge `edge` (two sample nibbles) of cell (ci, cj): its lower end on the face grid, axis
// and level, then its end values.
struct TransitionEdge {
    start: vec2<u32>,
    axis: u32,
    level: u32,
}

fn transition_edge(b: Block, face: u32, edge: u32, ci: u32, cj: u32) -> TransitionEdge {
    let a = transition_sample(edge & 15u, ci, cj);
    let c = transition_sample((edge >> 4u) & 15u, ci, cj);
    let axes = face_axes(face);
    var level = b.level - 1u;
    if ((edge & 15u) >= 9u) {
        level = b.level;
    }
    return TransitionEdge(min(a, c), select(axes.y, axes.x, a.x != c.x), level);
}

@compute @workgroup_size(64)
fn find_cells(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let slot = slot_of(workgroup);
    let b = block_at(slot);
    let step = 1u << b.level;
    for (var i = local; i < LOD_POINTS * LOD_POINTS * LOD_POINTS; i += 64u) {
        let c = vec3<u32>(i % LOD_POINTS, (i / LOD_POINTS) % LOD_POINTS, i / (LOD_POINTS * LOD_POINTS));
        block_values[i] = sample(b.origin + c * step);
    }
    for (var face = 0u; face < 6u; face++) {
        if ((b.transitions & (1u << face)) != 0u) {
            for (var i = local; i < FACE_POINTS * FACE_POINTS; i += 64u) {
                let p = face_point(b, face, i % FACE_POINTS, i / FACE_POINTS);
                face_values[face * FACE_POINTS * FACE_POINTS + i] = sample(p);
            }
        }
    }
    workgroupBarrier();

    for (var cell = local; cell < REGULAR_CELLS; cell += 64u) {
        let at = vec3<u32>(cell % LOD_CELLS, (cell / LOD_CELLS) % LOD_CELLS, cell / (LOD_CELLS * LOD_CELLS));
        var case_index = 0u;
        for (var c = 0u; c < 8u; c++) {
            if (block_values[point_index(at + corner_offset(c))] > grid.iso) {
                case_index |= 1u << c;
            }
        }
        let crossed = lod_tables[CASES + case_index] & 0xfffu;
        if (crossed == 0u) {
            continue;
        }
        let listed = atomicAdd(&counters.active_cells, 1u);
        if (listed < grid.max_cells) {
            cells[listed] = vec2<u32>(slot, cell | (case_index << 10u));
        }
        for (var e = 0u; e < 12u; e++) {
            if ((crossed & (1u << e)) != 0u) {
                let ca = at + corner_offset(EDGE_CORNERS[e] & 15u);
                let cb = at + corner_offset(EDGE_CORNERS[e] >> 4u);
                let axis = select(select(2u, 1u, ca.y != cb.y), 0u, ca.x != cb.x);
                let fa = block_values[point_index(ca)];
                let fb = block_values[point_index(cb)];
                make_vertex(b.origin + ca * step, axis, b.level, fa, fb);
            }
        }
    }

    for (var t = local; t < 6u * LOD_CELLS * LOD_CELLS; t += 64u) {
        let face = t / (LOD_CELLS * LOD_CELLS);
        if ((b.transitions & (1u << face)) == 0u) {
            continue;
        }
        let ci = t % LOD_CELLS;
        let cj = (t / LOD_CELLS) % LOD_CELLS;
        let case_index = transition_case(face, ci, cj);
        if (case_index == 0u || case_index == 511u) {
            continue;
        }
        let listed = atomicAdd(&counters.active_cells, 1u);
        if (listed < grid.max_cells) {
            cells[listed] = vec2<u32>(slot, (REGULAR_CELLS + t) | (case_index << 10u));
        }
        let row = case_index * 13u;
        let count = lod_tables[TRANSITIONS + row];
        for (var k = 0u; k < count; k++) {
            let triangle = lod_tables[TRANSITIONS + row + 1u + k];
            for (var j = 0u; j < 3u; j++) {
                let edge = (triangle >> (8u * j)) & 0xffu;
                let e = transition_edge(b, face, edge, ci, cj);
                let lo = e.start;
                let hi = lo + select(vec2<u32>(0u, 1u), vec2<u32>(1u, 0u), e.axis == face_axes(face).x)
                    * select(1u, 2u, e.level == b.level);
                let start = face_point(b, face, lo.x, lo.y);
                make_vertex(start, e.axis, e.level, face_value(face, lo), face_value(face, hi));
            }
        }
    }
}

// The vertex on an edge, or INVALID where it was lost to a full buffer or table.
fn vertex_of(start: vec3<u32>, axis: u32, level: u32) -> u32 {
    let s = edge_slot(start, axis, level, false);
    if (s == INVALID) {
        return INVALID;
    }
    return atomicLoad(&hash[2u * s + 1u]);
}

fn append_triangle(first: u32, k: u32, triangle: vec3<u32>, level: u32) {
    let at = first + 3u * k;
    if (at + 3u > grid.max_indices) {
        return;
    }
    var t = triangle;
    // A vertex lost to a full buffer leaves a degenerate triangle, which draws nothing.
    if (any(t == vec3<u32>(INVALID))) {
        t = vec3<u32>(0u);
    }
    indices[at] = t.x;
    indices[at + 1u] = t.y;
    indices[at + 2u] = t.z;
    lod_data[at / 3u] = level;
}

@compute @workgroup_size(64)
fn make_triangles(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let id = slot_of(workgroup) * 64u + local;
    if (id >= min(atomicLoad(&counters.active_cells), grid.max_cells)) {
        return;
    }
    let listed = cells[id];
    let b = block_at(listed.x);
    let cell = listed.y & 0x3ffu;
    let case_index = listed.y >> 10u;
    let step = 1u << b.level;
    if (cell < REGULAR_CELLS) {
        let count = lod_tables[CASES + case_index] >> 16u;
        let first = atomicAdd(&counters.indices, count * 3u);
        atomicAdd(&counters.level_triangles[b.level], count);
        let at = vec3<u32>(cell % LOD_CELLS, (cell / LOD_CELLS) % LOD_CELLS, cell / (LOD_CELLS * LOD_CELLS));
        let row = case_index * 16u;
        for (var k = 0u; k < count; k++) {
            var triangle = vec3<u32>(0u);
            // The table winds clockwise seen from outside; emit counter-clockwise.
            let order = vec3<u32>(0u, 2u, 1u);
            for (var j = 0u; j < 3u; j++) {
                let e = lod_tables[TRIANGLES + row + 3u * k + order[j]];
                let ca = at + corner_offset(EDGE_CORNERS[e] & 15u);
                let cb = at + corner_offset(EDGE_CORNERS[e] >> 4u);
                let axis = select(select(2u, 1u, ca.y != cb.y), 0u, ca.x != cb.x);
                triangle[j] = vertex_of(b.origin + ca * step, axis, b.level);
            }
            append_triangle(first, k, triangle, b.level);
        }
        return;
    }
    let t = cell - REGULAR_CELLS;
    let face = t / (LOD_CELLS * LOD_CELLS);
    let ci = t % LOD_CELLS;
    let cj = (t / LOD_CELLS) % LOD_CELLS;
    let row = case_index * 13u;
    let count = lod_tables[TRANSITIONS + row];
    let first = atomicAdd(&counters.indices, count * 3u);
    atomicAdd(&counters.level_triangles[b.level], count);
    for (var k = 0u; k < count; k++) {
        let packed = lod_tables[TRANSITIONS + row + 1u + k];
        var triangle = vec3<u32>(0u);
        for (var j = 0u; j < 3u; j++) {
            let e = transition_edge(b, face, (packed >> (8u * j)) & 0xffu, ci, cj);
            triangle[j] = vertex_of(face_point(b, face, e.start.x, e.start.y), e.axis, e.level);
        }
        // (u, v, w) with w into the block is left-handed on a block's high face.
        if (face % 2u == 1u) {
            triangle = triangle.xzy;
        }
        append_triangle(first, k, triangle, b.level | TRANSITION);
    }
}

@group(0) @binding(13) var<storage, read_write> draw_args: DrawIndexedIndirect;

@compute @workgroup_size(1)
fn finalize_draw() {
    // A frame whose selection ran out of room draws the mesh it had.
    if (counters.lod_overflowed != 0u) {
        return;
    }
    draw_args = indexed_draw(atomicLoad(&counters.indices));
}
