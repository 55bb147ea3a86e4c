//! The CPU oracle: the same field, tables and interpolation as the GPU passes, in plain Rust, for tests
//! and tools. It favours being obviously right over being fast.

use crate::extract::decider::{MAX_DECIDED_TRIANGLES, decided_triangles, face_choices};
use crate::extract::interior::interior_code;
use crate::extract::kernel::Terms;
use crate::extract::mesh::Mesh;
use crate::extract::tables::{CORNER_OFFSETS, EDGE_CORNERS, EDGE_TABLE};
use crate::scene::params::view::{CaseTable, Interpolation, March, Split};
use crate::scene::{BOX_HALF_EXTENT, Sphere};
use glam::{UVec3, Vec3};

pub use crate::extract::kernel::MIN_DISTANCE_SQUARED;

/// The sampling grid over the box: `cells_per_axis` cells, `cells_per_axis + 1` points, along each axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Grid {
    pub cells_per_axis: u32,
}

impl Grid {
    /// Width of one cell in world units.
    pub fn cell_size(&self) -> f32 {
        2.0 * BOX_HALF_EXTENT / self.cells_per_axis as f32
    }

    /// Grid points along each axis.
    pub fn points_per_axis(&self) -> u32 {
        self.cells_per_axis + 1
    }

    /// World position of grid point `id`, computed as the GPU does.
    pub fn point(&self, id: UVec3) -> Vec3 {
        Vec3::splat(-BOX_HALF_EXTENT) + id.as_vec3() * self.cell_size()
    }

    /// Index of grid point `id` in the field buffer (x fastest).
    pub fn point_index(&self, id: UVec3) -> usize {
        let n = self.points_per_axis() as usize;
        id.x as usize + n * (id.y as usize + n * id.z as usize)
    }

    /// Points on the box's faces read as outside, which closes the surface where it meets a wall.
    pub fn is_boundary(&self, id: UVec3) -> bool {
        id.min_element() == 0 || id.max_element() == self.cells_per_axis
    }
}

/// The least share of its edge that keeps a vertex off the edge's ends: t is clamped to
/// [EDGE_MARGIN, 1 − EDGE_MARGIN]. Where a sample equals the iso level (it reads as outside), every
/// crossed edge from it would otherwise put its vertex on that one grid point, and welded by position
/// (as an STL reader or a slicer welds) the mesh would have flattened triangles and edges in four.
/// Kept off the ends, each crossed edge's vertex is a point of its own: a cell's width times the margin
/// is still several units in the last place of a coordinate at 2048 cells (the GPU uses the same
/// constant, `EDGE_MARGIN` in `shaders/common.wgsl`).
pub const EDGE_MARGIN: f32 = 1.0 / 1024.0;

/// How the surface is built: where vertices land on edges, how the spheres' fields combine, and how
/// marching cubes joins ambiguous faces.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Construction {
    pub interpolation: Interpolation,
    /// The field: the spheres' kernel and how their terms combine.
    pub terms: Terms,
    pub case_table: CaseTable,
    /// The step-through of the march: only the cells it has reached give triangles (`March`).
    pub march: Option<[u32; 3]>,
    /// How marching tetrahedra cuts each cell.
    pub split: Split,
}

impl Construction {
    /// The triangles of a cell of case `case` with corner values `values` (corner order), as edge
    /// triples wound clockwise seen from outside: the classic table's; with `CaseTable::Decider` the
    /// asymptotic decider's where the cell has an ambiguous face; with `CaseTable::Mc33` those and a
    /// tunnel where the cell's interior joins two of its loops. Returns how many of `out` it filled.
    pub fn cell_triangles(
        &self,
        case: usize,
        values: [f32; 8],
        iso: f32,
        out: &mut [[usize; 3]; MAX_DECIDED_TRIANGLES],
    ) -> usize {
        let decided = self.case_table != CaseTable::Classic;
        let joined = if decided { face_choices(case, values, iso) } else { 0 };
        let code = if self.case_table == CaseTable::Mc33 { interior_code(values, iso) } else { 0 };
        let (joined, code) = self.drawn_choices(joined, code);
        let mut n = 0;
        for t in decided_triangles(case, joined, code) {
            out[n] = t;
            n += 1;
        }
        n
    }
}

impl Construction {
    /// Of a cell's face choices (`joined`) and interior code, those its case table draws with: none for
    /// the classic table, the faces' for the decider, both for MC33.
    pub fn drawn_choices(&self, joined: u8, code: u32) -> (u8, u32) {
        match self.case_table {
            CaseTable::Classic => (0, 0),
            CaseTable::Decider => (joined, 0),
            CaseTable::Mc33 => (joined, code),
        }
    }

    /// Where on an edge from value `fa` to value `fb` the vertex for level `iso` lands, never nearer an
    /// end than `EDGE_MARGIN`.
    pub fn edge_parameter(&self, iso: f32, fa: f32, fb: f32) -> f32 {
        match self.interpolation {
            Interpolation::Linear => ((iso - fa) / (fb - fa)).clamp(EDGE_MARGIN, 1.0 - EDGE_MARGIN),
            Interpolation::Midpoint => 0.5,
        }
    }
}

/// f(p) = Σ rᵢ² / |p − cᵢ|², summed in sphere order in `f32` like the GPU.
pub fn field_at(spheres: &[Sphere], p: Vec3) -> f32 {
    blended_field_at(spheres, p, Terms::default())
}

/// f(p) with the spheres' terms shaped by `terms`' kernel and summed (subtractive ones with their
/// sign) or, with the blend by max, the largest adding term less the largest subtracting one.
#[inline(never)]
pub fn blended_field_at(spheres: &[Sphere], p: Vec3, terms: Terms) -> f32 {
    let (mut f, mut dent) = (0.0f32, 0.0f32);
    for s in spheres {
        let d = p - s.center;
        let size = terms.size(s.radius * s.radius, d.dot(d));
        match (terms.by_max(), s.is_subtractive()) {
            (false, false) => f += size,
            (false, true) => f -= size,
            (true, true) => dent = dent.max(size),
            (true, false) => f = f.max(size),
        }
    }
    f - dent
}

/// −∇f / 2 = Σ chargeᵢ slopeᵢ (p − cᵢ) (for the inverse square, Σ chargeᵢ rᵢ² (p − cᵢ) / |p − cᵢ|⁴):
/// it points out of the surface (the field falls outwards). With the blend by max, the largest adding
/// term's less the largest subtracting term's.
#[inline(never)]
pub fn outward_gradient(spheres: &[Sphere], p: Vec3, terms: Terms) -> Vec3 {
    let (mut g, mut dent) = (Vec3::ZERO, Vec3::ZERO);
    let (mut largest, mut deepest) = (-1.0f32, -1.0f32);
    for s in spheres {
        let d = p - s.center;
        let (r2, d2) = (s.radius * s.radius, d.dot(d));
        let slope = terms.slope(r2, d2);
        let term = d * if s.is_subtractive() { -slope } else { slope };
        if !terms.by_max() {
            g += term;
            continue;
        }
        let value = terms.size(r2, d2);
        if s.is_subtractive() {
            if value > deepest {
                deepest = value;
                dent = term;
            }
        } else if value > largest {
            largest = value;
            g = term;
        }
    }
    g + dent
}

/// Newton steps that project a point onto the surface (`NEWTON_STEPS` in `shaders/common.wgsl`).
pub const NEWTON_STEPS: u32 = 8;

/// The distance from `p` to the exact surface f = iso, in cells of `grid`, as `surface_distance` in
/// `shaders/common.wgsl` measures it: Newton steps along the gradient, p ← p − (f(p) − iso) ∇f / |∇f|²,
/// each at most a cell long; or to the box face the solid meets, where the face is its surface.
pub fn surface_distance(spheres: &[Sphere], iso: f32, terms: Terms, p: Vec3, grid: Grid) -> f32 {
    let cell = grid.cell_size();
    let mut q = p;
    for _ in 0..NEWTON_STEPS {
        let g = outward_gradient(spheres, q, terms);
        let g2 = g.dot(g);
        if g2 <= 0.0 {
            break;
        }
        let mut step = (blended_field_at(spheres, q, terms) - iso) / (2.0 * g2) * g;
        let len = step.length();
        if len > cell {
            step *= cell / len;
        }
        q += step;
    }
    let mut d = (q - p).length();
    let a = p.abs();
    let axis = if a.z > a.x.max(a.y) {
        2
    } else if a.y > a.x {
        1
    } else {
        0
    };
    let mut wall = p;
    wall[axis] = BOX_HALF_EXTENT.copysign(p[axis]);
    if p[axis] == 0.0 {
        wall[axis] = -BOX_HALF_EXTENT;
    }
    if blended_field_at(spheres, wall, terms) >= iso {
        d = d.min(BOX_HALF_EXTENT - a[axis]);
    }
    d / cell
}

/// Where the edge from `pa` (value `fa`) to `pb` (value `fb`) crosses `iso`, and the outward normal
/// there: analytic, or across the wall when an end lies on the box's faces (`a_on_wall`, `b_on_wall`;
/// the cap there is flat), or along the edge where the gradient vanishes. Every extractor on the CPU
/// places its vertices with this (`edge_vertex` in `shaders/common.wgsl` on the GPU).
#[allow(clippy::too_many_arguments)]
pub fn surface_vertex(
    spheres: &[Sphere],
    iso: f32,
    construction: Construction,
    (pa, fa, a_on_wall): (Vec3, f32, bool),
    (pb, fb, b_on_wall): (Vec3, f32, bool),
) -> (Vec3, Vec3) {
    let (p, fallback) = edge_point(construction, iso, (pa, fa), (pb, fb));
    let normal = if a_on_wall {
        (pa - pb).normalize()
    } else if b_on_wall {
        (pb - pa).normalize()
    } else {
        let g = outward_gradient(spheres, p, construction.terms);
        g.try_normalize().unwrap_or(fallback.normalize())
    };
    (p, normal)
}

/// Where the edge from `pa` (value `fa`) to `pb` (value `fb`) crosses `iso`, and the direction along
/// the edge from inside to outside (the normal where the gradient vanishes), unnormalised.
pub fn edge_point(
    construction: Construction,
    iso: f32,
    (pa, fa): (Vec3, f32),
    (pb, fb): (Vec3, f32),
) -> (Vec3, Vec3) {
    let t = construction.edge_parameter(iso, fa, fb);
    let p = pa + (pb - pa) * t;
    (p, if fa > iso { pb - pa } else { pa - pb })
}

/// Field values at every grid point, boundary points forced to 0 (outside).
pub fn sample_field(spheres: &[Sphere], grid: Grid) -> Vec<f32> {
    sample_blended_field(spheres, grid, Terms::default())
}

/// Field values at every grid point with `terms`, boundary points forced to 0 (outside).
pub fn sample_blended_field(spheres: &[Sphere], grid: Grid, terms: Terms) -> Vec<f32> {
    let n = grid.points_per_axis();
    let mut values = vec![0.0; (n as usize).pow(3)];
    for z in 0..n {
        for y in 0..n {
            for x in 0..n {
                let id = UVec3::new(x, y, z);
                if !grid.is_boundary(id) {
                    values[grid.point_index(id)] = blended_field_at(spheres, grid.point(id), terms);
                }
            }
        }
    }
    values
}

/// Extracts the surface f = iso as a triangle soup, cell by cell in x-fastest order, each cell's
/// triangles in table order with counter-clockwise winding seen from outside. Each vertex carries the
/// id of the grid edge it lies on (`Mesh::edge_ids`).
pub fn extract(spheres: &[Sphere], iso: f32, grid: Grid) -> Mesh {
    extract_with(spheres, iso, grid, Construction::default())
}

/// `extract` with the vertex placement, blend, table and march of `construction`.
pub fn extract_with(spheres: &[Sphere], iso: f32, grid: Grid, construction: Construction) -> Mesh {
    let values = sample_blended_field(spheres, grid, construction.terms);
    let mut mesh = Mesh::default();
    for (cell, f) in cells_and_values(&values, grid) {
        let corner = |c: usize| cell + UVec3::from_array(CORNER_OFFSETS[c]);
        let case = (0..8).fold(0usize, |m, c| m | (((f[c] > iso) as usize) << c));
        if EDGE_TABLE[case] == 0 || !March::reached(construction.march, cell.to_array()) {
            continue;
        }
        let vertex = |e: usize| {
            let [a, b] = EDGE_CORNERS[e];
            let (ia, ib) = (corner(a), corner(b));
            let (p, normal) = surface_vertex(
                spheres,
                iso,
                construction,
                (grid.point(ia), f[a], grid.is_boundary(ia)),
                (grid.point(ib), f[b], grid.is_boundary(ib)),
            );
            let axis = (0..3).find(|&i| ia[i] != ib[i]).unwrap() as u64;
            (p, normal, grid.point_index(ia) as u64 * 3 + axis)
        };
        let mut triangles = [[0; 3]; MAX_DECIDED_TRIANGLES];
        let count = construction.cell_triangles(case, f, iso, &mut triangles);
        for tri in &triangles[..count] {
            for e in [tri[0], tri[2], tri[1]] {
                let (p, normal, edge) = vertex(e);
                mesh.positions.push(p);
                mesh.normals.push(normal);
                mesh.edge_ids.push(edge);
            }
        }
    }
    mesh
}

/// Every cell of `grid` (its lowest corner), x fastest, with its corners' values in corner order, read
/// from `values`, the field at every grid point: the walk each oracle takes.
pub fn cells_and_values(values: &[f32], grid: Grid) -> impl Iterator<Item = (UVec3, [f32; 8])> + '_ {
    let n = grid.cells_per_axis;
    let cells = (0..n).flat_map(move |z| (0..n).flat_map(move |y| (0..n).map(move |x| UVec3::new(x, y, z))));
    cells.map(move |cell| {
        let value = |c: usize| values[grid.point_index(cell + UVec3::from_array(CORNER_OFFSETS[c]))];
        (cell, std::array::from_fn(value))
    })
}

/// Where the ray from `origin` along unit `direction` first enters the solid {f > iso} ∩ box, by brute
/// force: steps of a thousandth of the box, then bisection. `None` where it misses. The exact view's
/// ray caster (`shaders/draw/views/exact.wgsl`) must agree with it.
pub fn exact_hit(spheres: &[Sphere], iso: f32, terms: Terms, origin: Vec3, direction: Vec3) -> Option<f32> {
    let h = BOX_HALF_EXTENT;
    let inv = direction.recip();
    let (a, b) = ((Vec3::splat(-h) - origin) * inv, (Vec3::splat(h) - origin) * inv);
    let (enter, leave) = (a.min(b).max_element().max(0.0), a.max(b).min_element());
    if enter >= leave {
        return None;
    }
    let inside = |t: f32| blended_field_at(spheres, origin + t * direction, terms) > iso;
    if inside(enter) {
        return Some(enter);
    }
    let step = 2.0 * h / 1000.0;
    let mut t = enter;
    while t < leave {
        let next = (t + step).min(leave);
        if inside(next) {
            let (mut lo, mut hi) = (t, next);
            for _ in 0..30 {
                let mid = 0.5 * (lo + hi);
                if inside(mid) { hi = mid } else { lo = mid }
            }
            return Some(hi);
        }
        t = next;
    }
    None
}
