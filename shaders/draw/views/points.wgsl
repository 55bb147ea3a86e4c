// The shared vertices (display=points) and their normals (display=normals), and with dual contouring
// the crossings of the grid's edges with the field's normals (the Hermite data its vertices solve for).

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

// With dual contouring, a segment along the field's normal at each crossing: vertex records from
// the first after the mesh's, two vertices each.
@vertex
fn crossing_vertex(@builtin(vertex_index) v: u32) -> MarkOut {
    let i = v / 2u;
    let p = mesh_position(i) + f32(v % 2u) * 0.6 * grid.cell_size * mesh_normal(i);
    return mark(clip_of(p), vec3<f32>(1.0, 0.8, 0.15), 1.0);
}
