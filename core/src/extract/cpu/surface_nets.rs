//! Surface nets on the CPU: the dual of marching cubes. Every cell the surface crosses gets one vertex,
//! at the mean of the crossings on its edges; every crossed grid edge joins the four cells around it
//! with a quad, split along its shorter diagonal into two triangles: two triangles for each vertex
//! marching cubes would make. The triangles are rounder, but the vertices lie off the surface (they
//! are averages, not crossings), and one vertex per cell joins the sheets an ambiguous cell keeps
//! apart in marching cubes.
//!
//! It reads the same field, block bounds, boundary rule and edge placement as every other extractor
//! (the crossings come from `reference::surface_vertex`), so the two meshes differ only in how they
//! join the crossings up.

use crate::extract::field::{BLOCK_CELLS, Spheres, sample_run};
use crate::extract::mesh::IndexedMesh;
use crate::extract::reference::{self, Construction, Grid};
use crate::extract::tables::{CORNER_OFFSETS, EDGE_CORNERS};
use crate::scene::{BOX_HALF_EXTENT, Sphere};
use glam::Vec3;

/// Marks a cell without a vertex.
const NONE: u32 = u32::MAX;

/// Counts of the last mesh.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SurfaceNetsStats {
    /// Blocks the bounds could not skip.
    pub active_blocks: u32,
    /// Cells the surface crosses: one vertex each.
    pub active_cells: u32,
}

/// A reusable surface-nets mesher, filling `vertices` (position then outward normal, 6 `f32` each) and
/// `indices` (three per triangle, counter-clockwise seen from outside) like the marching-cubes mesher.
#[derive(Default)]
pub struct SurfaceNetsMesher {
    pub vertices: Vec<f32>,
    pub indices: Vec<u32>,
    stats: SurfaceNetsStats,
    spheres: Spheres,
    coords: Vec<f32>,
    /// Field values at every grid point of a kept block (others are never read).
    values: Vec<f32>,
    /// The vertex of each cell, `NONE` where the surface does not cross it.
    cell_vertex: Vec<u32>,
    /// The crossed cells, in the order their vertices were made.
    crossed: Vec<[u32; 3]>,
    kept: Vec<[u32; 3]>,
}

impl SurfaceNetsMesher {
    pub fn stats(&self) -> SurfaceNetsStats {
        self.stats
    }

    pub fn vertex_count(&self) -> u32 {
        (self.vertices.len() / 6) as u32
    }

    pub fn to_indexed(&self) -> IndexedMesh {
        IndexedMesh::from_interleaved(&self.vertices, &self.indices)
    }

    /// Takes a mesh made by another mesher of its kind as its last one, with what that one counted.
    pub fn install(&mut self, vertices: Vec<f32>, indices: Vec<u32>, counts: [u32; 2], _grid: Grid) {
        let [active_blocks, active_cells] = counts;
        self.vertices = vertices;
        self.indices = indices;
        self.stats = SurfaceNetsStats { active_blocks, active_cells };
    }

    /// Meshes the surface f = `iso` of `spheres` on `grid`.
    pub fn mesh(&mut self, spheres: &[Sphere], iso: f32, grid: Grid, construction: Construction) {
        let n = grid.cells_per_axis;
        let cell = grid.cell_size();
        self.spheres.set(spheres);
        self.coords.clear();
        self.coords.extend((0..=n).map(|i| -BOX_HALF_EXTENT + i as f32 * cell));
        // Forget last frame's vertices where the grid is the same size; start afresh otherwise.
        let cells = (n as usize).pow(3);
        if self.cell_vertex.len() == cells {
            for c in self.crossed.drain(..) {
                self.cell_vertex[index(c, n)] = NONE;
            }
        } else {
            self.cell_vertex.clear();
            self.cell_vertex.resize(cells, NONE);
            self.crossed.clear();
        }
        self.values.resize((n as usize + 1).pow(3), 0.0);
        self.vertices.clear();
        self.indices.clear();
        self.keep_blocks(iso, n, construction);
        let kept = std::mem::take(&mut self.kept);
        for &block in &kept {
            self.sample_block(block, n, construction);
        }
        for &block in &kept {
            self.place_vertices(spheres, block, iso, grid, construction);
        }
        self.kept = kept;
        self.stats.active_cells = self.crossed.len() as u32;
        for k in 0..self.crossed.len() {
            self.join(self.crossed[k], iso, n);
        }
    }

    /// The blocks whose field bounds straddle `iso`, as every extractor keeps them.
    fn keep_blocks(&mut self, iso: f32, n: u32, construction: Construction) {
        let nb = n.div_ceil(BLOCK_CELLS);
        let by_max = construction.blend == crate::scene::params::view::Blend::Max;
        self.kept.clear();
        for bz in 0..nb {
            for by in 0..nb {
                for bx in 0..nb {
                    if self.spheres.block_straddles(&self.coords, [bx, by, bz], n, iso, by_max) {
                        self.kept.push([bx, by, bz]);
                    }
                }
            }
        }
        self.stats.active_blocks = self.kept.len() as u32;
    }

    /// Field values at a kept block's points, in rows along x (points on the box's faces read 0).
    fn sample_block(&mut self, [bx, by, bz]: [u32; 3], n: u32, construction: Construction) {
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
                sample_run(run, &self.coords[x0..=x1], py, pz, &self.spheres, construction.blend);
                if x0 == 0 {
                    run[0] = 0.0;
                }
                if x1 == n as usize {
                    run[x1 - x0] = 0.0;
                }
            }
        }
    }

    fn value(&self, p: [u32; 3], n: u32) -> f32 {
        let width = n as usize + 1;
        self.values[p[0] as usize + width * (p[1] as usize + width * p[2] as usize)]
    }

    /// One vertex in each crossed cell of a kept block: the mean of its edges' crossings, with the
    /// normalised mean of their normals.
    fn place_vertices(
        &mut self,
        spheres: &[Sphere],
        [bx, by, bz]: [u32; 3],
        iso: f32,
        grid: Grid,
        construction: Construction,
    ) {
        let n = grid.cells_per_axis;
        let end = |b: u32| ((b + 1) * BLOCK_CELLS).min(n);
        for z in bz * BLOCK_CELLS..end(bz) {
            for y in by * BLOCK_CELLS..end(by) {
                for x in bx * BLOCK_CELLS..end(bx) {
                    let corner = |c: usize| {
                        let o = CORNER_OFFSETS[c];
                        [x + o[0], y + o[1], z + o[2]]
                    };
                    let inside: [bool; 8] = std::array::from_fn(|c| self.value(corner(c), n) > iso);
                    if inside.iter().all(|&i| i) || !inside.iter().any(|&i| i) {
                        continue;
                    }
                    let (mut sum, mut normals, mut count) = (Vec3::ZERO, Vec3::ZERO, 0.0);
                    for [a, b] in EDGE_CORNERS {
                        if inside[a] == inside[b] {
                            continue;
                        }
                        let end = |c: usize| {
                            let p = corner(c);
                            let on_wall = p.contains(&0) || p.contains(&n);
                            (Vec3::from_array(p.map(|i| self.coords[i as usize])), self.value(p, n), on_wall)
                        };
                        let (p, normal) =
                            reference::surface_vertex(spheres, iso, construction, end(a), end(b));
                        sum += p;
                        normals += normal;
                        count += 1.0;
                    }
                    let p = sum / count;
                    let normal = normals.try_normalize().unwrap_or(Vec3::Z);
                    self.cell_vertex[index([x, y, z], n)] = self.vertex_count();
                    self.vertices.extend_from_slice(&[p.x, p.y, p.z, normal.x, normal.y, normal.z]);
                    self.crossed.push([x, y, z]);
                }
            }
        }
    }

    /// The quads of the crossed edges leaving `cell`'s lowest corner along each axis. Every crossed
    /// edge is reached once this way: from the cell with the largest coordinates of the four around it.
    fn join(&mut self, cell: [u32; 3], iso: f32, n: u32) {
        for axis in 0..3 {
            let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
            if cell[u] == 0 || cell[v] == 0 {
                continue;
            }
            let mut far = cell;
            far[axis] += 1;
            let inside = self.value(cell, n) > iso;
            if inside == (self.value(far, n) > iso) {
                continue;
            }
            // The four cells around the edge, counter-clockwise seen from +axis.
            let around = [(1, 1), (0, 1), (0, 0), (1, 0)].map(|(du, dv)| {
                let mut c = cell;
                c[u] -= du;
                c[v] -= dv;
                self.cell_vertex[index(c, n)]
            });
            if around.contains(&NONE) {
                continue;
            }
            // Outward is +axis when the edge's near end is inside.
            let [a, b, c, d] = if inside { around } else { [around[3], around[2], around[1], around[0]] };
            let at = |i: u32| Vec3::from_slice(&self.vertices[6 * i as usize..6 * i as usize + 3]);
            let quad = if at(a).distance_squared(at(c)) <= at(b).distance_squared(at(d)) {
                [a, b, c, a, c, d]
            } else {
                [a, b, d, b, c, d]
            };
            self.indices.extend_from_slice(&quad);
        }
    }
}

fn index([x, y, z]: [u32; 3], n: u32) -> usize {
    x as usize + n as usize * (y as usize + n as usize * z as usize)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_sphere_makes_one_closed_ball_near_its_radius() {
        let sphere = Sphere::from_signed(Vec3::new(0.05, -0.02, 0.01), 0.5, Vec3::ZERO);
        let mut mesher = SurfaceNetsMesher::default();
        mesher.mesh(&[sphere], 1.0, Grid { cells_per_axis: 24 }, Construction::default());
        let mesh = mesher.to_indexed();
        let shape = mesh.shape();
        assert_eq!((shape.components, shape.genus, shape.closed), (1, 0, true), "{shape:?}");
        for (p, n) in mesh.positions.iter().zip(&mesh.normals) {
            let r = (*p - sphere.center).length();
            assert!((r - 0.5).abs() < 0.02, "a vertex {r} from the centre");
            assert!(n.dot((*p - sphere.center).normalize()) > 0.99, "normal {n}");
        }
        let volume = mesh.enclosed_volume() as f32;
        let exact = 4.0 / 3.0 * std::f32::consts::PI * 0.125;
        assert!((volume / exact - 1.0).abs() < 0.03, "{volume} against {exact}");
    }
}
