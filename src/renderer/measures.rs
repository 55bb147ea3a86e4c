//! How good the mesh is: while a view colours it by its error or its shape, the measures pass runs after
//! extraction, and its sums come back with the frame statistics (a frame or two late; nothing waits).

use super::Renderer;
use crate::draw::measure::{MeasurePass, MeshMeasures};
use crate::draw::shade::DrawCount;
use crate::scene::params::view::ColorBy;

impl Renderer {
    /// True when this frame's mesh is measured: `color_by` is `error` or `quality`, on a device with
    /// compute shaders.
    pub fn measuring(&self) -> bool {
        matches!(self.settings.view.color_by, ColorBy::Error | ColorBy::Quality) && self.context.has_compute()
    }

    /// Runs the measures pass over the mesh `make_mesh` just made, when the view asks for it. Returns
    /// whether it ran.
    pub(super) fn encode_measures(&mut self, encoder: &mut wgpu::CommandEncoder, count: DrawCount) -> bool {
        if !self.measuring() {
            self.teaching.latest_measures = None;
            return false;
        }
        let known = match count {
            DrawCount::Indirect => None,
            DrawCount::Direct(indices) => {
                let capacity = self.stage.buffers.capacity;
                let vertices = self.stats.latest.map_or(0, |s| s.vertices).min(capacity.vertices);
                Some((vertices, indices / 3))
            }
        };
        let pass = self.teaching.measures.get_or_insert_with(|| MeasurePass::new(&self.device));
        pass.encode(&self.device, &self.queue, encoder, &self.scene_buffers, &self.stage.buffers, known);
        true
    }

    /// The newest measures of the mesh (RMS and largest distance to the exact surface in cells, the
    /// shape histogram), while `color_by` is `error` or `quality`.
    pub fn measures(&self) -> Option<MeshMeasures> {
        self.teaching.latest_measures
    }
}
