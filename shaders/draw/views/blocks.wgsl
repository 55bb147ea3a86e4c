// The blocks empty-space skipping kept (grid=blocks); with level of detail, the LOD blocks the surface
// may cross, coloured by level, with a cross on each face that holds transition cells.

// The blocks empty-space skipping kept, as box outlines.
@vertex
fn block_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let first = vec3<f32>(block_coords(active_blocks[i]) * BLOCK_CELLS);
    let last = min(first + f32(BLOCK_CELLS), vec3<f32>(f32(grid.cells_per_axis)));
    let p = grid.box_min + mix(first, last, cube_edge_point(v / 2u, v & 1u)) * grid.cell_size;
    return mark(clip_of(p), vec3<f32>(0.25, 0.75, 1.0), 0.8);
}

// A LOD block: vertices 0..23 its twelve edges in its level's colour, then per face two diagonals, drawn
// only on a face with transition cells.
@vertex
fn lod_block_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let b = lod_block(i);
    let level = b.w & 0xffu;
    let first = vec3<f32>(b.xyz);
    let last = first + f32(8u << level);
    if (v < 24u) {
        let p = grid.box_min + mix(first, last, cube_edge_point(v / 2u, v & 1u)) * grid.cell_size;
        return mark(clip_of(p), level_color(level), 0.9);
    }
    let face = (v - 24u) / 4u;
    if (((b.w >> 8u) & (1u << face)) == 0u) {
        return mark(HIDDEN, vec3<f32>(0.0), 0.0);
    }
    let axis = face / 2u;
    let u = (axis + 1u) % 3u;
    let w = (axis + 2u) % 3u;
    let diagonal = ((v - 24u) / 2u) % 2u;
    let end = f32(v & 1u);
    var t = vec3<f32>(0.0);
    t[axis] = f32(face % 2u);
    t[u] = end;
    t[w] = select(end, 1.0 - end, diagonal == 1u);
    let p = grid.box_min + mix(first, last, t) * grid.cell_size;
    return mark(clip_of(p), vec3<f32>(1.0), 0.7);
}
