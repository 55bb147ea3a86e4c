//! The CPU mesher's shared vertices: each crossed grid edge gets one vertex, numbered on its first use
//! by a triangle and found again through the edge it lies on. Triangles take their numbers at once;
//! the new vertices of a layer of cells are placed after it, in the order they were numbered, and their
//! normals summed together.

use crate::extract::cpu::normals::PendingNormals;
use crate::extract::cpu::planes::Planes;
use crate::extract::field::Spheres;
use crate::extract::kernel::Terms;
use crate::extract::reference::{self, Construction};
use crate::scene::Sphere;
use glam::Vec3;

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

/// The vertices on the grid edges of an `n`³ grid, swept a layer of cells at a time.
#[derive(Default)]
pub struct EdgeVertices {
    /// Points per row of a plane.
    width: usize,
    /// The stamp and vertex of the three edges leaving each point of two planes (plane z at `z % 2`,
    /// point by point, x, y then z): an x or y edge in plane z, or a z edge from it, holds a current
    /// vertex where its stamp is `epoch + z`.
    slots: Vec<[u32; 2]>,
    /// Each mesh moves the epoch past the stamps of the last, so stale slots are told from current
    /// ones.
    epoch: u32,
    /// For the current layer of cells, per edge of a cell: where its slot lies from the cell's lowest
    /// corner's, and the stamp of a current vertex.
    layer_edges: [(usize, u32); 12],
    /// Vertices numbered in this mesh so far.
    numbered: u32,
    /// The vertices numbered in this layer but not yet placed, as their cell and its edge;
    /// `fresh_count` of them are current, the rest is room.
    fresh: Vec<[u32; 4]>,
    fresh_count: usize,
    /// Vertices waiting for their normals.
    normals: PendingNormals,
    /// The grid edge of each vertex placed.
    keys: Vec<u32>,
}

impl EdgeVertices {
    /// Forgets every vertex, for a new mesh of an `n`³ grid.
    pub fn start(&mut self, n: u32) {
        if self.epoch == 0 || self.epoch.checked_add(2 * (n + 1)).is_none() {
            self.slots.fill([0, 0]);
            self.epoch = 1;
        }
        self.width = n as usize + 1;
        self.slots.resize(6 * self.width * self.width, [0, 0]);
        self.numbered = 0;
        self.fresh_count = 0;
        self.keys.clear();
    }

    /// The grid edge of each vertex placed in this mesh: `(x + (n + 1) (y + (n + 1) z)) · 3 + axis`
    /// of the edge's lower end.
    pub fn keys(&self) -> &[u32] {
        &self.keys
    }

    /// Ends the mesh of an `n`³ grid: the next one's stamps are all new.
    pub fn end(&mut self, n: u32) {
        self.epoch += n + 1;
    }

    /// Starts the layer of cells between planes `z` and `z + 1`.
    pub fn start_layer(&mut self, z: u32) {
        let plane = 3 * self.width * self.width;
        self.layer_edges = EDGE_START.map(|([x, y, dz], axis)| {
            let parity = ((z + dz) % 2) as usize;
            (parity * plane + 3 * (x as usize + self.width * y as usize) + axis, self.epoch + z + dz)
        });
    }

    /// Appends to `indices` the numbers of the vertices on the corners of `triangles` of `cell` (in the
    /// current layer), each triangle's corners in the order `[0, 2, 1]`, numbering the vertices of
    /// edges that have none yet.
    pub fn number(
        &mut self,
        cell: [u32; 3],
        triangles: impl IntoIterator<Item = [usize; 3]>,
        indices: &mut Vec<u32>,
    ) {
        // Room for a new vertex on every edge of the cell.
        if self.fresh.len() < self.fresh_count + 12 {
            self.fresh.resize(self.fresh_count + 12, [0; 4]);
        }
        // The counts in locals, so that they stay in registers while the slots are written.
        let (mut numbered, mut fresh_count) = (self.numbered, self.fresh_count);
        let corner = 3 * (cell[0] as usize + self.width * cell[1] as usize);
        for t in triangles {
            let mut ids = [0; 3];
            for (id, k) in ids.iter_mut().zip([0, 2, 1]) {
                let (offset, stamp) = self.layer_edges[t[k]];
                let slot = &mut self.slots[corner + offset];
                let [known, vertex] = *slot;
                let new = known != stamp;
                *id = if new { numbered } else { vertex };
                *slot = [stamp, *id];
                if new {
                    self.fresh[fresh_count] = [cell[0], cell[1], cell[2], t[k] as u32];
                    fresh_count += 1;
                    numbered += 1;
                }
            }
            indices.extend_from_slice(&ids);
        }
        self.numbered = numbered;
        self.fresh_count = fresh_count;
    }

    /// Places the vertices numbered in the current layer, appending each's position and normal to
    /// `vertices` (6 `f32` each), as [`reference::surface_vertex`] does.
    pub fn place(&mut self, planes: &Planes, field: &Field, vertices: &mut Vec<f32>) {
        let (n, iso, construction) = (field.n, field.iso, field.construction);
        let width = self.width;
        // The batched gradients sum inverse squares; other terms take the oracle's own.
        let (terms, plain) = (construction.terms, Terms::default());
        let by_sum = terms.kernel == plain.kernel && terms.blend == plain.blend;
        for &[x, y, z, edge] in &self.fresh[..self.fresh_count] {
            let id = (vertices.len() / 6) as u32;
            let (offset, axis) = EDGE_START[edge as usize];
            let a = [x + offset[0], y + offset[1], z + offset[2]];
            let side = width as u32;
            self.keys.push((a[0] + side * (a[1] + side * a[2])) * 3 + axis as u32);
            let mut b = a;
            b[axis] += 1;
            let value =
                |p: [u32; 3]| planes.values[(p[2] % 2) as usize][p[0] as usize + width * p[1] as usize];
            let (fa, fb) = (value(a), value(b));
            let point = |p: [u32; 3]| Vec3::from_array(p.map(|i| field.coords[i as usize]));
            let boundary = |p: [u32; 3]| p.contains(&0) || p.contains(&n);
            let (pa, pb) = (point(a), point(b));
            let (a_on_wall, b_on_wall) = (boundary(a), boundary(b));
            if by_sum && !a_on_wall && !b_on_wall {
                // Placed as `reference::surface_vertex` places it (`edge_point`); the normal follows
                // with the layer's others.
                let (p, fallback) = reference::edge_point(construction, iso, (pa, fa), (pb, fb));
                self.normals.push(id, p, fallback);
                vertices.extend_from_slice(&[p.x, p.y, p.z, 0.0, 0.0, 0.0]);
                continue;
            }
            let (p, normal) = reference::surface_vertex(
                field.spheres,
                iso,
                construction,
                (pa, fa, a_on_wall),
                (pb, fb, b_on_wall),
            );
            vertices.extend_from_slice(&[p.x, p.y, p.z, normal.x, normal.y, normal.z]);
        }
        self.fresh_count = 0;
        self.normals.finish(field.arrays, vertices);
    }
}

/// What placing vertices reads.
pub struct Field<'a> {
    pub n: u32,
    pub iso: f32,
    pub construction: Construction,
    /// Coordinate of grid point `i` along any axis.
    pub coords: &'a [f32],
    pub spheres: &'a [Sphere],
    /// The same spheres as arrays.
    pub arrays: &'a Spheres,
}
