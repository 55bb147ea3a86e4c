// The cells the surface crosses (grid=cells).

// The crossed cells as box outlines, coloured by their case's class.
@vertex
fn cell_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let reference = active_cells[i];
    let cell = vec3<f32>(cell_of_block_cell(reference));
    let corner = 0.04 + 0.92 * cube_edge_point(v / 2u, v & 1u);
    let p = grid.box_min + (cell + corner) * grid.cell_size;
    return mark(clip_of(p), class_color(class_of(cell_cases[reference] & CASE_BITS)), 1.0);
}
