//! Choosing the extractor for a frame and running it into the renderer's buffers. The renderer knows
//! extractors by their capabilities; names appear only where the `mesher` setting picks one.

use super::{FrameStats, Renderer, Sizing};
use crate::draw::shade::DrawCount;
use crate::draw::views;
use crate::extract::lod::LodSummary;
use crate::extract::lod::select::Eye;
use crate::extract::reference::Construction;
use crate::extract::uniforms::LEVEL_SLOTS;
use crate::extract::{Capabilities, Extractor, Job, LodJob, MeshCount, Output, Viewpoint};
use crate::scene::BOX_HALF_EXTENT;
use crate::scene::params::ParamError;
use crate::scene::params::view::MeshOn;
use crate::scene::params::view::{Method, Projection};

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
            lod: view.lod.then(|| LodJob { eye: self.lod_eye(), freeze: view.lod_freeze }),
        };
        if let Some(mut room) = self.extractors[self.active].prepare(&job) {
            if let Sizing::FixedTriangles(n) = self.sizing {
                room.indices = room.indices.min(3 * n);
            }
            if !self.mesh.capacity.holds(&room) {
                self.reallocate(self.mesh.capacity.grown_for(&room));
            }
        }
        let front_faces = self.front_faces_from();
        let output = Output {
            device: &self.device,
            queue: &self.queue,
            scene: &self.scene_buffers,
            encoder,
            buffers: &self.mesh,
            timing: self.timing.as_ref().filter(|_| timed),
            front_faces,
        };
        self.counted_on_device = false;
        self.mesh_closed = false;
        self.drawn = None;
        match self.extractors[self.active].write(output) {
            MeshCount::OnDevice => {
                self.counted_on_device = true;
                DrawCount::Indirect
            }
            MeshCount::Known { needed, indices, drawn } => {
                let (grid, capacity, bytes) = (self.grid(), self.mesh.capacity, self.mesh.bytes());
                let overflowed = indices < needed.indices;
                let made_by = self.extractors[self.active].capabilities();
                self.mesh_closed = !overflowed && !made_by.lod && made_by.method == Method::MarchingCubes;
                let mut levels = [0; LEVEL_SLOTS];
                if let Some(triangles) = self.lod_summary().and_then(|s| s.triangles) {
                    for (slot, n) in levels.iter_mut().zip(triangles) {
                        *slot = n;
                    }
                }
                self.latest_stats = Some(FrameStats::from_counts(
                    self.frame, grid, capacity, needed, overflowed, bytes, levels,
                ));
                self.drawn = Some(drawn);
                DrawCount::Direct(drawn)
            }
        }
    }

    /// True when no back face of the mesh can show: marching cubes gives a closed surface inside the
    /// box (the grid's boundary reads 0, below any iso level), so from an eye outside the box every back
    /// face lies behind a front face. The margin keeps the near plane clear of the box.
    pub(super) fn back_faces_hidden(&self) -> bool {
        self.mesh_closed && self.eye_outside_box()
    }

    fn eye_outside_box(&self) -> bool {
        self.settings.camera.eye().abs().max_element() > BOX_HALF_EXTENT + 0.1
    }

    /// Where the mesh is seen from, when the extractor may leave its back faces out of the index
    /// buffer: the eye is outside the box, and nothing but the shading pass reads the buffer.
    fn front_faces_from(&self) -> Option<Viewpoint> {
        if !self.eye_outside_box() || self.views_shown() || self.measuring() {
            return None;
        }
        let eye = self.settings.camera.eye();
        Some(match self.settings.view.projection {
            Projection::Perspective => Viewpoint::At(eye),
            Projection::Orthographic => Viewpoint::Along(-eye),
        })
    }

    /// True when the teaching views draw this frame. They read the lists the compute passes fill, so
    /// without an extractor that fills them (WebGL2, level of detail, surface nets) the surface shows
    /// alone.
    pub(super) fn views_shown(&self) -> bool {
        let mesh_only = views::mesh_only(&self.settings.view);
        // With level of detail or surface nets the views draw the mesh alone (display modes, colours),
        // which needs storage buffers but no cell lists.
        let drawable = if mesh_only {
            self.context.has_compute()
        } else {
            self.extractors.iter().any(|e| self.in_mode(e.capabilities()) && e.capabilities().cell_lists)
        };
        drawable && views::needed(&self.settings.view, self.selected.is_some() && !mesh_only)
    }

    /// True for the extractors of the current mode: level of detail (marching cubes and its transition
    /// cells) or the uniform grid with the chosen method.
    fn in_mode(&self, c: Capabilities) -> bool {
        let view = &self.settings.view;
        c.lod == view.lod && (view.lod || c.method == view.method)
    }

    /// The extractor for the next frame, among those of the current mode (`lod`): one with the
    /// active-cell lists while a teaching view reads them; else as `mesher` names it, `auto` choosing
    /// one on the CPU on a software adapter (where compute passes are emulated on the CPU) and one in
    /// compute shaders on hardware; the first the device runs when the named one cannot.
    fn next_extractor(&self) -> usize {
        let find = |wanted: &dyn Fn(Capabilities, &'static str) -> bool| {
            self.extractors
                .iter()
                .position(|e| self.in_mode(e.capabilities()) && wanted(e.capabilities(), e.name()))
        };
        let chosen = if self.views_shown() && !views::mesh_only(&self.settings.view) {
            find(&|c, _| c.cell_lists)
        } else if self.pinned.is_some() {
            self.pinned
        } else {
            match self.settings.view.mesh_on {
                MeshOn::Gpu => find(&|c, _| c.needs_compute),
                MeshOn::Cpu => find(&|c, _| !c.needs_compute),
                MeshOn::Auto => {
                    let software = self.context.is_software();
                    find(&|c, _| c.needs_compute != software)
                }
            }
        };
        chosen.or_else(|| find(&|_, _| true)).unwrap_or(0)
    }

    /// The camera as level selection sees it.
    fn lod_eye(&self) -> Eye {
        let camera = &self.settings.camera;
        let half_fov = (camera.fov_y_degrees.to_radians() / 2.0).tan();
        let orthographic = self.settings.view.projection == Projection::Orthographic;
        let height = self.size.1 as f32;
        Eye {
            position: camera.eye(),
            view_projection: self.view_projection(),
            pixels_per_unit: if orthographic {
                height / (2.0 * camera.distance * half_fov)
            } else {
                height / (2.0 * half_fov)
            },
            orthographic,
            lod_pixels: self.settings.view.lod_pixels,
        }
    }

    /// The latest frame's level-of-detail selection and counts, when a LOD extractor made it.
    pub fn lod_summary(&self) -> Option<LodSummary> {
        self.extractors[self.active].lod_summary()
    }

    /// What the extractor the next frame will use can do.
    pub fn next_capabilities(&self) -> Capabilities {
        self.extractors[self.next_extractor()].capabilities()
    }

    /// Triangles the latest frame drew, where the CPU counted them: fewer than the mesh has where its
    /// back faces were left out.
    pub fn triangles_drawn(&self) -> Option<u32> {
        self.drawn.map(|indices| indices / 3)
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
