//! The field on the CPU as the compute passes evaluate it, for the CPU meshers: the spheres in
//! separate arrays, the exact bounds of the field over a box (`straddles` in `shaders/common.wgsl`),
//! and rows of samples summed in sphere order like the oracle.

use crate::extract::reference::MIN_DISTANCE_SQUARED;
use crate::scene::Sphere;
use crate::scene::params::view::Blend;
use glam::Vec3;

/// Cells along each edge of a block (`BLOCK_CELLS` in `shaders/common.wgsl`).
pub const BLOCK_CELLS: u32 = 4;

/// Bounds skip a box only with this relative margin (`BOUND_MARGIN` in `shaders/common.wgsl`).
const BOUND_MARGIN: f32 = 1e-4;

/// The spheres as separate arrays of coordinates, read in the innermost loops.
#[derive(Default)]
pub struct Spheres {
    x: Vec<f32>,
    y: Vec<f32>,
    z: Vec<f32>,
    /// `charge · r²`: negative for a subtractive sphere.
    r2: Vec<f32>,
}

impl Spheres {
    /// Holds `spheres` from now on.
    pub fn set(&mut self, spheres: &[Sphere]) {
        self.x.clear();
        self.y.clear();
        self.z.clear();
        self.r2.clear();
        for sphere in spheres {
            self.x.push(sphere.center.x);
            self.y.push(sphere.center.y);
            self.z.push(sphere.center.z);
            self.r2.push(sphere.weight());
        }
    }

    /// False only when the field's bounds over the box from `low` to `high` keep every point on one
    /// side of `iso` (as `classify_blocks` in `shaders/extract/blocks.wgsl` decides): no cell there can
    /// emit a triangle. A box touching the walls is never all inside, as the walls read outside.
    /// Adding and subtracting terms are bounded apart: the field is at most the adding terms' upper
    /// bound less the subtracting terms' lower bound, and at least the other way round.
    pub fn straddles(&self, low: Vec3, high: Vec3, touches_walls: bool, iso: f32, by_max: bool) -> bool {
        self.ball_straddles(0.5 * (low + high), 0.5 * (high - low).length(), touches_walls, iso, by_max)
    }

    /// [`Spheres::straddles`] over the ball of radius `h` about `centre`, which holds the box. A ball
    /// holding another bounds the field more loosely, so where it keeps every point on one side of
    /// `iso`, so does the ball it holds.
    pub fn ball_straddles(&self, centre: Vec3, h: f32, touches_walls: bool, iso: f32, by_max: bool) -> bool {
        let mut adding = Bounds::default();
        let mut subtracting = Bounds::default();
        for i in 0..self.r2.len() {
            let d = (centre - Vec3::new(self.x[i], self.y[i], self.z[i])).length();
            let r2 = self.r2[i].abs();
            let low_term = r2 / ((d + h) * (d + h));
            let gap = d - h;
            let high_term = if gap <= 0.0 { f32::INFINITY } else { r2 / (gap * gap) };
            let bounds = if self.r2[i] < 0.0 { &mut subtracting } else { &mut adding };
            bounds.add(low_term, high_term, by_max);
        }
        // The margin widens each sum on its own, so rounding in either cannot skip a crossed cell.
        let upper = adding.upper * (1.0 + BOUND_MARGIN) - subtracting.lower * (1.0 - BOUND_MARGIN);
        let lower = adding.lower * (1.0 - BOUND_MARGIN) - subtracting.upper * (1.0 + BOUND_MARGIN);
        let all_outside = upper.is_finite() && upper <= iso;
        let all_inside = !touches_walls && lower.is_finite() && lower > iso;
        !all_outside && !all_inside
    }
}

impl Spheres {
    /// True when block `[bx, by, bz]` (of `BLOCK_CELLS`³ cells) of an `n`³ grid with point coordinates
    /// `coords` may hold the surface, as [`Spheres::straddles`] decides: the block every extractor
    /// keeps.
    pub fn block_straddles(&self, coords: &[f32], block: [u32; 3], n: u32, iso: f32, by_max: bool) -> bool {
        let first = block.map(|b| b * BLOCK_CELLS);
        let last = first.map(|f| (f + BLOCK_CELLS).min(n));
        let low = Vec3::from_array(first.map(|i| coords[i as usize]));
        let high = Vec3::from_array(last.map(|i| coords[i as usize]));
        let touches_walls = first.contains(&0) || last.contains(&n);
        self.straddles(low, high, touches_walls, iso, by_max)
    }

    /// False only when no block of the `group`³ blocks from block `first` on (as many as the grid has)
    /// can straddle `iso` by [`Spheres::block_straddles`]: one bound for them all, over a ball holding
    /// each block's ball with room to spare for rounding. Most of a grid is far from every sphere, so
    /// most blocks are passed over a group at a time.
    pub fn group_straddles(
        &self,
        coords: &[f32],
        first: [u32; 3],
        group: u32,
        n: u32,
        iso: f32,
        by_max: bool,
    ) -> bool {
        let nb = n.div_ceil(BLOCK_CELLS);
        let last = first.map(|b| (b + group).min(nb));
        let corner =
            |blocks: [u32; 3]| Vec3::from_array(blocks.map(|b| coords[(b * BLOCK_CELLS).min(n) as usize]));
        let (low, high) = (corner(first), corner(last));
        let centre = 0.5 * (low + high);
        let mut reach = 0.0f32;
        for bz in first[2]..last[2] {
            for by in first[1]..last[1] {
                for bx in first[0]..last[0] {
                    let (a, b) = (corner([bx, by, bz]), corner([bx + 1, by + 1, bz + 1]));
                    reach = reach.max((0.5 * (a + b) - centre).length() + 0.5 * (b - a).length());
                }
            }
        }
        let touches_walls = first.contains(&0) || last.contains(&nb);
        self.ball_straddles(centre, reach * (1.0 + 1e-3) + 1e-5, touches_walls, iso, by_max)
    }
}

/// Bounds of one kind of term over a box: summed, or the largest with blend by max; an infinite upper
/// bound where a sphere's centre may lie in the box.
#[derive(Default)]
struct Bounds {
    lower: f32,
    upper: f32,
}

impl Bounds {
    fn add(&mut self, low: f32, high: f32, by_max: bool) {
        if by_max {
            self.lower = self.lower.max(low);
            self.upper = self.upper.max(high);
        } else {
            self.lower += low;
            self.upper += high;
        }
    }
}

/// Field values along a run of points sharing y and z: the sphere loop outside, the points inside, so
/// the inner loop has no dependence between iterations and vectorises; each point still sums its
/// spheres in order. With blend by max, the largest subtracting term is taken off after the loop, as
/// `field_at` in `shaders/common.wgsl` does.
pub fn sample_run(run: &mut [f32], xs: &[f32], py: f32, pz: f32, s: &Spheres, blend: Blend) {
    run.fill(0.0);
    let mut subtracting = false;
    for i in 0..s.r2.len() {
        let (dy, dz, r2) = (py - s.y[i], pz - s.z[i], s.r2[i]);
        let (dy2, dz2, cx) = (dy * dy, dz * dz, s.x[i]);
        match blend {
            Blend::Sum => {
                for (f, &x) in run.iter_mut().zip(xs) {
                    let dx = x - cx;
                    let d2 = dx * dx + dy2 + dz2;
                    *f += r2 / if d2 < MIN_DISTANCE_SQUARED { MIN_DISTANCE_SQUARED } else { d2 };
                }
            }
            Blend::Max if r2 < 0.0 => subtracting = true,
            Blend::Max => {
                for (f, &x) in run.iter_mut().zip(xs) {
                    let dx = x - cx;
                    let d2 = dx * dx + dy2 + dz2;
                    let term = r2 / if d2 < MIN_DISTANCE_SQUARED { MIN_DISTANCE_SQUARED } else { d2 };
                    *f = if term > *f { term } else { *f };
                }
            }
        }
    }
    if subtracting {
        for (f, &x) in run.iter_mut().zip(xs) {
            let mut dent = 0.0f32;
            for i in (0..s.r2.len()).filter(|&i| s.r2[i] < 0.0) {
                let d2 = (Vec3::new(x, py, pz) - Vec3::new(s.x[i], s.y[i], s.z[i])).length_squared();
                dent = dent.max(-s.r2[i] / d2.max(MIN_DISTANCE_SQUARED));
            }
            *f -= dent;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Scene;

    /// Where a group's bound passes its blocks over, every block's own bound would too, with adding
    /// and subtracting spheres, both blends, iso levels near and far from the spheres' values, and grids
    /// whose last group and block are cut short.
    #[test]
    fn a_group_passed_over_holds_no_block_that_straddles() {
        let mut groups_passed = 0;
        for (seed, count, n) in [(1, 16, 64u32), (2, 5, 37), (3, 40, 50), (4, 3, 22), (5, 64, 29)] {
            let mut spheres = Scene::new(seed, count).unwrap().spheres().to_vec();
            for (k, sphere) in spheres.iter_mut().enumerate() {
                if k % 3 == 1 {
                    sphere.charge = -1.0;
                }
            }
            let mut s = Spheres::default();
            s.set(&spheres);
            let cell = 2.0 * crate::scene::BOX_HALF_EXTENT / n as f32;
            let coords: Vec<f32> =
                (0..=n).map(|i| -crate::scene::BOX_HALF_EXTENT + i as f32 * cell).collect();
            let nb = n.div_ceil(BLOCK_CELLS);
            for iso in [0.05, 0.4, 1.0, 3.0] {
                for by_max in [false, true] {
                    for gz in (0..nb).step_by(2) {
                        for gy in (0..nb).step_by(2) {
                            for gx in (0..nb).step_by(2) {
                                if s.group_straddles(&coords, [gx, gy, gz], 2, n, iso, by_max) {
                                    continue;
                                }
                                groups_passed += 1;
                                for b in [
                                    [0, 0, 0],
                                    [1, 0, 0],
                                    [0, 1, 0],
                                    [1, 1, 1],
                                    [0, 1, 1],
                                    [1, 0, 1],
                                    [0, 0, 1],
                                    [1, 1, 0],
                                ] {
                                    let block = [gx + b[0], gy + b[1], gz + b[2]];
                                    if block.iter().all(|&c| c < nb) {
                                        assert!(
                                            !s.block_straddles(&coords, block, n, iso, by_max),
                                            "seed {seed}, {n} cells, iso {iso}, max {by_max}: block {block:?} straddles"
                                        );
                                    }
                                }
                            }
                        }
                    }
                }
            }
        }
        assert!(groups_passed > 1000, "only {groups_passed} groups were passed over");
    }
}
