//! Marching tetrahedra on the CPU: the kept blocks' crossed cells, each cut into tetrahedra
//! ([`tetra`](crate::extract::tetra)), each vertex made once, on first use, and found again through
//! its segment (its lowest point and slot), in the vertex and index layout every CPU mesher fills.
//! It yields the oracle's triangles (`tetra::extract_tetrahedra`) exactly.

use super::dual::DualStats;
use super::kept::KeptField;
use crate::extract::mesh::IndexedMesh;
use crate::extract::reference::{Construction, Grid, surface_vertex};
use crate::extract::tables::CORNER_OFFSETS;
use crate::extract::tetra::{
    SLOTS, TETRAHEDRON_TRIANGLE_COUNTS, TETRAHEDRON_TRIANGLES, segment_slot, tetrahedra,
};
use crate::scene::Sphere;
use glam::Vec3;
use rustc_hash::FxHashMap;

/// A reusable marching-tetrahedra mesher, filling `vertices` (position then outward normal, 6 `f32`
/// each) and `indices` (three per triangle, counter-clockwise seen from outside).
#[derive(Default)]
pub struct TetraMesher {
    pub vertices: Vec<f32>,
    pub indices: Vec<u32>,
    stats: DualStats,
    field: KeptField,
    /// The vertex on each segment used so far, by `point index · SLOTS + slot`.
    segments: FxHashMap<u64, u32>,
}

impl TetraMesher {
    /// Blocks the bounds kept, and cells the surface crosses, in the last mesh.
    pub fn stats(&self) -> DualStats {
        self.stats
    }

    pub fn to_indexed(&self) -> IndexedMesh {
        IndexedMesh::from_interleaved(&self.vertices, &self.indices)
    }

    /// Takes a mesh made by another mesher of its kind as its last one, with what that one counted.
    pub fn install(&mut self, vertices: Vec<f32>, indices: Vec<u32>, counts: [u32; 2], _grid: Grid) {
        self.vertices = vertices;
        self.indices = indices;
        let [active_blocks, active_cells] = counts;
        self.stats = DualStats { active_blocks, active_cells };
    }

    /// Meshes the surface f = `iso` of `spheres` on `grid`, each cell cut by `construction.split` (the
    /// whole surface: the step-through of the march walks marching cubes alone).
    pub fn mesh(&mut self, spheres: &[Sphere], iso: f32, grid: Grid, construction: Construction) {
        let n = grid.cells_per_axis;
        self.vertices.clear();
        self.indices.clear();
        self.segments.clear();
        self.field.sample(spheres, iso, n, construction.terms);
        let mut crossed = 0;
        let kept = std::mem::take(&mut self.field.kept);
        for &block in &kept {
            for cell in KeptField::cells(block, n) {
                let corner = |c: usize| {
                    let o = CORNER_OFFSETS[c];
                    [cell[0] + o[0], cell[1] + o[1], cell[2] + o[2]]
                };
                let values: [f32; 8] = std::array::from_fn(|c| self.field.value(corner(c), n));
                let inside = values.map(|v| v > iso);
                if inside.iter().all(|&i| i) || !inside.iter().any(|&i| i) {
                    continue;
                }
                crossed += 1;
                for t in tetrahedra(construction.split, cell) {
                    let case = (0..4).fold(0, |m, i| m | (inside[t[i]] as usize) << i);
                    for triangle in &TETRAHEDRON_TRIANGLES[case][..TETRAHEDRON_TRIANGLE_COUNTS[case]] {
                        for &[i, j] in triangle {
                            let field = (spheres, iso, grid, construction);
                            let vertex = self.vertex(field, cell, [t[i], t[j]], &values);
                            self.indices.push(vertex);
                        }
                    }
                }
            }
        }
        self.stats = DualStats { active_blocks: kept.len() as u32, active_cells: crossed };
        self.field.kept = kept;
    }

    /// The vertex on the segment between corners `ends` of `cell`, made on first use.
    fn vertex(
        &mut self,
        (spheres, iso, grid, construction): (&[Sphere], f32, Grid, Construction),
        cell: [u32; 3],
        [a, b]: [usize; 2],
        values: &[f32; 8],
    ) -> u32 {
        let (low, slot) = segment_slot(a, b);
        let n = grid.cells_per_axis;
        let point = |o: [u32; 3]| [cell[0] + o[0], cell[1] + o[1], cell[2] + o[2]];
        let index = |p: [u32; 3]| p[0] as u64 + (n as u64 + 1) * (p[1] as u64 + (n as u64 + 1) * p[2] as u64);
        let key = index(point(low)) * SLOTS as u64 + slot as u64;
        let next = (self.vertices.len() / 6) as u32;
        let made = *self.segments.entry(key).or_insert(next);
        if made == next {
            // From the end first in grid order, as the oracle and the GPU interpolate it.
            let (a, b) = if index(point(CORNER_OFFSETS[a])) < index(point(CORNER_OFFSETS[b])) {
                (a, b)
            } else {
                (b, a)
            };
            let end = |c: usize| {
                let p = point(CORNER_OFFSETS[c]);
                let on_wall = p.contains(&0) || p.contains(&n);
                (Vec3::from_array(p.map(|i| self.field.coords[i as usize])), values[c], on_wall)
            };
            let (p, normal) = surface_vertex(spheres, iso, construction, end(a), end(b));
            self.vertices.extend_from_slice(&[p.x, p.y, p.z, normal.x, normal.y, normal.z]);
        }
        made
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::extract::tetra::extract_tetrahedra;
    use crate::scene::Scene;
    use crate::scene::params::view::Split;

    #[test]
    fn matches_the_oracle_exactly_under_either_split() {
        for split in [Split::Six, Split::Five] {
            for (seed, count, n) in [(1, 1, 8), (2, 5, 13), (3, 16, 32)] {
                let scene = Scene::new(seed, count).unwrap();
                let construction = Construction { split, ..Construction::default() };
                let grid = Grid { cells_per_axis: n };
                let mut mesher = TetraMesher::default();
                mesher.mesh(scene.spheres(), 1.0, grid, construction);
                let oracle = extract_tetrahedra(scene.spheres(), 1.0, grid, construction);
                let ours = mesher.to_indexed().to_soup();
                ours.matches(&oracle, 0.0, 1e-6).unwrap_or_else(|e| panic!("{split:?}, {n} cells: {e}"));
                let shape = mesher.to_indexed().to_soup().weld_by_position().shape();
                assert!(shape.closed && shape.manifold, "{split:?}, {n} cells: {shape:?}");
            }
        }
    }
}
