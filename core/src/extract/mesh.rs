//! Triangle meshes as the passes emit them, and the properties the tests hold them to: equality with a
//! tolerance, welding, closedness and topology.

use glam::Vec3;
use std::collections::HashMap;

/// Where a mesh is seen from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Viewpoint {
    /// A perspective camera's eye.
    At(Vec3),
    /// An orthographic camera looking along this direction.
    Along(Vec3),
}

/// A triangle soup: vertices `3k`, `3k+1`, `3k+2` form triangle `k`, counter-clockwise seen from outside.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    pub positions: Vec<Vec3>,
    /// Unit normals pointing out of the surface.
    pub normals: Vec<Vec3>,
    /// For meshes from the CPU oracle, the grid edge each vertex lies on; empty otherwise.
    pub edge_ids: Vec<u64>,
}

/// A welded mesh: shared vertices and triangles indexing them.
#[derive(Clone, Debug, Default)]
pub struct IndexedMesh {
    pub positions: Vec<Vec3>,
    /// Unit normals pointing out of the surface, one per vertex.
    pub normals: Vec<Vec3>,
    pub triangles: Vec<[u32; 3]>,
}

/// Counts of an indexed mesh's parts that make up its topology.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Topology {
    /// Edges used by a number of triangles other than two (0 for a closed 2-manifold).
    pub open_or_nonmanifold_edges: usize,
    /// Edges used by one triangle only: the rims of holes in the surface (0 for a closed surface).
    pub open_edges: usize,
    /// Edges used twice in the same direction (0 for a consistently oriented surface).
    pub misoriented_edges: usize,
    /// Euler characteristic V − E + F of each connected component, sorted.
    pub component_euler: Vec<i64>,
    /// Each component's Euler characteristic and vertex count, sorted.
    pub components: Vec<(i64, i64)>,
}

/// What a person asks of a surface's shape: how many separate blobs, how many holes through them, and
/// whether it is a closed, well-formed surface.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ShapeSummary {
    /// Connected pieces with at least one triangle.
    pub components: u32,
    /// Handles (holes through the surface) summed over the closed components: (2 − χ) / 2 each.
    pub genus: u32,
    /// No edge lies on one triangle only.
    pub closed: bool,
    /// Every edge lies on exactly two triangles, wound in opposite directions.
    pub manifold: bool,
}

impl Mesh {
    /// Triangles in the soup.
    pub fn triangle_count(&self) -> usize {
        self.positions.len() / 3
    }

    /// Triangle `k`'s vertex positions.
    pub fn triangle(&self, k: usize) -> [Vec3; 3] {
        [self.positions[3 * k], self.positions[3 * k + 1], self.positions[3 * k + 2]]
    }

    /// Joins vertices with bit-identical positions (vertices on one grid edge are computed identically
    /// by both cells that share it).
    pub fn weld_by_position(&self) -> IndexedMesh {
        self.weld(|i| self.positions[i].to_array().map(f32::to_bits))
    }

    /// Joins vertices lying on the same grid edge (oracle meshes only).
    pub fn weld_by_edge(&self) -> IndexedMesh {
        assert_eq!(self.edge_ids.len(), self.positions.len(), "weld_by_edge needs edge ids");
        self.weld(|i| self.edge_ids[i])
    }

    fn weld<K: std::hash::Hash + Eq>(&self, key: impl Fn(usize) -> K) -> IndexedMesh {
        let mut index: HashMap<K, u32> = HashMap::new();
        let mut out = IndexedMesh::default();
        let mut ids = Vec::with_capacity(self.positions.len());
        for i in 0..self.positions.len() {
            let id = *index.entry(key(i)).or_insert_with(|| {
                out.positions.push(self.positions[i]);
                out.normals.push(self.normals[i]);
                out.positions.len() as u32 - 1
            });
            ids.push(id);
        }
        out.triangles = ids.chunks(3).map(|t| [t[0], t[1], t[2]]).collect();
        out
    }

    /// Checks that the two meshes have the same triangles: equal counts, and `contained_in` holds.
    pub fn matches(&self, other: &Mesh, tolerance: f32, normal_tolerance: f32) -> Result<(), String> {
        if self.triangle_count() != other.triangle_count() {
            return Err(format!(
                "triangle counts differ: {} against {}",
                self.triangle_count(),
                other.triangle_count()
            ));
        }
        self.contained_in(other, tolerance, normal_tolerance)
    }

    /// Checks that every triangle of `self` has its own counterpart in `other` whose vertices, in the
    /// same cyclic order, lie within `tolerance` with normals within `normal_tolerance` radians.
    /// Returns a description of the first triangle without one.
    pub fn contained_in(&self, other: &Mesh, tolerance: f32, normal_tolerance: f32) -> Result<(), String> {
        // Bucket the other mesh's triangles by centroid on a lattice coarser than the tolerance, then
        // look for a match in the 27 buckets around each centroid.
        let bucket_size = (tolerance * 4.0).max(1e-6);
        let bucket = |c: Vec3| (c / bucket_size).floor().as_ivec3();
        let mut buckets: HashMap<glam::IVec3, Vec<usize>> = HashMap::new();
        for k in 0..other.triangle_count() {
            let t = other.triangle(k);
            buckets.entry(bucket((t[0] + t[1] + t[2]) / 3.0)).or_default().push(k);
        }
        let mut used = vec![false; other.triangle_count()];
        for k in 0..self.triangle_count() {
            let t = self.triangle(k);
            let home = bucket((t[0] + t[1] + t[2]) / 3.0);
            let close = |j: usize, r: usize| {
                (0..3).all(|i| {
                    let (a, b) = (3 * k + i, 3 * j + (r + i) % 3);
                    self.positions[a].distance(other.positions[b]) <= tolerance
                        && angle(self.normals[a], other.normals[b]) <= normal_tolerance
                })
            };
            let found = (-1..=1)
                .flat_map(|x| (-1..=1).flat_map(move |y| (-1..=1).map(move |z| glam::IVec3::new(x, y, z))))
                .filter_map(|off| buckets.get(&(home + off)))
                .flatten()
                .copied()
                .find(|&j| !used[j] && (0..3).any(|r| close(j, r)));
            match found {
                Some(j) => used[j] = true,
                None => {
                    let n = [0, 1, 2].map(|i| self.normals[3 * k + i]);
                    return Err(format!(
                        "triangle {k} at {t:?} with normals {n:?} has no counterpart within {tolerance} \
                         (normals within {normal_tolerance} rad)"
                    ));
                }
            }
        }
        Ok(())
    }
}

/// The angle between two directions, to the last bits of a small one (the arc cosine of their dot
/// product is blind below about 3 × 10⁻⁴ radians in `f32`: one unit in the last place of the dot
/// product near 1 is that angle).
fn angle(a: Vec3, b: Vec3) -> f32 {
    a.cross(b).length().atan2(a.dot(b))
}

impl IndexedMesh {
    /// The same triangles as a soup.
    pub fn to_soup(&self) -> Mesh {
        let corners = self.triangles.iter().flatten().map(|&i| i as usize);
        Mesh {
            positions: corners.clone().map(|i| self.positions[i]).collect(),
            normals: corners.map(|i| self.normals[i]).collect(),
            edge_ids: Vec::new(),
        }
    }

    /// A mesh from interleaved vertices (position then normal, 6 `f32` each) and three indices per
    /// triangle, as the CPU meshers and the buffers hold them.
    pub fn from_interleaved(vertices: &[f32], indices: &[u32]) -> Self {
        let at = |v: &[f32]| Vec3::new(v[0], v[1], v[2]);
        IndexedMesh {
            positions: vertices.chunks_exact(6).map(at).collect(),
            normals: vertices.chunks_exact(6).map(|v| at(&v[3..])).collect(),
            triangles: indices.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect(),
        }
    }

    /// The volume the mesh encloses (divergence theorem over its triangles; positive when they are
    /// wound counter-clockwise seen from outside).
    pub fn enclosed_volume(&self) -> f64 {
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| self.positions[i as usize].as_dvec3());
                a.dot(b.cross(c)) / 6.0
            })
            .sum()
    }

    /// Components, genus, closed and manifold, from `topology`.
    pub fn shape(&self) -> ShapeSummary {
        shape_of(self.positions.len(), &self.triangles)
    }

    /// Edge use, orientation and per-component Euler characteristic.
    pub fn topology(&self) -> Topology {
        topology_of(self.positions.len(), &self.triangles)
    }
}

/// Components, genus, closed and manifold of `triangles` over `vertex_count` vertices, from
/// `topology_of`.
pub fn shape_of(vertex_count: usize, triangles: &[[u32; 3]]) -> ShapeSummary {
    let t = topology_of(vertex_count, triangles);
    let closed = t.open_edges == 0;
    let manifold = t.open_or_nonmanifold_edges == 0 && t.misoriented_edges == 0;
    // A component of one vertex and no triangle is a vertex no triangle uses: not a blob.
    let blobs: Vec<i64> = t.components.iter().filter(|c| c.1 > 1).map(|c| c.0).collect();
    let genus = if closed { blobs.iter().map(|&euler| ((2 - euler) / 2).max(0) as u32).sum() } else { 0 };
    ShapeSummary { components: blobs.len() as u32, genus, closed, manifold }
}

/// Edge use, orientation and per-component Euler characteristic of `triangles` over `vertex_count`
/// vertices. Edges are counted by sorting them as numbers (`from << 32 | to`), not by hashing: the
/// figure asks for this every second while its statistics show, on meshes of hundreds of thousands of
/// triangles.
pub fn topology_of(vertex_count: usize, triangles: &[[u32; 3]]) -> Topology {
    let edge = |a: u32, b: u32| (a as u64) << 32 | b as u64;
    let mut directed: Vec<u64> =
        triangles.iter().flat_map(|t| (0..3).map(move |k| edge(t[k], t[(k + 1) % 3]))).collect();
    directed.sort_unstable();
    let misoriented_edges = directed.chunk_by(|a, b| a == b).filter(|run| run.len() > 1).count();
    let mut undirected: Vec<u64> = directed
        .iter()
        .map(|&e| {
            let (a, b) = ((e >> 32) as u32, e as u32);
            edge(a.min(b), a.max(b))
        })
        .collect();
    undirected.sort_unstable();
    let undirected: Vec<(u32, usize)> =
        undirected.chunk_by(|a, b| a == b).map(|run| ((run[0] >> 32) as u32, run.len())).collect();
    let open_or_nonmanifold_edges = undirected.iter().filter(|&&(_, n)| n != 2).count();
    let open_edges = undirected.iter().filter(|&&(_, n)| n == 1).count();

    // Components by union-find over vertices joined by triangles.
    let mut parent: Vec<u32> = (0..vertex_count as u32).collect();
    fn find(parent: &mut [u32], mut x: u32) -> u32 {
        while parent[x as usize] != x {
            parent[x as usize] = parent[parent[x as usize] as usize];
            x = parent[x as usize];
        }
        x
    }
    for t in triangles {
        for k in 1..3 {
            let (a, b) = (find(&mut parent, t[0]), find(&mut parent, t[k]));
            parent[a as usize] = b;
        }
    }
    // Vertices, edges and faces of each component, at its root.
    let mut per_root = vec![(0i64, 0i64, 0i64); vertex_count];
    for v in 0..vertex_count as u32 {
        per_root[find(&mut parent, v) as usize].0 += 1;
    }
    for &(a, _) in &undirected {
        per_root[find(&mut parent, a) as usize].1 += 1;
    }
    for t in triangles {
        per_root[find(&mut parent, t[0]) as usize].2 += 1;
    }
    // Each component's (Euler characteristic, vertices), in order, sorted as numbers like the edges:
    // χ (offset into u32; |χ| ≤ 3 × triangles) above, the vertex count (< 2³², the indices are u32)
    // below.
    let per_component = per_root.into_iter().filter(|c| c.0 > 0);
    let key = |(v, e, f): (i64, i64, i64)| (((v - e + f) as i32 as u32 ^ 1 << 31) as u64) << 32 | v as u64;
    let mut keys: Vec<u64> = per_component.map(key).collect();
    keys.sort_unstable();
    let components: Vec<(i64, i64)> =
        keys.iter().map(|&k| (((k >> 32) as u32 ^ 1 << 31) as i32 as i64, (k as u32) as i64)).collect();
    let component_euler = components.iter().map(|c| c.0).collect();
    Topology { open_or_nonmanifold_edges, open_edges, misoriented_edges, component_euler, components }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn components_are_counted_and_sorted_whatever_the_sign_of_their_euler_characteristic() {
        // The Fano plane's seven lines as triangles: 7 vertices, 21 edges (each used once), 7 faces,
        // so χ = −7; then a lone triangle (χ = 1, 3 vertices) and a vertex no triangle uses (χ = 1).
        let mut triangles = vec![[0, 1, 2], [0, 3, 4], [0, 5, 6], [1, 3, 5], [1, 4, 6], [2, 3, 6], [2, 4, 5]];
        triangles.push([7, 8, 9]);
        let topology = topology_of(11, &triangles);
        assert_eq!(topology.components, vec![(-7, 7), (1, 1), (1, 3)]);
        assert_eq!(topology.component_euler, vec![-7, 1, 1]);
        assert_eq!((topology.open_edges, topology.open_or_nonmanifold_edges), (24, 24));
    }
}
