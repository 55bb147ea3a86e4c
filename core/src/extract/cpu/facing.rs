//! Which triangles of a closed mesh face the viewer. From outside a closed surface every triangle that
//! faces away lies behind one that faces the eye, so it never shows; leaving it out of the index buffer
//! spares a software rasteriser its vertices and set-up. Only triangles that face away by a clear margin
//! are left out: those nearly edge-on stay, and the shading pass culls them as it always would.

use crate::extract::mesh::Viewpoint;
use glam::Vec3;

/// How clearly a triangle must face away to be left out: the cosine of its angle to the line of sight.
const MARGIN: f32 = 1e-3;

/// Fills `front` with the triangles of `indices` (three per triangle, counter-clockwise seen from
/// outside, over `vertices` of 6 `f32` each, position first) that do not clearly face away from
/// `viewpoint`, in their order.
pub fn front_faces(vertices: &[f32], indices: &[u32], viewpoint: Viewpoint, front: &mut Vec<u32>) {
    let position = |i: u32| {
        let at = 6 * i as usize;
        Vec3::new(vertices[at], vertices[at + 1], vertices[at + 2])
    };
    front.clear();
    front.reserve(indices.len());
    for triangle in indices.chunks_exact(3) {
        let [a, b, c] = [triangle[0], triangle[1], triangle[2]].map(position);
        // Points out of the surface: the triangles wind counter-clockwise seen from outside.
        let normal = (b - a).cross(c - a);
        let sight = match viewpoint {
            Viewpoint::At(eye) => a - eye,
            Viewpoint::Along(direction) => direction,
        };
        let away = normal.dot(sight);
        let faces_away =
            away > 0.0 && away * away > MARGIN * MARGIN * normal.length_squared() * sight.length_squared();
        if !faces_away {
            front.extend_from_slice(triangle);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::extract::reference::{Grid, extract};
    use crate::scene::Scene;

    /// Casts a ray from `eye` through `target` and returns the nearest triangle it hits, by index.
    fn first_hit(vertices: &[f32], indices: &[u32], eye: Vec3, target: Vec3) -> Option<usize> {
        let p = |i: u32| Vec3::from_slice(&vertices[6 * i as usize..6 * i as usize + 3]);
        let dir = (target - eye).normalize();
        let mut best = (f32::INFINITY, None);
        for (k, t) in indices.chunks_exact(3).enumerate() {
            let (a, b, c) = (p(t[0]), p(t[1]), p(t[2]));
            let (e1, e2) = (b - a, c - a);
            let h = dir.cross(e2);
            let det = e1.dot(h);
            if det.abs() < 1e-12 {
                continue;
            }
            let s = eye - a;
            let u = s.dot(h) / det;
            let q = s.cross(e1);
            let v = dir.dot(q) / det;
            let d = e2.dot(q) / det;
            if u >= 0.0 && v >= 0.0 && u + v <= 1.0 && d > 0.0 && d < best.0 {
                best = (d, Some(k));
            }
        }
        best.1
    }

    #[test]
    fn leaves_out_about_half_and_keeps_every_triangle_a_ray_from_the_eye_meets_first() {
        let scene = Scene::new(3, 6).unwrap();
        // The oracle's mesh, welded as the meshers weld it (one vertex per crossed edge), interleaved
        // as they hold it.
        let mesh = extract(scene.spheres(), 1.0, Grid { cells_per_axis: 24 }).weld_by_edge();
        let vertices: Vec<f32> = mesh
            .positions
            .iter()
            .zip(&mesh.normals)
            .flat_map(|(p, n)| [p.x, p.y, p.z, n.x, n.y, n.z])
            .collect();
        let indices: Vec<u32> = mesh.triangles.iter().flatten().copied().collect();
        let (vertices, indices) = (&vertices, &indices);
        for viewpoint in
            [Viewpoint::At(Vec3::new(0.4, 1.3, 3.0)), Viewpoint::Along(Vec3::new(-0.3, -0.5, -1.0))]
        {
            let mut front = Vec::new();
            front_faces(vertices, indices, viewpoint, &mut front);
            let (kept, all) = (front.len() / 3, indices.len() / 3);
            assert!(kept > all / 3 && kept < 2 * all / 3, "{viewpoint:?}: kept {kept} of {all}");
            let kept: std::collections::HashSet<&[u32]> = front.chunks_exact(3).collect();
            // Rays towards the centroids of the mesh's triangles: each first hit is kept.
            let mut seen = 0;
            for t in indices.chunks_exact(3).step_by(7) {
                let p = |i: u32| Vec3::from_slice(&vertices[6 * i as usize..6 * i as usize + 3]);
                let target = (p(t[0]) + p(t[1]) + p(t[2])) / 3.0;
                let eye = match viewpoint {
                    Viewpoint::At(eye) => eye,
                    Viewpoint::Along(d) => target - 4.0 * d.normalize(),
                };
                if let Some(k) = first_hit(vertices, indices, eye, target) {
                    seen += 1;
                    assert!(
                        kept.contains(&indices[3 * k..3 * k + 3]),
                        "{viewpoint:?}: triangle {k} seen first but left out"
                    );
                }
            }
            assert!(seen > all / 10, "{viewpoint:?}: only {seen} rays hit");
        }
    }
}
