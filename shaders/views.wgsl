// Teaching views, drawn from the buffers the compute passes fill (no readback): the mesh as flat
// facets, wireframe, coloured triangles or points, normals, the sampling lattice, the crossed cells by
// case class, the kept blocks, the ambiguous faces, the field slice and its contour, the selected cell,
// and an axis gizmo. Compiled after shaders/common.wgsl and shaders/shade.wgsl (uniforms, lighting).

@group(0) @binding(3) var<storage, read> active_blocks: array<u32>;
@group(0) @binding(4) var<storage, read> block_slots: array<u32>;
@group(0) @binding(8) var<storage, read> cell_cases: array<u32>;
@group(0) @binding(10) var<storage, read> vertices: array<f32>;
@group(0) @binding(11) var<storage, read> indices: array<u32>;
@group(0) @binding(13) var<storage, read> active_cells: array<u32>;
// The slice's samples, (n + 1)² values, first in-plane axis fastest (shaders/overlays.wgsl).
@group(0) @binding(21) var<storage, read> slice_values: array<f32>;
// The slice's contour: two points per segment.
@group(0) @binding(22) var<storage, read> segments: array<vec4<f32>>;
// The class (0..14) of each case, four to an element (src/case_classes.rs).
@group(0) @binding(23) var<uniform> case_classes: array<vec4<u32>, 64>;

fn class_of(case_index: u32) -> u32 {
    return case_classes[case_index / 4u][case_index % 4u];
}

const DISPLAY_FLAT: u32 = 1u;
const DISPLAY_WIREFRAME: u32 = 2u;
const COLOR_AREA: u32 = 1u;
const COLOR_QUALITY: u32 = 2u;
const COLOR_CASE: u32 = 3u;
// Lines and points hidden by this vertex: outside the clip volume.
const HIDDEN: vec4<f32> = vec4<f32>(2.0, 2.0, 2.0, 1.0);

fn srgb_to_linear(c: vec3<f32>) -> vec3<f32> {
    return pow(c, vec3<f32>(2.2));
}

// A perceptual ramp from dark violet (0) through teal to yellow (1); www/lib/legends.js draws the same.
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

// Colour of case class k (0..14): hues a 24° step apart (www/lib/legends.js draws the same).
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
    return cell_cases[slot * 64u + at.x + BLOCK_CELLS * (at.y + BLOCK_CELLS * at.z)];
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

// ---- The mesh, one triangle at a time: flat facets, wireframe, coloured triangles ----

struct TriangleOut {
    @builtin(position) clip: vec4<f32>,
    @location(0) world: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) @interpolate(flat) face_normal: vec3<f32>,
    @location(3) barycentric: vec3<f32>,
    @location(4) @interpolate(flat) albedo: vec3<f32>,
}

fn triangle_color(a: vec3<f32>, b: vec3<f32>, c: vec3<f32>) -> vec3<f32> {
    let doubled = length(cross(b - a, c - a));
    let face = grid.cell_size * grid.cell_size;
    if (shading.color_by == COLOR_AREA) {
        // Area as a fraction of a cell face's, up to half a face.
        return ramp(0.5 * doubled / face / 0.5);
    } else if (shading.color_by == COLOR_QUALITY) {
        // 4√3 A / (a² + b² + c²): 1 for an equilateral triangle, 0 for a sliver.
        let sum = dot(b - a, b - a) + dot(c - b, c - b) + dot(a - c, a - c);
        return ramp(select(0.0, 2.0 * sqrt(3.0) * doubled / sum, sum > 0.0));
    } else if (shading.color_by == COLOR_CASE) {
        return class_color(class_of(case_at((a + b + c) / 3.0)));
    }
    return shading.base_color;
}

@vertex
fn triangle_vertex(@builtin(vertex_index) v: u32) -> TriangleOut {
    let first = v - v % 3u;
    let a = mesh_position(indices[first]);
    let b = mesh_position(indices[first + 1u]);
    let c = mesh_position(indices[first + 2u]);
    let mine = indices[v];
    var out: TriangleOut;
    out.world = mesh_position(mine);
    out.clip = clip_of(out.world);
    out.normal = mesh_normal(mine);
    let n = cross(b - a, c - a);
    out.face_normal = select(out.normal, normalize(n), dot(n, n) > 0.0);
    out.barycentric = vec3<f32>(f32(v % 3u == 0u), f32(v % 3u == 1u), f32(v % 3u == 2u));
    out.albedo = triangle_color(a, b, c);
    return out;
}

@fragment
fn triangle_fragment(in: TriangleOut, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    var n = normalize(in.normal);
    if (shading.display == DISPLAY_FLAT) {
        n = in.face_normal;
    }
    if (!front) {
        n = -n;
    }
    var color = lit(in.albedo, in.world, n);
    if (shading.display == DISPLAY_WIREFRAME) {
        // Dark edges about a pixel wide whatever the triangle's size on screen, over a paler surface.
        let width = fwidth(in.barycentric);
        let inside = smoothstep(vec3<f32>(0.0), width, in.barycentric);
        let line = 1.0 - min(inside.x, min(inside.y, inside.z));
        let pale = mix(color, vec3<f32>(0.55, 0.58, 0.62), 0.45);
        color = mix(pale, vec3<f32>(0.01, 0.012, 0.02), line);
    }
    return to_output(color);
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

// The shared vertices as dots, lit like the surface.
@vertex
fn point_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let p = mesh_position(i);
    let n = mesh_normal(i);
    let albedo = shading.base_color;
    let color = max(lit(albedo, p, n), lit(albedo, p, -n));
    return mark(screen_square_corner(clip_of(p), v, 1.6), color, 1.0);
}

// A short segment along each vertex normal.
@vertex
fn normal_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let p = mesh_position(i) + f32(v) * 0.8 * grid.cell_size * mesh_normal(i);
    return mark(clip_of(p), vec3<f32>(0.35, 0.9, 1.0), 1.0);
}

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

// The crossed cells as box outlines, coloured by their case's class.
@vertex
fn cell_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let reference = active_cells[i];
    let cell = vec3<f32>(cell_of_block_cell(reference));
    let corner = 0.04 + 0.92 * cube_edge_point(v / 2u, v & 1u);
    let p = grid.box_min + (cell + corner) * grid.cell_size;
    return mark(clip_of(p), class_color(class_of(cell_cases[reference])), 1.0);
}

// The blocks empty-space skipping kept, as box outlines.
@vertex
fn block_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let first = vec3<f32>(block_coords(active_blocks[i]) * BLOCK_CELLS);
    let last = min(first + f32(BLOCK_CELLS), vec3<f32>(f32(grid.cells_per_axis)));
    let p = grid.box_min + mix(first, last, cube_edge_point(v / 2u, v & 1u)) * grid.cell_size;
    return mark(clip_of(p), vec3<f32>(0.25, 0.75, 1.0), 0.8);
}

// The corner of a cell at offset o (each 0 or 1), numbered as in src/tables.rs.
fn corner_number(o: vec3<u32>) -> u32 {
    return (o.z << 2u) | (o.y << 1u) | (o.x ^ o.y);
}

// A cross over each ambiguous face of each crossed cell: a face whose two inside corners (or two
// outside corners) sit on a diagonal. 6 faces × 2 diagonals × 2 ends.
@vertex
fn ambiguous_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    let reference = active_cells[i];
    let case_index = cell_cases[reference];
    let face = v / 4u;
    let axis = face / 2u;
    // The face's corners in order around it.
    var q: array<vec3<u32>, 4>;
    for (var k = 0u; k < 4u; k++) {
        var o = vec3<u32>(0u);
        o[axis] = face & 1u;
        o[(axis + 1u) % 3u] = ((k >> 1u) ^ k) & 1u;
        o[(axis + 2u) % 3u] = (k >> 1u) & 1u;
        q[k] = o;
    }
    var inside: array<bool, 4>;
    for (var k = 0u; k < 4u; k++) {
        inside[k] = ((case_index >> corner_number(q[k])) & 1u) == 1u;
    }
    let ambiguous = inside[0] == inside[2] && inside[1] == inside[3] && inside[0] != inside[1];
    if (!ambiguous) {
        return mark(HIDDEN, vec3<f32>(0.0), 0.0);
    }
    let diagonal = (v / 2u) & 1u;
    let corner = q[diagonal + 2u * (v & 1u)];
    let cell = vec3<f32>(cell_of_block_cell(reference));
    let p = grid.box_min + (cell + vec3<f32>(corner)) * grid.cell_size;
    return mark(clip_of(p), vec3<f32>(1.0, 0.2, 0.85), 1.0);
}

// The slice's iso contour, drawn a little towards the eye so the surface it lies on does not hide it.
@vertex
fn contour_vertex(@builtin(vertex_index) v: u32, @builtin(instance_index) i: u32) -> MarkOut {
    var clip = clip_of(segments[2u * i + v].xyz);
    clip.z -= 2e-4 * clip.w;
    return mark(clip, vec3<f32>(1.0, 1.0, 1.0), 1.0);
}

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

// ---- The field slice ----

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
