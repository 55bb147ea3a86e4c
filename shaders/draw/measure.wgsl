// Measures pass: how good the mesh is, measured on the GPU every frame that asks, with nothing read back
// in the frame. Each vertex's distance to the exact surface (surface_distance in shaders/common.wgsl) is
// summed in squares and kept at its largest; each triangle's shape (as color-by=quality shows it) is
// counted in ten bins. The sums land in the counters buffer from byte 512 (`Measures` in
// src/extract/uniforms.rs) and come back with the frame statistics.

struct Job {
    // 1 when the mesh was uploaded (its counts are below); 0 when the compute passes counted it.
    known: u32,
    vertices: u32,
    triangles: u32,
    _pad: u32,
}

struct CounterWords {
    active_blocks: u32,
    vertices: u32,
    indices: u32,
    active_cells: u32,
    _before: array<u32, 124>,
    // Σ error², in cells² / 2²⁰, as a 64-bit sum.
    squares_low: atomic<u32>,
    squares_high: atomic<u32>,
    // The largest error's bits (errors are not negative, so their bits order as they do).
    largest: atomic<u32>,
    measured: atomic<u32>,
    quality: array<atomic<u32>, 10>,
    _after: array<u32, 2>,
}

const SQUARES_SCALE: f32 = 1048576.0;

@group(0) @binding(2) var<storage, read_write> counters: CounterWords;
@group(0) @binding(11) var<storage, read> vertices: array<f32>;
@group(0) @binding(12) var<storage, read> indices: array<u32>;
@group(0) @binding(36) var<uniform> measure_job: Job;
@group(0) @binding(37) var<storage, read_write> measure_dispatch: DispatchIndirect;

fn vertex_count() -> u32 {
    if (measure_job.known == 1u) {
        return measure_job.vertices;
    }
    return min(counters.vertices, grid.max_vertices);
}

fn triangle_count() -> u32 {
    if (measure_job.known == 1u) {
        return measure_job.triangles;
    }
    return min(counters.indices, grid.max_indices) / 3u;
}

// One invocation: a workgroup per 64 vertices or triangles, whichever are more, in rows.
@compute @workgroup_size(1)
fn plan_measures() {
    let count = (max(vertex_count(), triangle_count()) + 63u) / 64u;
    measure_dispatch = rows(count);
}

fn position(i: u32) -> vec3<f32> {
    return vec3<f32>(vertices[6u * i], vertices[6u * i + 1u], vertices[6u * i + 2u]);
}

fn add_square(e: f32) {
    let units = u32(min(e * e, 4000.0) * SQUARES_SCALE);
    let before = atomicAdd(&counters.squares_low, units);
    if (before + units < before) {
        atomicAdd(&counters.squares_high, 1u);
    }
}

@compute @workgroup_size(64)
fn measure(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) local: u32) {
    let i = (workgroup.x + workgroup.y * DISPATCH_ROW) * 64u + local;
    if (i < vertex_count()) {
        let e = surface_distance(position(i));
        add_square(e);
        atomicMax(&counters.largest, bitcast<u32>(e));
        atomicAdd(&counters.measured, 1u);
    }
    if (i < triangle_count()) {
        let a = position(indices[3u * i]);
        let b = position(indices[3u * i + 1u]);
        let c = position(indices[3u * i + 2u]);
        // 4√3 A / (a² + b² + c²), as shaders/draw/views/triangles.wgsl colours it.
        let doubled = length(cross(b - a, c - a));
        let sum = dot(b - a, b - a) + dot(c - b, c - b) + dot(a - c, a - c);
        let q = select(0.0, 2.0 * sqrt(3.0) * doubled / sum, sum > 0.0);
        atomicAdd(&counters.quality[min(u32(q * 10.0), 9u)], 1u);
    }
}
