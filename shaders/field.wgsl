// Field pass: one invocation per grid point writes f there (0 on the box's faces).

@group(0) @binding(2) var<storage, read_write> field: array<f32>;

@compute @workgroup_size(4, 4, 4)
fn evaluate_field(@builtin(global_invocation_id) id: vec3<u32>) {
    if (any(id > vec3<u32>(grid.cells_per_axis))) {
        return;
    }
    var value = 0.0;
    if (!is_boundary(id)) {
        value = field_at(grid_point(id));
    }
    field[point_index(id)] = value;
}
