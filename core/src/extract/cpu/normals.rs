//! The CPU mesher's analytic normals, made a batch at a time: the vertices off the walls with blend
//! by sum wait here for their gradients, which are summed for a chunk of vertices at once with the
//! sphere loop outside (each vertex still sums its spheres in order, so the normals are the oracle's
//! bit for bit).

use crate::extract::field::Spheres;
use glam::Vec3;

/// Vertices waiting for their normals.
#[derive(Default)]
pub struct PendingNormals {
    /// Each vertex's index in the mesh, and its normal where the gradient vanishes: along the edge,
    /// out of the solid.
    ids: Vec<(u32, Vec3)>,
    /// Positions, one array per axis; then the gradients there.
    positions: [Vec<f32>; 3],
}

impl PendingNormals {
    /// Vertex `id` at `p` waits for its normal.
    pub fn push(&mut self, id: u32, p: Vec3, fallback: Vec3) {
        self.ids.push((id, fallback));
        for (axis, positions) in self.positions.iter_mut().enumerate() {
            positions.push(p[axis]);
        }
    }

    /// Writes the waiting vertices' normals into `vertices` (position then normal, 6 `f32` each) as
    /// [`reference::surface_vertex`](crate::extract::reference::surface_vertex) makes them, and
    /// forgets them.
    pub fn finish(&mut self, spheres: &Spheres, vertices: &mut [f32]) {
        let [x, y, z] = &mut self.positions;
        spheres.outward_gradients([x, y, z]);
        for (k, &(id, fallback)) in self.ids.iter().enumerate() {
            let g = Vec3::new(x[k], y[k], z[k]);
            let normal = g.try_normalize().unwrap_or_else(|| fallback.normalize());
            let at = 6 * id as usize + 3;
            vertices[at..at + 3].copy_from_slice(&normal.to_array());
        }
        self.ids.clear();
        for positions in &mut self.positions {
            positions.clear();
        }
    }
}
