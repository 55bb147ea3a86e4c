// The cell the inspector picked.

fn selected_corner_value(o: vec3<u32>) -> f32 {
    let id = shading.selected_cell + o;
    if (is_boundary(id)) {
        return 0.0;
    }
    return field_at(grid_point(id));
}

// The selected cell's twelve edges: crossed ones yellow, the others grey.
@vertex
fn selected_edge_vertex(@builtin(vertex_index) v: u32) -> MarkOut {
    let e = v / 2u;
    let a = vec3<u32>(cube_edge_point(e, 0u));
    let b = vec3<u32>(cube_edge_point(e, 1u));
    let crossed = (selected_corner_value(a) > grid.iso) != (selected_corner_value(b) > grid.iso);
    let p = grid_point(shading.selected_cell + select(a, b, (v & 1u) == 1u));
    let color = select(vec3<f32>(0.6, 0.6, 0.65), vec3<f32>(1.0, 0.85, 0.1), crossed);
    return mark(clip_of(p), color, 1.0);
}

// The selected cell's corners as dots: orange inside (f > iso), blue outside.
@vertex
fn selected_corner_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) c: u32) -> MarkOut {
    let o = corner_offset(c);
    let inside = selected_corner_value(o) > grid.iso;
    let color = select(vec3<f32>(0.25, 0.55, 1.0), vec3<f32>(1.0, 0.5, 0.1), inside);
    return mark(screen_square_corner(clip_of(grid_point(shading.selected_cell + o)), v, 4.0), color, 1.0);
}
