// The blocks empty-space skipping kept (grid=blocks).

// The blocks empty-space skipping kept, as box outlines.
@vertex
fn block_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let first = vec3<f32>(block_coords(active_blocks[i]) * BLOCK_CELLS);
    let last = min(first + f32(BLOCK_CELLS), vec3<f32>(f32(grid.cells_per_axis)));
    let p = grid.box_min + mix(first, last, cube_edge_point(v / 2u, v & 1u)) * grid.cell_size;
    return mark(clip_of(p), vec3<f32>(0.25, 0.75, 1.0), 0.8);
}
