//! The field slice: a grid plane through the box, its samples, and its iso contour by marching squares
//! on those samples — interpolated from each edge's lower end exactly as marching cubes places its
//! vertices, so the contour meets the surface where the plane cuts it. The GPU draws it
//! (`shaders/draw/overlays.wgsl`); this is the CPU oracle and the table both use.

use crate::extract::kernel::Terms;
use crate::extract::reference::{Construction, Grid, blended_field_at};
use crate::scene::Sphere;
use crate::scene::params::view::{Saddle, Slice};
use glam::{UVec2, UVec3, Vec3};

/// Square corners: 0 (0,0), 1 (1,0), 2 (1,1), 3 (0,1). Edges: 0 bottom (0→1), 1 right (1→2),
/// 2 top (3→2), 3 left (0→3), each from its lower end.
pub const SQUARE_EDGES: [[usize; 2]; 4] = [[0, 1], [1, 2], [3, 2], [0, 3]];

/// Per case (bit k set when corner k is inside), its segments as pairs of edges. Where two inside
/// corners sit on a diagonal (cases 5 and 10), each is cut off on its own.
pub const SQUARE_SEGMENTS: [&[[usize; 2]]; 16] = [
    &[],
    &[[3, 0]],
    &[[0, 1]],
    &[[3, 1]],
    &[[1, 2]],
    &[[3, 0], [1, 2]],
    &[[0, 2]],
    &[[3, 2]],
    &[[2, 3]],
    &[[0, 2]],
    &[[0, 1], [2, 3]],
    &[[1, 2]],
    &[[1, 3]],
    &[[0, 1]],
    &[[3, 0]],
    &[],
];

/// `SQUARE_SEGMENTS` as the GPU reads it: per case, 4 bits per edge, a pair per byte, 0xf after the
/// last pair; four cases to a 16-byte element.
pub fn packed_square_segments() -> [[u32; 4]; 4] {
    let packed: [u32; 16] = std::array::from_fn(|case| {
        let mut word = 0xffff_u32;
        for (s, pair) in SQUARE_SEGMENTS[case].iter().enumerate() {
            let byte = pair[0] as u32 | (pair[1] as u32) << 4;
            word = (word & !(0xff << (8 * s))) | byte << (8 * s);
        }
        word
    });
    std::array::from_fn(|i| std::array::from_fn(|j| packed[4 * i + j]))
}

fn corner(k: usize) -> UVec2 {
    UVec2::new((((k >> 1) ^ k) & 1) as u32, ((k >> 1) & 1) as u32)
}

/// Grid point (i, j) of the slice's plane: i along the next axis after the slice's, j the one after.
pub fn plane_point(slice: Slice, grid: Grid, i: u32, j: u32) -> UVec3 {
    let mut id = [0u32; 3];
    let a = slice.axis as usize;
    id[a] = slice.plane(grid.cells_per_axis);
    id[(a + 1) % 3] = i;
    id[(a + 2) % 3] = j;
    UVec3::from_array(id)
}

/// The slice's samples, (n + 1)² values, i fastest; points on the box's faces read 0 as the GPU's.
pub fn samples(spheres: &[Sphere], grid: Grid, slice: Slice, terms: Terms) -> Vec<f32> {
    let row = grid.points_per_axis();
    let mut values = Vec::with_capacity((row * row) as usize);
    for j in 0..row {
        for i in 0..row {
            let id = plane_point(slice, grid, i, j);
            values.push(if grid.is_boundary(id) {
                0.0
            } else {
                blended_field_at(spheres, grid.point(id), terms)
            });
        }
    }
    values
}

/// Whether a saddle square's inside corners join (the contour then cuts off its outside corners),
/// from the values at its corners 0 to 3, by `rule`.
pub fn saddle_joins(rule: Saddle, f: [f32; 4], iso: f32) -> bool {
    match rule {
        Saddle::Table => false,
        Saddle::Center => (f[0] + f[1] + f[2] + f[3]) * 0.25 > iso,
        // The bilinear interpolant's value at its saddle point.
        Saddle::Decider => (f[0] * f[2] - f[1] * f[3]) / (f[0] + f[2] - f[1] - f[3]) > iso,
    }
}

/// The iso contour on the slice: segments, square by square, in the table's order, saddle squares
/// joined by `saddle`.
pub fn contour(
    spheres: &[Sphere],
    iso: f32,
    grid: Grid,
    slice: Slice,
    construction: Construction,
    saddle: Saddle,
) -> Vec<[Vec3; 2]> {
    let values = samples(spheres, grid, slice, construction.terms);
    let row = grid.points_per_axis();
    let value = |p: UVec2| values[(p.x + row * p.y) as usize];
    let mut segments = Vec::new();
    for j in 0..grid.cells_per_axis {
        for i in 0..grid.cells_per_axis {
            let square = UVec2::new(i, j);
            let case = (0..4).fold(0, |m, k| m | ((value(square + corner(k)) > iso) as usize) << k);
            let point = |e: usize| {
                let [a, b] = SQUARE_EDGES[e].map(|k| square + corner(k));
                let (pa, pb) = (
                    grid.point(plane_point(slice, grid, a.x, a.y)),
                    grid.point(plane_point(slice, grid, b.x, b.y)),
                );
                let t = construction.edge_parameter(iso, value(a), value(b));
                pa + (pb - pa) * t
            };
            let corners = [0, 1, 2, 3].map(|k| value(square + corner(k)));
            let joined = (case == 5 || case == 10) && saddle_joins(saddle, corners, iso);
            for pair in SQUARE_SEGMENTS[if joined { 15 - case } else { case }] {
                segments.push([point(pair[0]), point(pair[1])]);
            }
        }
    }
    segments
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_segment_joins_two_edges_whose_ends_differ() {
        for (case, segments) in SQUARE_SEGMENTS.iter().enumerate() {
            let inside = |k: usize| case >> k & 1 == 1;
            let crossed: Vec<usize> =
                (0..4).filter(|&e| inside(SQUARE_EDGES[e][0]) != inside(SQUARE_EDGES[e][1])).collect();
            let mut used: Vec<usize> = segments.iter().flatten().copied().collect();
            used.sort();
            assert_eq!(used, crossed, "case {case}");
        }
        let packed = packed_square_segments();
        assert_eq!(packed[0][0], 0xffff);
        assert_eq!(packed[1][1], 0x21 << 8 | 0x03);
    }

    #[test]
    fn saddle_rules_decide_by_the_corners_the_centre_or_the_interpolants_saddle() {
        // Corners 0 and 2 inside at iso 1. The centre's mean (0.8475) leaves them apart; the bilinear
        // interpolant's saddle (1.44 / 1.41 ≈ 1.021) lies above the level, joining them.
        let f = [1.2, 0.99, 1.2, 0.0];
        assert!(!saddle_joins(Saddle::Table, f, 1.0));
        assert!(!saddle_joins(Saddle::Center, f, 1.0));
        assert!(saddle_joins(Saddle::Decider, f, 1.0));
        // High inside corners: every rule but the table's joins them.
        let f = [3.0, 0.0, 3.0, 0.5];
        assert!(saddle_joins(Saddle::Center, f, 1.0) && saddle_joins(Saddle::Decider, f, 1.0));
        // Case 10 (corners 1 and 3 inside): the same rules, the other diagonal.
        let f = [0.99, 1.2, 0.0, 1.2];
        assert!(saddle_joins(Saddle::Decider, f, 1.0) && !saddle_joins(Saddle::Center, f, 1.0));
        // Joined, a saddle square takes the other diagonal's segments: they cut off the outside corners.
        assert_eq!(SQUARE_SEGMENTS[15 - 5], &[[0, 1], [2, 3]]);
    }

    #[test]
    fn a_sphere_cut_through_its_centre_gives_a_closed_ring_on_its_circle() {
        let spheres = [Sphere { center: Vec3::ZERO, radius: 0.5, velocity: Vec3::ZERO, charge: 1.0 }];
        let grid = Grid { cells_per_axis: 32 };
        let slice = Slice { axis: 2, position: 0.0 };
        let segments = contour(&spheres, 1.0, grid, slice, Construction::default(), Saddle::Table);
        assert!(segments.len() > 40);
        for s in &segments {
            for p in s {
                assert!((p.length() - 0.5).abs() < grid.cell_size() * 0.1, "{p} is on the circle");
                assert_eq!(p.z, 0.0);
            }
        }
    }
}
