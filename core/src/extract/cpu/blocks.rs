//! The blocks the CPU mesher keeps, as `classify_blocks` in `shaders/extract/blocks.wgsl` keeps them:
//! those whose field bounds straddle the iso level. Groups of blocks that cannot hold the surface are
//! passed over first, coarse ones then the fine ones inside the coarse ones kept, then each block of
//! the fine groups kept is bounded on its own, then again over its box.

use crate::extract::field::{BLOCK_CELLS, Ball, Spheres, block_ball, block_box, group_ball};
use crate::extract::kernel::Terms;
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
    /// The groups or blocks being bounded, each with a key: a group's index, a block's x and y.
    balls: Vec<(u32, Ball)>,
}

/// Keeps of `balls` (each with a key) those over which the field's bounds straddle the iso level
/// (with the spheres' `terms`), in order.
fn keep_straddling(spheres: &Spheres, (iso, terms): (f32, Terms), balls: &mut Vec<(u32, Ball)>) {
    balls.retain(|(_, b)| spheres.ball_straddles(b.centre, b.h, b.touches_walls, iso, terms));
}

impl Blocks {
    /// Keeps the blocks of the layers `layers` of blocks of an `n`³ grid with point coordinates
    /// `coords` that may hold the surface f = `iso` (with the spheres' `terms`), and lists them by
    /// layer (the other layers' lists are left empty). Returns how many it kept.
    pub fn classify(
        &mut self,
        spheres: &Spheres,
        coords: &[f32],
        bounds: (f32, Terms),
        n: u32,
        layers: Range<u32>,
    ) -> u32 {
        let (iso, terms) = bounds;
        let nb = n.div_ceil(BLOCK_CELLS);
        let ng = nb.div_ceil(GROUP_BLOCKS);
        let nc = ng.div_ceil(GROUP_BLOCKS);
        let coarse = GROUP_BLOCKS * GROUP_BLOCKS;
        let within = |first: u32, size: u32| first < layers.end && first + size > layers.start;
        // Coarse groups, then the fine groups of the coarse ones kept (groups a side, blocks a side of a
        // group).
        for level in 0..2 {
            let (count, size) = if level == 0 { (nc, coarse) } else { (ng, GROUP_BLOCKS) };
            self.balls.clear();
            for z in 0..count {
                for y in 0..count {
                    for x in 0..count {
                        let first = [x, y, z].map(|g| g * size);
                        let [cx, cy, cz] = first.map(|b| b / coarse);
                        if within(first[2], size)
                            && (level == 0 || self.coarse[(cx + nc * (cy + nc * cz)) as usize])
                        {
                            let at = x + count * (y + count * z);
                            self.balls.push((at, group_ball(coords, first, size, n)));
                        }
                    }
                }
            }
            keep_straddling(spheres, bounds, &mut self.balls);
            let answers = if level == 0 { &mut self.coarse } else { &mut self.fine };
            answers.clear();
            answers.resize((count as usize).pow(3), false);
            for &(at, _) in &self.balls {
                answers[at as usize] = true;
            }
        }
        self.layers.resize_with(nb as usize, Vec::new);
        self.layers.truncate(nb as usize);
        let mut active = 0;
        for layer in &mut self.layers {
            layer.clear();
        }
        for bz in layers {
            self.balls.clear();
            for by in 0..nb {
                for bx in 0..nb {
                    let [gx, gy, gz] = [bx, by, bz].map(|b| b / GROUP_BLOCKS);
                    if self.fine[(gx + ng * (gy + ng * gz)) as usize] {
                        self.balls.push((bx | by << 16, block_ball(coords, [bx, by, bz], n)));
                    }
                }
            }
            keep_straddling(spheres, bounds, &mut self.balls);
            active += self.balls.len() as u32;
            let layer = &mut self.layers[bz as usize];
            layer.extend(self.balls.iter().map(|&(key, _)| (key & 0xffff, key >> 16)));
            // Of the blocks kept, those whose box's tighter bounds keep every point on one side are
            // passed over: no cell of theirs is crossed, and their points need no field values.
            layer.retain(|&(bx, by)| spheres.box_straddles(block_box(coords, [bx, by, bz], n), iso, terms));
        }
        active
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::extract::field::tests::mixed_spheres;
    use crate::extract::kernel::Terms;
    use crate::extract::reference::{self, Grid};
    use crate::scene::BOX_HALF_EXTENT;

    /// Every block left out of the layers (by its groups', its ball's or its box's bounds) holds no
    /// cell the oracle's field crosses, with adding and subtracting spheres, every kernel and blend, and iso levels
    /// near and far from the spheres' values; and the box's bounds leave out some blocks the ball's
    /// keep.
    #[test]
    fn the_blocks_left_out_hold_no_crossed_cell() {
        let (mut left_out_by_boxes, mut blocks) = (0, Blocks::default());
        for (seed, count, n) in [(1, 16, 48u32), (2, 5, 37), (3, 40, 30), (5, 64, 29)] {
            let spheres = mixed_spheres(seed, count);
            let mut s = Spheres::default();
            s.set(&spheres);
            let grid = Grid { cells_per_axis: n };
            let coords: Vec<f32> = (0..=n).map(|i| -BOX_HALF_EXTENT + i as f32 * grid.cell_size()).collect();
            let nb = n.div_ceil(BLOCK_CELLS);
            for iso in [0.05, 0.4, 1.0, 3.0] {
                for terms in Terms::every() {
                    let active = blocks.classify(&s, &coords, (iso, terms), n, 0..nb);
                    let kept: usize = blocks.layers.iter().map(Vec::len).sum();
                    left_out_by_boxes += active as usize - kept;
                    let values = reference::sample_blended_field(&spheres, grid, terms);
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
                                "seed {seed}, {n} cells, iso {iso}, {terms:?}: block {:?} is crossed",
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
