//! The camera and the lights as the shaders take them, and what the teaching views ask of the
//! renderer: picking and inspecting a cell, projecting points to pixels.

use super::Renderer;
use crate::ParamError;
use crate::Settings;
use crate::inspect::{self, CellReport, Target};
use crate::params::view::{GridView, Projection};
use crate::reference::Construction;
use crate::uniforms::LightUniform;
use glam::{Mat4, UVec3, Vec3};

impl Renderer {
    /// Sets parameter `name` (a view option, light strength or the field of view; see
    /// `Settings::with_parameter`) from its text.
    pub fn set_parameter(&mut self, name: &str, text: &str) -> Result<(), ParamError> {
        self.set_settings(self.settings.with_parameter(name, text)?)
    }

    /// How the surface is built (vertex placement and blend), as the oracle takes it.
    pub fn construction(&self) -> Construction {
        Construction { interpolation: self.settings.view.interpolation, blend: self.settings.view.blend }
    }

    /// The cell under pixel (`x`, `y`) of the output (origin top left): the cell whose triangles the ray
    /// from the eye meets first (in the cells view, the first crossed cell it enters), or `None` over the
    /// background.
    pub fn pick(&self, x: f32, y: f32) -> Option<UVec3> {
        let (width, height) = (self.size.0 as f32, self.size.1 as f32);
        let ndc = glam::Vec2::new(2.0 * x / width - 1.0, 1.0 - 2.0 * y / height);
        let inverse = self.view_projection().inverse();
        let near = inverse.project_point3(ndc.extend(0.0));
        let far = inverse.project_point3(ndc.extend(1.0));
        let s = &self.settings;
        // In the cells view, the box under the pointer; otherwise the surface.
        let target = if s.view.grid == GridView::Cells { Target::CrossedCell } else { Target::Surface };
        inspect::pick(self.scene.spheres(), s.iso, self.grid(), self.construction(), near, far - near, target)
    }

    /// Where world point `p` lands in the output, in pixels from the top left.
    pub fn project(&self, p: Vec3) -> glam::Vec2 {
        let ndc = self.view_projection().project_point3(p);
        glam::Vec2::new((ndc.x + 1.0) * 0.5 * self.size.0 as f32, (1.0 - ndc.y) * 0.5 * self.size.1 as f32)
    }

    /// Shows `cell` in the inspector (highlighted in the view every frame), or nothing.
    pub fn select_cell(&mut self, cell: Option<UVec3>) {
        let n = self.settings.resolution;
        self.selected = cell.filter(|c| c.max_element() < n);
    }

    /// The cell the inspector shows.
    pub fn selected_cell(&self) -> Option<UVec3> {
        self.selected
    }

    /// What marching cubes decides in `cell` now.
    pub fn inspect(&self, cell: UVec3) -> CellReport {
        inspect::inspect(self.scene.spheres(), self.settings.iso, self.grid(), self.construction(), cell)
    }

    /// The camera's projection times its view: perspective, or orthographic with the same framing at
    /// the box's centre.
    pub(super) fn view_projection(&self) -> Mat4 {
        let camera = &self.settings.camera;
        let aspect = self.size.0 as f32 / self.size.1 as f32;
        let fov = camera.fov_y_degrees.to_radians();
        let projection = match self.settings.view.projection {
            Projection::Perspective => glam::camera::rh::proj::directx::perspective(fov, aspect, 0.05, 100.0),
            Projection::Orthographic => {
                let half_height = camera.distance * (fov / 2.0).tan();
                let half_width = half_height * aspect;
                glam::camera::rh::proj::directx::orthographic(
                    -half_width,
                    half_width,
                    -half_height,
                    half_height,
                    0.05,
                    100.0,
                )
            }
        };
        projection * view_matrix(camera.eye())
    }
}

pub(super) fn view_matrix(eye: Vec3) -> Mat4 {
    glam::camera::rh::view::look_at_mat4(eye, Vec3::ZERO, Vec3::Y)
}

/// The lights `settings` turn on: the point light where the settings put it, in white; a cool
/// directional light from the upper left; a warm spot from the front left aimed at the box's centre.
pub(super) fn lights(settings: &Settings) -> [LightUniform; 3] {
    let on = settings.view.lights;
    let spot_position = Vec3::new(-1.8, 2.6, 2.6);
    let half_angle = settings.view.spot_angle.to_radians();
    [
        LightUniform {
            position: settings.light_position.to_array(),
            kind: if on.point { 1 } else { 0 },
            color: [1.0; 3],
            ..Default::default()
        },
        LightUniform {
            kind: if on.directional { 2 } else { 0 },
            direction: Vec3::new(0.8, -1.0, -0.3).normalize().to_array(),
            color: [0.55, 0.62, 0.85],
            ..Default::default()
        },
        LightUniform {
            position: spot_position.to_array(),
            kind: if on.spot { 3 } else { 0 },
            direction: (-spot_position).normalize().to_array(),
            cos_outer: half_angle.cos(),
            color: [1.0, 0.8, 0.5],
            cos_inner: (half_angle * (1.0 - settings.view.spot_softness)).cos(),
        },
    ]
}
