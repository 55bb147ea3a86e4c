//! Marching cubes on the CPU, built for speed (in wasm above all, where it beats a software GPU adapter):
//! the same tables, block bounds and arithmetic as the GPU passes and the oracle, so that it yields the
//! oracle's triangles exactly, in the vertex and index layout the shading pass draws.
//!
//! The grid is swept one plane of points at a time. Blocks of 4³ cells are bounded first, as on the GPU;
//! only the points of kept blocks get field values, each computed once, in rows of consecutive points
//! with the sphere loop outside so the compiler can vectorise across points (every point still sums its
//! spheres in order, as the oracle does). Then the cells of kept blocks between two planes are
//! classified and their triangles emitted, each vertex made once on first use and found again through
//! the edge it lies on. Every array is kept between frames: after warm-up a frame allocates nothing.

use crate::extract::decider::{
    MAX_DECIDED_TRIANGLES, ambiguous_faces, face_choices, has_tunnel, tunnel_possible,
};
use crate::extract::field::{BLOCK_CELLS, Spheres, sample_run};
use crate::extract::interior::interior_code;
use crate::extract::mesh::IndexedMesh;
use crate::extract::reference::{self, Construction, Grid};
use crate::extract::tables::EDGE_TABLE;
use crate::scene::params::view::{Blend, March};
use crate::scene::{BOX_HALF_EXTENT, Sphere};
use glam::Vec3;
use std::ops::Range;

/// Blocks per side of the groups bounded before their blocks.
const GROUP_BLOCKS: u32 = 2;

/// Marks an edge without a vertex yet.
const NONE: u32 = u32::MAX;

/// Edge `e` of a cell starts at this corner offset and runs along this axis (`EDGE_CORNERS` in
/// `src/extract/tables.rs`, each edge from its lower corner).
const EDGE_START: [([u32; 3], usize); 12] = [
    ([0, 0, 0], 0),
    ([1, 0, 0], 1),
    ([0, 1, 0], 0),
    ([0, 0, 0], 1),
    ([0, 0, 1], 0),
    ([1, 0, 1], 1),
    ([0, 1, 1], 0),
    ([0, 0, 1], 1),
    ([0, 0, 0], 2),
    ([1, 0, 0], 2),
    ([1, 1, 0], 2),
    ([0, 1, 0], 2),
];

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
#[derive(Default)]
pub struct CpuMesher {
    /// Position then normal of each vertex.
    pub vertices: Vec<f32>,
    /// Three per triangle.
    pub indices: Vec<u32>,
    stats: CpuMeshStats,
    spheres: Spheres,
    /// Coordinate of grid point `i` along any axis.
    coords: Vec<f32>,
    /// Per group of `GROUP_BLOCKS`³ blocks: whether its blocks need bounding one by one.
    groups: Vec<bool>,
    /// Per layer of blocks: the kept blocks' (x, y) block coordinates.
    layer_blocks: Vec<Vec<(u32, u32)>>,
    /// Per column of blocks in the current plane: its points are needed.
    columns: Vec<bool>,
    /// Field values of two planes of points (plane z at `z % 2`).
    values: [Vec<f32>; 2],
    /// The vertex on the x and y edges leaving each point of two planes.
    plane_edges: [Vec<u32>; 2],
    /// The vertex on the z edge leaving each point of the lower plane of the current layer of cells.
    z_edges: Vec<u32>,
    /// The grid edge of each vertex, so a stale entry in the edge arrays is told from a current one.
    vertex_edges: Vec<u32>,
    /// The crossed cells whose triangles the decider or MC33 changes, with their kind, whatever the
    /// table (`decided_cells`).
    decided: Vec<[u32; 4]>,
}

impl CpuMesher {
    pub fn new() -> Self {
        Self::default()
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

    /// The grid edge each vertex of the last mesh lies on (point index times three plus the axis, as
    /// `metaballs::extract::cpu::slabs::edge_key` makes it), for joining slabs.
    pub fn vertex_keys(&self) -> &[u32] {
        &self.vertex_edges
    }

    /// Extracts the surface f = `iso` of `spheres` on `grid`.
    pub fn mesh(&mut self, spheres: &[Sphere], iso: f32, grid: Grid, construction: Construction) {
        self.mesh_layers(spheres, iso, grid, construction, 0..grid.cells_per_axis);
    }

    /// [`CpuMesher::mesh`] of the layers of cells `layers` alone (a slab a whole number of blocks
    /// thick, or ending at the grid's end): the vertices their cells use, in the order the whole grid's
    /// mesh makes them, their triangles, and their blocks and cells in the figures.
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
        self.classify_blocks(iso, n, construction.blend, block_layers);
        let points = (n as usize + 1).pow(2);
        for plane in 0..2 {
            self.values[plane].resize(points, 0.0);
            self.plane_edges[plane].resize(2 * points, NONE);
        }
        self.z_edges.resize(points, NONE);
        self.vertices.clear();
        self.indices.clear();
        self.vertex_edges.clear();
        self.decided.clear();
        self.stats.active_cells = 0;
        self.sample_plane(layers.start, n, construction.blend);
        for z in layers {
            self.sample_plane(z + 1, n, construction.blend);
            self.march_layer(spheres, z, iso, grid, construction);
        }
    }

    fn prepare(&mut self, spheres: &[Sphere], grid: Grid) {
        self.spheres.set(spheres);
        let cell = grid.cell_size();
        self.coords.clear();
        self.coords.extend((0..=grid.cells_per_axis).map(|i| -BOX_HALF_EXTENT + i as f32 * cell));
    }

    /// Keeps the blocks of the layers `block_layers` whose field bounds straddle `iso`, as
    /// `classify_blocks` in `shaders/extract/blocks.wgsl` does, and lists them by layer (the other
    /// layers' lists are left empty). Groups of blocks that cannot hold the surface are passed over
    /// first, then each block of the other groups is bounded on its own.
    fn classify_blocks(&mut self, iso: f32, n: u32, blend: Blend, block_layers: Range<u32>) {
        let nb = n.div_ceil(BLOCK_CELLS);
        let total = (nb as usize).pow(3);
        let ng = nb.div_ceil(GROUP_BLOCKS);
        let by_max = blend == Blend::Max;
        self.groups.clear();
        self.groups.resize((ng * ng * (block_layers.start / GROUP_BLOCKS)) as usize, false);
        for gz in block_layers.start / GROUP_BLOCKS..block_layers.end.div_ceil(GROUP_BLOCKS) {
            for gy in 0..ng {
                for gx in 0..ng {
                    let first = [gx, gy, gz].map(|g| g * GROUP_BLOCKS);
                    self.groups.push(self.spheres.group_straddles(
                        &self.coords,
                        first,
                        GROUP_BLOCKS,
                        n,
                        iso,
                        by_max,
                    ));
                }
            }
        }
        self.layer_blocks.resize_with(nb as usize, Vec::new);
        self.layer_blocks.truncate(nb as usize);
        let mut active = 0;
        for layer in &mut self.layer_blocks {
            layer.clear();
        }
        for bz in block_layers {
            let layer = &mut self.layer_blocks[bz as usize];
            for by in 0..nb {
                for bx in 0..nb {
                    let [gx, gy, gz] = [bx, by, bz].map(|b| b / GROUP_BLOCKS);
                    if self.groups[(gx + ng * (gy + ng * gz)) as usize]
                        && self.spheres.block_straddles(&self.coords, [bx, by, bz], n, iso, by_max)
                    {
                        layer.push((bx, by));
                        active += 1;
                    }
                }
            }
        }
        self.stats.active_blocks = active;
        self.stats.total_blocks = total as u32;
    }

    /// Field values at the points of plane `z` that kept blocks use (boundary points read 0).
    fn sample_plane(&mut self, z: u32, n: u32, blend: Blend) {
        let nb = n.div_ceil(BLOCK_CELLS);
        let width = n as usize + 1;
        // The block layers holding this plane: the one above it and, on a layer boundary, the one below.
        self.columns.clear();
        self.columns.resize((nb * nb) as usize, false);
        let layers = [z / BLOCK_CELLS, (z / BLOCK_CELLS).wrapping_sub(1)];
        for (k, &layer) in layers.iter().enumerate() {
            if layer >= nb || (k == 1 && !z.is_multiple_of(BLOCK_CELLS)) {
                continue;
            }
            for &(bx, by) in &self.layer_blocks[layer as usize] {
                self.columns[(bx + nb * by) as usize] = true;
            }
        }
        let values = &mut self.values[(z % 2) as usize];
        let boundary_plane = z == 0 || z == n;
        let pz = self.coords[z as usize];
        for y in 0..=n {
            let rows = [y / BLOCK_CELLS, (y / BLOCK_CELLS).wrapping_sub(1)];
            let needed = |bx: u32| {
                rows.iter().enumerate().any(|(k, &by)| {
                    by < nb
                        && (k == 0 || y.is_multiple_of(BLOCK_CELLS))
                        && self.columns[(bx + nb * by) as usize]
                })
            };
            let row = &mut values[y as usize * width..(y as usize + 1) * width];
            // Runs of consecutive needed blocks become runs of points.
            let mut bx = 0;
            while bx < nb {
                if !needed(bx) {
                    bx += 1;
                    continue;
                }
                let start = bx;
                while bx < nb && needed(bx) {
                    bx += 1;
                }
                let x0 = (start * BLOCK_CELLS) as usize;
                let x1 = ((bx * BLOCK_CELLS).min(n)) as usize;
                let run = &mut row[x0..=x1];
                if boundary_plane || y == 0 || y == n {
                    run.fill(0.0);
                    continue;
                }
                sample_run(run, &self.coords[x0..=x1], self.coords[y as usize], pz, &self.spheres, blend);
                if x0 == 0 {
                    run[0] = 0.0;
                }
                if x1 == n as usize {
                    run[x1 - x0] = 0.0;
                }
            }
        }
    }

    /// Classifies the cells of kept blocks between planes `z` and `z + 1` and emits their triangles.
    fn march_layer(&mut self, spheres: &[Sphere], z: u32, iso: f32, grid: Grid, construction: Construction) {
        let n = grid.cells_per_axis;
        let width = n as usize + 1;
        let (low, high) = ((z % 2) as usize, ((z + 1) % 2) as usize);
        let blocks = std::mem::take(&mut self.layer_blocks[(z / BLOCK_CELLS) as usize]);
        for &(bx, by) in &blocks {
            let y_end = (by * BLOCK_CELLS + BLOCK_CELLS).min(n);
            let x_end = (bx * BLOCK_CELLS + BLOCK_CELLS).min(n);
            for y in by * BLOCK_CELLS..y_end {
                for x in bx * BLOCK_CELLS..x_end {
                    if !March::reached(construction.march, [x, y, z]) {
                        continue;
                    }
                    let at = x as usize + width * y as usize;
                    let corners = [at, at + 1, at + 1 + width, at + width];
                    let (lo, hi) = (&self.values[low], &self.values[high]);
                    let mut case = 0usize;
                    for (c, &p) in corners.iter().enumerate() {
                        case |= ((lo[p] > iso) as usize) << c;
                        case |= ((hi[p] > iso) as usize) << (c + 4);
                    }
                    if EDGE_TABLE[case] == 0 {
                        continue;
                    }
                    self.stats.active_cells += 1;
                    let values = [
                        lo[corners[0]],
                        lo[corners[1]],
                        lo[corners[2]],
                        lo[corners[3]],
                        hi[corners[0]],
                        hi[corners[1]],
                        hi[corners[2]],
                        hi[corners[3]],
                    ];
                    // What the decider changes (its faces) and what MC33 changes beyond them (a
                    // tunnel), whatever the table drawn.
                    let joined = if ambiguous_faces(case) != 0 { face_choices(case, values, iso) } else { 0 };
                    let tunnel =
                        tunnel_possible(case) && has_tunnel(case, joined, interior_code(values, iso));
                    let kind = (joined != 0) as u32 | (tunnel as u32) << 1;
                    if kind != 0 {
                        self.decided.push([x, y, z, kind]);
                    }
                    let mut triangles = [[0; 3]; MAX_DECIDED_TRIANGLES];
                    let count = construction.cell_triangles(case, values, iso, &mut triangles);
                    for t in &triangles[..count] {
                        // The tables wind clockwise seen from outside; emit counter-clockwise.
                        for k in [0, 2, 1] {
                            let id = self.vertex_on(spheres, t[k], [x, y, z], iso, grid, construction);
                            self.indices.push(id);
                        }
                    }
                }
            }
        }
        self.layer_blocks[(z / BLOCK_CELLS) as usize] = blocks;
    }

    /// The vertex on edge `edge` of `cell`, made on first use.
    fn vertex_on(
        &mut self,
        spheres: &[Sphere],
        edge: usize,
        cell: [u32; 3],
        iso: f32,
        grid: Grid,
        construction: Construction,
    ) -> u32 {
        let n = grid.cells_per_axis;
        let width = n as usize + 1;
        let (offset, axis) = EDGE_START[edge];
        let a = [cell[0] + offset[0], cell[1] + offset[1], cell[2] + offset[2]];
        let planar = a[0] as usize + width * a[1] as usize;
        let key = (a[0] + (n + 1) * (a[1] + (n + 1) * a[2])) * 3 + axis as u32;
        let plane = (a[2] % 2) as usize;
        let slot = match axis {
            2 => &mut self.z_edges[planar],
            _ => &mut self.plane_edges[plane][2 * planar + axis],
        };
        let known = *slot;
        if (known as usize) < self.vertex_edges.len() && self.vertex_edges[known as usize] == key {
            return known;
        }
        let id = self.vertex_edges.len() as u32;
        *slot = id;
        self.vertex_edges.push(key);

        let mut b = a;
        b[axis] += 1;
        let value = |p: [u32; 3]| self.values[(p[2] % 2) as usize][p[0] as usize + width * p[1] as usize];
        let (fa, fb) = (value(a), value(b));
        let point = |p: [u32; 3]| Vec3::from_array(p.map(|i| self.coords[i as usize]));
        let boundary = |p: [u32; 3]| p.contains(&0) || p.contains(&n);
        let (p, normal) = reference::surface_vertex(
            spheres,
            iso,
            construction,
            (point(a), fa, boundary(a)),
            (point(b), fb, boundary(b)),
        );
        self.vertices.extend_from_slice(&[p.x, p.y, p.z, normal.x, normal.y, normal.z]);
        id
    }
}

#[cfg(test)]
mod tests {
    use super::*;
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
