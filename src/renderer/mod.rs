//! One renderer for every output: it owns the scene, the settings and the passes, and draws a frame into
//! any texture view of its format (a canvas's current texture or an offscreen texture).

pub mod context;
mod editing;
mod exact;
mod extraction;
mod inspector;
mod limits;
mod measures;
mod readback;
mod setters;
mod stage;
mod stats;
mod target;
mod teaching;
mod uniforms;

pub use limits::max_resolution;
pub use readback::{MeshReadback, OverlayReadback};
pub use stats::FrameStats;

use crate::device::timing::StageTimes;
use crate::draw::shade::{MULTISAMPLES, MeshDraw, ShadePass};
use crate::draw::views::ViewFrame;
use crate::draw::views::{self, ViewState};
use crate::extract::buffers::{BLOCK_CELLS, Capacity};
use crate::extract::gpu::scene_buffers::SceneBuffers;
use crate::extract::reference::Grid;
use crate::scene::Scene;
use crate::scene::params::{ParamError, Settings};
use context::{GpuContext, RendererToken};
use limits::{automatic_capacity, check_resolution_fits};
use stage::MeshStage;
use stats::Statistics;
use target::Target;
use teaching::Teaching;

/// Draws merging spheres: block skipping, field and marching cubes (in GPU compute passes or on the
/// CPU), then shading.
pub struct Renderer {
    context: GpuContext,
    _alive: RendererToken,
    device: wgpu::Device,
    queue: wgpu::Queue,
    target: Target,
    settings: Settings,
    scene: Scene,
    scene_buffers: SceneBuffers,
    shade: ShadePass,
    /// The mesh buffers and the extractors that fill them.
    stage: MeshStage,
    stats: Statistics,
    teaching: Teaching,
    /// How many times `lod_pixels` level of detail's cells may look on screen (see
    /// `set_lod_coarsening`).
    lod_coarsening: f32,
    /// Level of detail leaves out the blocks outside the view: true while a frame is drawn, false
    /// while the mesh is made for a readback (exports, tests), which wants the whole surface.
    cull_lod: bool,
    /// The latest mesh was made with blocks outside the view left out.
    lod_culled: bool,
}

impl Renderer {
    /// A renderer with a device of its own, drawing into `width` × `height` textures of `format`, with
    /// validated `settings`.
    pub fn new(
        device: wgpu::Device,
        queue: wgpu::Queue,
        format: wgpu::TextureFormat,
        width: u32,
        height: u32,
        settings: Settings,
    ) -> Result<Self, ParamError> {
        Self::on_context(&GpuContext::new(device, queue), format, width, height, settings)
    }

    /// A renderer on a shared device: it uses the context's pipelines and owns only its buffers,
    /// targets and scene.
    pub fn on_context(
        context: &GpuContext,
        format: wgpu::TextureFormat,
        width: u32,
        height: u32,
        settings: Settings,
    ) -> Result<Self, ParamError> {
        let settings = settings.validated()?;
        let (device, queue) = (context.device().clone(), context.queue().clone());
        let target = Target::new(context.limits(), format, width, height)?;
        let lod = settings.view.lod;
        if !lod {
            check_resolution_fits(context.limits(), settings.resolution)?;
        }
        let scene = Scene::new(settings.seed, settings.sphere_count)?;

        let grid = Grid { cells_per_axis: settings.resolution };
        let capacity = automatic_capacity(context.limits(), grid, lod, context.has_compute());
        let buffer_grid = if lod { Grid { cells_per_axis: BLOCK_CELLS } } else { grid };
        Ok(Self {
            stage: MeshStage::new(&device, context.extractors(), buffer_grid, capacity),
            shade: ShadePass::new(
                &device,
                context.shade_pipelines(format, sample_count(settings.antialiasing)),
                width,
                height,
            ),
            stats: Statistics::new(&device),
            teaching: Teaching::default(),
            lod_coarsening: 1.0,
            cull_lod: true,
            lod_culled: false,
            scene_buffers: SceneBuffers::new(&device),
            _alive: context.renderer_token(),
            context: context.clone(),
            device,
            queue,
            target,
            settings,
            scene,
        })
    }

    /// The queue frames are submitted on.
    pub fn queue(&self) -> &wgpu::Queue {
        &self.queue
    }

    /// The current settings.
    pub fn settings(&self) -> &Settings {
        &self.settings
    }

    /// The spheres and their motion.
    pub fn scene(&self) -> &Scene {
        &self.scene
    }

    /// The texture format this renderer draws.
    pub fn format(&self) -> wgpu::TextureFormat {
        self.target.format
    }

    /// The output size in pixels.
    pub fn size(&self) -> (u32, u32) {
        self.target.size
    }

    /// The largest resolution this device holds.
    pub fn max_resolution(&self) -> u32 {
        max_resolution(self.context.limits())
    }

    /// What the mesh buffers hold now.
    pub fn capacity(&self) -> Capacity {
        self.stage.buffers.capacity
    }

    /// GPU memory held by the mesh buffers, in bytes.
    pub fn mesh_bytes(&self) -> u64 {
        self.stage.buffers.bytes()
    }

    /// GPU memory held by this renderer's own buffers and targets (not the shared pipelines), in bytes.
    pub fn gpu_bytes(&self) -> u64 {
        self.stage.buffers.bytes() + self.shade.bytes() + self.teaching.bytes()
    }

    /// The device context this renderer draws on.
    pub fn context(&self) -> &GpuContext {
        &self.context
    }

    /// True when a past frame asked for larger buffers, so the next frame would differ from the last
    /// even with nothing else changed.
    pub fn needs_redraw(&self) -> bool {
        self.stage.pending_capacity.is_some()
    }

    /// The newest statistics the GPU has reported, if any yet.
    pub fn stats(&self) -> Option<FrameStats> {
        self.stats.latest
    }

    /// Frames rendered so far: the newest frame's statistics carry this number once read back.
    pub fn frames_rendered(&self) -> u64 {
        self.stats.frame
    }

    /// The first GPU error raised outside an error scope, if any (they are also logged).
    pub fn gpu_error(&self) -> Option<String> {
        self.context.gpu_error()
    }

    /// Follows a new output size.
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), ParamError> {
        if self.target.resize(self.context.limits(), width, height)? {
            self.shade.resize(&self.device, width, height);
        }
        Ok(())
    }

    /// Applies all settings at once, or none if any is refused.
    pub fn set_settings(&mut self, settings: Settings) -> Result<(), ParamError> {
        let settings = settings.validated()?;
        if !settings.view.lod {
            check_resolution_fits(self.context.limits(), settings.resolution)?;
        }
        if settings.seed != self.settings.seed {
            self.scene = Scene::new(settings.seed, settings.sphere_count)?;
        } else if settings.sphere_count != self.settings.sphere_count {
            self.scene.set_count(settings.sphere_count)?;
        }
        let resolution_changed =
            settings.resolution != self.settings.resolution || settings.view.lod != self.settings.view.lod;
        if settings.antialiasing != self.settings.antialiasing {
            let (width, height) = self.target.size;
            let pipelines =
                self.context.shade_pipelines(self.target.format, sample_count(settings.antialiasing));
            self.shade.destroy();
            self.shade = ShadePass::new(&self.device, pipelines, width, height);
            self.teaching.drop_views();
        }
        self.settings = settings;
        if resolution_changed {
            self.teaching.selected = None;
            self.reallocate(self.starting_capacity());
        }
        Ok(())
    }

    /// Advances the animation by `dt` seconds.
    pub fn update(&mut self, dt: f32) -> Result<(), ParamError> {
        self.scene.step(dt)
    }

    /// Replaces the spheres (tests and tools); the sphere count follows them.
    pub fn set_scene(&mut self, scene: Scene) {
        self.settings.sphere_count = scene.spheres().len() as u32;
        self.scene = scene;
    }

    fn grid(&self) -> Grid {
        Grid { cells_per_axis: self.settings.resolution }
    }

    /// The grid the uniform extractors' tables are made for: none to speak of with level of detail,
    /// whose extractors keep their own.
    fn buffer_grid(&self) -> Grid {
        if self.settings.view.lod { Grid { cells_per_axis: BLOCK_CELLS } } else { self.grid() }
    }

    /// Makes the mesh buffers anew with `capacity`; what was bound to the old ones (the teaching views,
    /// the measures pass, the extractors' passes) is bound again when next used.
    fn reallocate(&mut self, capacity: Capacity) {
        self.stage.reallocate(&self.device, self.buffer_grid(), capacity);
        self.teaching.follow_new_buffers();
    }

    /// Draws one frame into `view` (a texture of this renderer's format and size). Never waits on the
    /// GPU: statistics come back asynchronously through `stats`.
    pub fn render(&mut self, view: &wgpu::TextureView) {
        self.render_frame(view, false);
    }

    fn render_frame(&mut self, view: &wgpu::TextureView, timed: bool) {
        self.collect_stats();
        if let Some(capacity) = self.stage.pending_capacity.take() {
            self.reallocate(capacity);
        }
        self.write_uniforms();
        self.stats.frame += 1;
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("frame: encoder") });
        let count = self.make_mesh(&mut encoder, timed);
        let measured = self.encode_measures(&mut encoder, count);
        let show_views = self.views_shown();
        if show_views && self.teaching.views.is_none() {
            let pipelines = self.shade.pipelines().views(&self.device);
            self.teaching.views = Some(ViewState::new(
                &self.device,
                pipelines,
                &self.scene_buffers,
                &self.stage.buffers,
                self.shade.uniform(),
            ));
        }
        let shown = views::shown(&self.settings.view);
        let selected = self.teaching.selected.is_some();
        let frame_views = match (&self.teaching.views, show_views) {
            (Some(state), true) => {
                let pipelines = self.shade.pipelines().views(&self.device);
                state.encode(&mut encoder, pipelines, &shown);
                let crossings = self.stage.active().crossings();
                Some(ViewFrame { state, pipelines, options: &shown, selected, crossings })
            }
            _ => None,
        };
        let timing = self.stats.timing_for(timed);
        let buffers = &self.stage.buffers;
        let mesh = MeshDraw {
            vertices: &buffers.vertices,
            indices: &buffers.indices,
            draw_args: &buffers.draw_args,
            count,
            light_slots: self.settings.view.lights.slots(),
            front_only: self.back_faces_hidden(),
        };
        self.shade.encode(&mut encoder, view, mesh, frame_views, timing.map(|t| t.render_writes(4)));
        if let Some(timing) = timing {
            timing.resolve(&mut encoder);
        }
        self.submit_counted(encoder, self.stats.frame, measured);
    }

    /// Submits `encoder` with a copy of the counters, when the device counted the mesh or measured it,
    /// that comes back as the figures of frame `frame` (0: never shown, but the buffers grow for it).
    fn submit_counted(&mut self, mut encoder: wgpu::CommandEncoder, frame: u64, measured: bool) {
        let counted = self.stage.counted.on_device;
        let buffers = &self.stage.buffers;
        let slot =
            if counted || measured { self.stats.ring.record(&mut encoder, &buffers.counters) } else { None };
        self.queue.submit([encoder.finish()]);
        if let Some(slot) = slot {
            self.stats.ring.map(slot, frame, buffers.capacity, counted, measured);
        }
    }

    /// Asks the device for timestamp queries, if it has them, so that `render_timed` can report the
    /// GPU time of each stage. Returns whether it can.
    pub fn enable_timing(&mut self) -> bool {
        self.stats.enable_timing(&self.device, &self.queue)
    }

    /// Draws a frame like `render` and waits for the GPU time of each stage (tools and benchmarks; it
    /// stalls). `None` without timestamp queries (`enable_timing`).
    pub async fn render_timed(&mut self, view: &wgpu::TextureView) -> Option<StageTimes> {
        self.stats.timing.as_ref()?;
        self.render_frame(view, true);
        self.read_timing().await
    }

    /// Draws a frame with timestamp queries, where the device has them (`enable_timing`), without
    /// waiting: `read_timing` then waits for its GPU time per stage. Benchmarks time the CPU's part of
    /// a frame (selection, encoding, submission) between the two.
    pub fn render_for_timing(&mut self, view: &wgpu::TextureView) {
        let timed = self.stats.timing.is_some();
        self.render_frame(view, timed);
    }

    /// The GPU time per stage of the frame `render_for_timing` drew; `None` without timestamp queries.
    pub async fn read_timing(&self) -> Option<StageTimes> {
        let timing = self.stats.timing.as_ref()?;
        Some(timing.read(&self.device, &self.queue).await)
    }

    /// Makes the mesh alone for the current state, without drawing or waiting: the chosen extractor's
    /// work and its upload (benchmarks time it against `Queue::on_submitted_work_done`), meshed anew
    /// even where the mesh of the same state is kept.
    pub fn extract(&mut self) {
        self.stage.forget_meshes();
        self.write_uniforms();
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("extract: encoder") });
        self.cull_lod = false;
        self.make_mesh(&mut encoder, false);
        self.cull_lod = true;
        // What the whole surface needed comes back as frame 0's figures, never shown, so that the
        // buffers grow for the next readback: level of detail meshes more here than in a frame drawn,
        // which leaves out what is outside the view.
        self.submit_counted(encoder, 0, false);
    }
}

impl Drop for Renderer {
    /// Frees the GPU memory at once: a view removed from a page gives its buffers back.
    fn drop(&mut self) {
        self.stage.destroy();
        self.shade.destroy();
        self.teaching.drop_views();
    }
}

fn sample_count(antialiasing: bool) -> u32 {
    if antialiasing { MULTISAMPLES } else { 1 }
}
