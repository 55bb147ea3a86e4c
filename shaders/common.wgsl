// Shared by the field and marching-cubes passes: the grid, the spheres and the field itself.
// Mirrors `GridUniform` in src/uniforms.rs and the oracle in src/reference.rs.

struct Grid {
    box_min: vec3<f32>,
    cell_size: f32,
    iso: f32,
    cells_per_axis: u32,
    sphere_count: u32,
    max_vertices: u32,
}

@group(0) @binding(0) var<uniform> grid: Grid;
// xyz: centre, w: radius.
@group(0) @binding(1) var<storage, read> spheres: array<vec4<f32>>;

// Squared distances are clamped to this so a grid point at a centre reads a huge but finite value.
const MIN_DISTANCE_SQUARED: f32 = 1e-20;

fn points_per_axis() -> u32 {
    return grid.cells_per_axis + 1u;
}

fn grid_point(id: vec3<u32>) -> vec3<f32> {
    return grid.box_min + vec3<f32>(id) * grid.cell_size;
}

fn point_index(id: vec3<u32>) -> u32 {
    let n = points_per_axis();
    return id.x + n * (id.y + n * id.z);
}

// Points on the box's faces read as outside, which closes the surface where it meets a wall.
fn is_boundary(id: vec3<u32>) -> bool {
    return any(id == vec3<u32>(0u)) || any(id == vec3<u32>(grid.cells_per_axis));
}

// f(p) = Σ r² / |p − c|²
fn field_at(p: vec3<f32>) -> f32 {
    var f = 0.0;
    for (var i = 0u; i < grid.sphere_count; i++) {
        let s = spheres[i];
        let d = p - s.xyz;
        f += s.w * s.w / max(dot(d, d), MIN_DISTANCE_SQUARED);
    }
    return f;
}

// −∇f / 2 = Σ r² (p − c) / |p − c|⁴, pointing out of the surface.
fn outward_gradient(p: vec3<f32>) -> vec3<f32> {
    var g = vec3<f32>(0.0);
    for (var i = 0u; i < grid.sphere_count; i++) {
        let s = spheres[i];
        let d = p - s.xyz;
        let d2 = max(dot(d, d), MIN_DISTANCE_SQUARED);
        g += d * (s.w * s.w / (d2 * d2));
    }
    return g;
}
