// The axis gizmo.

// Three axes, x red, y green, z blue, turned with the camera (drawn into a small corner viewport).
@vertex
fn gizmo_vertex(@builtin(vertex_index) v: u32) -> MarkOut {
    let axis = v / 2u;
    var direction = vec3<f32>(0.0);
    direction[axis] = f32(v & 1u);
    let turned = (shading.view * vec4<f32>(direction, 0.0)).xyz;
    var color = vec3<f32>(0.2);
    color[axis] = 1.0;
    return mark(vec4<f32>(turned.xy * 0.8, 0.5, 1.0), color, 1.0);
}
