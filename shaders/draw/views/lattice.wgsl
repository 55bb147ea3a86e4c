// The sampling grid (grid=lattice).

// The sampling lattice: instance i draws the n + 1 lines along axis i / (n + 1) whose third
// coordinate is i % (n + 1); one instanced draw of 3 (n + 1) instances of 2 (n + 1) vertices. Only the
// slab between two grid planes across one axis is drawn (the whole grid at low resolutions), so that
// fine grids stay readable: lines across the slab are cut to it, lines outside it are dropped.
@vertex
fn lattice_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let n = grid.cells_per_axis;
    let axis = i / (n + 1u);
    let slab = shading.lattice_slab;
    var id = vec3<u32>(0u);
    id[axis] = (v & 1u) * n;
    id[(axis + 1u) % 3u] = v / 2u;
    id[(axis + 2u) % 3u] = i % (n + 1u);
    if (axis == slab.x) {
        id[axis] = select(slab.y, slab.z, (v & 1u) == 1u);
    } else if (id[slab.x] < slab.y || id[slab.x] > slab.z) {
        return mark(HIDDEN, vec3<f32>(0.0), 0.0);
    }
    let p = grid.box_min + vec3<f32>(id) * grid.cell_size;
    // Fades from the front of the box to its back.
    let depth = dot(p - shading.camera_position, shading.camera_forward);
    let centre = dot(-shading.camera_position, shading.camera_forward);
    let fade = clamp(0.6 - 0.5 * (depth - centre) / (1.8 * shading.box_half_extent), 0.15, 1.0);
    return mark(clip_of(p), vec3<f32>(0.75, 0.8, 0.9), shading.lattice_alpha * fade);
}
