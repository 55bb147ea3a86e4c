//! What the teaching views ask of the renderer: options by name, and picking and inspecting a cell.

use super::Renderer;
use crate::extract::kernel::Terms;
use crate::extract::reference::Construction;
use crate::scene::params::ParamError;
use crate::scene::params::view::March;
use crate::teach::inspect::{self, CellReport};
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

    /// How the surface is built (vertex placement, kernel and blend), as the oracle takes it.
    pub fn construction(&self) -> Construction {
        Construction {
            interpolation: self.settings.view.interpolation,
            terms: Terms::of(&self.settings.view),
            case_table: self.settings.view.case_table,
            march: March::on_grid(self.settings.view.march, self.settings.resolution),
            split: self.settings.view.split,
        }
    }

    /// The cell under pixel (`x`, `y`) of the output (origin top left): the cell whose triangles the ray
    /// from the eye meets first (in the cells view, the first crossed cell it enters), or `None` over the
    /// background.
    pub fn pick(&self, x: f32, y: f32) -> Option<UVec3> {
        self.picker().cell(x, y, self.settings.view.grid)
    }

    /// The ray from the eye through pixel (`x`, `y`) of the output (origin top left): a point on the
    /// near plane and a direction, for perspective and orthographic projections alike.
    pub fn ray(&self, x: f32, y: f32) -> (glam::Vec3, glam::Vec3) {
        self.camera_view().ray(x, y)
    }

    /// Shows `cell` in the inspector (highlighted in the view every frame), or nothing.
    pub fn select_cell(&mut self, cell: Option<UVec3>) {
        self.teaching.select(cell, self.settings.resolution);
    }

    /// The cell the inspector shows.
    pub fn selected_cell(&self) -> Option<UVec3> {
        self.teaching.selected
    }

    /// The first cell after `after` in the march's order that the surface crosses now, if any.
    pub fn next_crossed(&self, after: Option<UVec3>) -> Option<UVec3> {
        let (spheres, terms) = (self.scene.spheres(), Terms::of(&self.settings.view));
        inspect::next_crossed(spheres, self.settings.iso, self.grid(), terms, after)
    }

    /// What marching cubes decides in `cell` now.
    pub fn inspect(&self, cell: UVec3) -> CellReport {
        inspect::inspect(self.scene.spheres(), self.settings.iso, self.grid(), self.construction(), cell)
    }
}
