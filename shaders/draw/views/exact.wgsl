// The exact surface f = iso, ray cast through the analytic field with no mesh (display=exact), beside
// the mesh (compare=split) or as its silhouette over the mesh (compare=overlay); `exact_probe` casts the
// same rays for given pixels and writes the hits, so tests hold them to a CPU ray caster.
//
// A ray crosses the box block by block (the 4³-cell blocks empty-space skipping uses). A block whose
// field bounds keep it off iso (`straddles`) is crossed in one step. In the others the ray steps by
// (iso − f) / L, where L bounds |∇f| over the block, so no step can jump over the surface (a step is at
// least MIN_STEP cells where L is unbounded, near a sphere's centre). The first point inside is then
// refined by bisection to far below a pixel, and lit with the analytic normal and the mesh's lights.

const COMPARE_SPLIT: u32 = 1u;
const COMPARE_OVERLAY: u32 = 2u;
const DISPLAY_EXACT: u32 = 5u;
// Steps per ray at most, over every block it crosses.
const MAX_STEPS: u32 = 384u;
// The shortest step in a block, in cells; and the bisection steps that refine a hit.
const MIN_STEP: f32 = 0.25;
const BISECTIONS: u32 = 20u;

struct Ray {
    origin: vec3<f32>,
    direction: vec3<f32>,
}

struct Hit {
    // Distance along the ray (unit direction), or -1 for a miss.
    t: f32,
    // The outward normal there: analytic, or a face's where the solid meets the box.
    normal: vec3<f32>,
}

// The ray through pixel `pixel` (from the top left) of the output.
fn pixel_ray(pixel: vec2<f32>) -> Ray {
    let ndc = vec2<f32>(2.0 * pixel.x / shading.viewport.x - 1.0, 1.0 - 2.0 * pixel.y / shading.viewport.y);
    let near = shading.inverse_view_proj * vec4<f32>(ndc, 0.0, 1.0);
    let far = shading.inverse_view_proj * vec4<f32>(ndc, 1.0, 1.0);
    let a = near.xyz / near.w;
    return Ray(a, normalize(far.xyz / far.w - a));
}

// Where the ray is inside the box [-h, h]³: (entry, exit) distances, entry > exit for a miss.
fn box_span(ray: Ray, h: f32) -> vec2<f32> {
    let inv = 1.0 / ray.direction;
    let a = (vec3<f32>(-h) - ray.origin) * inv;
    let b = (vec3<f32>(h) - ray.origin) * inv;
    let lo = min(a, b);
    let hi = max(a, b);
    return vec2<f32>(max(max(max(lo.x, lo.y), lo.z), 0.0), min(min(hi.x, hi.y), hi.z));
}

// An upper bound of a term's |∇| beyond `gap` from its centre (`Terms::steepness_beyond` in
// core/src/extract/kernel.rs): 2 r² / gap³ for the inverse square (huge where gap ≤ 0); for Blinn's, its
// value at the gap or at its steepest point, r / √(2B), whichever is farther; for Wyvill's, its
// steepest anywhere, 1.6 / r, or 0 beyond its support.
fn term_steepness_beyond(r2: f32, gap: f32) -> f32 {
    switch (kernel_index()) {
        case 1u: {
            let d = max(gap, sqrt(r2 / (2.0 * grid.blobbiness)));
            return 2.0 * term(r2, d * d).y * d;
        }
        case 2u: {
            return select(1.6 / sqrt(r2), 0.0, gap >= 2.0 * sqrt(r2));
        }
        default: {
            if (gap <= 0.0) {
                return 1e30;
            }
            return 2.0 * term(r2, gap * gap).y * gap;
        }
    }
}

// An upper bound of |∇f| over the box around `centre` with half-diagonal `h`: the sum of the terms'
// (the largest terms bound the blend by max too).
fn gradient_bound(centre: vec3<f32>, h: f32) -> f32 {
    var bound = 0.0;
    for (var i = 0u; i < grid.sphere_count; i++) {
        let s = spheres[i];
        bound += term_steepness_beyond(s.w * s.w, length(centre - s.xyz) - h);
    }
    return min(bound, 1e30);
}

fn inside_at(p: vec3<f32>) -> bool {
    return field_at(p) > grid.iso;
}

// The first point of the ray in the solid {f > iso} ∩ box.
fn cast_ray(ray: Ray) -> Hit {
    let h = -grid.box_min.x;
    let span = box_span(ray, h);
    var miss = Hit(-1.0, vec3<f32>(0.0));
    if (span.x >= span.y) {
        return miss;
    }
    let entry = ray.origin + span.x * ray.direction;
    if (inside_at(entry)) {
        // The solid meets the box's face here: the face is its surface.
        let axis = nearest_face_axis(entry);
        var n = vec3<f32>(0.0);
        n[axis] = sign(entry[axis]);
        return Hit(span.x, n);
    }
    let block = grid.cell_size * f32(BLOCK_CELLS);
    let blocks = f32(blocks_per_axis());
    var t = span.x;
    var before = t;
    var found = false;
    var steps = 0u;
    loop {
        if (t >= span.y || steps >= MAX_STEPS) {
            break;
        }
        let p = ray.origin + t * ray.direction;
        let b = clamp(floor((p + h) / block), vec3<f32>(0.0), vec3<f32>(blocks - 1.0));
        let low = -h + b * block;
        let high = min(low + block, vec3<f32>(h));
        // Where the ray leaves this block.
        let ends = select(low, high, ray.direction > vec3<f32>(0.0));
        let out = (ends - ray.origin) / ray.direction;
        let leave = min(min(min(out.x, out.y), out.z), span.y);
        steps++;
        if (!straddles(low, high, false)) {
            before = t;
            t = max(leave, t + 1e-5) + 1e-5;
            continue;
        }
        let bound = gradient_bound(0.5 * (low + high), 0.5 * length(high - low));
        loop {
            let f = field_at(ray.origin + t * ray.direction);
            if (f > grid.iso) {
                found = true;
                break;
            }
            steps++;
            if (t >= leave || steps >= MAX_STEPS) {
                break;
            }
            before = t;
            t = min(t + max((grid.iso - f) / bound, MIN_STEP * grid.cell_size), leave);
        }
        if (found) {
            break;
        }
        t = leave + 1e-5;
    }
    if (!found) {
        return miss;
    }
    // f(before) ≤ iso < f(t): halve the interval.
    var lo = before;
    var hi = t;
    for (var k = 0u; k < BISECTIONS; k++) {
        let mid = 0.5 * (lo + hi);
        if (inside_at(ray.origin + mid * ray.direction)) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    let p = ray.origin + hi * ray.direction;
    var n = outward_gradient(p);
    n = select(-ray.direction, normalize(n), dot(n, n) > 0.0);
    return Hit(hi, n);
}

struct ExactOut {
    @builtin(position) clip: vec4<f32>,
}

// A full-screen triangle.
@vertex
fn exact_vertex(@builtin(vertex_index) i: u32) -> ExactOut {
    let uv = vec2<f32>(f32((i << 1u) & 2u), f32(i & 2u));
    return ExactOut(vec4<f32>(uv * 2.0 - 1.0, 0.0, 1.0));
}

struct ExactFragment {
    @location(0) color: vec4<f32>,
    @builtin(frag_depth) depth: f32,
}

fn depth_of(p: vec3<f32>) -> f32 {
    let clip = shading.view_proj * vec4<f32>(p, 1.0);
    return clip.z / clip.w;
}

// The exact surface, shaded like the mesh; with compare=split, a divider line at its left edge.
@fragment
fn exact_fragment(in: ExactOut) -> ExactFragment {
    let ray = pixel_ray(in.clip.xy);
    let hit = cast_ray(ray);
    if (shading.compare == COMPARE_SPLIT && in.clip.x < shading.divider * shading.viewport.x + 1.5) {
        return ExactFragment(to_output(vec3<f32>(0.9, 0.92, 0.95)), 0.0);
    }
    if (hit.t < 0.0) {
        discard;
    }
    let p = ray.origin + hit.t * ray.direction;
    return ExactFragment(to_output(lit(shading.base_color, p, hit.normal)), depth_of(p));
}

// compare=overlay: the exact surface's outline, over everything: where the hit mask changes within
// the 2×2 pixel quad or towards the diagonal neighbour (which joins the quads up into a line).
@fragment
fn exact_outline_fragment(in: ExactOut) -> @location(0) vec4<f32> {
    let here = select(0.0, 1.0, cast_ray(pixel_ray(in.clip.xy)).t >= 0.0);
    let there = select(0.0, 1.0, cast_ray(pixel_ray(in.clip.xy + vec2<f32>(1.0))).t >= 0.0);
    if (fwidth(here) <= 0.0 && here == there) {
        discard;
    }
    return vec4<f32>(to_output(vec3<f32>(0.25, 0.95, 1.0)).rgb, 1.0);
}

@group(0) @binding(38) var<storage, read> probe_pixels: array<vec2<f32>>;
@group(0) @binding(39) var<storage, read_write> probe_hits: array<f32>;

// For each pixel asked for: the hit's distance along the ray from the near plane, or -1.
@compute @workgroup_size(64)
fn exact_probe(@builtin(global_invocation_id) g: vec3<u32>) {
    if (g.x >= arrayLength(&probe_pixels)) {
        return;
    }
    probe_hits[g.x] = cast_ray(pixel_ray(probe_pixels[g.x])).t;
}
