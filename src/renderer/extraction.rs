//! Choosing the extractor for a frame and running it into the renderer's buffers. The renderer knows
//! extractors by their capabilities; names appear only where the `mesher` setting picks one.

use super::{FrameStats, Renderer, Sizing};
use crate::draw::shade::DrawCount;
use crate::draw::views;
use crate::extract::reference::Construction;
use crate::extract::{Capabilities, Extractor, Job, MeshCount, Output};
use crate::scene::params::ParamError;
use crate::scene::params::view::Mesher;

impl Renderer {
    /// Makes this frame's mesh with the chosen extractor: the room it reports is made first (a fixed
    /// triangle budget clamps instead, as on the device), then it writes into the buffers.
    pub(super) fn make_mesh(&mut self, encoder: &mut wgpu::CommandEncoder, timed: bool) -> DrawCount {
        self.active = self.next_extractor();
        let view = &self.settings.view;
        let job = Job {
            spheres: self.scene.spheres(),
            iso: self.settings.iso,
            grid: self.grid(),
            construction: Construction { interpolation: view.interpolation, blend: view.blend },
        };
        if let Some(mut room) = self.extractors[self.active].prepare(&job) {
            if let Sizing::FixedTriangles(n) = self.sizing {
                room.indices = room.indices.min(3 * n);
            }
            if !self.mesh.capacity.holds(&room) {
                self.reallocate(self.mesh.capacity.grown_for(&room));
            }
        }
        let output = Output {
            device: &self.device,
            queue: &self.queue,
            scene: &self.scene_buffers,
            encoder,
            buffers: &self.mesh,
            timing: self.timing.as_ref().filter(|_| timed),
        };
        self.counted_on_device = false;
        match self.extractors[self.active].write(output) {
            MeshCount::OnDevice => {
                self.counted_on_device = true;
                DrawCount::Indirect
            }
            MeshCount::Known { needed, indices } => {
                let (grid, capacity, bytes) = (self.grid(), self.mesh.capacity, self.mesh.bytes());
                let overflowed = indices < needed.indices;
                self.latest_stats =
                    Some(FrameStats::from_counts(self.frame, grid, capacity, needed, overflowed, bytes));
                DrawCount::Direct(indices)
            }
        }
    }

    /// True when the teaching views draw this frame. They read the lists the compute passes fill, so
    /// without an extractor that fills them (WebGL2) the surface shows alone.
    pub(super) fn views_shown(&self) -> bool {
        self.extractors.iter().any(|e| e.capabilities().cell_lists)
            && views::needed(&self.settings.view, self.selected.is_some())
    }

    /// The extractor for the next frame: one with the active-cell lists while a teaching view reads
    /// them; else as `mesher` names it, `auto` choosing one on the CPU on a software adapter (where
    /// compute passes are emulated on the CPU) and one in compute shaders on hardware; the first the
    /// device runs when the named one cannot.
    fn next_extractor(&self) -> usize {
        let find = |wanted: &dyn Fn(Capabilities, &'static str) -> bool| {
            self.extractors.iter().position(|e| wanted(e.capabilities(), e.name()))
        };
        let chosen = if self.views_shown() {
            find(&|c, _| c.cell_lists)
        } else if self.pinned.is_some() {
            self.pinned
        } else {
            match self.settings.view.mesher {
                Mesher::Gpu => find(&|_, name| name == "gpu"),
                Mesher::Cpu => find(&|_, name| name == "cpu"),
                Mesher::Auto => {
                    let software = self.context.is_software();
                    find(&|c, _| c.needs_compute != software)
                }
            }
        };
        chosen.unwrap_or(0)
    }

    /// What the extractor the next frame will use can do.
    pub fn next_capabilities(&self) -> Capabilities {
        self.extractors[self.next_extractor()].capabilities()
    }

    /// The extractor that made the latest frame's mesh (`gpu`, `cpu`).
    pub fn mesh_source(&self) -> &'static str {
        self.extractors[self.active].name()
    }

    /// What the extractor of the latest frame can do.
    pub fn mesh_capabilities(&self) -> Capabilities {
        self.extractors[self.active].capabilities()
    }

    /// The names of the extractors this renderer's device runs, in order of preference.
    pub fn extractor_names(&self) -> Vec<&'static str> {
        self.extractors.iter().map(|e| e.name()).collect()
    }

    /// Makes every frame with the extractor called `name` whatever `mesher` says (`None` lets the setting
    /// choose again), except while a teaching view needs the active-cell lists. For tests and tools
    /// that compare extractors.
    pub fn pin_extractor(&mut self, name: Option<&str>) -> Result<(), ParamError> {
        self.pinned = match name {
            None => None,
            Some(name) => Some(self.extractors.iter().position(|e| e.name() == name).ok_or_else(|| {
                ParamError::Invalid {
                    name: "extractor",
                    value: name.to_string(),
                    expected: format!("one of {}", self.extractor_names().join(", ")),
                }
            })?),
        };
        Ok(())
    }

    pub(super) fn active_extractor(&self) -> &dyn Extractor {
        self.extractors[self.active].as_ref()
    }
}
