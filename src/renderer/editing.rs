//! Editing the scene by hand: which sphere is under the pointer, moving it in the plane facing the
//! camera, adding one where the pointer is, and where a sphere appears on the screen. All of it on the
//! CPU from the scene's sphere list and the camera: nothing is read back from the GPU.

use super::Renderer;
use crate::scene::SceneError;
use crate::scene::{Scene, Sphere, nominal_radius};
use crate::teach::inspect::{self, Target};
use glam::Vec3;

impl Renderer {
    /// The sphere whose term dominates the field where the ray through pixel (`x`, `y`) first meets the
    /// surface (the picking the cell inspector uses), or `None` over the background.
    pub fn pick_sphere(&self, x: f32, y: f32) -> Option<usize> {
        let (origin, direction) = self.ray(x, y);
        let s = &self.settings;
        let spheres = self.scene.spheres();
        let on_surface = inspect::pick(
            spheres,
            s.iso,
            self.grid(),
            self.construction(),
            origin,
            direction,
            Target::Surface,
        )
        .and_then(|(_, point)| Some(((point - origin).length(), inspect::dominant_sphere(spheres, point)?)));
        // A subtracting sphere has no surface of its own: it is picked where the ray meets its ball
        // before any surface.
        let subtracting = spheres
            .iter()
            .enumerate()
            .filter(|(_, sphere)| sphere.is_subtractive())
            .filter_map(|(i, sphere)| {
                let to_centre = sphere.center - origin;
                let along = to_centre.dot(direction);
                let miss2 = to_centre.length_squared() - along * along;
                let r2 = sphere.radius * sphere.radius;
                (along > 0.0 && miss2 <= r2).then(|| (along - (r2 - miss2).sqrt(), i))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0));
        match (on_surface, subtracting) {
            (Some(hit), Some(ball)) => Some(if ball.0 < hit.0 { ball.1 } else { hit.1 }),
            (hit, ball) => hit.or(ball).map(|h| h.1),
        }
    }

    /// Where the ray through pixel (`x`, `y`) meets the plane through `point` facing the camera.
    fn on_camera_plane(&self, x: f32, y: f32, point: Vec3) -> Option<Vec3> {
        let (origin, direction) = self.ray(x, y);
        let normal = -self.settings.camera.eye().normalize();
        let facing = direction.dot(normal);
        (facing.abs() > 1e-6).then(|| origin + direction * ((point - origin).dot(normal) / facing))
    }

    /// Moves sphere `index` as the pointer went from pixel `from` to pixel `to`, in the plane through
    /// its centre facing the camera, keeping it inside the box.
    pub fn move_sphere(&mut self, index: usize, from: (f32, f32), to: (f32, f32)) -> Result<(), SceneError> {
        let sphere = *self
            .scene
            .spheres()
            .get(index)
            .ok_or_else(|| SceneError(format!("there is no sphere {}", index + 1)))?;
        let (Some(a), Some(b)) = (
            self.on_camera_plane(from.0, from.1, sphere.center),
            self.on_camera_plane(to.0, to.1, sphere.center),
        ) else {
            return Ok(());
        };
        self.edit(|scene| scene.set_sphere(index, Sphere { center: sphere.center + (b - a), ..sphere }))
    }

    /// Adds a still sphere where the ray through pixel (`x`, `y`) meets the plane through the box's
    /// centre facing the camera, sized like the others; returns its index.
    pub fn add_sphere(&mut self, x: f32, y: f32) -> Result<usize, SceneError> {
        let center = self.on_camera_plane(x, y, Vec3::ZERO).unwrap_or(Vec3::ZERO);
        let spheres = self.scene.spheres();
        let mut radii: Vec<f32> = spheres.iter().map(|s| s.radius).collect();
        radii.sort_by(f32::total_cmp);
        let radius = radii.get(radii.len() / 2).copied().unwrap_or(nominal_radius(spheres.len() as u32 + 1));
        let mut index = 0;
        self.edit(|scene| {
            index = scene.add_sphere(Sphere { center, radius, velocity: Vec3::ZERO, charge: 1.0 })?;
            Ok(())
        })?;
        Ok(index)
    }

    /// Changes the scene with `f`: on success the renderer takes the new scene (and its sphere count),
    /// on failure nothing changes.
    pub fn edit(&mut self, f: impl FnOnce(&mut Scene) -> Result<(), SceneError>) -> Result<(), SceneError> {
        let mut scene = self.scene.clone();
        f(&mut scene)?;
        self.set_scene(scene);
        Ok(())
    }

    /// Where sphere `index` appears in the output: its centre's pixel and its radius in pixels, or
    /// `None` when it is behind the eye.
    pub fn sphere_on_screen(&self, index: usize) -> Option<[f32; 3]> {
        let sphere = self.scene.spheres().get(index)?;
        let view_projection = self.view_projection();
        let eye = self.settings.camera.eye();
        let forward = -eye.normalize();
        let right = forward.cross(Vec3::Y).normalize_or(Vec3::X);
        let to_pixel = |p: Vec3| {
            let clip = view_projection * p.extend(1.0);
            (clip.w > 1e-6).then(|| {
                let ndc = clip.truncate() / clip.w;
                glam::Vec2::new(
                    (ndc.x + 1.0) * 0.5 * self.size.0 as f32,
                    (1.0 - ndc.y) * 0.5 * self.size.1 as f32,
                )
            })
        };
        let centre = to_pixel(sphere.center)?;
        let edge = to_pixel(sphere.center + right * sphere.radius)?;
        Some([centre.x, centre.y, centre.distance(edge)])
    }
}
