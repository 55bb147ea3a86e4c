// The field on a plane and its iso contour (slice); shaders/draw/overlays.wgsl samples it.

// The slice's iso contour, drawn a little towards the eye so the surface it lies on does not hide it.
@vertex
fn contour_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    var clip = clip_of(segments[2u * i + v].xyz);
    clip.z -= 2e-4 * clip.w;
    return mark(clip, vec3<f32>(1.0, 1.0, 1.0), 1.0);
}

struct SliceOut {
    @builtin(position) clip: vec4<f32>,
    // Grid coordinates along the plane's two axes.
    @location(0) uv: vec2<f32>,
}

fn slice_point(uv: vec2<f32>) -> vec3<f32> {
    let a = shading.slice_axis;
    var id = vec3<f32>(0.0);
    id[a] = f32(shading.slice_plane);
    id[(a + 1u) % 3u] = uv.x;
    id[(a + 2u) % 3u] = uv.y;
    return grid.box_min + id * grid.cell_size;
}

@vertex
fn slice_vertex(@builtin(vertex_index) v: u32) -> SliceOut {
    var corners = array<vec2<f32>, 6>(
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 0.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(0.0, 0.0), vec2<f32>(1.0, 1.0), vec2<f32>(0.0, 1.0),
    );
    var out: SliceOut;
    out.uv = corners[v] * f32(grid.cells_per_axis);
    out.clip = clip_of(slice_point(out.uv));
    // A little behind its own contour.
    out.clip.z += 1e-4 * out.clip.w;
    return out;
}

// f on the plane, bilinear between its samples, as a log-scaled colour: iso / 16 (dark) to iso × 16
// (bright), iso at the middle.
@fragment
fn slice_fragment(in: SliceOut) -> @location(0) vec4<f32> {
    let n = grid.cells_per_axis;
    let cell = min(vec2<u32>(max(in.uv, vec2<f32>(0.0))), vec2<u32>(n - 1u));
    let f = fract(in.uv - vec2<f32>(cell));
    let row = n + 1u;
    let at = cell.x + row * cell.y;
    let value = mix(
        mix(slice_values[at], slice_values[at + 1u], f.x),
        mix(slice_values[at + row], slice_values[at + row + 1u], f.x),
        f.y,
    );
    let t = (log2(max(value, 1e-6) / grid.iso) + 4.0) / 8.0;
    return to_output(ramp(t));
}
