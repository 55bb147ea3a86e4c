//! Editing the scene by hand: which sphere is under the pointer, moving it in the plane facing the
//! camera, adding one where the pointer is, and where a sphere appears on the screen. The work is the
//! device-free `view::edit` and `view::pick` over this renderer's scene, settings and size.

use super::Renderer;
use crate::scene::Scene;
use crate::scene::SceneError;
use crate::view::{CameraView, Picker, edit};

impl Renderer {
    /// The camera as it frames this renderer's output.
    pub fn camera_view(&self) -> CameraView {
        CameraView::new(&self.settings, self.target.size)
    }

    /// The current surface as the camera shows it, for picking.
    pub fn picker(&self) -> Picker<'_> {
        Picker {
            view: self.camera_view(),
            spheres: self.scene.spheres(),
            iso: self.settings.iso,
            grid: self.grid(),
            construction: self.construction(),
        }
    }

    /// The sphere whose term dominates the field where the ray through pixel (`x`, `y`) first meets the
    /// surface (the picking the cell inspector uses), or `None` over the background.
    pub fn pick_sphere(&self, x: f32, y: f32) -> Option<usize> {
        self.picker().sphere(x, y)
    }

    /// Moves sphere `index` as the pointer went from pixel `from` to pixel `to`, in the plane through
    /// its centre facing the camera, keeping it inside the box.
    pub fn move_sphere(&mut self, index: usize, from: (f32, f32), to: (f32, f32)) -> Result<(), SceneError> {
        let sphere = *self
            .scene
            .spheres()
            .get(index)
            .ok_or_else(|| SceneError(format!("there is no sphere {}", index + 1)))?;
        let Some(moved) = edit::dragged(&self.camera_view(), sphere, from, to) else {
            return Ok(());
        };
        self.edit(|scene| scene.set_sphere(index, moved))
    }

    /// Adds a still sphere where the ray through pixel (`x`, `y`) meets the plane through the box's
    /// centre facing the camera, sized like the others; returns its index.
    pub fn add_sphere(&mut self, x: f32, y: f32) -> Result<usize, SceneError> {
        let sphere = edit::added(&self.camera_view(), self.scene.spheres(), x, y);
        let mut index = 0;
        self.edit(|scene| {
            index = scene.add_sphere(sphere)?;
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
        edit::on_screen(&self.camera_view(), self.scene.spheres().get(index)?)
    }
}
