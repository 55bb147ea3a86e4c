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
mod stats;
mod uniforms;

pub use limits::max_resolution;
pub use readback::{MeshReadback, OverlayReadback};
pub use stats::FrameStats;

use crate::device::timing::{StageTimes, Timing};
use crate::draw::measure::{MeasurePass, MeshMeasures};
use crate::draw::shade::{MULTISAMPLES, MeshDraw, ShadePass, ViewFrame};
use crate::draw::views::{self, ViewState};
use crate::extract::Extractor;
use crate::extract::buffers::{BLOCK_CELLS, Capacity, MeshBuffers};
use crate::extract::gpu::scene_buffers::SceneBuffers;
use crate::extract::reference::Grid;
use crate::scene::Scene;
use crate::scene::params::{ParamError, Settings};
use context::{GpuContext, RendererToken};
use glam::UVec3;
use limits::{automatic_capacity, check_resolution_fits, check_size};
use stats::StatsRing;

/// How the buffers are sized.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Sizing {
    /// Start from `Capacity::for_grid` and grow when a frame reports it needed more.
    Automatic,
    /// A fixed triangle budget (tests and tools); overflow is reported, nothing grows.
    FixedTriangles(u32),
}

/// Draws merging spheres: block skipping, field and marching cubes (in GPU compute passes or on the
/// CPU), then shading.
pub struct Renderer {
    context: GpuContext,
    _alive: RendererToken,
    device: wgpu::Device,
    queue: wgpu::Queue,
    format: wgpu::TextureFormat,
    size: (u32, u32),
    settings: Settings,
    scene: Scene,
    scene_buffers: SceneBuffers,
    mesh: MeshBuffers,
    /// Every extractor the device runs, in order of preference (`extract::EXTRACTORS`).
    extractors: Vec<Box<dyn Extractor>>,
    /// Which of them made the latest frame's mesh.
    active: usize,
    /// Which of them `pin_extractor` fixed, if any.
    pinned: Option<usize>,
    /// True when the latest frame's mesh was counted on the device (its statistics come back later).
    counted_on_device: bool,
    /// The latest mesh is known to be closed: whole, by marching cubes, counted on the CPU.
    mesh_closed: bool,
    /// Indices the latest frame drew, when counted on the CPU.
    drawn: Option<u32>,
    shade: ShadePass,
    sizing: Sizing,
    /// Capacity a past frame asked for, applied before the next one.
    pending_capacity: Option<Capacity>,
    stats: StatsRing,
    latest_stats: Option<FrameStats>,
    frame: u64,
    timing: Option<Timing>,
    /// The teaching views' buffers, made when a view needs them.
    views: Option<ViewState>,
    /// The cell the inspector shows, if any.
    selected: Option<UVec3>,
    /// The measures pass, made when a view first asks for the mesh's error or shape.
    measures: Option<MeasurePass>,
    latest_measures: Option<MeshMeasures>,
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
        check_size(&device, width, height)?;
        let lod = settings.view.lod;
        if !lod {
            check_resolution_fits(&device, settings.resolution)?;
        }
        let scene = Scene::new(settings.seed, settings.sphere_count)?;

        let scene_buffers = SceneBuffers::new(&device);
        let grid = Grid { cells_per_axis: settings.resolution };
        let capacity = automatic_capacity(&device, grid, lod, context.has_compute());
        let buffer_grid = if lod { Grid { cells_per_axis: BLOCK_CELLS } } else { grid };
        let mesh = MeshBuffers::new(&device, buffer_grid, capacity);
        Ok(Self {
            extractors: context.extractors().iter().map(|e| e.fresh()).collect(),
            active: 0,
            pinned: None,
            counted_on_device: false,
            mesh_closed: false,
            drawn: None,
            shade: ShadePass::new(
                &device,
                context.shade_pipelines(format, sample_count(settings.antialiasing)),
                width,
                height,
            ),
            stats: StatsRing::new(&device),
            _alive: context.renderer_token(),
            context: context.clone(),
            device,
            queue,
            format,
            size: (width, height),
            settings,
            scene,
            scene_buffers,
            mesh,
            sizing: Sizing::Automatic,
            pending_capacity: None,
            latest_stats: None,
            frame: 0,
            timing: None,
            views: None,
            measures: None,
            latest_measures: None,
            selected: None,
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
        self.format
    }

    /// The output size in pixels.
    pub fn size(&self) -> (u32, u32) {
        self.size
    }

    /// The largest resolution this device holds.
    pub fn max_resolution(&self) -> u32 {
        max_resolution(&self.device)
    }

    /// What the mesh buffers hold now.
    pub fn capacity(&self) -> Capacity {
        self.mesh.capacity
    }

    /// GPU memory held by the mesh buffers, in bytes.
    pub fn mesh_bytes(&self) -> u64 {
        self.mesh.bytes()
    }

    /// GPU memory held by this renderer's own buffers and targets (not the shared pipelines), in bytes.
    pub fn gpu_bytes(&self) -> u64 {
        self.mesh.bytes() + self.shade.bytes() + self.views.as_ref().map_or(0, ViewState::bytes)
    }

    /// The device context this renderer draws on.
    pub fn context(&self) -> &GpuContext {
        &self.context
    }

    /// True when a past frame asked for larger buffers, so the next frame would differ from the last
    /// even with nothing else changed.
    pub fn needs_redraw(&self) -> bool {
        self.pending_capacity.is_some()
    }

    /// The newest statistics the GPU has reported, if any yet.
    pub fn stats(&self) -> Option<FrameStats> {
        self.latest_stats
    }

    /// Frames rendered so far: the newest frame's statistics carry this number once read back.
    pub fn frames_rendered(&self) -> u64 {
        self.frame
    }

    /// The first GPU error raised outside an error scope, if any (they are also logged).
    pub fn gpu_error(&self) -> Option<String> {
        self.context.gpu_error()
    }

    /// Follows a new output size.
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), ParamError> {
        check_size(&self.device, width, height)?;
        if (width, height) != self.size {
            self.shade.resize(&self.device, width, height);
            self.size = (width, height);
        }
        Ok(())
    }

    /// Applies all settings at once, or none if any is refused.
    pub fn set_settings(&mut self, settings: Settings) -> Result<(), ParamError> {
        let settings = settings.validated()?;
        if !settings.view.lod {
            check_resolution_fits(&self.device, settings.resolution)?;
        }
        if settings.seed != self.settings.seed {
            self.scene = Scene::new(settings.seed, settings.sphere_count)?;
        } else if settings.sphere_count != self.settings.sphere_count {
            self.scene.set_count(settings.sphere_count)?;
        }
        let resolution_changed =
            settings.resolution != self.settings.resolution || settings.view.lod != self.settings.view.lod;
        if settings.antialiasing != self.settings.antialiasing {
            let (width, height) = self.size;
            let pipelines = self.context.shade_pipelines(self.format, sample_count(settings.antialiasing));
            self.shade.destroy();
            self.shade = ShadePass::new(&self.device, pipelines, width, height);
            self.drop_views();
        }
        self.settings = settings;
        if resolution_changed {
            self.selected = None;
            self.reallocate(self.starting_capacity());
        }
        Ok(())
    }

    fn drop_views(&mut self) {
        if let Some(views) = self.views.take() {
            views.destroy();
        }
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

    fn reallocate(&mut self, capacity: Capacity) {
        self.mesh.destroy();
        self.mesh = MeshBuffers::new(&self.device, self.buffer_grid(), capacity);
        self.pending_capacity = None;
        self.follow_new_buffers();
    }

    /// What was bound to the old buffers (the teaching views, the extractors' passes) is bound again
    /// when next used.
    fn follow_new_buffers(&mut self) {
        self.drop_views();
        if let Some(measures) = &mut self.measures {
            measures.unbind();
        }
        for extractor in &mut self.extractors {
            extractor.buffers_changed();
        }
    }

    /// Draws one frame into `view` (a texture of this renderer's format and size). Never waits on the
    /// GPU: statistics come back asynchronously through `stats`.
    pub fn render(&mut self, view: &wgpu::TextureView) {
        self.render_frame(view, false);
    }

    fn render_frame(&mut self, view: &wgpu::TextureView, timed: bool) {
        self.collect_stats();
        if let Some(capacity) = self.pending_capacity.take() {
            self.reallocate(capacity);
        }
        self.write_uniforms();
        self.frame += 1;
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("frame: encoder") });
        let count = self.make_mesh(&mut encoder, timed);
        let measured = self.encode_measures(&mut encoder, count);
        let show_views = self.views_shown();
        if show_views && self.views.is_none() {
            let pipelines = self.shade.pipelines().views(&self.device);
            self.views = Some(ViewState::new(
                &self.device,
                pipelines,
                &self.scene_buffers,
                &self.mesh,
                self.shade.uniform(),
            ));
        }
        let shown = views::shown(&self.settings.view);
        let frame_views = match (&self.views, show_views) {
            (Some(state), true) => {
                let pipelines = self.shade.pipelines().views(&self.device);
                state.encode(&mut encoder, pipelines, &shown);
                Some(ViewFrame { state, pipelines, options: &shown, selected: self.selected.is_some() })
            }
            _ => None,
        };
        let timing = self.timing.as_ref().filter(|_| timed);
        let mesh = MeshDraw {
            vertices: &self.mesh.vertices,
            indices: &self.mesh.indices,
            draw_args: &self.mesh.draw_args,
            count,
            light_slots: self.settings.view.lights.slots(),
            front_only: self.back_faces_hidden(),
        };
        self.shade.encode(&mut encoder, view, mesh, frame_views, timing.map(|t| t.render_writes(3)));
        if let Some(timing) = timing {
            timing.resolve(&mut encoder);
        }
        let counted = self.counted_on_device;
        let slot =
            if counted || measured { self.stats.record(&mut encoder, &self.mesh.counters) } else { None };
        self.queue.submit([encoder.finish()]);
        if let Some(slot) = slot {
            self.stats.map(slot, self.frame, self.mesh.capacity, counted, measured);
        }
    }

    /// Asks the device for timestamp queries, if it has them, so that `render_timed` can report the
    /// GPU time of each stage. Returns whether it can.
    pub fn enable_timing(&mut self) -> bool {
        if self.timing.is_none() {
            self.timing = Timing::new(&self.device, &self.queue);
        }
        self.timing.is_some()
    }

    /// Draws a frame like `render` and waits for the GPU time of each stage (tools and benchmarks; it
    /// stalls). `None` without timestamp queries (`enable_timing`).
    pub async fn render_timed(&mut self, view: &wgpu::TextureView) -> Option<StageTimes> {
        self.timing.as_ref()?;
        self.render_frame(view, true);
        let timing = self.timing.as_ref()?;
        Some(timing.read(&self.device, &self.queue).await)
    }

    /// Makes the mesh alone for the current state, without drawing or waiting: the chosen extractor's
    /// work and its upload (benchmarks time it against `Queue::on_submitted_work_done`).
    pub fn extract(&mut self) {
        self.write_uniforms();
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("extract: encoder") });
        self.make_mesh(&mut encoder, false);
        self.queue.submit([encoder.finish()]);
    }
}

impl Drop for Renderer {
    /// Frees the GPU memory at once: a view removed from a page gives its buffers back.
    fn drop(&mut self) {
        self.mesh.destroy();
        self.shade.destroy();
        self.drop_views();
    }
}

fn sample_count(antialiasing: bool) -> u32 {
    if antialiasing { MULTISAMPLES } else { 1 }
}
