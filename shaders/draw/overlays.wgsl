// Overlay pass, after marching cubes: the field slice's samples and its iso contour (marching squares
// on the same grid points, interpolated as the surface's vertices are, so the contour meets the surface
// exactly where the plane cuts it), then the indirect draw arguments of every teaching view, from the
// counts the compute passes left. Compiled after shaders/common.wgsl and shaders/draw/shade.wgsl.

@group(0) @binding(2) var<storage, read_write> counters: Counters;
// (n + 1)² samples of the slice plane, first in-plane axis fastest.
@group(0) @binding(31) var<storage, read_write> slice_values: array<f32>;
// Two points per contour segment.
@group(0) @binding(32) var<storage, read_write> segments: array<vec4<f32>>;

struct Overlays {
    segment_count: atomic<u32>,
    _pad0: u32,
    _pad1: u32,
    _pad2: u32,
    // Nine indirect draws of four words (src/draw/views/, `Draw`).
    draws: array<u32, 36>,
}

@group(0) @binding(34) var<storage, read_write> overlays: Overlays;
// Per marching-squares case: its segments as pairs of square edges, 4 bits each, low pair first,
// 0xf after the last (src/draw/slice.rs, SQUARE_SEGMENTS).
@group(0) @binding(35) var<uniform> square_segments: array<vec4<u32>, 4>;

// Grid point (i, j) of the slice plane.
fn slice_id(i: u32, j: u32) -> vec3<u32> {
    let a = shading.slice_axis;
    var id = vec3<u32>(0u);
    id[a] = shading.slice_plane;
    id[(a + 1u) % 3u] = i;
    id[(a + 2u) % 3u] = j;
    return id;
}

@compute @workgroup_size(8, 8)
fn sample_slice(@builtin(global_invocation_id) g: vec3<u32>) {
    let row = grid.cells_per_axis + 1u;
    if (g.x >= row || g.y >= row) {
        return;
    }
    let id = slice_id(g.x, g.y);
    var value = 0.0;
    if (!is_boundary(id)) {
        value = field_at(grid_point(id));
    }
    slice_values[g.x + row * g.y] = value;
}

// Square corner k (0..3) at (i, j) + offset: 0 (0,0), 1 (1,0), 2 (1,1), 3 (0,1).
fn square_corner(k: u32) -> vec2<u32> {
    return vec2<u32>(((k >> 1u) ^ k) & 1u, (k >> 1u) & 1u);
}

// The contour point on square edge e: 0 bottom, 1 right, 2 top, 3 left, always interpolated from the
// edge's lower end as marching cubes does.
fn edge_point(square: vec2<u32>, e: u32) -> vec3<f32> {
    var lo = vec2<u32>(0u, 0u);
    var hi = vec2<u32>(1u, 0u);
    if (e == 1u) {
        lo = vec2<u32>(1u, 0u);
        hi = vec2<u32>(1u, 1u);
    } else if (e == 2u) {
        lo = vec2<u32>(0u, 1u);
        hi = vec2<u32>(1u, 1u);
    } else if (e == 3u) {
        hi = vec2<u32>(0u, 1u);
    }
    let row = grid.cells_per_axis + 1u;
    let a = square + lo;
    let b = square + hi;
    let fa = slice_values[a.x + row * a.y];
    let fb = slice_values[b.x + row * b.y];
    let pa = grid_point(slice_id(a.x, a.y));
    let pb = grid_point(slice_id(b.x, b.y));
    let t = edge_parameter(fa, fb);
    return pa + (pb - pa) * t;
}

// Whether a saddle square's inside corners join, by the rule `shading.saddle` (src/draw/slice.rs,
// `saddle_joins`, is the same rule on the CPU).
fn saddle_joins(square: vec2<u32>) -> bool {
    let row = grid.cells_per_axis + 1u;
    var f: array<f32, 4>;
    for (var k = 0u; k < 4u; k++) {
        let c = square + square_corner(k);
        f[k] = slice_values[c.x + row * c.y];
    }
    if (shading.saddle == 1u) {
        return (f[0] + f[1] + f[2] + f[3]) * 0.25 > grid.iso;
    }
    if (shading.saddle == 2u) {
        // The bilinear interpolant's value at its saddle point; the diagonals differ in sign, so the
        // denominator is never zero here.
        return (f[0] * f[2] - f[1] * f[3]) / (f[0] + f[2] - f[1] - f[3]) > grid.iso;
    }
    return false;
}

@compute @workgroup_size(8, 8)
fn contour_slice(@builtin(global_invocation_id) g: vec3<u32>) {
    let n = grid.cells_per_axis;
    if (g.x >= n || g.y >= n) {
        return;
    }
    let row = n + 1u;
    var case_index = 0u;
    for (var k = 0u; k < 4u; k++) {
        let c = g.xy + square_corner(k);
        case_index |= select(0u, 1u << k, slice_values[c.x + row * c.y] > grid.iso);
    }
    // A saddle square (two inside corners on a diagonal) whose inside corners the rule joins takes the
    // other diagonal's segments, which cut off the outside corners instead.
    var segment_case = case_index;
    if ((case_index == 5u || case_index == 10u) && saddle_joins(g.xy)) {
        segment_case = 15u - case_index;
    }
    let packed = square_segments[segment_case / 4u][segment_case % 4u];
    for (var s = 0u; s < 2u; s++) {
        let pair = (packed >> (8u * s)) & 0xffu;
        if ((pair & 0xfu) == 0xfu) {
            return;
        }
        let place = atomicAdd(&overlays.segment_count, 1u);
        if (place < 2u * n * n) {
            segments[2u * place] = vec4<f32>(edge_point(g.xy, pair & 0xfu), 1.0);
            segments[2u * place + 1u] = vec4<f32>(edge_point(g.xy, pair >> 4u), 1.0);
        }
    }
}

fn set_draw(k: u32, vertex_count: u32, instance_count: u32) {
    overlays.draws[4u * k] = vertex_count;
    overlays.draws[4u * k + 1u] = instance_count;
    overlays.draws[4u * k + 2u] = 0u;
    overlays.draws[4u * k + 3u] = 0u;
}

// One invocation: the draws of the views, sized by what the passes produced (never past a buffer).
@compute @workgroup_size(1)
fn plan_overlays() {
    let n = grid.cells_per_axis;
    let vertex_count = min(atomicLoad(&counters.vertices), grid.max_vertices);
    let cell_count = min(atomicLoad(&counters.active_cells), grid.max_cells);
    set_draw(0u, min(atomicLoad(&counters.indices), grid.max_indices), 1u);
    set_draw(1u, 6u, vertex_count);
    set_draw(2u, 2u, vertex_count);
    set_draw(3u, 24u, cell_count);
    set_draw(4u, 24u, min(atomicLoad(&counters.active_blocks), grid.max_blocks));
    set_draw(5u, 72u, cell_count);
    set_draw(6u, 2u, min(atomicLoad(&overlays.segment_count), 2u * n * n));
    // Level of detail's kept blocks: 12 edges and two diagonals on each of six faces.
    set_draw(7u, 48u, min(atomicLoad(&counters.active_blocks), grid.max_blocks));
    // Dual contouring's crossings on the GPU: two vertices each, in the records after the mesh's.
    set_draw(8u, 2u * min(atomicLoad(&counters.crossings), grid.max_vertices - vertex_count), 1u);
    overlays.draws[34u] = 2u * vertex_count;
}
