//! The field where the cell-by-cell meshers (the dual methods and marching tetrahedra) read it: the
//! blocks whose bounds straddle the iso level, as every extractor keeps them, and the field at every
//! point of those blocks, sampled in rows as the marching-cubes mesher samples it (so every mesher
//! reads the oracle's values).

use crate::extract::field::{BLOCK_CELLS, Spheres, sample_run};
use crate::extract::kernel::Terms;
use crate::scene::{BOX_HALF_EXTENT, Sphere};

/// The kept blocks of a grid and the field at their points.
#[derive(Default)]
pub struct KeptField {
    pub spheres: Spheres,
    /// Coordinate of grid point `i` along any axis.
    pub coords: Vec<f32>,
    /// Field values at every grid point of a kept block (others are never read).
    values: Vec<f32>,
    /// The kept blocks, in x-fastest order.
    pub kept: Vec<[u32; 3]>,
}

impl KeptField {
    /// Keeps the blocks of an `n`³ grid whose bounds straddle `iso` and samples the field at their
    /// points (points on the box's faces read 0, outside).
    pub fn sample(&mut self, spheres: &[Sphere], iso: f32, n: u32, terms: Terms) {
        let cell = 2.0 * BOX_HALF_EXTENT / n as f32;
        self.spheres.set(spheres);
        self.coords.clear();
        self.coords.extend((0..=n).map(|i| -BOX_HALF_EXTENT + i as f32 * cell));
        self.values.resize((n as usize + 1).pow(3), 0.0);
        let nb = n.div_ceil(BLOCK_CELLS);
        self.kept.clear();
        for bz in 0..nb {
            for by in 0..nb {
                for bx in 0..nb {
                    if self.spheres.block_straddles(&self.coords, [bx, by, bz], n, iso, terms) {
                        self.kept.push([bx, by, bz]);
                    }
                }
            }
        }
        for k in 0..self.kept.len() {
            self.sample_block(self.kept[k], n, terms);
        }
    }

    /// Field values at a kept block's points, in rows along x.
    fn sample_block(&mut self, [bx, by, bz]: [u32; 3], n: u32, terms: Terms) {
        let width = n as usize + 1;
        let (x0, x1) = ((bx * BLOCK_CELLS) as usize, ((bx + 1) * BLOCK_CELLS).min(n) as usize);
        for z in bz * BLOCK_CELLS..=((bz + 1) * BLOCK_CELLS).min(n) {
            for y in by * BLOCK_CELLS..=((by + 1) * BLOCK_CELLS).min(n) {
                let at = width * (y as usize + width * z as usize);
                let run = &mut self.values[at + x0..=at + x1];
                if z == 0 || z == n || y == 0 || y == n {
                    run.fill(0.0);
                    continue;
                }
                let (py, pz) = (self.coords[y as usize], self.coords[z as usize]);
                sample_run(run, &self.coords[x0..=x1], py, pz, &self.spheres, terms);
                if x0 == 0 {
                    run[0] = 0.0;
                }
                if x1 == n as usize {
                    run[x1 - x0] = 0.0;
                }
            }
        }
    }

    /// The field at grid point `p` of an `n`³ grid (a point of a kept block).
    pub fn value(&self, p: [u32; 3], n: u32) -> f32 {
        let width = n as usize + 1;
        self.values[p[0] as usize + width * (p[1] as usize + width * p[2] as usize)]
    }

    /// The cells of kept block `[bx, by, bz]` of an `n`³ grid, x fastest.
    pub fn cells([bx, by, bz]: [u32; 3], n: u32) -> impl Iterator<Item = [u32; 3]> {
        let span = move |b: u32| b * BLOCK_CELLS..((b + 1) * BLOCK_CELLS).min(n);
        span(bz).flat_map(move |z| span(by).flat_map(move |y| span(bx).map(move |x| [x, y, z])))
    }
}
