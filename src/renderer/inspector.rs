//! What the teaching views ask of the renderer: options by name, and picking and inspecting a cell.

use super::Renderer;
use crate::extract::reference::Construction;
use crate::scene::params::ParamError;
use crate::scene::params::view::GridView;
use crate::teach::inspect::{self, CellReport, Target};
use glam::UVec3;

impl Renderer {
    /// Sets renderer setting `name` (any of its names in the parameter table) from its text.
    pub fn set_parameter(&mut self, name: &str, text: &str) -> Result<(), ParamError> {
        self.set_settings(self.settings.with_parameter(name, text)?)
    }

    /// Sets several renderer settings from their text, checked together: all or nothing.
    pub fn set_parameters(&mut self, pairs: &[(&str, &str)]) -> Result<(), ParamError> {
        self.set_settings(self.settings.with_parameters(pairs)?)
    }

    /// How the surface is built (vertex placement and blend), as the oracle takes it.
    pub fn construction(&self) -> Construction {
        Construction { interpolation: self.settings.view.interpolation, blend: self.settings.view.blend }
    }

    /// The cell under pixel (`x`, `y`) of the output (origin top left): the cell whose triangles the ray
    /// from the eye meets first (in the cells view, the first crossed cell it enters), or `None` over the
    /// background.
    pub fn pick(&self, x: f32, y: f32) -> Option<UVec3> {
        let (origin, direction) = self.ray(x, y);
        let s = &self.settings;
        // In the cells view, the box under the pointer; otherwise the surface.
        let target = if s.view.grid == GridView::Cells { Target::CrossedCell } else { Target::Surface };
        inspect::pick(
            self.scene.spheres(),
            s.iso,
            self.grid(),
            self.construction(),
            origin,
            direction,
            target,
        )
        .map(|(cell, _)| cell)
    }

    /// The ray from the eye through pixel (`x`, `y`) of the output (origin top left): a point on the
    /// near plane and a direction, for perspective and orthographic projections alike.
    pub fn ray(&self, x: f32, y: f32) -> (glam::Vec3, glam::Vec3) {
        let (width, height) = (self.size.0 as f32, self.size.1 as f32);
        let ndc = glam::Vec2::new(2.0 * x / width - 1.0, 1.0 - 2.0 * y / height);
        let inverse = self.view_projection().inverse();
        let near = inverse.project_point3(ndc.extend(0.0));
        let far = inverse.project_point3(ndc.extend(1.0));
        (near, (far - near).normalize())
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
}
