//! The field on the CPU as the compute passes evaluate it, for the CPU meshers: the spheres in
//! separate arrays, the exact bounds of the field over a box (`straddles` in `shaders/common.wgsl`),
//! and rows of samples summed in sphere order like the oracle.

use crate::extract::kernel::{MIN_DISTANCE_SQUARED, Terms};
use crate::extract::lanes::{self, F32x4, LANES};
use crate::scene::Sphere;
use crate::scene::params::view::Kernel;
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
    pub fn straddles(&self, low: Vec3, high: Vec3, touches_walls: bool, iso: f32, terms: Terms) -> bool {
        self.ball_straddles(0.5 * (low + high), 0.5 * (high - low).length(), touches_walls, iso, terms)
    }

    /// [`Spheres::straddles`] over the ball of radius `h` about `centre`, which holds the box. A ball
    /// holding another bounds the field more loosely, so where it keeps every point on one side of
    /// `iso`, so does the ball it holds.
    pub fn ball_straddles(&self, centre: Vec3, h: f32, touches_walls: bool, iso: f32, terms: Terms) -> bool {
        let mut adding = Bounds::default();
        let mut subtracting = Bounds::default();
        for i in 0..self.r2.len() {
            let d = (centre - Vec3::new(self.x[i], self.y[i], self.z[i])).length();
            let r2 = self.r2[i].abs();
            let low_term = terms.size(r2, (d + h) * (d + h));
            let high_term = terms.size_beyond(r2, d - h);
            let bounds = if self.r2[i] < 0.0 { &mut subtracting } else { &mut adding };
            bounds.add(low_term, high_term, terms.by_max());
        }
        Bounds::straddle(adding, subtracting, touches_walls, iso)
    }

    /// [`Spheres::straddles`] over the box `b` with the bounds of each term at the box's nearest and
    /// farthest points from the sphere's centre, tighter than over the ball holding the box, so a box
    /// a ball keeps may still be passed over (with the same margin).
    pub fn box_straddles(&self, b: Block, iso: f32, terms: Terms) -> bool {
        let mut adding = Bounds::default();
        let mut subtracting = Bounds::default();
        let (low, high) = (b.low.to_array(), b.high.to_array());
        for i in 0..self.r2.len() {
            let c = [self.x[i], self.y[i], self.z[i]];
            // Per axis, how far the box's nearest and farthest points lie from the centre.
            let at_least = |x: f32, floor: f32| if x < floor { floor } else { x };
            let near: [f32; 3] =
                std::array::from_fn(|a| at_least(at_least(low[a] - c[a], c[a] - high[a]), 0.0));
            let far: [f32; 3] = std::array::from_fn(|a| at_least(c[a] - low[a], high[a] - c[a]));
            let squared = |d: [f32; 3]| d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            let (near, far) = (squared(near), squared(far));
            let r2 = self.r2[i].abs();
            let high_term = terms.size(r2, near);
            let bounds = if self.r2[i] < 0.0 { &mut subtracting } else { &mut adding };
            bounds.add(terms.size(r2, far), high_term, terms.by_max());
        }
        Bounds::straddle(adding, subtracting, b.touches_walls, iso)
    }
}

/// A block's box: its lowest and highest corners, and whether it touches the walls.
#[derive(Clone, Copy)]
pub struct Block {
    pub low: Vec3,
    pub high: Vec3,
    pub touches_walls: bool,
}

/// A ball the field is bounded over (by [`Spheres::ball_straddles`]): its centre and radius, and
/// whether the box it holds touches the walls.
#[derive(Clone, Copy)]
pub struct Ball {
    pub centre: Vec3,
    pub h: f32,
    pub touches_walls: bool,
}

impl Spheres {
    /// True when block `[bx, by, bz]` (of `BLOCK_CELLS`³ cells) of an `n`³ grid with point coordinates
    /// `coords` may hold the surface, as [`Spheres::straddles`] decides: the block every extractor
    /// keeps.
    pub fn block_straddles(&self, coords: &[f32], block: [u32; 3], n: u32, iso: f32, terms: Terms) -> bool {
        let ball = block_ball(coords, block, n);
        self.ball_straddles(ball.centre, ball.h, ball.touches_walls, iso, terms)
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
        terms: Terms,
    ) -> bool {
        let ball = group_ball(coords, first, group, n);
        self.ball_straddles(ball.centre, ball.h, ball.touches_walls, iso, terms)
    }
}

/// The ball [`Spheres::block_straddles`] bounds block `[bx, by, bz]` of an `n`³ grid over, as
/// [`Spheres::straddles`] makes it of the block's box.
pub fn block_ball(coords: &[f32], block: [u32; 3], n: u32) -> Ball {
    let Block { low, high, touches_walls } = block_box(coords, block, n);
    Ball { centre: 0.5 * (low + high), h: 0.5 * (high - low).length(), touches_walls }
}

/// The box of block `[bx, by, bz]` (of `BLOCK_CELLS`³ cells) of an `n`³ grid.
pub fn block_box(coords: &[f32], block: [u32; 3], n: u32) -> Block {
    let first = block.map(|b| b * BLOCK_CELLS);
    let last = first.map(|f| (f + BLOCK_CELLS).min(n));
    let low = Vec3::from_array(first.map(|i| coords[i as usize]));
    let high = Vec3::from_array(last.map(|i| coords[i as usize]));
    Block { low, high, touches_walls: first.contains(&0) || last.contains(&n) }
}

/// The ball [`Spheres::group_straddles`] bounds the group of `group`³ blocks from block `first` on
/// over.
pub fn group_ball(coords: &[f32], first: [u32; 3], group: u32, n: u32) -> Ball {
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
                let block_reach = (0.5 * (a + b) - centre).length() + 0.5 * (b - a).length();
                // A comparison, not `f32::max`, which the browser's build calls out of line.
                if block_reach > reach {
                    reach = block_reach;
                }
            }
        }
    }
    let touches_walls = first.contains(&0) || last.contains(&nb);
    Ball { centre, h: reach * (1.0 + 1e-3) + 1e-5, touches_walls }
}

/// Bounds of one kind of term over a box: summed, or the largest with blend by max; an infinite upper
/// bound where a sphere's centre may lie in the box.
#[derive(Default)]
struct Bounds {
    lower: f32,
    upper: f32,
}

impl Bounds {
    /// False only when the bounds of the adding and of the subtracting terms keep every point on one
    /// side of `iso` (never all inside where the box touches the walls).
    fn straddle(adding: Bounds, subtracting: Bounds, touches_walls: bool, iso: f32) -> bool {
        // The margin widens each sum on its own, so rounding in either cannot skip a crossed cell.
        let upper = adding.upper * (1.0 + BOUND_MARGIN) - subtracting.lower * (1.0 - BOUND_MARGIN);
        let lower = adding.lower * (1.0 - BOUND_MARGIN) - subtracting.upper * (1.0 + BOUND_MARGIN);
        let all_outside = upper.is_finite() && upper <= iso;
        let all_inside = !touches_walls && lower.is_finite() && lower > iso;
        !all_outside && !all_inside
    }

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

/// Field values along a run of points sharing y and z, in chunks of points whose partial sums stay in
/// registers while the sphere loop runs, so the inner loop has no dependence between iterations;
/// each point still takes its spheres in order. With blend by max, the largest adding term less the
/// largest subtracting term, as `field_at` in `shaders/common.wgsl` makes it.
pub fn sample_run(run: &mut [f32], xs: &[f32], py: f32, pz: f32, s: &Spheres, terms: Terms) {
    let xs = &xs[..run.len()];
    let count = s.r2.len();
    let (sx, sy, sz, sr) = (&s.x[..count], &s.y[..count], &s.z[..count], &s.r2[..count]);
    let floor = F32x4::splat(MIN_DISTANCE_SQUARED);
    let inverse_square_sum = terms.kernel == Kernel::InverseSquare && !terms.by_max();
    for start in (0..run.len()).step_by(LANES) {
        let (x, len) = lanes::load(xs, start);
        let mut f = [F32x4::splat(0.0); 2];
        if inverse_square_sum {
            for i in 0..count {
                let (dy, dz) = (py - sy[i], pz - sz[i]);
                let (dy2, dz2) = (F32x4::splat(dy * dy), F32x4::splat(dz * dz));
                let (cx, r2) = (F32x4::splat(sx[i]), F32x4::splat(sr[i]));
                for v in 0..2 {
                    let dx = x[v] - cx;
                    f[v] = f[v] + r2 / (dx * dx + dy2 + dz2).at_least(floor);
                }
            }
        } else {
            // With blend by max, the largest adding term, and the largest subtracting one (the dent).
            let mut dent = f;
            for i in 0..count {
                let (dy, dz) = (py - sy[i], pz - sz[i]);
                let (dy2, dz2) = (F32x4::splat(dy * dy), F32x4::splat(dz * dz));
                let cx = F32x4::splat(sx[i]);
                let subtracting = sr[i] < 0.0;
                for v in 0..2 {
                    let dx = x[v] - cx;
                    let size = sizes(terms, sr[i].abs(), dx * dx + dy2 + dz2);
                    if terms.by_max() {
                        let largest = if subtracting { &mut dent } else { &mut f };
                        largest[v] = largest[v].at_least(size);
                    } else if subtracting {
                        f[v] = f[v] - size;
                    } else {
                        f[v] = f[v] + size;
                    }
                }
            }
            f = [f[0] - dent[0], f[1] - dent[1]];
        }
        lanes::store(run, start, f, len);
    }
}

/// [`Terms::size`] in each lane: the inverse square four lanes at a time, the others (Blinn's `exp`
/// has no vector form) a lane at a time by the oracle's own code.
#[inline(always)]
fn sizes(terms: Terms, r2: f32, d2: F32x4) -> F32x4 {
    match terms.kernel {
        Kernel::InverseSquare => F32x4::splat(r2) / d2.at_least(F32x4::splat(MIN_DISTANCE_SQUARED)),
        _ => F32x4::from_array(d2.to_array().map(|d2| terms.size(r2, d2))),
    }
}

impl Spheres {
    /// −∇f / 2 with blend by sum at the points `x`, `y`, `z`, in their place, as
    /// [`reference::outward_gradient`](crate::extract::reference::outward_gradient) sums it for each
    /// (the same terms in the same order), a chunk of points at a time with the sphere loop outside.
    pub fn outward_gradients(&self, [x, y, z]: [&mut [f32]; 3]) {
        let count = self.r2.len();
        let (sx, sy, sz, sr) = (&self.x[..count], &self.y[..count], &self.z[..count], &self.r2[..count]);
        let (y, z) = (&mut y[..x.len()], &mut z[..x.len()]);
        let floor = F32x4::splat(MIN_DISTANCE_SQUARED);
        for start in (0..x.len()).step_by(LANES) {
            let ((px, len), (py, _), (pz, _)) =
                (lanes::load(x, start), lanes::load(y, start), lanes::load(z, start));
            let mut g = [[F32x4::splat(0.0); 2]; 3];
            for i in 0..count {
                let (cx, cy, cz, w) =
                    (F32x4::splat(sx[i]), F32x4::splat(sy[i]), F32x4::splat(sz[i]), F32x4::splat(sr[i]));
                for v in 0..2 {
                    let (dx, dy, dz) = (px[v] - cx, py[v] - cy, pz[v] - cz);
                    let d2 = (dx * dx + dy * dy + dz * dz).at_least(floor);
                    let s = w / (d2 * d2);
                    g[0][v] = g[0][v] + dx * s;
                    g[1][v] = g[1][v] + dy * s;
                    g[2][v] = g[2][v] + dz * s;
                }
            }
            lanes::store(x, start, g[0], len);
            lanes::store(y, start, g[1], len);
            lanes::store(z, start, g[2], len);
        }
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::scene::Scene;

    /// The spheres of the scene of `seed` with `count` spheres, every third from the second one
    /// subtracting.
    pub(crate) fn mixed_spheres(seed: u64, count: u32) -> Vec<crate::scene::Sphere> {
        let mut spheres = Scene::new(seed, count).unwrap().spheres().to_vec();
        for (k, sphere) in spheres.iter_mut().enumerate() {
            if k % 3 == 1 {
                sphere.charge = -1.0;
            }
        }
        spheres
    }

    /// The first blocks of the groups of `group`³ blocks of a grid of `nb`³ blocks.
    fn groups(nb: u32, group: u32) -> impl Iterator<Item = [u32; 3]> {
        let side = move || (0..nb).step_by(group as usize);
        side().flat_map(move |z| side().flat_map(move |y| side().map(move |x| [x, y, z])))
    }

    /// Where a group's bound passes its blocks over (groups of 2³ and of 4³ blocks, as the CPU mesher
    /// bounds them), every block's own bound would too, with adding and subtracting spheres, both
    /// blends, iso levels near and far from the spheres' values, and grids whose last group and block
    /// are cut short.
    #[test]
    fn a_group_passed_over_holds_no_block_that_straddles() {
        let mut groups_passed = 0;
        for (seed, count, n) in [(1, 16, 64u32), (2, 5, 37), (3, 40, 50), (4, 3, 22), (5, 64, 29)] {
            let spheres = mixed_spheres(seed, count);
            let mut s = Spheres::default();
            s.set(&spheres);
            let cell = 2.0 * crate::scene::BOX_HALF_EXTENT / n as f32;
            let coords: Vec<f32> =
                (0..=n).map(|i| -crate::scene::BOX_HALF_EXTENT + i as f32 * cell).collect();
            let nb = n.div_ceil(BLOCK_CELLS);
            for iso in [0.05, 0.4, 1.0, 3.0] {
                for terms in Terms::every() {
                    for group in [2, 4] {
                        for first in groups(nb, group) {
                            if s.group_straddles(&coords, first, group, n, iso, terms) {
                                continue;
                            }
                            groups_passed += 1;
                            for block in groups(group, 1).map(|b| [0, 1, 2].map(|k| first[k] + b[k])) {
                                if block.iter().all(|&c| c < nb) {
                                    assert!(
                                        !s.block_straddles(&coords, block, n, iso, terms),
                                        "seed {seed}, {n} cells, iso {iso}, {terms:?}: block {block:?} of \
                                         group {first:?} ({group}) straddles"
                                    );
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
