// What every teaching view shares, drawn from the buffers the compute passes fill (no readback): the
// bindings, the mesh and grid lookups, colour ramps, and the marks (lines and dots) most views draw.
// The views' module is shaders/common.wgsl, shaders/draw/shade.wgsl (uniforms, lighting), this file,
// then one file per view (src/draw/views/pipelines.rs lists them).

@group(0) @binding(3) var<storage, read> active_blocks: array<u32>;
@group(0) @binding(4) var<storage, read> block_slots: array<u32>;
@group(0) @binding(7) var<storage, read> cell_cases: array<u32>;
@group(0) @binding(11) var<storage, read> vertices: array<f32>;
@group(0) @binding(12) var<storage, read> indices: array<u32>;
@group(0) @binding(8) var<storage, read> active_cells: array<u32>;
// With lod=on: each triangle's level of detail (TRANSITION, 128, added for a transition cell's), then
// from shading.lod_blocks_offset the kept blocks, four words each: origin in finest cells, then
// level | transition faces << 8.
@group(0) @binding(14) var<storage, read> lod_data: array<u32>;

fn lod_block(i: u32) -> vec4<u32> {
    let at = shading.lod_blocks_offset + 4u * i;
    return vec4<u32>(lod_data[at], lod_data[at + 1u], lod_data[at + 2u], lod_data[at + 3u]);
}
// The slice's samples, (n + 1)² values, first in-plane axis fastest (shaders/draw/overlays.wgsl).
@group(0) @binding(31) var<storage, read> slice_values: array<f32>;
// The slice's contour: two points per segment.
@group(0) @binding(32) var<storage, read> segments: array<vec4<f32>>;
// The class (0..14) of each case, four to an element (src/teach/case_classes.rs).
@group(0) @binding(33) var<uniform> case_classes: array<vec4<u32>, 64>;

fn class_of(case_index: u32) -> u32 {
    return case_classes[case_index / 4u][case_index % 4u];
}

const DISPLAY_FLAT: u32 = 1u;
const DISPLAY_WIREFRAME: u32 = 2u;
const COLOR_AREA: u32 = 1u;
const COLOR_QUALITY: u32 = 2u;
const COLOR_CASE: u32 = 3u;
const COLOR_LEVEL: u32 = 4u;
const COLOR_ERROR: u32 = 5u;
const COLOR_RANK: u32 = 6u;
// The error at the top of its key, in cells.
const ERROR_TOP: f32 = 0.5;

// Colour of an error of `cells`: the ramp over the square root of its share of ERROR_TOP, so that the
// hundredths of a cell linear placement leaves stay apart (www/lib/features/legends.js draws the same key).
fn error_color(cells: f32) -> vec3<f32> {
    return ramp(sqrt(clamp(cells / ERROR_TOP, 0.0, 1.0)));
}

// Colour of level of detail k (0 the finest): the case classes' hues, 96° apart from level to level
// so that neighbouring levels differ most (www/lib/features/legends.js draws the same key).
fn level_color(k: u32) -> vec3<f32> {
    return class_color((9u + 4u * k) % 15u);
}
// Colour of a QEF of rank 1 (a face), 2 (an edge) or 3 (a corner): the first three levels' colours;
// darker where its minimiser lay outside its cell (www/lib/features/legends.js draws the same).
fn rank_color(mark: u32) -> vec3<f32> {
    let color = level_color(max(mark & 3u, 1u) - 1u);
    return select(color, 0.3 * color, (mark & 4u) != 0u);
}

// Lines and points hidden by this vertex: outside the clip volume.
const HIDDEN: vec4<f32> = vec4<f32>(2.0, 2.0, 2.0, 1.0);

fn srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    return pow(c, vec3<f32>(2.2));
}

// A perceptual ramp from dark violet (0) through teal to yellow (1); www/lib/features/legends.js draws the same.
fn ramp(t: f32) -> vec3<f32> {
    var stops = array<vec3<f32>, 5>(
        vec3<f32>(0.267, 0.005, 0.329),
        vec3<f32>(0.231, 0.322, 0.545),
        vec3<f32>(0.129, 0.569, 0.549),
        vec3<f32>(0.369, 0.788, 0.384),
        vec3<f32>(0.992, 0.906, 0.145),
    );
    let x = clamp(t, 0.0, 1.0) * 4.0;
    let i = min(u32(x), 3u);
    return srgb_to_linear(mix(stops[i], stops[i + 1u], x - f32(i)));
}

// Colour of case class k (0..14): hues a 24° step apart (www/lib/features/legends.js draws the same).
fn class_color(k: u32) -> vec3<f32> {
    let h = f32(k) / 15.0 * 6.0;
    let x = 1.0 - abs(h % 2.0 - 1.0);
    var c: vec3<f32>;
    if (h < 1.0) { c = vec3<f32>(1.0, x, 0.0); }
    else if (h < 2.0) { c = vec3<f32>(x, 1.0, 0.0); }
    else if (h < 3.0) { c = vec3<f32>(0.0, 1.0, x); }
    else if (h < 4.0) { c = vec3<f32>(0.0, x, 1.0); }
    else if (h < 5.0) { c = vec3<f32>(x, 0.0, 1.0); }
    else { c = vec3<f32>(1.0, 0.0, x); }
    // Value 0.95, saturation 0.65.
    return srgb_to_linear(0.95 * (1.0 - 0.65 + 0.65 * c));
}

fn mesh_position(i: u32) -> vec3<f32> {
    return vec3<f32>(vertices[i * 6u], vertices[i * 6u + 1u], vertices[i * 6u + 2u]);
}

fn mesh_normal(i: u32) -> vec3<f32> {
    return vec3<f32>(vertices[i * 6u + 3u], vertices[i * 6u + 4u], vertices[i * 6u + 5u]);
}

fn cell_of_block_cell(reference: u32) -> vec3<u32> {
    let slot = reference / 64u;
    let local = reference % 64u;
    let at = vec3<u32>(local % BLOCK_CELLS, (local / BLOCK_CELLS) % BLOCK_CELLS, local / (BLOCK_CELLS * BLOCK_CELLS));
    return block_coords(active_blocks[slot]) * BLOCK_CELLS + at;
}

// The case of the cell holding world point `p` (0 when its block was skipped).
fn case_at(p: vec3<f32>) -> u32 {
    let n = grid.cells_per_axis;
    let cell = min(vec3<u32>(max((p - grid.box_min) / grid.cell_size, vec3<f32>(0.0))), vec3<u32>(n - 1u));
    let slot = block_slots[block_index(cell / BLOCK_CELLS)];
    if (slot >= grid.max_blocks) {
        return 0u;
    }
    let at = cell % BLOCK_CELLS;
    return cell_cases[slot * 64u + at.x + BLOCK_CELLS * (at.y + BLOCK_CELLS * at.z)] & CASE_BITS;
}

fn clip_of(p: vec3<f32>) -> vec4<f32> {
    return shading.view_proj * vec4<f32>(p, 1.0);
}

// A corner of a screen-aligned square of `pixels` around clip position `clip`, for corner k of 6.
fn screen_square_corner(clip: vec4<f32>, k: u32, pixels: f32) -> vec4<f32> {
    var corners = array<vec2<f32>, 6>(
        vec2<f32>(-1.0, -1.0), vec2<f32>(1.0, -1.0), vec2<f32>(1.0, 1.0),
        vec2<f32>(-1.0, -1.0), vec2<f32>(1.0, 1.0), vec2<f32>(-1.0, 1.0),
    );
    let offset = corners[k] * pixels / shading.viewport * clip.w;
    return vec4<f32>(clip.xy + offset, clip.zw);
}

// Edge e (0..11) of a unit cube, end `end`: edges 0..3 along x, 4..7 along y, 8..11 along z.
fn cube_edge_point(e: u32, end: u32) -> vec3<f32> {
    let axis = e / 4u;
    let a = f32(e & 1u);
    let b = f32((e >> 1u) & 1u);
    let t = f32(end);
    if (axis == 0u) {
        return vec3<f32>(t, a, b);
    } else if (axis == 1u) {
        return vec3<f32>(a, t, b);
    }
    return vec3<f32>(a, b, t);
}

// ---- Lines and dots ----

struct MarkOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) color: vec4<f32>,
}

fn mark(clip: vec4<f32>, color: vec3<f32>, alpha: f32) -> MarkOut {
    var out: MarkOut;
    out.clip = clip;
    out.color = vec4<f32>(color, alpha);
    return out;
}

@fragment
fn mark_fragment(in: MarkOut) -> @location(0) vec4<f32> {
    let c = to_output(in.color.rgb);
    return vec4<f32>(c.rgb, in.color.a);
}
