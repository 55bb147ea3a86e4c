//! Marching cubes on the CPU, built for speed (in wasm above all, where it beats a software GPU adapter):
//! the same tables, block bounds and arithmetic as the GPU passes and the oracle, so that it yields the
//! oracle's triangles exactly, in the vertex and index layout the shading pass draws.
//!
//! The grid is swept one plane of points at a time. Blocks of 4³ cells are bounded first, as on the GPU,
//! then the blocks kept are bounded again over their boxes, more tightly;
//! only the points of blocks both keep get field values, each computed once, in rows of consecutive
//! points, chunks of eight points summing all the spheres in vectors (every point still sums its
//! spheres in order, as the oracle does), with a bit per point saying whether it lies inside. Then the
//! cells of those blocks between two planes are classified from the bits, four at a time where all
//! their corners agree, and their triangles emitted, each vertex numbered on first use and found again
//! through the edge it lies on; vertices are placed after each layer, their normals summed in vectors.
//! Every array is kept between frames: after warm-up a frame allocates nothing.

use crate::extract::cpu::blocks::Blocks;
use crate::extract::cpu::planes::{ALL_INSIDE, Planes, Sweep};
use crate::extract::cpu::vertices::{EdgeVertices, Field};
use crate::extract::decider::{
    ambiguous_faces, decided_triangles, face_choices, has_tunnel, tunnel_possible,
};
use crate::extract::field::{BLOCK_CELLS, Spheres};
use crate::extract::interior::interior_code;
use crate::extract::kernel::Terms;
use crate::extract::mesh::IndexedMesh;
use crate::extract::reference::{Construction, Grid};
use crate::extract::tables::EDGE_TABLE;
use crate::scene::params::view::March;
use crate::scene::{BOX_HALF_EXTENT, Sphere};
use std::ops::Range;

/// What a mesh took: the counts the HUD and the statistics show.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CpuMeshStats {
    /// Blocks the bounds could not skip.
    pub active_blocks: u32,
    /// Blocks in the grid.
    pub total_blocks: u32,
    /// Cells the surface crosses.
    pub active_cells: u32,
}

/// A reusable CPU mesher. `mesh` fills `vertices` (position then outward normal, 6 `f32` each) and
/// `indices` (three per triangle, counter-clockwise seen from outside).
pub struct CpuMesher {
    /// Position then normal of each vertex.
    pub vertices: Vec<f32>,
    /// Three per triangle.
    pub indices: Vec<u32>,
    stats: CpuMeshStats,
    spheres: Spheres,
    /// Coordinate of grid point `i` along any axis.
    coords: Vec<f32>,
    /// The kept blocks, by layer.
    blocks: Blocks,
    /// Field values and inside bits of two planes of points.
    planes: Planes,
    /// The vertices, found through the edges they lie on.
    edges: EdgeVertices,
    /// The crossed cells whose triangles the decider or MC33 changes, with their kind, whatever the
    /// table (`decided_cells`).
    decided: Vec<[u32; 4]>,
}

impl Default for CpuMesher {
    fn default() -> Self {
        Self::new()
    }
}

impl CpuMesher {
    /// An empty mesher (made in one place, not wherever one is made: it sets up many arrays).
    #[inline(never)]
    pub fn new() -> Self {
        Self {
            vertices: Vec::new(),
            indices: Vec::new(),
            stats: CpuMeshStats::default(),
            spheres: Spheres::default(),
            coords: Vec::new(),
            blocks: Blocks::default(),
            planes: Planes::default(),
            edges: EdgeVertices::default(),
            decided: Vec::new(),
        }
    }

    /// Figures of the last mesh.
    pub fn stats(&self) -> CpuMeshStats {
        self.stats
    }

    /// Triangles of the last mesh.
    pub fn triangle_count(&self) -> u32 {
        (self.indices.len() / 3) as u32
    }

    /// Vertices of the last mesh.
    pub fn vertex_count(&self) -> u32 {
        (self.vertices.len() / 6) as u32
    }

    /// The last mesh as positions, normals and triangles.
    pub fn to_indexed(&self) -> IndexedMesh {
        IndexedMesh::from_interleaved(&self.vertices, &self.indices)
    }

    /// The grid edge of each vertex of the last mesh made here, as `(x + (n + 1) (y + (n + 1) z)) · 3 +
    /// axis` of the edge's lower end.
    pub fn vertex_keys(&self) -> &[u32] {
        self.edges.keys()
    }

    /// The cells of the last mesh whose triangles a table changes, each as x, y, z and a kind: bit 0
    /// where the asymptotic decider joins an ambiguous face (the classic table's triangles and the
    /// decider's differ), bit 1 where MC33 draws a tunnel (the decider's and MC33's differ).
    pub fn decided_cells(&self) -> &[[u32; 4]] {
        &self.decided
    }

    /// Takes a mesh made by another mesher of its kind as its last one, with what that one counted.
    pub fn install(&mut self, vertices: Vec<f32>, indices: Vec<u32>, counts: [u32; 2], grid: Grid) {
        let [active_blocks, active_cells] = counts;
        self.decided.clear();
        self.vertices = vertices;
        self.indices = indices;
        self.stats = CpuMeshStats {
            active_blocks,
            total_blocks: grid.cells_per_axis.div_ceil(BLOCK_CELLS).pow(3),
            active_cells,
        };
    }

    /// Extracts the surface f = `iso` of `spheres` on `grid`.
    pub fn mesh(&mut self, spheres: &[Sphere], iso: f32, grid: Grid, construction: Construction) {
        self.mesh_layers(spheres, iso, grid, construction, 0..grid.cells_per_axis);
    }

    /// [`CpuMesher::mesh`] of the layers of cells `layers` alone (a slab a whole number of blocks
    /// thick, or ending at the grid's end): the vertices their cells use, in the order the whole
    /// grid's mesh makes them, their triangles, and their blocks and cells in the figures.
    pub fn mesh_layers(
        &mut self,
        spheres: &[Sphere],
        iso: f32,
        grid: Grid,
        construction: Construction,
        layers: Range<u32>,
    ) {
        let n = grid.cells_per_axis;
        self.prepare(spheres, grid);
        let block_layers = layers.start / BLOCK_CELLS..layers.end.div_ceil(BLOCK_CELLS);
        self.classify_blocks(iso, n, construction.terms, block_layers);
        self.edges.start(n);
        self.planes.resize(n);
        self.vertices.clear();
        self.indices.clear();
        self.decided.clear();
        self.stats.active_cells = 0;
        let mut planes = std::mem::take(&mut self.planes);
        let terms = construction.terms;
        planes.sample(layers.start, &self.sweep(n, iso, terms));
        for z in layers {
            planes.sample(z + 1, &self.sweep(n, iso, terms));
            self.march_layer(&planes, z, iso, grid, construction);
            let field = Field { n, iso, construction, coords: &self.coords, spheres, arrays: &self.spheres };
            self.edges.place(&planes, &field, &mut self.vertices);
        }
        self.planes = planes;
        self.edges.end(n);
    }

    /// What sampling a plane reads.
    fn sweep(&self, n: u32, iso: f32, terms: Terms) -> Sweep<'_> {
        Sweep {
            n,
            iso,
            terms,
            coords: &self.coords,
            spheres: &self.spheres,
            layer_blocks: &self.blocks.layers,
        }
    }

    fn prepare(&mut self, spheres: &[Sphere], grid: Grid) {
        self.spheres.set(spheres);
        let cell = grid.cell_size();
        self.coords.clear();
        self.coords.extend((0..=grid.cells_per_axis).map(|i| -BOX_HALF_EXTENT + i as f32 * cell));
    }

    /// Keeps the blocks whose field bounds straddle `iso`, as `classify_blocks` in
    /// `shaders/extract/blocks.wgsl` does, and lists them by layer.
    fn classify_blocks(&mut self, iso: f32, n: u32, terms: Terms, layers: Range<u32>) {
        let bounds = (iso, terms);
        self.stats.active_blocks = self.blocks.classify(&self.spheres, &self.coords, bounds, n, layers);
        self.stats.total_blocks = n.div_ceil(BLOCK_CELLS).pow(3);
    }

    /// Classifies the cells of kept blocks between planes `z` and `z + 1` and emits their triangles.
    fn march_layer(&mut self, planes: &Planes, z: u32, iso: f32, grid: Grid, construction: Construction) {
        let n = grid.cells_per_axis;
        let nb = n.div_ceil(BLOCK_CELLS) as usize;
        let width = n as usize + 1;
        let (low, high) = ((z % 2) as usize, ((z + 1) % 2) as usize);
        let (lo, hi) = (&planes.values[low], &planes.values[high]);
        let blocks = std::mem::take(&mut self.blocks.layers[(z / BLOCK_CELLS) as usize]);
        self.edges.start_layer(z);
        for &(bx, by) in &blocks {
            let y_end = (by * BLOCK_CELLS + BLOCK_CELLS).min(n);
            let x_end = (bx * BLOCK_CELLS + BLOCK_CELLS).min(n);
            for y in by * BLOCK_CELLS..y_end {
                // The inside bits of the four rows of points around this row of cells.
                let row = |plane: usize, y: u32| planes.inside[plane][y as usize * nb + bx as usize];
                let rows = [row(low, y), row(low, y + 1), row(high, y), row(high, y + 1)];
                let (all, any) =
                    (rows[0] & rows[1] & rows[2] & rows[3], rows[0] | rows[1] | rows[2] | rows[3]);
                if any == 0 || all == ALL_INSIDE {
                    continue;
                }
                for x in bx * BLOCK_CELLS..x_end {
                    let k = x - bx * BLOCK_CELLS;
                    // Corners 0 to 3 at (x, y), (x + 1, y), (x + 1, y + 1), (x, y + 1), below then above.
                    let bit = |r: u8, dx: u32| ((r >> (k + dx)) & 1) as usize;
                    let case = bit(rows[0], 0)
                        | bit(rows[0], 1) << 1
                        | bit(rows[1], 1) << 2
                        | bit(rows[1], 0) << 3
                        | bit(rows[2], 0) << 4
                        | bit(rows[2], 1) << 5
                        | bit(rows[3], 1) << 6
                        | bit(rows[3], 0) << 7;
                    if EDGE_TABLE[case] == 0
                        || (construction.march.is_some() && !March::reached(construction.march, [x, y, z]))
                    {
                        continue;
                    }
                    self.stats.active_cells += 1;
                    // The values at (x, y) and (x + 1, y), then at (x, y + 1) and (x + 1, y + 1).
                    let at = x as usize + width * y as usize;
                    let pair =
                        |plane: &[f32], at: usize| -> [f32; 2] { plane[at..at + 2].try_into().unwrap() };
                    let ([a, b], [d, c]) = (pair(lo, at), pair(lo, at + width));
                    let ([e, f], [h, g]) = (pair(hi, at), pair(hi, at + width));
                    let values = [a, b, c, d, e, f, g, h];
                    // What the decider changes (its faces) and what MC33 changes beyond them (a
                    // tunnel), whatever the table drawn.
                    let joined = if ambiguous_faces(case) != 0 { face_choices(case, values, iso) } else { 0 };
                    let code = if tunnel_possible(case) { interior_code(values, iso) } else { 0 };
                    let tunnel = code != 0 && has_tunnel(case, joined, code);
                    let kind = (joined != 0) as u32 | (tunnel as u32) << 1;
                    if kind != 0 {
                        self.decided.push([x, y, z, kind]);
                    }
                    // The triangles `Construction::cell_triangles` gives, from the choices made above
                    // (where no interior join can make a tunnel, every one gives the same triangles).
                    let (joined, code) = construction.drawn_choices(joined, code);
                    // The tables wind clockwise seen from outside; emit counter-clockwise.
                    self.edges.number([x, y, z], decided_triangles(case, joined, code), &mut self.indices);
                }
            }
        }
        self.blocks.layers[(z / BLOCK_CELLS) as usize] = blocks;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::extract::decider::MAX_DECIDED_TRIANGLES;
    use crate::extract::reference;
    use crate::scene::Scene;

    fn assert_matches_oracle(spheres: &[Sphere], iso: f32, n: u32, construction: Construction) {
        let grid = Grid { cells_per_axis: n };
        let mut mesher = CpuMesher::new();
        mesher.mesh(spheres, iso, grid, construction);
        let oracle = reference::extract_with(spheres, iso, grid, construction);
        let ours = mesher.to_indexed().to_soup();
        ours.matches(&oracle, 0.0, 1e-3).unwrap_or_else(|e| panic!("{n} cells, iso {iso}: {e}"));
    }

    #[test]
    fn matches_the_oracle_exactly_on_seeded_scenes() {
        for (seed, count, n) in [(1, 1, 8), (2, 5, 13), (3, 16, 32), (4, 64, 24)] {
            let scene = Scene::new(seed, count).unwrap();
            assert_matches_oracle(scene.spheres(), 1.0, n, Construction::default());
        }
    }

    /// The decided cells are exactly those whose triangles the decider changes (kind 1), and those
    /// whose triangles MC33 changes beyond the decider's (kind 2).
    #[test]
    fn the_decided_cells_are_those_the_decider_or_mc33_changes() {
        // Seed 11 at 96³ has faces the decider joins.
        let mut kinds = 0;
        for (seed, count, n, iso) in [(11, 64, 96, 1.5), (4, 64, 24, 1.0)] {
            kinds |= check_decided_cells(Scene::new(seed, count).unwrap(), Grid { cells_per_axis: n }, iso);
        }
        // Two spheres on the ends of a cell's body diagonal: a tunnel.
        let sphere = |c: f32| Sphere {
            center: glam::Vec3::splat(c),
            radius: 0.14,
            velocity: glam::Vec3::ZERO,
            charge: 1.0,
        };
        let pair = Scene::from_spheres(vec![sphere(-0.106), sphere(0.116)]).unwrap();
        kinds |= check_decided_cells(pair, Grid { cells_per_axis: 9 }, 1.0);
        assert_eq!(kinds, 3, "the scenes hold faces the decider joins and tunnels");
    }

    /// Checks the decided cells of one scene; returns the kinds found.
    fn check_decided_cells(scene: Scene, grid: Grid, iso: f32) -> u32 {
        use crate::scene::params::view::CaseTable;
        let n = grid.cells_per_axis;
        let mut mesher = CpuMesher::new();
        let tables = [CaseTable::Classic, CaseTable::Decider, CaseTable::Mc33]
            .map(|case_table| Construction { case_table, ..Construction::default() });
        mesher.mesh(scene.spheres(), iso, grid, tables[2]);
        let mut decided = mesher.decided_cells().to_vec();
        mesher.mesh(scene.spheres(), iso, grid, tables[0]);
        assert_eq!(mesher.decided_cells(), decided, "the same cells under either table");
        decided.sort_by_key(|&[x, y, z, _]| [z, y, x]);
        let values = reference::sample_field(scene.spheres(), grid);
        let mut changed = Vec::new();
        for z in 0..n {
            for y in 0..n {
                for x in 0..n {
                    let corner = |c: usize| {
                        let o = crate::extract::tables::CORNER_OFFSETS[c];
                        let p = glam::UVec3::new(x + o[0], y + o[1], z + o[2]);
                        values[grid.point_index(p)]
                    };
                    let f: [f32; 8] = std::array::from_fn(corner);
                    let case = (0..8).fold(0, |m, c| m | ((f[c] > iso) as usize) << c);
                    let triangles = |t: &Construction| {
                        let mut out = [[0; 3]; MAX_DECIDED_TRIANGLES];
                        let k = t.cell_triangles(case, f, iso, &mut out);
                        out[..k].to_vec()
                    };
                    let [classic, decider, mc33] = [0, 1, 2].map(|k| triangles(&tables[k]));
                    let kind = (classic != decider) as u32 | ((decider != mc33) as u32) << 1;
                    if kind != 0 {
                        changed.push([x, y, z, kind]);
                    }
                }
            }
        }
        assert_eq!(decided, changed);
        changed.iter().fold(0, |k, c| k | c[3])
    }
}
