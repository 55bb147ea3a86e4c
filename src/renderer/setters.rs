//! One-setting changes, each through `Renderer::set_settings`: all checked, none applied if refused.

use super::Renderer;
use crate::scene::params::{Camera, Material, ParamError, Settings};
use glam::Vec3;

impl Renderer {
    /// Puts `count` spheres in play (1 to `MAX_SPHERES`).
    pub fn set_sphere_count(&mut self, count: u32) -> Result<(), ParamError> {
        self.set_settings(Settings { sphere_count: count, ..self.settings })
    }

    /// Sets the level the surface is drawn at.
    pub fn set_iso(&mut self, iso: f32) -> Result<(), ParamError> {
        self.set_settings(Settings { iso, ..self.settings })
    }

    /// Sets the cells per axis; the old grid's buffers are freed.
    pub fn set_resolution(&mut self, cells_per_axis: u32) -> Result<(), ParamError> {
        self.set_settings(Settings { resolution: cells_per_axis, ..self.settings })
    }

    /// Draws a new layout from `seed`.
    pub fn set_seed(&mut self, seed: u64) -> Result<(), ParamError> {
        self.set_settings(Settings { seed, ..self.settings })
    }

    /// Sets the surface material.
    pub fn set_material(&mut self, material: Material) -> Result<(), ParamError> {
        self.set_settings(Settings { material, ..self.settings })
    }

    /// Moves the light.
    pub fn set_light_position(&mut self, position: Vec3) -> Result<(), ParamError> {
        self.set_settings(Settings { light_position: position, ..self.settings })
    }

    /// Turns 4× multisampling on or off.
    pub fn set_antialiasing(&mut self, on: bool) -> Result<(), ParamError> {
        self.set_settings(Settings { antialiasing: on, ..self.settings })
    }

    /// Moves the camera.
    pub fn set_camera(&mut self, camera: Camera) -> Result<(), ParamError> {
        self.set_settings(Settings { camera, ..self.settings })
    }
}
