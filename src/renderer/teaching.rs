//! The teaching state: the views' buffers, the cell the inspector shows, and the measures of the mesh.

use crate::draw::measure::{MeasurePass, MeshMeasures};
use crate::draw::views::ViewState;
use crate::extract::uniforms::Measures;
use glam::UVec3;

/// What the teaching views and the inspector hold between frames.
#[derive(Default)]
pub(super) struct Teaching {
    /// The teaching views' buffers, made when a view needs them.
    pub views: Option<ViewState>,
    /// The cell the inspector shows, if any.
    pub selected: Option<UVec3>,
    /// The measures pass, made when a view first asks for the mesh's error or shape.
    pub measures: Option<MeasurePass>,
    pub latest_measures: Option<MeshMeasures>,
}

impl Teaching {
    /// Shows `cell` in the inspector, or nothing when it lies outside a grid of `resolution` cells per
    /// axis.
    pub fn select(&mut self, cell: Option<UVec3>, resolution: u32) {
        self.selected = cell.filter(|c| c.max_element() < resolution);
    }

    /// Takes the measures pass's sums for `frame`, unless newer ones are in.
    pub fn take_measures(&mut self, frame: u64, sums: &Measures) {
        if self.latest_measures.is_none_or(|m| m.frame < frame) {
            self.latest_measures = Some(MeshMeasures::from_sums(frame, sums));
        }
    }

    /// GPU memory the views' buffers hold, in bytes.
    pub fn bytes(&self) -> u64 {
        self.views.as_ref().map_or(0, ViewState::bytes)
    }

    /// Frees the views' buffers; they are made again when a view next needs them.
    pub fn drop_views(&mut self) {
        if let Some(views) = self.views.take() {
            views.destroy();
        }
    }

    /// What was bound to the old mesh buffers (the views, the measures pass) is bound again when next
    /// used.
    pub fn follow_new_buffers(&mut self) {
        self.drop_views();
        if let Some(measures) = &mut self.measures {
            measures.unbind();
        }
    }
}
