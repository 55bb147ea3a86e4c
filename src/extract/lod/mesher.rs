//! The LOD mesh on the CPU: marching cubes in every selected block at its level, and Transvoxel
//! transition cells on the faces where a finer block meets it. The same tables, field arithmetic and
//! block bounds as the uniform CPU mesher, so the finest blocks' triangles are the oracle's.
//!
//! A vertex is known by the edge it lies on: its lower end in finest cells, its axis and its level.
//! A fine block and the transition cells of its coarse neighbour name the edges of their common face
//! alike, as do a coarse block and its own transition cells, so each seam vertex is made once and the
//! mesh is closed.

use super::select::{BLOCK_CELLS, Block, Selection};
use super::transition::{self, HALF_RESOLUTION};
use crate::extract::field::{Spheres, sample_run};
use crate::extract::mesh::IndexedMesh;
use crate::extract::reference::{self, Construction, Grid};
use crate::extract::tables::{CASE_TRIANGLES, CORNER_OFFSETS, EDGE_CORNERS, EDGE_TABLE, TRI_TABLE};
use crate::scene::Sphere;
use glam::UVec3;
use rustc_hash::FxHashMap;

/// Marks a transition cell's triangle in `LodMesher::triangle_levels`.
pub const TRANSITION: u8 = 0x80;

/// What a LOD mesh took, level by level (finest first).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LodStats {
    /// Selected blocks per level.
    pub blocks: Vec<u32>,
    /// Blocks the bounds could not skip.
    pub active_blocks: u32,
    /// Regular cells the surface crosses.
    pub active_cells: u32,
    /// Transition cells the surface crosses.
    pub transition_cells: u32,
    /// Triangles per level (a transition cell's count at its coarse block's level).
    pub triangles: Vec<u32>,
    /// Cells visited: regular cells of kept blocks plus their transition cells.
    pub cells_processed: u64,
}

/// A reusable LOD mesher; `vertices` and `indices` as the uniform CPU mesher lays them out.
#[derive(Default)]
pub struct LodMesher {
    /// Position then outward normal of each vertex.
    pub vertices: Vec<f32>,
    /// Three per triangle, counter-clockwise seen from outside.
    pub indices: Vec<u32>,
    /// The level of each triangle, with [`TRANSITION`] added for a transition cell's.
    pub triangle_levels: Vec<u8>,
    /// The blocks the bounds kept: origin, then level | transition faces << 8.
    pub kept_blocks: Vec<[u32; 4]>,
    stats: LodStats,
    spheres: Spheres,
    /// Vertex by edge key.
    edges: FxHashMap<u64, u32>,
    /// A block's samples at its level, x fastest.
    values: Vec<f32>,
    /// A transition face's samples at the finer level.
    face: Vec<f32>,
    xs: Vec<f32>,
}

/// Everything a frame's vertices depend on.
struct Frame<'a> {
    spheres: &'a [Sphere],
    iso: f32,
    grid: Grid,
    construction: Construction,
}

impl Frame<'_> {
    fn coordinate(&self, i: u32) -> f32 {
        self.grid.point(UVec3::new(i, 0, 0)).x
    }

    /// The field at finest grid point `id`, as the oracle samples it.
    fn value(&self, id: UVec3) -> f32 {
        if self.grid.is_boundary(id) {
            0.0
        } else {
            reference::blended_field_at(self.spheres, self.grid.point(id), self.construction.terms)
        }
    }
}

fn edge_key(start: UVec3, axis: usize, level: u32) -> u64 {
    (start.x as u64)
        | (start.y as u64) << 13
        | (start.z as u64) << 26
        | (axis as u64) << 39
        | (level as u64) << 41
}

impl LodMesher {
    pub fn new() -> Self {
        Self::default()
    }

    pub fn stats(&self) -> &LodStats {
        &self.stats
    }

    pub fn vertex_count(&self) -> u32 {
        (self.vertices.len() / 6) as u32
    }

    pub fn triangle_count(&self) -> u32 {
        (self.indices.len() / 3) as u32
    }

    /// The last mesh as positions, normals and triangles.
    pub fn to_indexed(&self) -> IndexedMesh {
        IndexedMesh::from_interleaved(&self.vertices, &self.indices)
    }

    /// Meshes the surface f = `iso` of `spheres` over the blocks of `selection`.
    pub fn mesh(&mut self, spheres: &[Sphere], iso: f32, construction: Construction, selection: &Selection) {
        let frame = Frame { spheres, iso, grid: Grid { cells_per_axis: selection.resolution }, construction };
        self.spheres.set(spheres);
        self.vertices.clear();
        self.indices.clear();
        self.triangle_levels.clear();
        self.kept_blocks.clear();
        self.edges.clear();
        let levels = selection.levels as usize;
        self.stats = LodStats {
            blocks: selection.blocks_per_level(),
            triangles: vec![0; levels],
            ..LodStats::default()
        };
        for block in &selection.blocks {
            self.mesh_block(&frame, block);
        }
    }

    fn mesh_block(&mut self, frame: &Frame, block: &Block) {
        let n = frame.grid.cells_per_axis;
        let (origin, step, width) = (block.origin, block.step(), block.width());
        let far = origin + UVec3::splat(width);
        let (low, high) = (frame.grid.point(origin), frame.grid.point(far));
        let walls = origin.min_element() == 0 || far.max_element() == n;
        if !self.spheres.straddles(low, high, walls, frame.iso, frame.construction.terms) {
            return;
        }
        self.stats.active_blocks += 1;
        self.kept_blocks.push([origin.x, origin.y, origin.z, block.level | (block.transitions as u32) << 8]);
        self.sample_block(frame, block);
        let m = (BLOCK_CELLS + 1) as usize;
        let at = |c: UVec3| c.x as usize + m * (c.y as usize + m * c.z as usize);
        self.stats.cells_processed += (BLOCK_CELLS as u64).pow(3);
        for z in 0..BLOCK_CELLS {
            for y in 0..BLOCK_CELLS {
                for x in 0..BLOCK_CELLS {
                    let cell = UVec3::new(x, y, z);
                    let corner = |c: usize| cell + UVec3::from_array(CORNER_OFFSETS[c]);
                    let case = (0..8)
                        .fold(0usize, |m, c| m | ((self.values[at(corner(c))] > frame.iso) as usize) << c);
                    if EDGE_TABLE[case] == 0 {
                        continue;
                    }
                    self.stats.active_cells += 1;
                    let row = &TRI_TABLE[case];
                    for t in 0..CASE_TRIANGLES[case] as usize {
                        for k in [0, 2, 1] {
                            let [a, b] = EDGE_CORNERS[row[3 * t + k] as usize];
                            let (ca, cb) = (corner(a), corner(b));
                            let axis = (0..3).find(|&i| ca[i] != cb[i]).unwrap();
                            let (fa, fb) = (self.values[at(ca)], self.values[at(cb)]);
                            let id = self.vertex(frame, origin + ca * step, axis, block.level, fa, fb);
                            self.indices.push(id);
                        }
                        self.triangle_levels.push(block.level as u8);
                    }
                    self.stats.triangles[block.level as usize] += CASE_TRIANGLES[case] as u32;
                }
            }
        }
        for face in 0..6 {
            if block.transitions & (1 << face) != 0 {
                self.mesh_transition_face(frame, block, face / 2, (face % 2) as u32);
            }
        }
    }

    /// The block's samples at its own level; points on the walls read 0.
    fn sample_block(&mut self, frame: &Frame, block: &Block) {
        let n = frame.grid.cells_per_axis;
        let m = (BLOCK_CELLS + 1) as usize;
        let (o, step) = (block.origin, block.step());
        self.values.resize(m * m * m, 0.0);
        self.xs.clear();
        self.xs.extend((0..m as u32).map(|x| frame.coordinate(o.x + x * step)));
        for z in 0..m as u32 {
            let (iz, pz) = (o.z + z * step, frame.coordinate(o.z + z * step));
            for y in 0..m as u32 {
                let (iy, py) = (o.y + y * step, frame.coordinate(o.y + y * step));
                let row = &mut self.values[m * (y as usize + m * z as usize)..][..m];
                if iy == 0 || iy == n || iz == 0 || iz == n {
                    row.fill(0.0);
                    continue;
                }
                sample_run(row, &self.xs, py, pz, &self.spheres, frame.construction.terms);
                if o.x == 0 {
                    row[0] = 0.0;
                }
                if o.x + block.width() == n {
                    row[m - 1] = 0.0;
                }
            }
        }
    }

    /// Transition cells on face `side` (0 low, 1 high) of `axis`, where a block one level finer lies.
    fn mesh_transition_face(&mut self, frame: &Frame, block: &Block, axis: usize, side: u32) {
        let (u_axis, v_axis) = ((axis + 1) % 3, (axis + 2) % 3);
        let fine = block.step() / 2;
        let samples = 2 * BLOCK_CELLS + 1;
        let mut base = block.origin;
        base[axis] += side * block.width();
        let point = |i: u32, j: u32| {
            let mut p = base;
            p[u_axis] += i * fine;
            p[v_axis] += j * fine;
            p
        };
        self.face.clear();
        for j in 0..samples {
            for i in 0..samples {
                self.face.push(frame.value(point(i, j)));
            }
        }
        // (u, v, w) with w into the block is right-handed on the low face, left-handed on the high one.
        let left_handed = side == 1;
        self.stats.cells_processed += (BLOCK_CELLS as u64).pow(2);
        for cj in 0..BLOCK_CELLS {
            for ci in 0..BLOCK_CELLS {
                let sample = |s: usize| {
                    let s = if transition::is_half_resolution(s) { HALF_RESOLUTION[s - 9] } else { s };
                    (2 * ci + s as u32 % 3, 2 * cj + s as u32 / 3)
                };
                let values: [f32; 13] = std::array::from_fn(|s| {
                    let (i, j) = sample(s);
                    self.face[(i + samples * j) as usize]
                });
                let value = |s: usize| values[s];
                let case = transition::case_of(|s| value(s) > frame.iso);
                if case == 0 || case == 511 {
                    continue;
                }
                self.stats.transition_cells += 1;
                let mut count = 0;
                for triangle in transition::triangles(case) {
                    let mut ids = [0u32; 3];
                    for (k, (a, b)) in triangle.into_iter().enumerate() {
                        let (a, b) = (a as usize, b as usize);
                        let level =
                            if transition::is_half_resolution(a) { block.level } else { block.level - 1 };
                        let ((ia, ja), (ib, jb)) = (sample(a), sample(b));
                        let edge_axis = if ia != ib { u_axis } else { v_axis };
                        // From the end nearer the grid's origin, as every edge is interpolated.
                        let (low_end, high_end) = if (ia, ja) <= (ib, jb) { (a, b) } else { (b, a) };
                        let (i, j) = sample(low_end);
                        ids[k] = self.vertex(
                            frame,
                            point(i, j),
                            edge_axis,
                            level,
                            value(low_end),
                            value(high_end),
                        );
                    }
                    if left_handed {
                        ids.swap(1, 2);
                    }
                    self.indices.extend_from_slice(&ids);
                    self.triangle_levels.push(block.level as u8 | TRANSITION);
                    count += 1;
                }
                self.stats.triangles[block.level as usize] += count;
            }
        }
    }

    /// The vertex on the edge of `level` from finest point `start` along `axis`, whose ends read `fa`
    /// and `fb`, made on first use.
    fn vertex(&mut self, frame: &Frame, start: UVec3, axis: usize, level: u32, fa: f32, fb: f32) -> u32 {
        let key = edge_key(start, axis, level);
        let next = self.vertex_count();
        let id = *self.edges.entry(key).or_insert(next);
        if id != next {
            return id;
        }
        let mut end = start;
        end[axis] += 1 << level;
        let grid = frame.grid;
        let (p, normal) = reference::surface_vertex(
            frame.spheres,
            frame.iso,
            frame.construction,
            (grid.point(start), fa, grid.is_boundary(start)),
            (grid.point(end), fb, grid.is_boundary(end)),
        );
        self.vertices.extend_from_slice(&[p.x, p.y, p.z, normal.x, normal.y, normal.z]);
        id
    }
}
