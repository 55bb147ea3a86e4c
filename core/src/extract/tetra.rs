//! Marching tetrahedra's tables, generated here from the cell's definition like the cubes' (`tables`),
//! and its oracle.
//!
//! A cell is cut into tetrahedra ([`Split`]), each given as four of the cell's corners (numbered as in
//! [`CORNER_OFFSETS`]) in positive order: det(b − a, c − a, d − a) > 0. A tetrahedron's case is the set
//! of its corners inside (bit `i` for its `i`-th corner); one inside or one outside corner gives one
//! triangle across the three edges from that corner, two of each give a quad, cut into two triangles
//! along a fixed diagonal. There is no ambiguous case: the linear interpolant of four values has one
//! planar crossing in a tetrahedron, and the triangles are exactly that crossing's (with linear
//! interpolation, up to the quad's fold).
//!
//! Vertices lie on the cell's edges, on the diagonals of its faces the split uses, and with the six-way
//! split on its body diagonal. Each lies on a segment named by its lowest corner (the component-wise
//! minimum of its ends) and a slot: 0–2 an edge along x, y or z; 3 + a the diagonal of the face across
//! axis a; 6 the body diagonal ([`segment_slot`]). Every split uses one diagonal per face, the same from
//! both cells that share it, so a segment and its slot name one vertex, found again from every cell.

use crate::extract::mesh::Mesh;
use crate::extract::reference::{Construction, Grid, cells_and_values, sample_blended_field, surface_vertex};
use crate::extract::tables::CORNER_OFFSETS;
use crate::scene::Sphere;
use crate::scene::params::view::Split;
use glam::UVec3;

/// Slots of segments per grid point: three edges, three face diagonals, one body diagonal.
pub const SLOTS: u32 = 7;

/// A cell's tetrahedra under a split: the six-way split's, then the five-way split's in a cell whose
/// lowest corner has even coordinates' sum, then in one whose sum is odd ([`tetrahedra`]).
pub const TETRAHEDRA: [[[usize; 4]; 6]; 3] = [six_way(), five_way(0), five_way(1)];

/// How many of each of [`TETRAHEDRA`]'s rows a cell uses.
pub const TETRAHEDRA_PER_CELL: [usize; 3] = [6, 5, 5];

/// Per tetrahedron case (bit `i`: its `i`-th corner inside), up to two triangles, each as three
/// vertices, each on the edge between two of the tetrahedron's corners (`[i, j]`), wound
/// counter-clockwise seen from outside.
pub const TETRAHEDRON_TRIANGLES: [[[[usize; 2]; 3]; 2]; 16] = case_triangles();

/// How many triangles each tetrahedron case has (0, 1 or 2).
pub const TETRAHEDRON_TRIANGLE_COUNTS: [usize; 16] = case_counts();

/// The row of [`TETRAHEDRA`] the cell with lowest corner `cell` uses under `split`.
pub fn tetrahedra_row(split: Split, cell: [u32; 3]) -> usize {
    match split {
        Split::Six => 0,
        Split::Five => 1 + ((cell[0] + cell[1] + cell[2]) % 2) as usize,
    }
}

/// The tetrahedra of the cell with lowest corner `cell` under `split`.
pub fn tetrahedra(split: Split, cell: [u32; 3]) -> &'static [[usize; 4]] {
    let row = tetrahedra_row(split, cell);
    &TETRAHEDRA[row][..TETRAHEDRA_PER_CELL[row]]
}

/// The segment between cell corners `a` and `b`: its lowest corner's offset in the cell and its slot.
pub fn segment_slot(a: usize, b: usize) -> ([u32; 3], u32) {
    let (pa, pb) = (CORNER_OFFSETS[a], CORNER_OFFSETS[b]);
    let low = [pa[0].min(pb[0]), pa[1].min(pb[1]), pa[2].min(pb[2])];
    let differs = [0, 1, 2].map(|i| pa[i] != pb[i]);
    let slot = match differs.iter().filter(|&&d| d).count() {
        1 => differs.iter().position(|&d| d).unwrap() as u32,
        2 => 3 + differs.iter().position(|&d| !d).unwrap() as u32,
        _ => 6,
    };
    (low, slot)
}

const fn offset(corner: usize) -> [i32; 3] {
    let o = CORNER_OFFSETS[corner];
    [o[0] as i32, o[1] as i32, o[2] as i32]
}

/// det(b − a, c − a, d − a) of four corners.
const fn orientation(t: [usize; 4]) -> i32 {
    let a = offset(t[0]);
    let [b, c, d] = [offset(t[1]), offset(t[2]), offset(t[3])];
    let u = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let v = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    let w = [d[0] - a[0], d[1] - a[1], d[2] - a[2]];
    u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0])
        + u[2] * (v[0] * w[1] - v[1] * w[0])
}

/// `t` in positive order (its last two swapped where it was negative).
const fn positive(t: [usize; 4]) -> [usize; 4] {
    if orientation(t) < 0 { [t[0], t[1], t[3], t[2]] } else { t }
}

/// The corner at offset `o`.
const fn corner_at(o: [u32; 3]) -> usize {
    let mut c = 0;
    while c < 8 {
        let p = CORNER_OFFSETS[c];
        if p[0] == o[0] && p[1] == o[1] && p[2] == o[2] {
            return c;
        }
        c += 1;
    }
    panic!("no such corner")
}

/// Kuhn's split: for each order of the three axes, the path from the lowest corner along them to the
/// highest.
const fn six_way() -> [[usize; 4]; 6] {
    const ORDERS: [[usize; 3]; 6] = [[0, 1, 2], [0, 2, 1], [1, 0, 2], [1, 2, 0], [2, 0, 1], [2, 1, 0]];
    let mut out = [[0; 4]; 6];
    let mut k = 0;
    while k < 6 {
        let [a, b, _] = ORDERS[k];
        let mut first = [0u32; 3];
        first[a] = 1;
        let mut second = first;
        second[b] = 1;
        out[k] = positive([corner_at([0, 0, 0]), corner_at(first), corner_at(second), corner_at([1, 1, 1])]);
        k += 1;
    }
    out
}

/// The five-way split of a cell whose lowest corner's coordinates sum to `parity` (mod 2): the
/// tetrahedron of the corners whose grid coordinates sum to an even number, then each other corner
/// with its three neighbours along the edges.
const fn five_way(parity: u32) -> [[usize; 4]; 6] {
    let mut out = [[0; 4]; 6];
    let mut even = [0usize; 4];
    let (mut e, mut k, mut c) = (0, 1, 0);
    while c < 8 {
        let o = CORNER_OFFSETS[c];
        if (o[0] + o[1] + o[2] + parity).is_multiple_of(2) {
            even[e] = c;
            e += 1;
        } else {
            let mut t = [c, 0, 0, 0];
            let mut axis = 0;
            while axis < 3 {
                let mut n = o;
                n[axis] = 1 - n[axis];
                t[1 + axis] = corner_at(n);
                axis += 1;
            }
            out[k] = positive(t);
            k += 1;
        }
        c += 1;
    }
    out[0] = positive(even);
    out
}

/// The even permutations of a tetrahedron's four corners (those that keep its orientation).
const EVEN: [[usize; 4]; 12] = [
    [0, 1, 2, 3],
    [0, 2, 3, 1],
    [0, 3, 1, 2],
    [1, 0, 3, 2],
    [1, 2, 0, 3],
    [1, 3, 2, 0],
    [2, 0, 1, 3],
    [2, 1, 3, 0],
    [2, 3, 0, 1],
    [3, 0, 2, 1],
    [3, 1, 0, 2],
    [3, 2, 1, 0],
];

/// Case `case`'s triangles. One corner `a` apart from the others `b, c, d` (with `a, b, c, d` in
/// positive order): the triangle on `ab, ac, ad` faces away from `a` (its normal is a positive multiple
/// of (c − b) × (d − b)), outward where `a` is inside, so it is reversed where `a` is outside. Two
/// inside `a, b` and two outside `c, d` (in positive order): the quad `ac, ad, bd, bc` faces from the
/// inside pair to the outside pair, cut along `ac`–`bd`.
const fn case_triangles() -> [[[[usize; 2]; 3]; 2]; 16] {
    let mut out = [[[[0; 2]; 3]; 2]; 16];
    let mut case = 1;
    while case < 15 {
        let inside = (case as u32).count_ones();
        let mut k = 0;
        while k < 12 {
            let [a, b, c, d] = EVEN[k];
            if inside == 2 && is_in(case, a) && is_in(case, b) {
                out[case] = [[[a, c], [a, d], [b, d]], [[a, c], [b, d], [b, c]]];
                break;
            }
            if inside == 1 && is_in(case, a) {
                out[case][0] = [[a, b], [a, c], [a, d]];
                break;
            }
            if inside == 3 && !is_in(case, a) {
                out[case][0] = [[a, b], [a, d], [a, c]];
                break;
            }
            k += 1;
        }
        case += 1;
    }
    out
}

const fn is_in(case: usize, corner: usize) -> bool {
    (case >> corner) & 1 == 1
}

const fn case_counts() -> [usize; 16] {
    let mut out = [0; 16];
    let mut case = 1;
    while case < 15 {
        out[case] = if (case as u32).count_ones() == 2 { 2 } else { 1 };
        case += 1;
    }
    out
}

/// Marching tetrahedra's oracle: the surface f = iso as a triangle soup, cell by cell in x-fastest
/// order, each cell's tetrahedra (cut by `construction.split`) in [`TETRAHEDRA`]'s order, each vertex placed by
/// `reference::surface_vertex` from the segment's lower end in grid order to its upper (so that every
/// cell places a shared vertex alike) and carrying its segment's id, `point index · SLOTS + slot`.
pub fn extract_tetrahedra(spheres: &[Sphere], iso: f32, grid: Grid, construction: Construction) -> Mesh {
    let values = sample_blended_field(spheres, grid, construction.terms);
    let mut mesh = Mesh::default();
    for (cell, f) in cells_and_values(&values, grid) {
        let corner = |c: usize| cell + UVec3::from_array(CORNER_OFFSETS[c]);
        let inside = f.map(|v| v > iso);
        if inside.iter().all(|&i| i) || !inside.iter().any(|&i| i) {
            continue;
        }
        for t in tetrahedra(construction.split, cell.to_array()) {
            let case = (0..4).fold(0, |m, i| m | (inside[t[i]] as usize) << i);
            for triangle in &TETRAHEDRON_TRIANGLES[case][..TETRAHEDRON_TRIANGLE_COUNTS[case]] {
                for &[i, j] in triangle {
                    let (a, b) = (t[i], t[j]);
                    let (a, b) = if grid.point_index(corner(a)) < grid.point_index(corner(b)) {
                        (a, b)
                    } else {
                        (b, a)
                    };
                    let end = |c: usize| (grid.point(corner(c)), f[c], grid.is_boundary(corner(c)));
                    let (p, normal) = surface_vertex(spheres, iso, construction, end(a), end(b));
                    let (low, slot) = segment_slot(a, b);
                    let id = grid.point_index(cell + UVec3::from_array(low)) as u64 * SLOTS as u64;
                    mesh.positions.push(p);
                    mesh.normals.push(normal);
                    mesh.edge_ids.push(id + slot as u64);
                }
            }
        }
    }
    mesh
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_split_fills_its_cell_with_positive_tetrahedra() {
        for (row, &count) in TETRAHEDRA_PER_CELL.iter().enumerate() {
            let tetrahedra = &TETRAHEDRA[row][..count];
            // Six times a tetrahedron's volume, summed: the cell's (6).
            let volume: i32 = tetrahedra.iter().map(|&t| orientation(t)).sum();
            assert!(tetrahedra.iter().all(|&t| orientation(t) > 0), "row {row}: {tetrahedra:?}");
            assert_eq!(volume, 6, "row {row}");
        }
    }

    /// Neighbouring cells cut their shared face along the same diagonal, under either split.
    #[test]
    fn neighbours_cut_their_shared_face_alike() {
        use std::collections::BTreeSet;
        for split in [Split::Six, Split::Five] {
            for cell in [[0, 0, 0], [1, 0, 0], [3, 2, 5]] {
                for axis in 0..3 {
                    let mut next = cell;
                    next[axis] += 1;
                    // The diagonals each cell uses on the face between them, as pairs of grid points.
                    let diagonals = |cell: [u32; 3], side: u32| -> BTreeSet<[[u32; 3]; 2]> {
                        let mut out = BTreeSet::new();
                        for t in tetrahedra(split, cell) {
                            for i in 0..4 {
                                for j in 0..4 {
                                    let (a, b) = (CORNER_OFFSETS[t[i]], CORNER_OFFSETS[t[j]]);
                                    if i < j
                                        && a[axis] == side
                                        && b[axis] == side
                                        && segment_slot(t[i], t[j]).1 >= 3
                                    {
                                        let at = |o: [u32; 3]| [0, 1, 2].map(|k| cell[k] + o[k]);
                                        let (pa, pb) = (at(a), at(b));
                                        out.insert([pa.min(pb), pa.max(pb)]);
                                    }
                                }
                            }
                        }
                        out
                    };
                    let (ours, theirs) = (diagonals(cell, 1), diagonals(next, 0));
                    assert_eq!(ours.len(), 1, "{split:?}: one diagonal on each face");
                    assert_eq!(ours, theirs, "{split:?}, cell {cell:?}, axis {axis}");
                }
            }
        }
    }

    /// Each case's triangles separate its inside corners from its outside ones and face outward, with
    /// the vertices at the edges' midpoints of the standard tetrahedron.
    #[test]
    fn each_case_cuts_the_inside_off_facing_out() {
        use glam::Vec3;
        let corners = [Vec3::ZERO, Vec3::X, Vec3::Y, Vec3::Z];
        for case in 0..16usize {
            let inside: Vec<usize> = (0..4).filter(|i| (case >> i) & 1 == 1).collect();
            let outside: Vec<usize> = (0..4).filter(|i| (case >> i) & 1 == 0).collect();
            let count = TETRAHEDRON_TRIANGLE_COUNTS[case];
            assert_eq!(count, [0, 1, 2, 1, 0][inside.len()], "case {case}");
            let mean = |s: &[usize]| s.iter().map(|&i| corners[i]).sum::<Vec3>() / s.len().max(1) as f32;
            for triangle in &TETRAHEDRON_TRIANGLES[case][..count] {
                let p = triangle.map(|[i, j]| {
                    assert_ne!(
                        (case >> i) & 1,
                        (case >> j) & 1,
                        "case {case}: a vertex on an uncrossed edge"
                    );
                    (corners[i] + corners[j]) / 2.0
                });
                let normal = (p[1] - p[0]).cross(p[2] - p[0]);
                assert!(normal.dot(mean(&outside) - mean(&inside)) > 0.0, "case {case} faces inward");
            }
        }
    }
}
