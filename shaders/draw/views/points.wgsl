// The shared vertices (display=points) and their normals (display=normals).

// The shared vertices as dots, lit like the surface.
@vertex
fn point_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let p = mesh_position(i);
    let n = mesh_normal(i);
    let albedo = shading.base_color;
    let color = max(lit(albedo, p, n), lit(albedo, p, -n));
    return mark(screen_square_corner(clip_of(p), v, 1.6), color, 1.0);
}

// A short segment along each vertex normal.
@vertex
fn normal_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let p = mesh_position(i) + f32(v) * 0.8 * grid.cell_size * mesh_normal(i);
    return mark(clip_of(p), vec3<f32>(0.35, 0.9, 1.0), 1.0);
}
