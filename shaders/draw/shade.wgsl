// Shading pass: a background gradient, the box's edges, then the surface lit by up to three lights
// (point, directional, spot) with Blinn-Phong. The teaching views (shaders/draw/views/) share the
// uniforms and the lighting defined here.
// Mirrors `ShadingUniform` and `LightUniform` in src/draw/uniforms.rs.

const LIGHT_POINT: u32 = 1u;
const LIGHT_DIRECTIONAL: u32 = 2u;
const LIGHT_SPOT: u32 = 3u;

struct Light {
    position: vec3<f32>,
    kind: u32,
    direction: vec3<f32>,
    cos_outer: f32,
    color: vec3<f32>,
    cos_inner: f32,
}

struct Shading {
    view_proj: mat4x4<f32>,
    view: mat4x4<f32>,
    camera_position: vec3<f32>,
    ambient: f32,
    camera_forward: vec3<f32>,
    orthographic: u32,
    base_color: vec3<f32>,
    diffuse: f32,
    specular: f32,
    shininess: f32,
    // 1 when the target is not an sRGB format and the shader must encode.
    encode_srgb: u32,
    box_half_extent: f32,
    display: u32,
    color_by: u32,
    grid_view: u32,
    cells_per_axis: u32,
    viewport: vec2<f32>,
    cell_size: f32,
    iso: f32,
    slice_axis: u32,
    slice_plane: u32,
    selected: u32,
    lattice_alpha: f32,
    selected_cell: vec3<u32>,
    // Where the LOD blocks start in `lod_data` (shaders/draw/views/common.wgsl), in words.
    lod_blocks_offset: u32,
    // x: the axis across the lattice's slab; y, z: its first and last grid planes.
    lattice_slab: vec4<u32>,
    lights: array<Light, 3>,
    // The background's gradient, linear RGB.
    background_top: vec3<f32>,
    // 0 none, 1 split, 2 overlay (shaders/draw/views/exact.wgsl).
    compare: u32,
    background_bottom: vec3<f32>,
    // With compare=split, where the exact half starts, as a fraction of the width.
    divider: f32,
    // Clip space to world: the exact view's rays.
    inverse_view_proj: mat4x4<f32>,
    // How the slice's contour joins a saddle square: 0 the table's choice, 1 the centre value, 2 the
    // asymptotic decider (shaders/draw/overlays.wgsl).
    saddle: u32,
}

@group(0) @binding(30) var<uniform> shading: Shading;

// The direction from `world` towards the eye.
fn view_direction(world: vec3<f32>) -> vec3<f32> {
    if (shading.orthographic == 1u) {
        return -shading.camera_forward;
    }
    return normalize(shading.camera_position - world);
}

// The light slots a pipeline may light with: bit i for `shading.lights[i]` (1 point, 2 directional,
// 4 spot). The surface pipeline is built for the slots that are on, so a software rasteriser skips the
// others' arithmetic; every other pipeline keeps all three and skips a slot whose kind is off.
override LIGHT_SLOTS: u32 = 7u;

// One light's Blinn-Phong term for surface colour `albedo` at `world` with unit normal `n`, seen along `v`.
// `kind` is the light's slot's kind (slot 0 holds the point light, 1 the directional, 2 the spot), a
// constant, so the branches for the other kinds compile away rather than run masked on a software
// rasteriser.
fn light_term(light: Light, kind: u32, albedo: vec3<f32>, world: vec3<f32>, n: vec3<f32>, v: vec3<f32>) -> vec3<f32> {
    if (light.kind == 0u) {
        return vec3<f32>(0.0);
    }
    var l = -light.direction;
    var strength = 1.0;
    if (kind != LIGHT_DIRECTIONAL) {
        l = normalize(light.position - world);
    }
    if (kind == LIGHT_SPOT) {
        strength = smoothstep(light.cos_outer, light.cos_inner, dot(-l, light.direction));
    }
    let lambert = max(dot(n, l), 0.0);
    var highlight = 0.0;
    if (lambert > 0.0) {
        highlight = pow(max(dot(n, normalize(l + v)), 0.0), shading.shininess);
    }
    return strength * light.color * (albedo * shading.diffuse * lambert + vec3<f32>(shading.specular * highlight));
}

// Blinn-Phong for surface colour `albedo` at `world` with unit normal `n`, summed over the lights.
fn lit(albedo: vec3<f32>, world: vec3<f32>, n: vec3<f32>) -> vec3<f32> {
    let v = view_direction(world);
    var color = albedo * shading.ambient;
    if ((LIGHT_SLOTS & 1u) != 0u) {
        color += light_term(shading.lights[0], LIGHT_POINT, albedo, world, n, v);
    }
    if ((LIGHT_SLOTS & 2u) != 0u) {
        color += light_term(shading.lights[1], LIGHT_DIRECTIONAL, albedo, world, n, v);
    }
    if ((LIGHT_SLOTS & 4u) != 0u) {
        color += light_term(shading.lights[2], LIGHT_SPOT, albedo, world, n, v);
    }
    return color;
}

// Whether `to_output` encodes sRGB: 0 never, 1 always (the shading pipelines, built for one output
// format, say which), 2 as `shading.encode_srgb` says (the teaching views). A software rasteriser runs
// both sides of a branch on a uniform, so the constant spares it the encoding where the format does it.
override ENCODE_SRGB: u32 = 2u;

fn to_output(linear: vec3<f32>) -> vec4<f32> {
    var c = clamp(linear, vec3<f32>(0.0), vec3<f32>(1.0));
    if (ENCODE_SRGB == 1u || (ENCODE_SRGB == 2u && shading.encode_srgb == 1u)) {
        let low = c * 12.92;
        let high = 1.055 * pow(c, vec3<f32>(1.0 / 2.4)) - 0.055;
        c = select(high, low, c <= vec3<f32>(0.0031308));
    }
    return vec4<f32>(c, 1.0);
}

struct BackgroundOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) height: f32,
}

// A full-screen triangle.
@vertex
fn background_vertex(@builtin(vertex_index) i: u32) -> BackgroundOut {
    let uv = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    var out: BackgroundOut;
    out.clip = vec4<f32>(uv * 2.0 - 1.0, 1.0, 1.0);
    out.height = uv.y;
    return out;
}

@fragment
fn background_fragment(in: BackgroundOut) -> @location(0) vec4<f32> {
    let t = clamp(in.height * 0.5, 0.0, 1.0);
    return to_output(mix(shading.background_bottom, shading.background_top, t));
}

// The box's 12 edges as a line list: vertex i is end (i & 1) of edge i / 2; edge e runs along axis e / 4
// with the other two coordinates taken from the bits of e % 4.
@vertex
fn box_vertex(@builtin(vertex_index) i: u32) -> @builtin(position) vec4<f32> {
    let edge = i / 2u;
    let axis = edge / 4u;
    let bits = vec2<f32>(f32(edge & 1u), f32((edge >> 1u) & 1u)) * 2.0 - 1.0;
    let along = f32(i & 1u) * 2.0 - 1.0;
    var p: vec3<f32>;
    if (axis == 0u) {
        p = vec3<f32>(along, bits.x, bits.y);
    } else if (axis == 1u) {
        p = vec3<f32>(bits.x, along, bits.y);
    } else {
        p = vec3<f32>(bits.x, bits.y, along);
    }
    return shading.view_proj * vec4<f32>(p * shading.box_half_extent, 1.0);
}

@fragment
fn box_fragment() -> @location(0) vec4<f32> {
    return to_output(vec3<f32>(0.07, 0.08, 0.11));
}

struct SurfaceOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
}

@vertex
fn surface_vertex(@location(0) position: vec3<f32>, @location(1) normal: vec3<f32>) -> SurfaceOut {
    var out: SurfaceOut;
    out.clip = shading.view_proj * vec4<f32>(position, 1.0);
    out.world = position;
    out.normal = normal;
    return out;
}

@fragment
fn surface_fragment(in: SurfaceOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    // Triangles wind counter-clockwise seen from outside; a back face is the inside of the surface.
    var n = normalize(in.normal);
    if (!front) {
        n = -n;
    }
    return to_output(lit(shading.base_color, in.world, n));
}
