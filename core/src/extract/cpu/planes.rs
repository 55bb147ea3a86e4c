//! The planes of grid points the CPU mesher sweeps: which points the kept blocks use, their field
//! values, and which of them lie inside, a bit per point in a byte per row of a block, so the cells
//! of a block's row that the surface cannot cross are passed over four at a time.

use crate::extract::field::{BLOCK_CELLS, Spheres, sample_run};

use crate::extract::kernel::Terms;

/// The inside bits of a block's row of points where all five lie inside.
pub const ALL_INSIDE: u8 = (1 << (BLOCK_CELLS + 1)) - 1;

/// Two planes of points (plane z at `z % 2`), of an `n`³ grid.
#[derive(Default)]
pub struct Planes {
    /// Field values, x fastest.
    pub values: [Vec<f32>; 2],
    /// Per row of points and column of blocks (`y · blocks + bx`): bit k set where point
    /// `BLOCK_CELLS · bx + k` of the row lies inside. Only the rows of kept blocks are current.
    pub inside: [Vec<u8>; 2],
    /// Per row of blocks, a bit per column of blocks: its points are needed in the current plane.
    columns: Vec<u64>,
}

/// `v` with `len` values (in one place for each type, not wherever one is resized).
#[inline(never)]
fn sized<T: Copy + Default>(v: &mut Vec<T>, len: usize) {
    v.resize(len, T::default());
}

/// The plane sampled and what it reads.
pub struct Sweep<'a> {
    pub n: u32,
    pub iso: f32,
    pub terms: Terms,
    /// Coordinate of grid point `i` along any axis.
    pub coords: &'a [f32],
    pub spheres: &'a Spheres,
    /// Per layer of blocks: the kept blocks' (x, y) block coordinates.
    pub layer_blocks: &'a [Vec<(u32, u32)>],
}

impl Planes {
    /// Makes room for the planes of an `n`³ grid.
    pub fn resize(&mut self, n: u32) {
        let points = (n as usize + 1).pow(2);
        let rows = (n as usize + 1) * n.div_ceil(BLOCK_CELLS) as usize;
        for plane in 0..2 {
            sized(&mut self.values[plane], points);
            sized(&mut self.inside[plane], rows);
        }
    }

    /// Field values and inside bits at the points of plane `z` that kept blocks use (boundary points
    /// read 0).
    pub fn sample(&mut self, z: u32, sweep: &Sweep) {
        let n = sweep.n;
        let nb = n.div_ceil(BLOCK_CELLS);
        let words = nb.div_ceil(64) as usize;
        let width = n as usize + 1;
        // The block layers holding this plane: the one above it and, on a layer boundary, the one below.
        self.columns.clear();
        self.columns.resize(nb as usize * words, 0);
        let layers = [z / BLOCK_CELLS, (z / BLOCK_CELLS).wrapping_sub(1)];
        for (k, &layer) in layers.iter().enumerate() {
            if layer >= nb || (k == 1 && !z.is_multiple_of(BLOCK_CELLS)) {
                continue;
            }
            for &(bx, by) in &sweep.layer_blocks[layer as usize] {
                self.columns[by as usize * words + bx as usize / 64] |= 1 << (bx % 64);
            }
        }
        let plane = (z % 2) as usize;
        let (values, inside) = (&mut self.values[plane], &mut self.inside[plane]);
        let boundary_plane = z == 0 || z == n;
        let pz = sweep.coords[z as usize];
        for y in 0..=n {
            // The block rows holding this row of points: the one above it and, on a block boundary,
            // the one below.
            let by = (y / BLOCK_CELLS) as usize;
            let below = y.is_multiple_of(BLOCK_CELLS) && by > 0;
            let row = &mut values[y as usize * width..(y as usize + 1) * width];
            let row_inside = &mut inside[y as usize * nb as usize..(y as usize + 1) * nb as usize];
            for word in 0..words {
                let mut bits = if by < nb as usize { self.columns[by * words + word] } else { 0 };
                if below {
                    bits |= self.columns[(by - 1) * words + word];
                }
                // Runs of consecutive needed blocks become runs of points.
                while bits != 0 {
                    let first = bits.trailing_zeros();
                    let len = (bits >> first).trailing_ones();
                    bits &= !((u64::MAX >> (64 - len)) << first);
                    let start = word as u32 * 64 + first;
                    let end = start + len;
                    let x0 = (start * BLOCK_CELLS) as usize;
                    let x1 = ((end * BLOCK_CELLS).min(n)) as usize;
                    let run = &mut row[x0..=x1];
                    if boundary_plane || y == 0 || y == n {
                        run.fill(0.0);
                    } else {
                        let (xs, py) = (&sweep.coords[x0..=x1], sweep.coords[y as usize]);
                        sample_run(run, xs, py, pz, sweep.spheres, sweep.terms);
                        if x0 == 0 {
                            run[0] = 0.0;
                        }
                        if x1 == n as usize {
                            run[x1 - x0] = 0.0;
                        }
                    }
                    for bx in start..end {
                        let from = ((bx - start) * BLOCK_CELLS) as usize;
                        // The block's points (fewer where the grid ends), a bit each.
                        let mut bits = 0;
                        for k in 0..=BLOCK_CELLS as usize {
                            if let Some(&f) = run.get(from + k) {
                                bits |= ((f > sweep.iso) as u8) << k;
                            }
                        }
                        row_inside[bx as usize] = bits;
                    }
                }
            }
        }
    }
}
