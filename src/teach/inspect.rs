//! The cell inspector: which cell a ray from the eye meets first among those the surface crosses, and
//! for one cell everything marching cubes decides there — its corner values and signs, its case and
//! class, the triangles the case emits, and where each crossed edge's vertex lands. Computed on the CPU
//! from the spheres with the oracle's field, on a click and for the selected cell only: nothing is
//! read back from the GPU.

use crate::extract::decider::{ambiguous_faces, decided_triangles, saddle_above};
use crate::extract::interior::{interior_code, joined_corners};
use crate::extract::kernel::Terms;
use crate::extract::reference::{Construction, Grid, blended_field_at};
use crate::extract::tables::{CORNER_OFFSETS, EDGE_CORNERS, EDGE_TABLE, FACE_CORNERS};
use crate::scene::Sphere;
use crate::scene::params::view::CaseTable;
use crate::teach::case_classes::case_classes;
use crate::teach::subcases::subcase_of;
use glam::{UVec3, Vec3};

/// One crossed edge of the inspected cell.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EdgeCrossing {
    /// Edge number (0..11, core/src/extract/tables.rs).
    pub edge: u8,
    /// Where on the edge, from its first corner (`EDGE_CORNERS`) to its second.
    pub t: f32,
    /// The vertex, in world space.
    pub vertex: Vec3,
}

/// An ambiguous face of the inspected cell (its inside corners on a diagonal) and how it is joined.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FaceDecision {
    /// Face number, 2 · axis + side (`FACE_CORNERS` in core/src/extract/tables.rs).
    pub face: u8,
    /// The saddle value of the bilinear interpolant of the face's four values, (f00 f11 − f10 f01) /
    /// (f00 + f11 − f10 − f01); `None` where the denominator is 0 (no saddle: never joined).
    pub saddle: Option<f32>,
    /// The asymptotic decider's choice: the inside corners joined across the face (saddle above iso).
    pub decider_joins: bool,
    /// The choice the cell's triangles follow (the decider's, or cut apart under the classic table).
    pub joined: bool,
}

/// What marching cubes decides in one cell.
#[derive(Clone, Debug, PartialEq)]
pub struct CellReport {
    /// Grid coordinates of the cell's lowest corner.
    pub cell: UVec3,
    /// f at the eight corners, numbered as in core/src/extract/tables.rs (points on the box's faces read 0).
    pub corners: [f32; 8],
    /// Bit c set when corner c is inside (f > iso).
    pub case: u8,
    /// Its class among the 15 (src/teach/case_classes.rs).
    pub class: u8,
    /// The triangles the cell emits under the construction's case table, as edge numbers, wound as
    /// drawn.
    pub triangles: Vec<[u8; 3]>,
    pub edges: Vec<EdgeCrossing>,
    /// Its ambiguous faces, in face order.
    pub faces: Vec<FaceDecision>,
    /// The corners (bit per corner) that MC33 joins by a tunnel through the cell's inside, between
    /// two of the loops the decider's faces leave apart (`extract::interior`), whatever the table; 0
    /// for none.
    pub interior: u8,
    /// True when the triangles drawn join two of the cell's loops by a tunnel (`table=mc33`).
    pub tunnel: bool,
    /// MC33's name for the interpolant's configuration in this cell (`teach::subcases`): the decider's
    /// faces and the interior test's tunnel, what `table=mc33` draws.
    pub subcase: &'static str,
    /// The configuration the table in use draws (the classic table cuts every ambiguous face apart,
    /// the decider draws no tunnel).
    pub drawn_subcase: &'static str,
}

/// Inspects `cell` (its coordinates must be below `grid.cells_per_axis`).
pub fn inspect(
    spheres: &[Sphere],
    iso: f32,
    grid: Grid,
    construction: Construction,
    cell: UVec3,
) -> CellReport {
    let point = |c: usize| cell + UVec3::from_array(CORNER_OFFSETS[c]);
    let corners: [f32; 8] = std::array::from_fn(|c| {
        let id = point(c);
        if grid.is_boundary(id) { 0.0 } else { blended_field_at(spheres, grid.point(id), construction.terms) }
    });
    let case = (0..8).fold(0u8, |m, c| m | ((corners[c] > iso) as u8) << c);
    let decided = construction.case_table != CaseTable::Classic;
    let mut faces = Vec::new();
    let (mut joined, mut decider_joined) = (0, 0);
    for (face, c) in FACE_CORNERS.iter().enumerate() {
        if ambiguous_faces(case as usize) & (1 << face) == 0 {
            continue;
        }
        let f = [corners[c[0]], corners[c[1]], corners[c[2]], corners[c[3]]];
        let denominator = (f[0] + f[2]) - (f[1] + f[3]);
        let saddle = (denominator != 0.0).then(|| (f[0] * f[2] - f[1] * f[3]) / denominator);
        let decider_joins = saddle_above(f, iso);
        joined |= ((decided && decider_joins) as u8) << face;
        decider_joined |= (decider_joins as u8) << face;
        faces.push(FaceDecision {
            face: face as u8,
            saddle,
            decider_joins,
            joined: decided && decider_joins,
        });
    }
    // The triangles `Construction::cell_triangles` gives for these choices.
    let code = interior_code(corners, iso);
    let mc33 = construction.case_table == CaseTable::Mc33;
    let triangles: Vec<[u8; 3]> = decided_triangles(case as usize, joined, if mc33 { code } else { 0 })
        .map(|t| [t[0] as u8, t[2] as u8, t[1] as u8])
        .collect();
    // A tunnel's band has four triangles more than the two loops' fills.
    let count = |code| decided_triangles(case as usize, decider_joined, code).count();
    let has_tunnel = count(code) != count(0);
    let edges = (0..12)
        .filter(|&e| EDGE_TABLE[case as usize] >> e & 1 == 1)
        .map(|e| {
            let [a, b] = EDGE_CORNERS[e];
            let t = construction.edge_parameter(iso, corners[a], corners[b]);
            let (pa, pb) = (grid.point(point(a)), grid.point(point(b)));
            EdgeCrossing { edge: e as u8, t, vertex: pa + (pb - pa) * t }
        })
        .collect();
    let interior = if has_tunnel { joined_corners(case as usize, code) } else { 0 };
    let tunnel = has_tunnel && mc33;
    let name = |joined, tunnel| subcase_of(case, joined, tunnel).map_or("", |s| s.name);
    CellReport {
        cell,
        corners,
        case,
        class: case_classes()[case as usize],
        triangles,
        edges,
        faces,
        interior,
        tunnel,
        subcase: name(decider_joined, has_tunnel),
        drawn_subcase: name(joined, tunnel),
    }
}

/// What a ray picks.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Target {
    /// The cell whose triangles the ray meets first: the surface under the pointer.
    Surface,
    /// The first cell the ray enters among those the surface crosses: the box under the pointer in the
    /// cells view.
    CrossedCell,
}

/// The first cell after `after` (all cells when `None`) in the march's order (x fastest, then y, then
/// z) that the surface crosses: one whose corners are not all inside nor all outside. `None` when no
/// cell after it is crossed. The field is sampled as the oracle samples it, two planes of points at a
/// time (boundary points outside), so it needs room for two planes whatever the grid.
pub fn next_crossed(
    spheres: &[Sphere],
    iso: f32,
    grid: Grid,
    terms: Terms,
    after: Option<UVec3>,
) -> Option<UVec3> {
    let n = grid.cells_per_axis;
    let plane = |z: u32| -> Vec<bool> {
        let mut inside = Vec::with_capacity(((n + 1) * (n + 1)) as usize);
        for y in 0..=n {
            for x in 0..=n {
                let id = UVec3::new(x, y, z);
                inside.push(!grid.is_boundary(id) && blended_field_at(spheres, grid.point(id), terms) > iso);
            }
        }
        inside
    };
    let start = after.map_or((0, 0, 0), |c| (c.z, c.y, c.x + 1));
    let mut below = plane(start.0);
    for z in start.0..n {
        let above = plane(z + 1);
        let at = |p: &[bool], x: u32, y: u32| p[(x + (n + 1) * y) as usize];
        let first = if z == start.0 { (start.1, start.2) } else { (0, 0) };
        for y in first.0..n {
            for x in if y == first.0 { first.1 } else { 0 }..n {
                let corners = [(x, y), (x + 1, y), (x + 1, y + 1), (x, y + 1)];
                let count =
                    corners.iter().map(|&(cx, cy)| at(&below, cx, cy) as u32 + at(&above, cx, cy) as u32);
                let count: u32 = count.sum();
                if count != 0 && count != 8 {
                    return Some(UVec3::new(x, y, z));
                }
            }
        }
        below = above;
    }
    None
}

/// The sphere whose term dominates the field at `point` (where a ray met the surface): the sphere a
/// person points at, also where several have merged.
pub fn dominant_sphere(spheres: &[Sphere], point: Vec3) -> Option<usize> {
    let influence = |s: &Sphere| s.weight() / (point - s.center).length_squared().max(1e-12);
    (0..spheres.len()).max_by(|&a, &b| influence(&spheres[a]).total_cmp(&influence(&spheres[b])))
}

/// The cell the ray from `origin` towards `direction` picks, walking the grid cell by cell through the
/// cells the surface crosses, and the point picked: where the ray meets the surface, or (crossed cells)
/// the centre of the cell it enters. `None` when it meets no `target`.
pub fn pick(
    spheres: &[Sphere],
    iso: f32,
    grid: Grid,
    construction: Construction,
    origin: Vec3,
    direction: Vec3,
    target: Target,
) -> Option<(UVec3, Vec3)> {
    let n = grid.cells_per_axis as f32;
    // In grid units: the box spans [0, n]³.
    let start = (origin - grid.point(UVec3::ZERO)) / grid.cell_size();
    let dir = direction.normalize_or_zero();
    let inverse = dir.recip();
    let (t0, t1) = (-start * inverse, (Vec3::splat(n) - start) * inverse);
    let enter = t0.min(t1).max_element().max(0.0);
    let exit = t0.max(t1).min_element();
    if enter.partial_cmp(&exit) != Some(std::cmp::Ordering::Less) {
        return None;
    }
    let p = start + dir * (enter + 1e-4);
    let mut cell = p.floor().clamp(Vec3::ZERO, Vec3::splat(n - 1.0));
    let step = dir.signum();
    let next_boundary = cell + step.max(Vec3::ZERO);
    let mut t_max = (next_boundary - start) * inverse;
    let t_delta = inverse.abs();
    for _ in 0..3 * grid.cells_per_axis + 3 {
        let id = cell.as_uvec3();
        let report = inspect(spheres, iso, grid, construction, id);
        let vertex = |e: u8| report.edges.iter().find(|c| c.edge == e).map(|c| c.vertex);
        let crossed = report.case != 0 && report.case != 255;
        if crossed && target == Target::CrossedCell {
            return Some((id, grid.point(id) + Vec3::splat(0.5 * grid.cell_size())));
        }
        let nearest = report
            .triangles
            .iter()
            .filter_map(|t| {
                let [a, b, c] = t.map(|e| vertex(e).expect("a triangle's edges are crossed"));
                ray_triangle(origin, dir, [a, b, c])
            })
            .min_by(f32::total_cmp);
        if let Some(t) = nearest {
            return Some((id, origin + dir * t));
        }
        let axis = if t_max.x < t_max.y && t_max.x < t_max.z {
            0
        } else if t_max.y < t_max.z {
            1
        } else {
            2
        };
        if t_max[axis] > exit {
            return None;
        }
        cell[axis] += step[axis];
        if cell[axis] < 0.0 || cell[axis] >= n {
            return None;
        }
        t_max[axis] += t_delta[axis];
    }
    None
}

/// Möller–Trumbore: the distance along the ray (unit `direction`) to triangle `[a, b, c]`, if it
/// meets it in front of `origin`.
pub fn ray_triangle(origin: Vec3, direction: Vec3, [a, b, c]: [Vec3; 3]) -> Option<f32> {
    let (e1, e2) = (b - a, c - a);
    let p = direction.cross(e2);
    let det = e1.dot(p);
    if det.abs() < 1e-12 {
        return None;
    }
    let s = origin - a;
    let u = s.dot(p) / det;
    let q = s.cross(e1);
    let v = direction.dot(q) / det;
    let t = e2.dot(q) / det;
    (u >= 0.0 && v >= 0.0 && u + v <= 1.0 && t > 0.0).then_some(t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_next_crossed_cell_walks_exactly_the_cells_whose_case_is_crossed_in_the_marchs_order() {
        let spheres = [
            Sphere { center: Vec3::new(0.2, -0.1, 0.0), radius: 0.4, velocity: Vec3::ZERO, charge: 1.0 },
            Sphere { center: Vec3::new(-0.4, 0.3, 0.2), radius: 0.3, velocity: Vec3::ZERO, charge: 1.0 },
        ];
        let grid = Grid { cells_per_axis: 7 };
        let mut walked = Vec::new();
        let mut at = None;
        while let Some(cell) = next_crossed(&spheres, 1.0, grid, Terms::default(), at) {
            walked.push(cell);
            at = Some(cell);
        }
        let n = grid.cells_per_axis;
        let crossed: Vec<UVec3> = (0..n * n * n)
            .map(|k| UVec3::new(k % n, k / n % n, k / (n * n)))
            .filter(|&c| {
                let case = inspect(&spheres, 1.0, grid, Construction::default(), c).case;
                case != 0 && case != 255
            })
            .collect();
        assert!(crossed.len() > 20, "{}", crossed.len());
        assert_eq!(walked, crossed);
    }

    #[test]
    fn a_ray_at_a_sphere_picks_a_crossed_cell_on_its_near_side() {
        let spheres = [Sphere { center: Vec3::ZERO, radius: 0.5, velocity: Vec3::ZERO, charge: 1.0 }];
        let grid = Grid { cells_per_axis: 16 };
        let origin = Vec3::new(0.03, 0.02, 3.0);
        let (cell, point) =
            pick(&spheres, 1.0, grid, Construction::default(), origin, -Vec3::Z, Target::Surface)
                .expect("the ray meets the sphere");
        assert!((point.length() - 0.5).abs() < 0.02 && point.z > 0.4, "the near side: {point}");
        let first = pick(&spheres, 1.0, grid, Construction::default(), origin, -Vec3::Z, Target::CrossedCell);
        assert!(
            first.is_some_and(|(c, _)| c.z >= cell.z),
            "the first crossed cell is no farther than the surface"
        );
        let report = inspect(&spheres, 1.0, grid, Construction::default(), cell);
        assert!(report.case != 0 && report.case != 255);
        // The near side: the cell holds z ≈ +0.5.
        assert!((grid.point(cell).z - 0.5).abs() <= grid.cell_size(), "{cell}");
        for e in &report.edges {
            assert!((0.0..=1.0).contains(&e.t));
            assert!((e.vertex.length() - 0.5).abs() < 0.02, "vertex {} near the sphere", e.vertex);
        }
        assert_eq!(
            report.triangles.len() as u8,
            crate::extract::tables::CASE_TRIANGLES[report.case as usize]
        );
        let miss = Vec3::new(0.9, 0.9, 3.0);
        for target in [Target::Surface, Target::CrossedCell] {
            assert_eq!(pick(&spheres, 1.0, grid, Construction::default(), miss, -Vec3::Z, target), None);
        }
    }

    /// The inspector shows the triangles the mesher draws: over every cell, its triangles are the
    /// oracle mesh's, under both case tables, in a scene whose ambiguous faces the decider joins.
    #[test]
    fn the_inspected_triangles_are_the_drawn_ones_under_both_tables() {
        use crate::extract::reference::extract_with;
        use std::collections::BTreeSet;
        let grid = Grid { cells_per_axis: 16 };
        let at = |x, y| grid.point(UVec3::new(x, y, 8)) + 0.003;
        let sphere = |center| Sphere { center, radius: 0.07, velocity: Vec3::ZERO, charge: 1.0 };
        let spheres = [sphere(at(8, 8)), sphere(at(9, 9))];
        // A triangle as its edges' ids, turned to start at its least (winding kept).
        let key = |t: [u64; 3]| {
            let k = (0..3).min_by_key(|&k| t[k]).unwrap();
            [t[k], t[(k + 1) % 3], t[(k + 2) % 3]]
        };
        for case_table in [CaseTable::Classic, CaseTable::Decider] {
            let construction = Construction { case_table, ..Construction::default() };
            let mesh = extract_with(&spheres, 1.0, grid, construction);
            let drawn: BTreeSet<_> = mesh.edge_ids.chunks(3).map(|t| key([t[0], t[1], t[2]])).collect();
            let mut inspected = BTreeSet::new();
            let mut joined = 0;
            for id in (0..16u32.pow(3)).map(|i| UVec3::new(i % 16, i / 16 % 16, i / 256)) {
                let report = inspect(&spheres, 1.0, grid, construction, id);
                let edge_id = |e: u8| {
                    let [a, b] = EDGE_CORNERS[e as usize];
                    let (ia, ib) = (
                        id + UVec3::from_array(CORNER_OFFSETS[a]),
                        id + UVec3::from_array(CORNER_OFFSETS[b]),
                    );
                    let axis = (0..3).find(|&i| ia[i] != ib[i]).unwrap() as u64;
                    grid.point_index(ia) as u64 * 3 + axis
                };
                inspected.extend(report.triangles.iter().map(|t| key(t.map(edge_id))));
                for face in &report.faces {
                    assert!(face.saddle.is_some_and(|s| s > 1.0) && face.decider_joins, "{face:?}");
                    assert_eq!(face.joined, case_table == CaseTable::Decider);
                    joined += 1;
                }
            }
            assert!(joined > 0, "the scene has ambiguous faces");
            assert_eq!(inspected, drawn, "{case_table:?}");
        }
    }

    /// The cell between two spheres on its body diagonal (the lecture's): the interpolant joins them
    /// through a tunnel (4.1.2), which only MC33 draws.
    #[test]
    fn the_inspector_names_the_configuration_and_the_one_drawn() {
        let sphere =
            |c: f32| Sphere { center: Vec3::splat(c), radius: 0.14, velocity: Vec3::ZERO, charge: 1.0 };
        let spheres = [sphere(-0.106), sphere(0.116)];
        let grid = Grid { cells_per_axis: 9 };
        for (case_table, drawn) in
            [(CaseTable::Classic, "4.1.1"), (CaseTable::Decider, "4.1.1"), (CaseTable::Mc33, "4.1.2")]
        {
            let construction = Construction { case_table, ..Construction::default() };
            let report = inspect(&spheres, 1.0, grid, construction, UVec3::splat(4));
            assert_eq!(
                (report.class, report.subcase, report.drawn_subcase),
                (4, "4.1.2", drawn),
                "{case_table:?}"
            );
        }
        // Every crossed cell is named; those of one corner inside as their class.
        let mut corners = 0;
        for id in (0..9u32.pow(3)).map(|i| UVec3::new(i % 9, i / 9 % 9, i / 81)) {
            let report = inspect(&spheres, 1.0, grid, Construction::default(), id);
            assert!(!report.subcase.is_empty() && !report.drawn_subcase.is_empty(), "{id}");
            if report.class == 1 {
                assert_eq!((report.subcase, report.drawn_subcase), ("1", "1"));
                corners += 1;
            }
        }
        assert!(corners > 0);
    }
}
