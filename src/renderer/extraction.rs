//! Choosing the extractor for a frame and running it into the renderer's buffers. The renderer knows
//! extractors by their capabilities; names appear only where the `mesher` setting picks one.

use super::stage::Counted;
use super::{FrameStats, Renderer};
use crate::draw::shade::DrawCount;
use crate::draw::views;
use crate::extract::cpu::elsewhere;
use crate::extract::lod::select::Eye;
use crate::extract::uniforms::LevelCounts;
use crate::extract::{
    Capabilities, Extractor, GivenMesh, Job, LodJob, LodSummary, MeshCount, Output, Viewpoint,
};
use crate::scene::checks::check_f32;
use crate::scene::params::ParamError;
use crate::scene::params::view::MeshOn;
use crate::scene::params::view::{ColorBy, Display};
use crate::scene::params::view::{Method, Projection};
use crate::scene::{BOX_HALF_EXTENT, Sphere};

/// The most [`Renderer::set_lod_coarsening`] takes, far beyond what a page asks (its largest cell
/// size over its smallest).
pub const MAX_LOD_COARSENING: f32 = 1024.0;

impl Renderer {
    /// Makes this frame's mesh with the chosen extractor: the room it reports is made first (a fixed
    /// triangle budget clamps instead, as on the device), then it writes into the buffers.
    pub(super) fn make_mesh(&mut self, encoder: &mut wgpu::CommandEncoder, timed: bool) -> DrawCount {
        let previous = self.stage.active;
        self.stage.active = self.next_extractor();
        let job = self.job_of(self.scene.spheres());
        self.lod_culled = job.lod.is_some_and(|l| l.eye.cull);
        let active = self.stage.active;
        if active != previous {
            // The buffers hold another extractor's mesh.
            self.stage.extractors[active].buffers_changed();
        }
        if let Some(room) = self.stage.extractors[active].prepare(&job) {
            let room = self.stage.budgeted(room);
            let capacity = self.stage.buffers.capacity;
            if !capacity.holds(&room) {
                self.reallocate(capacity.grown_for(&room));
            }
        }
        let front_faces = self.front_faces_from();
        let stage = &mut self.stage;
        let output = Output {
            device: &self.device,
            queue: &self.queue,
            scene: &self.scene_buffers,
            encoder,
            buffers: &stage.buffers,
            timing: self.stats.timing_for(timed),
            front_faces,
        };
        stage.counted = Counted::default();
        match stage.extractors[active].write(output) {
            MeshCount::OnDevice => {
                stage.counted.on_device = true;
                DrawCount::Indirect
            }
            MeshCount::Known { needed, indices, drawn } => {
                let (capacity, bytes) = (stage.buffers.capacity, stage.buffers.bytes());
                let overflowed = indices < needed.indices;
                let made_by = stage.extractors[active].capabilities();
                // Part way through the march the mesh is open.
                stage.counted.closed =
                    !overflowed && made_by.method.closes_its_mesh() && self.settings.view.march.is_none();
                stage.counted.drawn = Some(drawn);
                let mut levels = LevelCounts::default();
                if let Some(triangles) = self.lod_summary().and_then(|s| s.triangles) {
                    for (slot, n) in levels.triangles.iter_mut().zip(triangles) {
                        *slot = n;
                    }
                }
                let frame = self.stats.frame;
                self.stats.latest = Some(FrameStats::from_counts(
                    frame,
                    self.grid(),
                    capacity,
                    needed,
                    overflowed,
                    bytes,
                    levels,
                ));
                DrawCount::Direct(drawn)
            }
        }
    }

    /// What the frame's mesh is made of: `spheres` (the scene's) and the settings.
    fn job_of<'a>(&self, spheres: &'a [Sphere]) -> Job<'a> {
        let view = &self.settings.view;
        Job {
            spheres,
            iso: self.settings.iso,
            grid: self.grid(),
            construction: self.construction(),
            lod: view.lod.then(|| LodJob { eye: self.lod_eye(), freeze: view.lod_freeze }),
            teaching: self.teaching_views(),
        }
    }

    /// The next frame's mesh job, packed for a mesher elsewhere (the page's mesher worker), when a
    /// mesher on the CPU makes it; `None` when compute passes do.
    pub fn cpu_job(&self) -> Option<Vec<f32>> {
        let capabilities = self.stage.extractors[self.next_extractor()].capabilities();
        // Part way through the march, the frame meshes its cells on its own; so does a frame showing
        // dual contouring's QEF ranks or crossings, which a mesh made elsewhere does not carry.
        let own = self.settings.view.march.is_some() || self.teaching_views();
        (!capabilities.needs_compute && !capabilities.lod && !own)
            .then(|| elsewhere::pack(capabilities.method, &self.job_of(self.scene.spheres())))
    }

    /// True when the frame's views show dual contouring's QEF ranks or crossings.
    fn teaching_views(&self) -> bool {
        let shown = views::shown(&self.settings.view);
        let dual = shown.method == Method::DualContouring && !shown.lod;
        dual && (shown.color_by == ColorBy::Rank || shown.display == Display::Normals) && self.views_shown()
    }

    /// The frame's scene as a job for the CPU's marching cubes, whichever extractor runs.
    pub fn scene_job(&self) -> Vec<f32> {
        elsewhere::pack(Method::MarchingCubes, &self.job_of(self.scene.spheres()))
    }

    /// A mesh made elsewhere for the job `cpu_job` gave: the next frame draws it where its job is still
    /// the frame's (else that frame meshes on its own).
    pub fn give_mesh(&mut self, mesh: GivenMesh) {
        let next = self.next_extractor();
        self.stage.extractors[next].give_mesh(mesh);
    }

    /// True when no back face of the mesh can show: marching cubes gives a closed surface inside the
    /// box (the grid's boundary reads 0, below any iso level; with level of detail, transition cells
    /// close every seam), so from an eye outside the box every back face lies behind a front face. The
    /// margin keeps the near plane clear of the box.
    pub(super) fn back_faces_hidden(&self) -> bool {
        self.stage.counted.closed && self.eye_outside_box()
    }

    fn eye_outside_box(&self) -> bool {
        self.settings.camera.eye().abs().max_element() > BOX_HALF_EXTENT + 0.1
    }

    /// Where the mesh is seen from, when the extractor may leave its back faces out of the index
    /// buffer: the eye is outside the box, and nothing but the shading pass reads the buffer.
    fn front_faces_from(&self) -> Option<Viewpoint> {
        // Part way through the march the mesh is open, and its back faces show through it.
        let open = self.settings.view.march.is_some();
        if open || !self.eye_outside_box() || self.views_shown() || self.measuring() {
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
            self.stage
                .extractors
                .iter()
                .any(|e| self.in_mode(e.capabilities()) && e.capabilities().cell_lists)
        };
        drawable && views::needed(&self.settings.view, self.teaching.selected.is_some() && !mesh_only)
    }

    /// True for the extractors of the current mode: level of detail (marching cubes and its transition
    /// cells) or the uniform grid with the chosen method.
    fn in_mode(&self, c: Capabilities) -> bool {
        let view = &self.settings.view;
        c.lod == view.lod && (view.lod || c.method == view.method)
    }

    /// The extractor for the next frame, among those of the current mode (`lod`): one with the
    /// active-cell lists while a teaching view reads them (the selected cell's outline alone does not); else as `mesher` names it, `auto` choosing
    /// one on the CPU on a software adapter (where compute passes are emulated on the CPU) and one in
    /// compute shaders on hardware; the first the device runs when the named one cannot.
    fn next_extractor(&self) -> usize {
        let find = |wanted: &dyn Fn(Capabilities, &'static str) -> bool| {
            self.stage
                .extractors
                .iter()
                .position(|e| self.in_mode(e.capabilities()) && wanted(e.capabilities(), e.name()))
        };
        // The selected cell's outline needs no cell lists: only the other views read them.
        let lists = views::needed(&self.settings.view, false) && !views::mesh_only(&self.settings.view);
        let chosen = if self.views_shown() && lists {
            find(&|c, _| c.cell_lists)
        } else if self.stage.pinned.is_some() {
            self.stage.pinned
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

    /// The camera as level selection sees it (for the frames drawn; a readback culls nothing).
    pub fn lod_eye(&self) -> Eye {
        let view = self.camera_view();
        Eye {
            position: view.eye(),
            view_projection: view.view_projection(),
            pixels_per_unit: view.pixels_per_unit(),
            orthographic: view.projection == Projection::Orthographic,
            lod_pixels: self.settings.view.lod_pixels * self.lod_coarsening,
            cull: self.cull_lod,
        }
    }

    /// True when the latest mesh left out the blocks outside the view (level of detail, while drawing):
    /// what reads its shape should mesh the whole surface first (`mesh_readback`).
    pub fn mesh_culled(&self) -> bool {
        self.lod_culled
    }

    /// With level of detail, the cell size in pixels the selection uses: `lod-pixels` times the
    /// coarsening, clamped where a larger one would let touching blocks differ by more than one level.
    pub fn lod_cell_pixels(&self) -> Option<f32> {
        self.settings.view.lod.then(|| self.lod_eye().cell_pixels())
    }

    /// Lets level of detail's cells look up to `factor` times `lod_pixels` on screen (1: as set),
    /// from the next frame on. The page raises it while frames run long and lowers it again when they
    /// are fast, as it does the render scale; the setting itself stays as given.
    pub fn set_lod_coarsening(&mut self, factor: f32) -> Result<(), ParamError> {
        self.lod_coarsening = check_f32("LOD coarsening", factor, 1.0, MAX_LOD_COARSENING)?;
        Ok(())
    }

    /// How many times `lod_pixels` level of detail's cells may look on screen now.
    pub fn lod_coarsening(&self) -> f32 {
        self.lod_coarsening
    }

    /// The latest frame's level-of-detail selection and counts, when a LOD extractor made it.
    pub fn lod_summary(&self) -> Option<LodSummary> {
        let mut summary = self.stage.active().lod_summary()?;
        // Selected on the device: the blocks per level come back with the statistics.
        if summary.blocks.is_empty() {
            let levels = crate::extract::lod::select::coarsest_level(summary.resolution) as usize + 1;
            let counted = self.stats().map(|s| s.level_blocks).unwrap_or_default();
            summary.blocks = counted[..levels].to_vec();
        }
        Some(summary)
    }

    /// What the extractor the next frame will use can do.
    pub fn next_capabilities(&self) -> Capabilities {
        self.stage.extractors[self.next_extractor()].capabilities()
    }

    /// Triangles the latest frame drew, where the CPU counted them: fewer than the mesh has where its
    /// back faces were left out.
    pub fn triangles_drawn(&self) -> Option<u32> {
        self.stage.counted.drawn.map(|indices| indices / 3)
    }

    /// The extractor that made the latest frame's mesh (`gpu`, `cpu`).
    pub fn mesh_source(&self) -> &'static str {
        self.stage.active().name()
    }

    /// What the extractor of the latest frame can do.
    pub fn mesh_capabilities(&self) -> Capabilities {
        self.stage.active().capabilities()
    }

    /// The names of the extractors this renderer's device runs, in order of preference.
    pub fn extractor_names(&self) -> Vec<&'static str> {
        self.stage.names()
    }

    /// Makes every frame with the extractor called `name` whatever `mesher` says (`None` lets the setting
    /// choose again), except while a teaching view needs the active-cell lists. For tests and tools
    /// that compare extractors.
    pub fn pin_extractor(&mut self, name: Option<&str>) -> Result<(), ParamError> {
        self.stage.pin(name)
    }

    pub(super) fn active_extractor(&self) -> &dyn Extractor {
        self.stage.active()
    }
}
