// The mesh one triangle at a time (display=flat, wireframe; color-by=area, quality, case, level, error,
// rank).

struct TriangleOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) @interpolate(flat) face_normal: vec3<f32>,
    @location(3) barycentric: vec3<f32>,
    @location(4) @interpolate(flat) albedo: vec3<f32>,
    // With color-by=error, this vertex's distance to the exact surface in cells.
    @location(5) error: f32,
    // With color-by=rank, the QEF marks of the triangle's three corners, three bits each.
    @location(6) @interpolate(flat) marks: u32,
}

fn triangle_color(a: vec3<f32>, b: vec3<f32>, c: vec3<f32>, triangle: u32) -> vec3<f32> {
    let doubled = length(cross(b - a, c - a));
    let face = grid.cell_size * grid.cell_size;
    if (shading.color_by == COLOR_AREA) {
        // Area as a fraction of a cell face's, up to half a face.
        return ramp(0.5 * doubled / face / 0.5);
    } else if (shading.color_by == COLOR_QUALITY) {
        // 4√3 A / (a² + b² + c²): 1 for an equilateral triangle, 0 for a sliver.
        let sum = dot(b - a, b - a) + dot(c - b, c - b) + dot(a - c, a - c);
        return ramp(select(0.0, 2.0 * sqrt(3.0) * doubled / sum, sum > 0.0));
    } else if (shading.color_by == COLOR_CASE) {
        return class_color(class_of(case_at((a + b + c) / 3.0)));
    } else if (shading.color_by == COLOR_LEVEL) {
        let level = lod_data[triangle];
        let color = level_color(level & 127u);
        // Transition cells' triangles, which stitch two levels, show paler.
        return select(color, mix(color, vec3<f32>(1.0), 0.55), level >= 128u);
    }
    return shading.base_color;
}

@vertex
fn triangle_vertex(@builtin(vertex_index) v: u32) -> TriangleOut {
    let first = v - v % 3u;
    let a = mesh_position(indices[first]);
    let b = mesh_position(indices[first + 1u]);
    let c = mesh_position(indices[first + 2u]);
    let mine = indices[v];
    var out: TriangleOut;
    out.world = mesh_position(mine);
    out.clip = clip_of(out.world);
    out.normal = mesh_normal(mine);
    let n = cross(b - a, c - a);
    out.face_normal = select(out.normal, normalize(n), dot(n, n) > 0.0);
    out.barycentric = vec3<f32>(f32(v % 3u == 0u), f32(v % 3u == 1u), f32(v % 3u == 2u));
    out.albedo = triangle_color(a, b, c, v / 3u);
    out.error = 0.0;
    out.marks = 0u;
    if (shading.color_by == COLOR_RANK) {
        out.marks = lod_data[v / 3u];
    }
    if (shading.color_by == COLOR_ERROR) {
        out.error = surface_distance(out.world);
    }
    return out;
}

@fragment
fn triangle_fragment(in: TriangleOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    var n = normalize(in.normal);
    if (shading.display == DISPLAY_FLAT) {
        n = in.face_normal;
    }
    if (!front) {
        n = -n;
    }
    var albedo = in.albedo;
    if (shading.color_by == COLOR_ERROR) {
        albedo = error_color(in.error);
    }
    if (shading.color_by == COLOR_RANK) {
        // Each corner's part of the triangle (nearest it) in its vertex's colour.
        let b = in.barycentric;
        let corner = select(select(2u, 1u, b.y >= b.z), 0u, b.x >= b.y && b.x >= b.z);
        albedo = rank_color(in.marks >> (3u * corner));
    }
    var color = lit(albedo, in.world, n);
    if (shading.display == DISPLAY_WIREFRAME) {
        // Dark edges about a pixel wide whatever the triangle's size on screen, over a paler surface.
        let width = fwidth(in.barycentric);
        let inside = smoothstep(vec3<f32>(0.0), width, in.barycentric);
        let line = 1.0 - min(inside.x, min(inside.y, inside.z));
        let pale = mix(color, vec3<f32>(0.55, 0.58, 0.62), 0.45);
        color = mix(pale, vec3<f32>(0.01, 0.012, 0.02), line);
    }
    return to_output(color);
}
