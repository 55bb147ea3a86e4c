// Shared by the compute passes: the grid, the spheres, the field, and the blocks of cells that
// empty-space skipping works on. Mirrors `GridUniform` and `Counters` (with `CounterBlock`'s next three
// words) in src/extract/uniforms.rs and the oracle in src/extract/reference.rs.

struct Grid {
    box_min: vec3<f32>,
    cell_size: f32,
    iso: f32,
    cells_per_axis: u32,
    sphere_count: u32,
    // Capacities of the buffers; the passes never write past them.
    max_blocks: u32,
    max_vertices: u32,
    max_indices: u32,
    max_cells: u32,
    // Bit 0: vertices at edge midpoints (else interpolated); bit 1: blend by max (else sum); bit 2:
    // ambiguous faces joined by the asymptotic decider (else the classic table); bit 3: and the cell's
    // interior resolved too (MC33); bits 4 and 5 (KERNEL_SHIFT): the kernel; bit 6 (FLAG_FIVE in
    // extract/cells.wgsl): marching tetrahedra cuts cells into five tetrahedra; bit 7 (FLAG_QEF in
    // extract/dual.wgsl): the dual pass places vertices by dual contouring (else surface nets).
    flags: u32,
    // The step-through of the march: only the cells up to this one (x fastest, then y, then z) give
    // triangles; all of them when it is u32's largest value on each axis.
    march: vec3<u32>,
    // Blinn's kernel's B.
    blobbiness: f32,
}

// True when the march has reached `cell` (`March::reached` on the CPU).
fn marched(cell: vec3<u32>) -> bool {
    let m = grid.march;
    return cell.z < m.z || (cell.z == m.z && (cell.y < m.y || (cell.y == m.y && cell.x <= m.x)));
}

const FLAG_MIDPOINT: u32 = 1u;
const FLAG_MAX: u32 = 2u;
const FLAG_DECIDER: u32 = 4u;
const FLAG_MC33: u32 = 8u;
// The kernel (`Kernel` in scene/src/params/view.rs): 0 inverse-square, 1 Blinn's, 2 Wyvill's.
const KERNEL_SHIFT: u32 = 4u;

// A cell's word in cell_cases: its case in bits 0..7; from bit 8 (CHOSEN_SHIFT), with the decider, the
// choices its triangles follow on its ambiguous faces, one bit per ambiguous face in face order; from
// bit 16 (DECIDED_SHIFT), in every mode, the decider's choice on each face (bit 16 + face, set where an
// ambiguous face's inside corners are joined), for the ambiguous view; and from bit 22
// (INTERIOR_SHIFT), with MC33, the interior's join (core/src/extract/interior.rs, 0 to 4).
const CASE_BITS: u32 = 0xffu;
const CHOSEN_SHIFT: u32 = 8u;
const DECIDED_SHIFT: u32 = 16u;
const INTERIOR_SHIFT: u32 = 22u;
// Interior codes per choice of faces in the table of variants (INTERIOR_CODES).
const INTERIOR_CODES: u32 = 5u;

fn blend_max() -> bool {
    return (grid.flags & FLAG_MAX) != 0u;
}

// The least share of its edge that keeps a vertex off the edge's ends, so that a sample equal to iso
// never puts the vertices of several edges on one point (EDGE_MARGIN in core/src/extract/reference.rs).
const EDGE_MARGIN: f32 = 0.0009765625;

// Where on an edge from value fa to value fb the vertex lands.
fn edge_parameter(fa: f32, fb: f32) -> f32 {
    if ((grid.flags & FLAG_MIDPOINT) != 0u) {
        return 0.5;
    }
    return clamp((grid.iso - fa) / (fb - fa), EDGE_MARGIN, 1.0 - EDGE_MARGIN);
}

// Counts the passes append with. A count above its capacity means the buffer overflowed.
struct Counters {
    active_blocks: atomic<u32>,
    vertices: atomic<u32>,
    indices: atomic<u32>,
    active_cells: atomic<u32>,
    // Level of detail's two words (LodCounters in extract/lod.wgsl).
    _lod: vec2<u32>,
    // Dual contouring's crossings, written after the mesh's vertices (extract/dual.wgsl).
    crossings: atomic<u32>,
}

// The same counters, read-only, for passes that only need the totals.
struct Totals {
    active_blocks: u32,
    vertices: u32,
    indices: u32,
    active_cells: u32,
}

@group(0) @binding(0) var<uniform> grid: Grid;
// xyz: centre, w: radius; a uniform array (MAX_SPHERES is prepended from src/scene/params/), which software
// adapters read much faster than storage.
@group(0) @binding(1) var<uniform> spheres: array<vec4<f32>, MAX_SPHERES>;

// Squared distances are clamped to this so a grid point at a centre reads a huge but finite value.
const MIN_DISTANCE_SQUARED: f32 = 1e-20;
// Cells along each edge of a block: a block is one workgroup of 4 × 4 × 4 invocations.
const BLOCK_CELLS: u32 = 4u;
// Grid points along each edge of a block (its cells' corners).
const BLOCK_POINTS: u32 = 5u;
// Per-block passes run a 2D grid of workgroups this wide (WebGPU allows 65535 per dimension).
const DISPATCH_ROW: u32 = 32768u;
const INVALID: u32 = 0xffffffffu;

fn grid_point(id: vec3<u32>) -> vec3<f32> {
    return grid.box_min + vec3<f32>(id) * grid.cell_size;
}

// Points on the box's faces read as outside, which closes the surface where it meets a wall.
fn is_boundary(id: vec3<u32>) -> bool {
    return any(id == vec3<u32>(0u)) || any(id >= vec3<u32>(grid.cells_per_axis));
}

fn blocks_per_axis() -> u32 {
    return (grid.cells_per_axis + BLOCK_CELLS - 1u) / BLOCK_CELLS;
}

fn block_coords(block: u32) -> vec3<u32> {
    let n = blocks_per_axis();
    return vec3<u32>(block % n, (block / n) % n, block / (n * n));
}

fn block_index(coords: vec3<u32>) -> u32 {
    let n = blocks_per_axis();
    return coords.x + n * (coords.y + n * coords.z);
}

// The arguments of an indirect dispatch.
struct DispatchIndirect {
    x: u32,
    y: u32,
    z: u32,
}

// Workgroups for `count`, in rows of at most DISPATCH_ROW (`slot_of` reads them back).
fn rows(count: u32) -> DispatchIndirect {
    return DispatchIndirect(min(count, DISPATCH_ROW), (count + DISPATCH_ROW - 1u) / DISPATCH_ROW, 1u);
}

// The active block a workgroup of a per-block pass works on.
fn slot_of(workgroup: vec3<u32>) -> u32 {
    return workgroup.x + workgroup.y * DISPATCH_ROW;
}

// Corner c of a cell sits at (c bit 0 xor c bit 1, c bit 1, c bit 2): 0 (0,0,0), 1 (1,0,0), 2 (1,1,0),
// 3 (0,1,0), then the same at z = 1 (src/extract/tables.rs, CORNER_OFFSETS).
fn corner_offset(c: u32) -> vec3<u32> {
    return vec3<u32>(((c >> 1u) ^ c) & 1u, (c >> 1u) & 1u, (c >> 2u) & 1u);
}

// A term's size with no bound: the inverse square's near its centre.
const UNBOUNDED: f32 = 3e38;

fn kernel_index() -> u32 {
    return (grid.flags >> KERNEL_SHIFT) & 3u;
}

// A sphere's term at squared distance d2 from its centre, as `Terms::size` and `Terms::slope` in
// core/src/extract/kernel.rs: x, its size (the sign is its charge's): r²/d², exp(B (1 − d²/r²)) or
// 2/9 t² (5 + 4t) with t = max(1 − d²/4r², 0), infinite at the centre only for the inverse square;
// y, its slope −d size / d(d²), so that its share of −∇f / 2 is the slope times (p − c).
fn term(r2: f32, d2: f32) -> vec2<f32> {
    switch (kernel_index()) {
        case 1u: {
            let size = exp(grid.blobbiness * (1.0 - d2 / r2));
            return vec2<f32>(size, grid.blobbiness / r2 * size);
        }
        case 2u: {
            let t = max(1.0 - d2 / (4.0 * r2), 0.0);
            return vec2<f32>(2.0 / 9.0 * t * t * (5.0 + 4.0 * t), t * (5.0 + 6.0 * t) / (9.0 * r2));
        }
        default: {
            let d = max(d2, MIN_DISTANCE_SQUARED);
            return vec2<f32>(r2 / d, r2 / (d * d));
        }
    }
}

// The largest size of a term beyond `gap` from its centre (any point for gap ≤ 0), as
// `Terms::size_beyond`; UNBOUNDED only for the inverse square.
fn term_size_beyond(r2: f32, gap: f32) -> f32 {
    if (gap > 0.0) {
        return term(r2, gap * gap).x;
    }
    if (kernel_index() == 0u) {
        return UNBOUNDED;
    }
    return term(r2, 0.0).x;
}

// f(p) = Σ chargeᵢ kernel(|p − cᵢ|²) (or, with blend by max, the largest adding term less the
// largest subtracting one: the union of separate spheres, dented)
fn field_at(p: vec3<f32>) -> f32 {
    var f = 0.0;
    var dent = 0.0;
    let largest = blend_max();
    for (var i = 0u; i < grid.sphere_count; i++) {
        let s = spheres[i];
        let d = p - s.xyz;
        let size = term(s.w * s.w, dot(d, d)).x;
        if (!largest) {
            f += select(size, -size, s.w < 0.0);
        } else if (s.w < 0.0) {
            dent = max(dent, size);
        } else {
            f = max(f, size);
        }
    }
    return f - dent;
}

// −∇f / 2 = Σ chargeᵢ slopeᵢ (p − cᵢ), pointing out of the surface (with blend by max, the largest
// adding term's less the largest subtracting term's).
fn outward_gradient(p: vec3<f32>) -> vec3<f32> {
    var g = vec3<f32>(0.0);
    var dent = vec3<f32>(0.0);
    var largest = -1.0;
    var deepest = -1.0;
    let by_max = blend_max();
    for (var i = 0u; i < grid.sphere_count; i++) {
        let s = spheres[i];
        let d = p - s.xyz;
        let t = term(s.w * s.w, dot(d, d));
        let share = d * select(t.y, -t.y, s.w < 0.0);
        if (!by_max) {
            g += share;
            continue;
        }
        if (s.w < 0.0) {
            if (t.x > deepest) {
                deepest = t.x;
                dent = share;
            }
        } else if (t.x > largest) {
            largest = t.x;
            g = share;
        }
    }
    return g + dent;
}

// Bounds are skipped on only with this relative margin, far above f32 rounding of the sums.
const BOUND_MARGIN: f32 = 1e-4;

// False only when the field's bounds over the box from `low` to `high` keep it on one side of iso: no
// cell there can emit a triangle. Over a box with centre c and half-diagonal h, a sphere's term, which
// falls with distance, lies between its size at d + h and at d − h (d = |c − cᵢ|; its size at the
// centre where d ≤ h). Adding and subtracting terms
// are bounded apart: f is at most the adding terms' upper bound less the subtracting terms' lower bound,
// and at least the adding terms' lower bound less the subtracting terms' upper bound (with blend by
// max, the largest bounds of each kind). A box touching the walls is never all inside, as the walls
// read outside. src/extract/field.rs decides the same on the CPU.
fn straddles(low: vec3<f32>, high: vec3<f32>, touches_walls: bool) -> bool {
    let centre = 0.5 * (low + high);
    let h = 0.5 * length(high - low);
    // x: adding, y: subtracting.
    var lower = vec2<f32>(0.0);
    var upper = vec2<f32>(0.0);
    var unbounded = vec2<bool>(false);
    let by_max = blend_max();
    for (var i = 0u; i < grid.sphere_count; i++) {
        let s = spheres[i];
        let d = length(centre - s.xyz);
        let r2 = s.w * s.w;
        let low_term = term(r2, (d + h) * (d + h)).x;
        let beyond = term_size_beyond(r2, d - h);
        let kind = select(0u, 1u, s.w < 0.0);
        unbounded[kind] = unbounded[kind] || beyond == UNBOUNDED;
        let high_term = select(beyond, 0.0, beyond == UNBOUNDED);
        if (by_max) {
            lower[kind] = max(lower[kind], low_term);
            upper[kind] = max(upper[kind], high_term);
        } else {
            lower[kind] += low_term;
            upper[kind] += high_term;
        }
    }
    // The margin widens each sum on its own, so rounding in either cannot skip a crossed cell.
    let all_outside = !unbounded.x && upper.x * (1.0 + BOUND_MARGIN) - lower.y * (1.0 - BOUND_MARGIN) <= grid.iso;
    let all_inside = !touches_walls && !unbounded.y
        && lower.x * (1.0 - BOUND_MARGIN) - upper.y * (1.0 + BOUND_MARGIN) > grid.iso;
    return !all_outside && !all_inside;
}

// The arguments of an indexed indirect draw.
struct DrawIndexedIndirect {
    index_count: u32,
    instance_count: u32,
    first_index: u32,
    base_vertex: i32,
    first_instance: u32,
}

// One instance of the first `indices` indices written, never more than the buffer holds.
fn indexed_draw(indices: u32) -> DrawIndexedIndirect {
    return DrawIndexedIndirect(min(indices, grid.max_indices), 1u, 0u, 0, 0u);
}

// A surface vertex: where the edge from grid point `a` to `b` (values fa, fb) crosses iso, and its
// outward normal: analytic, or across the wall where one end lies on the box's faces (the cap there is
// flat), or along the edge where the gradient vanishes (reference.rs does the same).
struct EdgeVertex {
    position: vec3<f32>,
    normal: vec3<f32>,
}

fn edge_vertex(a: vec3<u32>, b: vec3<u32>, fa: f32, fb: f32) -> EdgeVertex {
    let pa = grid_point(a);
    let pb = grid_point(b);
    let t = edge_parameter(fa, fb);
    let p = pa + (pb - pa) * t;
    var n: vec3<f32>;
    if (is_boundary(a)) {
        n = normalize(pa - pb);
    } else if (is_boundary(b)) {
        n = normalize(pb - pa);
    } else {
        let g = outward_gradient(p);
        let len2 = dot(g, g);
        if (len2 > 0.0) {
            n = g * inverseSqrt(len2);
        } else {
            n = normalize(select(pa - pb, pb - pa, fa > grid.iso));
        }
    }
    return EdgeVertex(p, n);
}

// The axis of the box's face nearest to `p` (the largest coordinate in size).
fn nearest_face_axis(p: vec3<f32>) -> u32 {
    let a = abs(p);
    var axis = 0u;
    if (a.y > a[axis]) {
        axis = 1u;
    }
    if (a.z > a[axis]) {
        axis = 2u;
    }
    return axis;
}

// Newton steps that project a point onto f = iso (src/extract/reference.rs, surface_distance, takes the
// same steps on the CPU).
const NEWTON_STEPS: u32 = 8u;

// The distance from `p` to the exact surface, in cells: Newton steps along the gradient,
// p ← p − (f(p) − iso) ∇f / |∇f|², each at most a cell long; or to the box face the solid meets, where
// the face is its surface.
fn surface_distance(p: vec3<f32>) -> f32 {
    var q = p;
    for (var k = 0u; k < NEWTON_STEPS; k++) {
        let g = outward_gradient(q);
        let g2 = dot(g, g);
        if (g2 <= 0.0) {
            break;
        }
        // ∇f = −2g.
        var step = (field_at(q) - grid.iso) / (2.0 * g2) * g;
        let len = length(step);
        if (len > grid.cell_size) {
            step *= grid.cell_size / len;
        }
        q += step;
    }
    var d = length(q - p);
    let half = -grid.box_min.x;
    let a = abs(p);
    let axis = nearest_face_axis(p);
    var wall = p;
    wall[axis] = select(-half, half, p[axis] > 0.0);
    if (field_at(wall) >= grid.iso) {
        d = min(d, half - a[axis]);
    }
    return d / grid.cell_size;
}
