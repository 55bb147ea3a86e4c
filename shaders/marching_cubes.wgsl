// Marching-cubes pass: one invocation per cell classifies it from the field values, and an active cell
// reserves room for its triangles with one atomic add and writes them. The counter feeds the indirect
// draw through `finalize_draw`, so the frame never waits on a readback.

struct Counters {
    // Vertices all cells asked for; above `grid.max_vertices` means the budget overflowed.
    vertices_requested: atomic<u32>,
}

struct DrawIndirect {
    vertex_count: u32,
    instance_count: u32,
    first_vertex: u32,
    first_instance: u32,
}

@group(0) @binding(2) var<storage, read> field: array<f32>;
// Per case: bits 0..11 the crossed edges, bits 16.. the triangle count.
@group(0) @binding(3) var<storage, read> case_table: array<u32, 256>;
// Per case, 16 entries: edge numbers of the triangles, -1 after the last.
@group(0) @binding(4) var<storage, read> triangle_table: array<i32, 4096>;
// Per vertex, 6 floats: position, then outward normal.
@group(0) @binding(5) var<storage, read_write> vertices: array<f32>;
@group(0) @binding(6) var<storage, read_write> counters: Counters;

// Corner c of a cell sits at (c bit 0 xor c bit 1, c bit 1, c bit 2): 0 (0,0,0), 1 (1,0,0), 2 (1,1,0),
// 3 (0,1,0), then the same at z = 1 (src/tables.rs, CORNER_OFFSETS).
fn corner_offset(c: u32) -> vec3<u32> {
    return vec3<u32>(((c >> 1u) ^ c) & 1u, (c >> 1u) & 1u, (c >> 2u) & 1u);
}

// Edges 0..3 run along the bottom face, 4..7 along the top face, 8..11 upwards; each from its lower
// corner (src/tables.rs, EDGE_CORNERS).
fn edge_corners(e: u32) -> vec2<u32> {
    switch e {
        case 0u: { return vec2<u32>(0u, 1u); }
        case 1u: { return vec2<u32>(1u, 2u); }
        case 2u: { return vec2<u32>(3u, 2u); }
        case 3u: { return vec2<u32>(0u, 3u); }
        case 4u: { return vec2<u32>(4u, 5u); }
        case 5u: { return vec2<u32>(5u, 6u); }
        case 6u: { return vec2<u32>(7u, 6u); }
        case 7u: { return vec2<u32>(4u, 7u); }
        default: { return vec2<u32>(e - 8u, e - 4u); }
    }
}

fn write_vertex(slot: u32, p: vec3<f32>, n: vec3<f32>) {
    let o = slot * 6u;
    vertices[o] = p.x;
    vertices[o + 1u] = p.y;
    vertices[o + 2u] = p.z;
    vertices[o + 3u] = n.x;
    vertices[o + 4u] = n.y;
    vertices[o + 5u] = n.z;
}

@compute @workgroup_size(4, 4, 4)
fn march_cells(@builtin(global_invocation_id) cell: vec3<u32>) {
    if (any(cell >= vec3<u32>(grid.cells_per_axis))) {
        return;
    }
    var values: array<f32, 8>;
    var case_index = 0u;
    for (var c = 0u; c < 8u; c++) {
        let v = field[point_index(cell + corner_offset(c))];
        values[c] = v;
        case_index |= select(0u, 1u << c, v > grid.iso);
    }
    let entry = case_table[case_index];
    let triangle_count = entry >> 16u;
    if (triangle_count == 0u) {
        return;
    }

    // Each crossed edge's vertex, computed once.
    var positions: array<vec3<f32>, 12>;
    var normals: array<vec3<f32>, 12>;
    for (var e = 0u; e < 12u; e++) {
        if ((entry & (1u << e)) == 0u) {
            continue;
        }
        let ab = edge_corners(e);
        let ia = cell + corner_offset(ab.x);
        let ib = cell + corner_offset(ab.y);
        let pa = grid_point(ia);
        let pb = grid_point(ib);
        let fa = values[ab.x];
        let fb = values[ab.y];
        let t = (grid.iso - fa) / (fb - fa);
        let p = pa + (pb - pa) * t;
        var n: vec3<f32>;
        if (is_boundary(ia)) {
            n = normalize(pa - pb);
        } else if (is_boundary(ib)) {
            n = normalize(pb - pa);
        } else {
            let g = outward_gradient(p);
            let len2 = dot(g, g);
            if (len2 > 0.0) {
                n = g * inverseSqrt(len2);
            } else {
                n = normalize(select(pa - pb, pb - pa, fa > grid.iso));
            }
        }
        positions[e] = p;
        normals[e] = n;
    }

    let first = atomicAdd(&counters.vertices_requested, triangle_count * 3u);
    let row = case_index * 16u;
    for (var k = 0u; k < triangle_count; k++) {
        let slot = first + 3u * k;
        // Past the budget: write nothing (the host sees the overflow in the counter).
        if (slot + 3u > grid.max_vertices) {
            return;
        }
        // The table winds clockwise seen from outside; emit counter-clockwise.
        let e0 = u32(triangle_table[row + 3u * k]);
        let e1 = u32(triangle_table[row + 3u * k + 2u]);
        let e2 = u32(triangle_table[row + 3u * k + 1u]);
        write_vertex(slot, positions[e0], normals[e0]);
        write_vertex(slot + 1u, positions[e1], normals[e1]);
        write_vertex(slot + 2u, positions[e2], normals[e2]);
    }
}

@group(0) @binding(7) var<storage, read_write> draw: DrawIndirect;

// One invocation: the draw covers the vertices written, never more than the buffer holds.
@compute @workgroup_size(1)
fn finalize_draw() {
    draw.vertex_count = min(atomicLoad(&counters.vertices_requested), grid.max_vertices);
    draw.instance_count = 1u;
    draw.first_vertex = 0u;
    draw.first_instance = 0u;
}
