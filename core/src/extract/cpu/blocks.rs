//! The blocks the CPU mesher keeps, as `classify_blocks` in `shaders/extract/blocks.wgsl` keeps them:
//! those whose field bounds straddle the iso level. Groups of blocks that cannot hold the surface are
//! passed over first, coarse ones then the fine ones inside the coarse ones kept, then each block of
//! the fine groups kept is bounded on its own. Balls are bounded four at a time, one to a lane.

use crate::extract::field::{BLOCK_CELLS, Ball, Spheres, block_ball, block_box, group_ball};
use std::ops::Range;

/// Blocks per side of the fine groups bounded before their blocks, and fine groups per side of the
/// coarse groups bounded before them.
const GROUP_BLOCKS: u32 = 2;

/// The kept blocks and the groups bounded on the way.
#[derive(Default)]
pub struct Blocks {
    /// Per layer of blocks: the (x, y) block coordinates of the kept blocks that the surface may cross
    /// by the tighter bounds of their boxes.
    pub layers: Vec<Vec<(u32, u32)>>,
    /// Per coarse group of `GROUP_BLOCKS`² blocks a side: whether its fine groups need bounding.
    coarse: Vec<bool>,
    /// Per fine group of `GROUP_BLOCKS`³ blocks: whether its blocks need bounding one by one.
    fine: Vec<bool>,
}

/// The field's bounds over balls, four at a time: each ball given with a key, and the keys handed
/// back in the same order with whether their balls straddle the iso level.
struct Batch<'a, T> {
    spheres: &'a Spheres,
    iso: f32,
    by_max: bool,
    pending: [(T, Ball); 4],
    count: usize,
}

impl<'a, T: Copy> Batch<'a, T> {
    fn new(spheres: &'a Spheres, iso: f32, by_max: bool, filler: (T, Ball)) -> Self {
        Self { spheres, iso, by_max, pending: [filler; 4], count: 0 }
    }

    fn push(&mut self, key: T, ball: Ball, kept: impl FnMut(T, bool)) {
        self.pending[self.count] = (key, ball);
        self.count += 1;
        if self.count == 4 {
            self.flush(kept);
        }
    }

    fn flush(&mut self, mut kept: impl FnMut(T, bool)) {
        if self.count == 0 {
            return;
        }
        let balls = [0, 1, 2, 3].map(|k| self.pending[k.min(self.count - 1)].1);
        let straddle = self.spheres.balls_straddle(balls, self.iso, self.by_max);
        for (&(key, _), straddles) in self.pending[..self.count].iter().zip(straddle) {
            kept(key, straddles);
        }
        self.count = 0;
    }
}

impl Blocks {
    /// Keeps the blocks of the layers `layers` of blocks of an `n`³ grid with point coordinates
    /// `coords` that may hold the surface f = `iso` (`by_max`: with blend by max), and lists them by
    /// layer (the other layers' lists are left empty). Returns how many it kept.
    pub fn classify(
        &mut self,
        spheres: &Spheres,
        coords: &[f32],
        (iso, by_max): (f32, bool),
        n: u32,
        layers: Range<u32>,
    ) -> u32 {
        let nb = n.div_ceil(BLOCK_CELLS);
        let ng = nb.div_ceil(GROUP_BLOCKS);
        let nc = ng.div_ceil(GROUP_BLOCKS);
        let coarse = GROUP_BLOCKS * GROUP_BLOCKS;
        let filler = Ball { centre: glam::Vec3::ZERO, h: 0.0, touches_walls: false };
        let mut batch = Batch::new(spheres, iso, by_max, (0, filler));
        self.coarse.clear();
        self.coarse.resize((nc as usize).pow(3), false);
        let mut keep = |at: usize, kept: bool| self.coarse[at] = kept;
        let within = |first: [u32; 3], size: u32| first[2] < layers.end && first[2] + size > layers.start;
        for (at, first) in cubes(nc, coarse).enumerate().filter(|&(_, first)| within(first, coarse)) {
            batch.push(at, group_ball(coords, first, coarse, n), &mut keep);
        }
        batch.flush(&mut keep);
        self.fine.clear();
        self.fine.resize((ng as usize).pow(3), false);
        let mut keep = |at: usize, kept: bool| self.fine[at] = kept;
        for (at, first) in cubes(ng, GROUP_BLOCKS).enumerate() {
            let [cx, cy, cz] = first.map(|b| b / coarse);
            if within(first, GROUP_BLOCKS) && self.coarse[(cx + nc * (cy + nc * cz)) as usize] {
                batch.push(at, group_ball(coords, first, GROUP_BLOCKS, n), &mut keep);
            }
        }
        batch.flush(&mut keep);
        self.layers.resize_with(nb as usize, Vec::new);
        self.layers.truncate(nb as usize);
        let mut batch = Batch::new(spheres, iso, by_max, ((0, 0), filler));
        let mut active = 0;
        for layer in &mut self.layers {
            layer.clear();
        }
        for bz in layers {
            let layer = &mut self.layers[bz as usize];
            let mut keep = |block: (u32, u32), kept: bool| {
                if kept {
                    layer.push(block);
                    active += 1;
                }
            };
            for by in 0..nb {
                for bx in 0..nb {
                    let [gx, gy, gz] = [bx, by, bz].map(|b| b / GROUP_BLOCKS);
                    if self.fine[(gx + ng * (gy + ng * gz)) as usize] {
                        batch.push((bx, by), block_ball(coords, [bx, by, bz], n), &mut keep);
                    }
                }
            }
            batch.flush(&mut keep);
            // Of the blocks kept, those whose box's tighter bounds keep every point on one side are
            // passed over: no cell of theirs is crossed, and their points need no field values.
            let mut tight = 0;
            for first in (0..layer.len()).step_by(4) {
                let end = (first + 4).min(layer.len());
                let block = |k: usize| {
                    let (bx, by) = layer[(first + k).min(end - 1)];
                    block_box(coords, [bx, by, bz], n)
                };
                let straddle = spheres.boxes_straddle([0, 1, 2, 3].map(block), iso, by_max);
                for k in first..end {
                    if straddle[k - first] {
                        layer[tight] = layer[k];
                        tight += 1;
                    }
                }
            }
            layer.truncate(tight);
        }
        active
    }
}

/// The first blocks of the groups of `size`³ blocks that cover `count`³ groups, x fastest.
fn cubes(count: u32, size: u32) -> impl Iterator<Item = [u32; 3]> {
    (0..count)
        .flat_map(move |z| (0..count).flat_map(move |y| (0..count).map(move |x| [x, y, z].map(|g| g * size))))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::extract::reference::{self, Grid};
    use crate::scene::params::view::Blend;
    use crate::scene::{BOX_HALF_EXTENT, Scene};

    /// Every block left out of the layers (by its groups', its ball's or its box's bounds) holds no
    /// cell the oracle's field crosses, with adding and subtracting spheres, both blends, and iso levels
    /// near and far from the spheres' values; and the box's bounds leave out some blocks the ball's
    /// keep.
    #[test]
    fn the_blocks_left_out_hold_no_crossed_cell() {
        let (mut left_out_by_boxes, mut blocks) = (0, Blocks::default());
        for (seed, count, n) in [(1, 16, 48u32), (2, 5, 37), (3, 40, 30), (5, 64, 29)] {
            let mut spheres = Scene::new(seed, count).unwrap().spheres().to_vec();
            for (k, sphere) in spheres.iter_mut().enumerate() {
                if k % 3 == 1 {
                    sphere.charge = -1.0;
                }
            }
            let mut s = Spheres::default();
            s.set(&spheres);
            let grid = Grid { cells_per_axis: n };
            let coords: Vec<f32> = (0..=n).map(|i| -BOX_HALF_EXTENT + i as f32 * grid.cell_size()).collect();
            let nb = n.div_ceil(BLOCK_CELLS);
            for iso in [0.05, 0.4, 1.0, 3.0] {
                for blend in [Blend::Sum, Blend::Max] {
                    let by_max = blend == Blend::Max;
                    let active = blocks.classify(&s, &coords, (iso, by_max), n, 0..nb);
                    let kept: usize = blocks.layers.iter().map(Vec::len).sum();
                    left_out_by_boxes += active as usize - kept;
                    let values = reference::sample_blended_field(&spheres, grid, blend);
                    for bz in 0..nb {
                        for (by, bx) in (0..nb).flat_map(|by| (0..nb).map(move |bx| (by, bx))) {
                            if blocks.layers[bz as usize].contains(&(bx, by)) {
                                continue;
                            }
                            let first = [bx, by, bz].map(|b| b * BLOCK_CELLS);
                            let last = first.map(|f| (f + BLOCK_CELLS).min(n));
                            let mut sides = [false; 2];
                            for z in first[2]..=last[2] {
                                for y in first[1]..=last[1] {
                                    for x in first[0]..=last[0] {
                                        let f = values[grid.point_index(glam::UVec3::new(x, y, z))];
                                        sides[(f > iso) as usize] = true;
                                    }
                                }
                            }
                            assert!(
                                !(sides[0] && sides[1]),
                                "seed {seed}, {n} cells, iso {iso}, {blend:?}: block {:?} is crossed",
                                [bx, by, bz]
                            );
                        }
                    }
                }
            }
        }
        assert!(left_out_by_boxes > 100, "the boxes left out only {left_out_by_boxes} blocks");
    }
}
