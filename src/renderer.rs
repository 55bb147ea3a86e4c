//! One renderer for every output: it owns the scene, the settings and the passes, and draws a frame into
//! any texture view of its format (a canvas's current texture or an offscreen texture).

use crate::blocks::BlockPass;
use crate::context::{GpuContext, RendererToken};
use crate::field_pass::FieldPass;
use crate::gpu::read_buffer;
use crate::marching_cubes::MarchingCubesPass;
use crate::mesh::IndexedMesh;
use crate::mesh_buffers::{BLOCK_CELLS, Capacity, INDEX_BYTES, MeshBuffers, VERTEX_BYTES};
use crate::params::{self, Camera, MAX_RESOLUTION, MIN_RESOLUTION, Material, ParamError, Settings};
use crate::reference::Grid;
use crate::scene::{BOX_HALF_EXTENT, Scene};
use crate::scene_buffers::SceneBuffers;
use crate::shade::{MULTISAMPLES, ShadePass};
use crate::timing::{StageTimes, Timing};
use crate::uniforms::{Counters, GridUniform, ShadingUniform};
use glam::{UVec3, Vec3};
use std::sync::Arc;
use std::sync::atomic::{AtomicU8, Ordering};

/// What the GPU reported for a past frame (a frame or two late; nothing waits for it).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameStats {
    /// Which frame (counted from 1) these figures are for.
    pub frame: u64,
    /// Triangles written and drawn.
    pub triangles: u32,
    /// Triangles the surface needed; more than `max_triangles` when the index buffer overflowed.
    pub triangles_requested: u32,
    /// Capacity of the index buffer, in triangles.
    pub max_triangles: u32,
    /// Shared vertices the surface needed.
    pub vertices: u32,
    /// Blocks of 4³ cells the surface may cross (the others were skipped).
    pub active_blocks: u32,
    /// Blocks in the grid.
    pub total_blocks: u32,
    /// Cells that emitted triangles.
    pub active_cells: u32,
    /// Cells in the grid.
    pub total_cells: u32,
    /// True when some buffer was too small for this frame, so part of the surface was not drawn (the
    /// buffers grow for the next frames).
    pub overflowed: bool,
    /// GPU memory held by the mesh buffers, in bytes.
    pub mesh_bytes: u64,
}

impl FrameStats {
    /// True when the surface needed more room than the buffers had, so some of it was not drawn.
    pub fn overflowed(&self) -> bool {
        self.overflowed
    }
}

const SLOT_FREE: u8 = 0;
const SLOT_PENDING: u8 = 1;
const SLOT_READY: u8 = 2;
/// Staging buffers for the statistics: enough that a slow map never makes a frame skip its copy.
const STATS_SLOTS: usize = 3;

struct StatsSlot {
    buffer: wgpu::Buffer,
    state: Arc<AtomicU8>,
    frame: u64,
    capacity: Capacity,
}

/// How the buffers are sized.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Sizing {
    /// Start from `Capacity::for_grid` and grow when a frame reports it needed more.
    Automatic,
    /// A fixed triangle budget (tests and tools); overflow is reported, nothing grows.
    FixedTriangles(u32),
}

/// Draws merging spheres: block skipping, field, marching cubes and shading, every frame on the GPU.
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
    blocks: BlockPass,
    field: FieldPass,
    marching: MarchingCubesPass,
    shade: ShadePass,
    sizing: Sizing,
    /// Capacity a past frame asked for, applied before the next one.
    pending_capacity: Option<Capacity>,
    stats_slots: Vec<StatsSlot>,
    latest_stats: Option<FrameStats>,
    frame: u64,
    timing: Option<Timing>,
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
        check_resolution_fits(&device, settings.resolution)?;
        let scene = Scene::new(settings.seed, settings.sphere_count)?;

        let pipelines = context.pipelines();
        let scene_buffers = SceneBuffers::new(&device);
        let grid = Grid { cells_per_axis: settings.resolution };
        let mesh = MeshBuffers::new(&device, grid, automatic_capacity(&device, grid));
        let mut renderer = Self {
            blocks: pipelines.blocks.clone(),
            field: pipelines.field.clone(),
            marching: pipelines.marching.clone(),
            shade: ShadePass::new(
                &device,
                context.shade_pipelines(format, sample_count(settings.antialiasing)),
                width,
                height,
            ),
            stats_slots: (0..STATS_SLOTS)
                .map(|_| StatsSlot {
                    buffer: device.create_buffer(&wgpu::BufferDescriptor {
                        label: Some("stats: staging"),
                        size: std::mem::size_of::<Counters>() as u64,
                        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                        mapped_at_creation: false,
                    }),
                    state: Arc::new(AtomicU8::new(SLOT_FREE)),
                    frame: 0,
                    capacity: mesh.capacity,
                })
                .collect(),
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
        };
        renderer.bind_passes();
        Ok(renderer)
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
        self.mesh.bytes() + self.shade.bytes()
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

    /// Takes in the statistics that have arrived since the last frame, without drawing (a paused view
    /// calls this so its figures still come in).
    pub fn poll_stats(&mut self) {
        self.collect_stats();
    }

    /// The newest statistics the GPU has reported, if any yet.
    pub fn stats(&self) -> Option<FrameStats> {
        self.latest_stats
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
        check_resolution_fits(&self.device, settings.resolution)?;
        if settings.seed != self.settings.seed {
            self.scene = Scene::new(settings.seed, settings.sphere_count)?;
        } else if settings.sphere_count != self.settings.sphere_count {
            self.scene.set_count(settings.sphere_count)?;
        }
        let resolution_changed = settings.resolution != self.settings.resolution;
        if settings.antialiasing != self.settings.antialiasing {
            let (width, height) = self.size;
            let pipelines = self.context.shade_pipelines(self.format, sample_count(settings.antialiasing));
            self.shade.destroy();
            self.shade = ShadePass::new(&self.device, pipelines, width, height);
        }
        self.settings = settings;
        if resolution_changed {
            self.reallocate(self.starting_capacity());
        }
        Ok(())
    }

    /// Puts `count` spheres in play (1 to `MAX_SPHERES`).
    pub fn set_sphere_count(&mut self, count: u32) -> Result<(), ParamError> {
        self.set_settings(Settings { sphere_count: count, ..self.settings })
    }

    /// Sets the level the surface is drawn at.
    pub fn set_iso(&mut self, iso: f32) -> Result<(), ParamError> {
        self.set_settings(Settings { iso, ..self.settings })
    }

    /// Sets the cells per axis; the old grid's buffers are freed.
    pub fn set_resolution(&mut self, cells_per_axis: u32) -> Result<(), ParamError> {
        self.set_settings(Settings { resolution: cells_per_axis, ..self.settings })
    }

    /// Draws a new layout from `seed`.
    pub fn set_seed(&mut self, seed: u64) -> Result<(), ParamError> {
        self.set_settings(Settings { seed, ..self.settings })
    }

    /// Sets the surface material.
    pub fn set_material(&mut self, material: Material) -> Result<(), ParamError> {
        self.set_settings(Settings { material, ..self.settings })
    }

    /// Moves the light.
    pub fn set_light_position(&mut self, position: Vec3) -> Result<(), ParamError> {
        self.set_settings(Settings { light_position: position, ..self.settings })
    }

    /// Turns 4× multisampling on or off.
    pub fn set_antialiasing(&mut self, on: bool) -> Result<(), ParamError> {
        self.set_settings(Settings { antialiasing: on, ..self.settings })
    }

    /// Moves the camera.
    pub fn set_camera(&mut self, camera: Camera) -> Result<(), ParamError> {
        self.set_settings(Settings { camera, ..self.settings })
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

    /// Fixes the triangle budget (`None` returns to buffers that grow with the surface). Past a fixed
    /// budget, triangles are dropped and `stats` says so.
    pub fn set_max_triangles(&mut self, max_triangles: Option<u32>) -> Result<(), ParamError> {
        self.sizing = match max_triangles {
            Some(n) => {
                let fits = Capacity::largest(self.grid(), storage_limit(&self.device)).indices / 3;
                Sizing::FixedTriangles(params::check_u32("triangle budget", n, 1, fits)?)
            }
            None => Sizing::Automatic,
        };
        self.reallocate(self.starting_capacity());
        Ok(())
    }

    fn grid(&self) -> Grid {
        Grid { cells_per_axis: self.settings.resolution }
    }

    fn starting_capacity(&self) -> Capacity {
        let automatic = automatic_capacity(&self.device, self.grid());
        match self.sizing {
            Sizing::Automatic => automatic,
            // Everything but the index buffer holds the whole grid, so only triangles overflow.
            Sizing::FixedTriangles(n) => {
                let largest = Capacity::largest(self.grid(), storage_limit(&self.device));
                Capacity { vertices: largest.vertices.min(3 * largest.cells), indices: 3 * n, ..largest }
            }
        }
    }

    fn reallocate(&mut self, capacity: Capacity) {
        self.mesh.destroy();
        self.mesh = MeshBuffers::new(&self.device, self.grid(), capacity);
        self.pending_capacity = None;
        self.bind_passes();
    }

    fn bind_passes(&mut self) {
        self.blocks.bind(&self.device, &self.scene_buffers, &self.mesh);
        self.field.bind(&self.device, &self.scene_buffers, &self.mesh);
        self.marching.bind(&self.device, &self.scene_buffers, &self.mesh);
    }

    fn write_uniforms(&self) {
        let grid = self.grid();
        let spheres = self.scene.spheres();
        let capacity = self.mesh.capacity;
        let grid_uniform = GridUniform {
            box_min: [-BOX_HALF_EXTENT; 3],
            cell_size: grid.cell_size(),
            iso: self.settings.iso,
            cells_per_axis: grid.cells_per_axis,
            sphere_count: spheres.len() as u32,
            max_blocks: capacity.blocks,
            max_vertices: capacity.vertices,
            max_indices: capacity.indices,
            max_cells: capacity.cells,
            _pad: 0,
        };
        self.queue.write_buffer(&self.scene_buffers.grid, 0, bytemuck::bytes_of(&grid_uniform));
        let packed: Vec<[f32; 4]> = spheres.iter().map(|s| s.to_gpu()).collect();
        self.queue.write_buffer(&self.scene_buffers.spheres, 0, bytemuck::cast_slice(&packed));

        let s = &self.settings;
        let eye = s.camera.eye();
        let aspect = self.size.0 as f32 / self.size.1 as f32;
        let projection = glam::camera::rh::proj::directx::perspective(
            s.camera.fov_y_degrees.to_radians(),
            aspect,
            0.05,
            100.0,
        );
        let view = glam::camera::rh::view::look_at_mat4(eye, Vec3::ZERO, Vec3::Y);
        let shading = ShadingUniform {
            view_proj: (projection * view).to_cols_array_2d(),
            camera_position: eye.to_array(),
            ambient: s.material.ambient,
            light_position: s.light_position.to_array(),
            diffuse: s.material.diffuse,
            base_color: s.material.base_color.to_array(),
            specular: s.material.specular,
            shininess: s.material.shininess,
            encode_srgb: (!self.format.is_srgb()) as u32,
            box_half_extent: BOX_HALF_EXTENT,
            _pad: 0,
        };
        self.queue.write_buffer(self.shade.uniform(), 0, bytemuck::bytes_of(&shading));
    }

    /// Records the extraction passes: blocks, field, marching cubes.
    fn encode_extraction(&self, encoder: &mut wgpu::CommandEncoder, timed: bool) {
        let timing = self.timing.as_ref().filter(|_| timed);
        self.blocks.encode(encoder, &self.mesh, timing.map(|t| t.compute_writes(0)));
        self.field.encode(encoder, &self.mesh, timing.map(|t| t.compute_writes(1)));
        self.marching.encode(encoder, &self.mesh, timing.map(|t| t.compute_writes(2)));
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
        self.encode_extraction(&mut encoder, timed);
        let timing = self.timing.as_ref().filter(|_| timed);
        self.shade.encode(&mut encoder, view, &self.mesh, timing.map(|t| t.render_writes(3)));
        if let Some(timing) = timing {
            timing.resolve(&mut encoder);
        }
        // With every staging buffer still in flight, this frame's figures are skipped.
        let slot = self.stats_slots.iter_mut().find(|s| s.state.load(Ordering::Acquire) == SLOT_FREE);
        if let Some(slot) = &slot {
            encoder.copy_buffer_to_buffer(&self.mesh.counters, 0, &slot.buffer, 0, None);
        }
        self.queue.submit([encoder.finish()]);
        if let Some(slot) = slot {
            slot.frame = self.frame;
            slot.capacity = self.mesh.capacity;
            slot.state.store(SLOT_PENDING, Ordering::Release);
            let state = slot.state.clone();
            slot.buffer.map_async(wgpu::MapMode::Read, .., move |result| {
                state.store(if result.is_ok() { SLOT_READY } else { SLOT_FREE }, Ordering::Release);
            });
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

    /// Reads the statistics whose buffers have been mapped since the last call, and plans larger
    /// buffers when a frame overflowed.
    fn collect_stats(&mut self) {
        #[cfg(not(target_arch = "wasm32"))]
        let _ = self.device.poll(wgpu::PollType::Poll);
        let grid = self.grid();
        let total_blocks = grid.cells_per_axis.div_ceil(BLOCK_CELLS).pow(3);
        for slot in &mut self.stats_slots {
            if slot.state.load(Ordering::Acquire) != SLOT_READY {
                continue;
            }
            let counters: Counters = match slot.buffer.get_mapped_range(..) {
                Ok(bytes) => bytemuck::pod_read_unaligned(&bytes),
                Err(_) => Counters::default(),
            };
            slot.buffer.unmap();
            slot.state.store(SLOT_FREE, Ordering::Release);
            let capacity = slot.capacity;
            let stats = FrameStats {
                frame: slot.frame,
                triangles: counters.indices.min(capacity.indices) / 3,
                triangles_requested: counters.indices / 3,
                max_triangles: capacity.indices / 3,
                vertices: counters.vertices,
                active_blocks: counters.active_blocks,
                total_blocks,
                active_cells: counters.active_cells,
                total_cells: grid.cells_per_axis.pow(3),
                overflowed: !capacity.holds(&counters),
                mesh_bytes: self.mesh.bytes(),
            };
            if self.latest_stats.is_none_or(|s| s.frame < stats.frame) {
                self.latest_stats = Some(stats);
            }
            // Grow once per size: figures from frames drawn with smaller buffers than now are stale.
            let current = self.pending_capacity.unwrap_or(self.mesh.capacity);
            if stats.overflowed && self.sizing == Sizing::Automatic && capacity == self.mesh.capacity {
                let largest = Capacity::largest(grid, storage_limit(&self.device));
                let grown = current.grown_for(&counters).min(largest);
                if grown != current {
                    self.pending_capacity = Some(grown);
                }
            }
        }
    }

    /// Waits until the statistics of every submitted frame are in (tests and tools).
    pub async fn flush_stats(&mut self) {
        if self.stats_slots.iter().any(|s| s.state.load(Ordering::Acquire) == SLOT_PENDING) {
            let (sender, receiver) = futures_channel::oneshot::channel::<()>();
            // Queue work done implies earlier map callbacks have run.
            self.queue.on_submitted_work_done(move || {
                let _ = sender.send(());
            });
            #[cfg(not(target_arch = "wasm32"))]
            let _ = self.device.poll(wgpu::PollType::wait_indefinitely());
            let _ = receiver.await;
        }
        self.collect_stats();
    }

    /// Runs the mesh generation passes alone for the current state, without drawing or waiting
    /// (benchmarks time it against `Queue::on_submitted_work_done`).
    pub fn extract(&mut self) {
        self.write_uniforms();
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("extract: encoder") });
        self.encode_extraction(&mut encoder, false);
        self.queue.submit([encoder.finish()]);
    }

    async fn run_extraction(&mut self) -> Counters {
        self.extract();
        let bytes = read_buffer(&self.device, &self.queue, &self.mesh.counters, 0, 16).await;
        bytemuck::pod_read_unaligned(&bytes)
    }

    /// Extracts the surface for the current state and reads the indexed mesh back, growing the buffers
    /// first if the surface needs it (unless the budget is fixed). Waits for the GPU: for tests and
    /// tools, not the frame loop.
    pub async fn extract_mesh(&mut self) -> IndexedMesh {
        let mut counters = self.run_extraction().await;
        while self.sizing == Sizing::Automatic && !self.mesh.capacity.holds(&counters) {
            let largest = Capacity::largest(self.grid(), storage_limit(&self.device));
            let grown = self.mesh.capacity.grown_for(&counters).min(largest);
            if grown == self.mesh.capacity {
                break;
            }
            self.reallocate(grown);
            counters = self.run_extraction().await;
        }
        let capacity = self.mesh.capacity;
        let vertex_count = counters.vertices.min(capacity.vertices) as u64;
        let index_count = counters.indices.min(capacity.indices) as u64;
        let vertex_bytes =
            read_buffer(&self.device, &self.queue, &self.mesh.vertices, 0, vertex_count * VERTEX_BYTES).await;
        let index_bytes =
            read_buffer(&self.device, &self.queue, &self.mesh.indices, 0, index_count * INDEX_BYTES).await;
        let floats: &[[f32; 6]] = bytemuck::cast_slice(&vertex_bytes);
        let indices: &[u32] = bytemuck::cast_slice(&index_bytes);
        IndexedMesh {
            positions: floats.iter().map(|v| Vec3::new(v[0], v[1], v[2])).collect(),
            normals: floats.iter().map(|v| Vec3::new(v[3], v[4], v[5])).collect(),
            triangles: indices.chunks(3).map(|t| [t[0], t[1], t[2]]).collect(),
        }
    }

    /// The field values the GPU computed for the current state: every grid point of every active block,
    /// with its grid coordinates (a point on a face between blocks appears once per block).
    pub async fn extract_field(&mut self) -> Vec<(UVec3, f32)> {
        let counters = self.run_extraction().await;
        let active = counters.active_blocks.min(self.mesh.capacity.blocks) as u64;
        let blocks = read_buffer(&self.device, &self.queue, &self.mesh.active_blocks, 0, active * 4).await;
        let values = read_buffer(&self.device, &self.queue, &self.mesh.block_values, 0, active * 500).await;
        let blocks: &[u32] = bytemuck::cast_slice(&blocks);
        let values: &[f32] = bytemuck::cast_slice(&values);
        let n = self.settings.resolution;
        let per_axis = n.div_ceil(BLOCK_CELLS);
        let mut points = Vec::new();
        for (slot, &block) in blocks.iter().enumerate() {
            let coords =
                UVec3::new(block % per_axis, (block / per_axis) % per_axis, block / (per_axis * per_axis));
            for i in 0..125u32 {
                let id = coords * BLOCK_CELLS + UVec3::new(i % 5, (i / 5) % 5, i / 25);
                if id.max_element() <= n {
                    points.push((id, values[slot * 125 + i as usize]));
                }
            }
        }
        points
    }
}

impl Drop for Renderer {
    /// Frees the GPU memory at once: a view removed from a page gives its buffers back.
    fn drop(&mut self) {
        self.mesh.destroy();
        self.shade.destroy();
    }
}

fn sample_count(antialiasing: bool) -> u32 {
    if antialiasing { MULTISAMPLES } else { 1 }
}

fn storage_limit(device: &wgpu::Device) -> u64 {
    let limits = device.limits();
    limits.max_storage_buffer_binding_size.min(limits.max_buffer_size)
}

fn automatic_capacity(device: &wgpu::Device, grid: Grid) -> Capacity {
    Capacity::for_grid(grid).min(Capacity::largest(grid, storage_limit(device)))
}

/// The largest resolution this device can run: its block table must fit one storage binding and its
/// block pass one dispatch.
pub fn max_resolution(device: &wgpu::Device) -> u32 {
    (MIN_RESOLUTION..=MAX_RESOLUTION)
        .rev()
        .find(|&n| resolution_fits(device, n).is_ok())
        .unwrap_or(MIN_RESOLUTION)
}

fn resolution_fits(device: &wgpu::Device, cells_per_axis: u32) -> Result<(), String> {
    let blocks = (cells_per_axis.div_ceil(BLOCK_CELLS) as u64).pow(3);
    let needed = blocks * 4;
    if needed > storage_limit(device) {
        return Err(format!(
            "its block table needs {:.1} MiB but the device's max_storage_buffer_binding_size is {:.1} MiB",
            needed as f64 / 1048576.0,
            storage_limit(device) as f64 / 1048576.0
        ));
    }
    let groups = blocks.div_ceil(64);
    let max_groups = device.limits().max_compute_workgroups_per_dimension as u64;
    if groups > max_groups {
        return Err(format!(
            "it needs {groups} workgroups in one dispatch but the device's max_compute_workgroups_per_dimension \
             is {max_groups}"
        ));
    }
    Ok(())
}

fn check_resolution_fits(device: &wgpu::Device, cells_per_axis: u32) -> Result<(), ParamError> {
    params::check_resolution(cells_per_axis)?;
    resolution_fits(device, cells_per_axis).map_err(|detail| ParamError::DeviceLimit {
        name: "resolution",
        value: cells_per_axis.to_string(),
        detail: format!("{detail}; the largest resolution it holds is {}", max_resolution(device)),
    })
}

fn check_size(device: &wgpu::Device, width: u32, height: u32) -> Result<(), ParamError> {
    let max = device.limits().max_texture_dimension_2d;
    params::check_u32("output width (pixels)", width, 1, max)?;
    params::check_u32("output height (pixels)", height, 1, max)?;
    Ok(())
}
