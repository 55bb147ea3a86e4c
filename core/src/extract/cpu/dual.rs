//! The dual methods on the CPU, surface nets and dual contouring. Every cell the surface crosses gets
//! one vertex; every crossed grid edge joins the four cells around it with a quad, split along its
//! shorter diagonal into two triangles: two triangles for each vertex marching cubes would make. One
//! vertex per cell joins the sheets an ambiguous cell keeps apart in marching cubes, so such a vertex
//! can be non-manifold (the shape's measures report it).
//!
//! The two differ only in where a cell's vertex goes:
//! - **Surface nets** ([`SurfaceNetsMesher`]): at the mean of the crossings on its edges. The triangles
//!   are round, but the vertices lie off the surface (they are averages), and sharp edges are cut off.
//! - **Dual contouring** ([`DualContouringMesher`]): at the minimiser of the crossings' quadratic error
//!   function ([`qef`](super::qef)), the point nearest every tangent plane through a crossing, so an
//!   edge or a corner where the surface folds stays sharp. The crossings are found on the field itself
//!   (not the linear interpolation of its samples) and their normals are its analytic gradient: the
//!   Hermite data. Where the minimiser lies more than [`SLACK`] outside its cell, the vertex is the
//!   QEF's minimiser over the cell so widened instead, and each vertex keeps its QEF's rank and
//!   whether its minimiser left the cell ([`Dual::placed`]), for the teaching views.
//!
//! Both read the same field, block bounds and boundary rule as every other extractor. Surface nets'
//! crossings are marching cubes' (`reference::surface_vertex`), so the two differ only in how they
//! join them up; dual contouring's are the field's own ([`hermite`]).

use super::hermite::hermite;
use super::kept::KeptField;
use super::qef;
use crate::extract::field::BLOCK_CELLS;
use crate::extract::mesh::IndexedMesh;
use crate::extract::reference::{self, Construction, Grid};
use crate::extract::tables::{CORNER_OFFSETS, EDGE_CORNERS};
use crate::scene::Sphere;
use glam::Vec3;

/// Marks a cell without a vertex.
const NONE: u32 = u32::MAX;

/// In [`Dual::placed`]: the vertex's QEF minimiser lay outside its cell.
pub const STRAYED: u8 = 4;

/// How far, in cells, a dual-contouring vertex may lie outside its cell. A quarter cell keeps the
/// vertices of cells two apart in order along each axis, so the clamp still bounds how far a
/// vertex can run; and where a crease only clips a corner of a cell, its minimiser lies just outside
/// (up to 0.21 cells on the crease scene of `tests/suite/dual.rs`), where clamping to the cell
/// itself would move the vertex off the crease by up to 0.15 cells.
pub const SLACK: f32 = 0.25;

/// Counts of the last mesh.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DualStats {
    /// Blocks the bounds could not skip.
    pub active_blocks: u32,
    /// Cells the surface crosses: one vertex each.
    pub active_cells: u32,
}

/// Surface nets: each vertex at its crossings' mean.
pub type SurfaceNetsMesher = DualMesher<false>;
/// Dual contouring: each vertex at its crossings' QEF minimiser, within [`SLACK`] of its cell.
pub type DualContouringMesher = DualMesher<true>;

/// A reusable dual mesher of one method (`QEF`: dual contouring, else surface nets). Both methods'
/// code is one ([`Dual`], which it dereferences to), so the page's WebAssembly carries it once.
#[derive(Default)]
pub struct DualMesher<const QEF: bool>(Dual);

impl<const QEF: bool> DualMesher<QEF> {
    /// Meshes the surface f = `iso` of `spheres` on `grid`.
    pub fn mesh(&mut self, spheres: &[Sphere], iso: f32, grid: Grid, construction: Construction) {
        self.0.qef = QEF;
        self.0.mesh(spheres, iso, grid, construction);
    }

    pub fn to_indexed(&self) -> IndexedMesh {
        self.0.to_indexed()
    }

    pub fn triangle_marks(&self) -> Vec<u32> {
        self.0.triangle_marks()
    }

    /// Takes a mesh made by another mesher of its kind as its last one, with what that one counted.
    pub fn install(&mut self, vertices: Vec<f32>, indices: Vec<u32>, counts: [u32; 2], grid: Grid) {
        self.0.install(vertices, indices, counts, grid);
    }
}

impl<const QEF: bool> std::ops::Deref for DualMesher<QEF> {
    type Target = Dual;
    fn deref(&self) -> &Dual {
        &self.0
    }
}

impl<const QEF: bool> std::ops::DerefMut for DualMesher<QEF> {
    fn deref_mut(&mut self) -> &mut Dual {
        &mut self.0
    }
}

/// A reusable dual mesher, filling `vertices` (position then outward normal, 6 `f32` each) and
/// `indices` (three per triangle, counter-clockwise seen from outside) like the marching-cubes
/// mesher.
#[derive(Default)]
pub struct Dual {
    /// Dual contouring, else surface nets.
    qef: bool,
    pub vertices: Vec<f32>,
    pub indices: Vec<u32>,
    /// With dual contouring, the crossings of the crossed grid edges (Hermite data: point, then the
    /// field's outward normal, 6 `f32` each), for the teaching views; empty with surface nets.
    pub crossings: Vec<f32>,
    /// With dual contouring, each vertex's QEF rank (1 a face, 2 an edge, 3 a corner), plus
    /// [`STRAYED`] where its solution left its cell; empty with surface nets.
    pub placed: Vec<u8>,
    stats: DualStats,
    field: KeptField,
    /// The vertex of each cell, `NONE` where the surface does not cross it.
    cell_vertex: Vec<u32>,
    /// The crossed cells, in the order their vertices were made.
    crossed: Vec<[u32; 3]>,
    /// The crossings (point, normal) on the edges of the block being placed ([`local`]).
    near: Vec<(Vec3, Vec3)>,
}

impl Dual {
    pub fn stats(&self) -> DualStats {
        self.stats
    }

    pub fn vertex_count(&self) -> u32 {
        (self.vertices.len() / 6) as u32
    }

    /// With dual contouring, one word per triangle: [`Dual::placed`] of its three corners, three
    /// bits each, first corner lowest (what `color-by=rank` reads); empty with surface nets.
    pub fn triangle_marks(&self) -> Vec<u32> {
        if self.placed.is_empty() {
            return Vec::new();
        }
        let mark = |i: &u32| self.placed[*i as usize] as u32;
        self.indices.chunks_exact(3).map(|t| mark(&t[0]) | mark(&t[1]) << 3 | mark(&t[2]) << 6).collect()
    }

    pub fn to_indexed(&self) -> IndexedMesh {
        IndexedMesh::from_interleaved(&self.vertices, &self.indices)
    }

    /// Takes a mesh made by another mesher of its kind as its last one, with what that one counted.
    pub fn install(&mut self, vertices: Vec<f32>, indices: Vec<u32>, counts: [u32; 2], _grid: Grid) {
        let [active_blocks, active_cells] = counts;
        self.vertices = vertices;
        self.indices = indices;
        self.placed.clear();
        self.crossings.clear();
        self.stats = DualStats { active_blocks, active_cells };
    }

    /// Meshes the surface f = `iso` of `spheres` on `grid`.
    fn mesh(&mut self, spheres: &[Sphere], iso: f32, grid: Grid, construction: Construction) {
        let n = grid.cells_per_axis;
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
        self.vertices.clear();
        self.indices.clear();
        self.placed.clear();
        self.crossings.clear();
        self.field.sample(spheres, iso, n, construction.terms);
        self.stats.active_blocks = self.field.kept.len() as u32;
        let kept = std::mem::take(&mut self.field.kept);
        for &block in &kept {
            self.place_vertices(spheres, block, iso, grid, construction);
        }
        self.field.kept = kept;
        self.stats.active_cells = self.crossed.len() as u32;
        for k in 0..self.crossed.len() {
            self.join(self.crossed[k], iso, n);
        }
    }

    fn value(&self, p: [u32; 3], n: u32) -> f32 {
        self.field.value(p, n)
    }

    /// One vertex in each crossed cell of a kept block, from the crossings on its edges: at their
    /// mean, or at their QEF's minimiser within [`SLACK`] of the cell; with the normalised mean of their
    /// normals.
    fn place_vertices(
        &mut self,
        spheres: &[Sphere],
        [bx, by, bz]: [u32; 3],
        iso: f32,
        grid: Grid,
        construction: Construction,
    ) {
        let (n, cell) = (grid.cells_per_axis, grid.cell_size());
        let origin = [bx, by, bz].map(|b| b * BLOCK_CELLS);
        self.find_crossings(spheres, origin, iso, n, construction);
        let end = |b: u32| ((b + 1) * BLOCK_CELLS).min(n);
        let mut crossings = [(Vec3::ZERO, Vec3::ZERO); 12];
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
                    let mut count = 0;
                    for [a, b] in EDGE_CORNERS {
                        if inside[a] != inside[b] {
                            // The edge leaves corner a (the one nearer the grid's origin) along one axis.
                            let (from, to) = (CORNER_OFFSETS[a], CORNER_OFFSETS[b]);
                            let axis = (0..3).find(|&i| from[i] != to[i]).unwrap_or(0);
                            let at = std::array::from_fn(|i| [x, y, z][i] + from[i] - origin[i]);
                            crossings[count] = self.near[local(at, axis)];
                            count += 1;
                        }
                    }
                    let crossings = &crossings[..count];
                    let normal =
                        crossings.iter().map(|c| c.1).sum::<Vec3>().try_normalize().unwrap_or(Vec3::Z);
                    let p = if self.qef {
                        let low = Vec3::from_array([x, y, z].map(|i| self.field.coords[i as usize]));
                        let high = Vec3::from_array([x, y, z].map(|i| self.field.coords[i as usize + 1]));
                        let qef = qef::Qef::new(crossings);
                        let qef::Solved { point: p, rank, strayed } = qef.solve_in(low, high, SLACK * cell);
                        self.placed.push(rank | if strayed { STRAYED } else { 0 });
                        p
                    } else {
                        crossings.iter().map(|c| c.0).sum::<Vec3>() / count as f32
                    };
                    self.cell_vertex[index([x, y, z], n)] = self.vertex_count();
                    self.vertices.extend_from_slice(&[p.x, p.y, p.z, normal.x, normal.y, normal.z]);
                    self.crossed.push([x, y, z]);
                }
            }
        }
    }

    /// The crossings of the crossed edges leaving each grid point of the block at `origin` and of the
    /// layer of points past its far faces, into `near` (each edge by its lower point and axis): every
    /// edge of the block's cells, each found once (`hermite` with dual contouring, else
    /// `surface_vertex`). Those whose lower point is one of the block's cells' are the block's own,
    /// kept in `crossings` for the views with dual contouring.
    fn find_crossings(&mut self, spheres: &[Sphere], origin: [u32; 3], iso: f32, n: u32, c: Construction) {
        let span = BLOCK_CELLS + 1;
        self.near.clear();
        self.near.resize((3 * span * span * span) as usize, (Vec3::ZERO, Vec3::ZERO));
        for lz in 0..span {
            for ly in 0..span {
                for lx in 0..span {
                    let p = [origin[0] + lx, origin[1] + ly, origin[2] + lz];
                    if p.iter().any(|&i| i >= n) {
                        // On or past the far walls: every edge from here runs along a wall (outside).
                        continue;
                    }
                    for axis in 0..3 {
                        if [lx, ly, lz][axis] == BLOCK_CELLS {
                            // Leaves the block through its far face: no cell of the block has it.
                            continue;
                        }
                        let mut q = p;
                        q[axis] += 1;
                        if (self.value(p, n) > iso) == (self.value(q, n) > iso) {
                            continue;
                        }
                        let end = |p: [u32; 3]| {
                            let on_wall = p.contains(&0) || p.contains(&n);
                            (
                                Vec3::from_array(p.map(|i| self.field.coords[i as usize])),
                                self.value(p, n),
                                on_wall,
                            )
                        };
                        let crossing = if self.qef {
                            hermite(spheres, iso, c, end(p), end(q))
                        } else {
                            reference::surface_vertex(spheres, iso, c, end(p), end(q))
                        };
                        self.near[local([lx, ly, lz], axis)] = crossing;
                        if self.qef && lx < BLOCK_CELLS && ly < BLOCK_CELLS && lz < BLOCK_CELLS {
                            let (p, normal) = crossing;
                            self.crossings.extend_from_slice(&[p.x, p.y, p.z, normal.x, normal.y, normal.z]);
                        }
                    }
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

/// The place in `Dual::near` of the edge leaving the block's point `[x, y, z]` (from its origin, 0 to
/// `BLOCK_CELLS`) along `axis`.
fn local([x, y, z]: [u32; 3], axis: usize) -> usize {
    let span = BLOCK_CELLS + 1;
    3 * (x + span * (y + span * z)) as usize + axis
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

    #[test]
    fn dual_contouring_keeps_each_vertex_within_a_quarter_cell_of_its_cell() {
        // Spheres of both signs, close enough to fold the surface where they meet.
        let spheres = [
            Sphere::from_signed(Vec3::new(-0.2, 0.05, 0.0), 0.45, Vec3::ZERO),
            Sphere::from_signed(Vec3::new(0.25, -0.1, 0.1), 0.4, Vec3::ZERO),
            Sphere::from_signed(Vec3::new(0.0, 0.3, 0.1), -0.2, Vec3::ZERO),
        ];
        let grid = Grid { cells_per_axis: 20 };
        for terms in crate::extract::kernel::Terms::every() {
            let mut mesher = DualContouringMesher::default();
            mesher.mesh(&spheres, 1.0, grid, Construction { terms, ..Construction::default() });
            assert_eq!(mesher.placed.len(), mesher.crossed.len());
            let cell = grid.cell_size();
            for (k, c) in mesher.crossed.iter().enumerate() {
                let p = Vec3::from_slice(&mesher.vertices[6 * k..6 * k + 3]);
                let low = Vec3::from_array(c.map(|i| mesher.field.coords[i as usize]));
                let out = (low - p).max(p - low - cell).max_element() / cell;
                assert!(out <= SLACK + 1e-4, "{terms:?}: vertex {k} {out} cells out of its cell");
                assert!((1..=3).contains(&(mesher.placed[k] & 3)));
            }
            assert!(mesher.to_indexed().shape().closed);
        }
    }
}
