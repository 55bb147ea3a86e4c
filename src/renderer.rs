//! One renderer for every output: it owns the scene, the settings and the passes, and draws a frame into
//! any texture view of its format (a canvas's current texture or an offscreen texture).

use crate::field_pass::{FieldPass, SceneBuffers, field_bytes, workgroups};
use crate::marching_cubes::{MarchingCubesPass, VERTEX_BYTES};
use crate::mesh::Mesh;
use crate::params::{
    self, Camera, MAX_RESOLUTION, MAX_SPHERES, MIN_RESOLUTION, Material, ParamError, Settings,
};
use crate::reference::Grid;
use crate::scene::{BOX_HALF_EXTENT, Scene};
use crate::shade::ShadePass;
use crate::uniforms::{Counters, GridUniform, ShadingUniform};
use glam::Vec3;
use std::sync::atomic::{AtomicU8, Ordering};
use std::sync::{Arc, Mutex};

/// Triangles the vertex buffer holds per cell of one face of the grid: a surface crossing the grid
/// emits about two triangles per cell of its area, and this leaves room for several such sheets.
pub const TRIANGLES_PER_FACE_CELL: u64 = 16;

/// What the GPU reported for a past frame (a frame or two late; nothing waits for it).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameStats {
    /// Which frame (counted from 1) these figures are for.
    pub frame: u64,
    /// Triangles written and drawn.
    pub triangles: u32,
    /// Triangles the surface needed; above `max_triangles` when the budget overflowed.
    pub triangles_requested: u32,
    /// Capacity of the vertex buffer, in triangles.
    pub max_triangles: u32,
}

impl FrameStats {
    /// True when the surface needed more triangles than the buffer holds, so some were not drawn.
    pub fn overflowed(&self) -> bool {
        self.triangles_requested > self.max_triangles
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
    max_triangles: u32,
}

/// Draws merging spheres: field, marching cubes and shading, every frame on the GPU.
pub struct Renderer {
    device: wgpu::Device,
    queue: wgpu::Queue,
    format: wgpu::TextureFormat,
    size: (u32, u32),
    settings: Settings,
    scene: Scene,
    scene_buffers: SceneBuffers,
    field: FieldPass,
    marching: MarchingCubesPass,
    shade: ShadePass,
    stats_slots: Vec<StatsSlot>,
    latest_stats: Option<FrameStats>,
    frame: u64,
    gpu_error: Arc<Mutex<Option<String>>>,
    /// A triangle budget set by hand, replacing the one derived from the resolution.
    budget_override: Option<u32>,
}

impl Renderer {
    /// A renderer drawing into `width` × `height` textures of `format`, with validated `settings`.
    pub fn new(
        device: wgpu::Device,
        queue: wgpu::Queue,
        format: wgpu::TextureFormat,
        width: u32,
        height: u32,
        settings: Settings,
    ) -> Result<Self, ParamError> {
        let settings = settings.validated()?;
        check_size(&device, width, height)?;
        check_resolution_fits(&device, settings.resolution)?;
        let scene = Scene::new(settings.seed, settings.sphere_count)?;

        let gpu_error: Arc<Mutex<Option<String>>> = Arc::default();
        let sink = gpu_error.clone();
        device.on_uncaptured_error(Arc::new(move |error: wgpu::Error| {
            let message = error.to_string();
            log_error(&message);
            sink.lock().unwrap_or_else(|e| e.into_inner()).get_or_insert(message);
        }));

        let scene_buffers = SceneBuffers {
            grid: device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("scene: grid uniforms"),
                size: std::mem::size_of::<GridUniform>() as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }),
            spheres: device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("scene: spheres"),
                size: MAX_SPHERES as u64 * 16,
                usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }),
        };
        let grid = Grid { cells_per_axis: settings.resolution };
        let field = FieldPass::new(&device, &scene_buffers, grid);
        let max_vertices = vertex_budget(&device, settings.resolution);
        let marching = MarchingCubesPass::new(&device, &scene_buffers, field.field(), grid, max_vertices);
        let shade = ShadePass::new(&device, format, width, height);
        let stats_slots = (0..STATS_SLOTS)
            .map(|_| StatsSlot {
                buffer: device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some("stats: staging"),
                    size: std::mem::size_of::<Counters>() as u64,
                    usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                    mapped_at_creation: false,
                }),
                state: Arc::new(AtomicU8::new(SLOT_FREE)),
                frame: 0,
                max_triangles: 0,
            })
            .collect();
        Ok(Self {
            device,
            queue,
            format,
            size: (width, height),
            settings,
            scene,
            scene_buffers,
            field,
            marching,
            shade,
            stats_slots,
            latest_stats: None,
            frame: 0,
            gpu_error,
            budget_override: None,
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

    /// The newest statistics the GPU has reported, if any yet.
    pub fn stats(&self) -> Option<FrameStats> {
        self.latest_stats
    }

    /// The first GPU error raised outside an error scope, if any (they are also logged).
    pub fn gpu_error(&self) -> Option<String> {
        self.gpu_error.lock().unwrap_or_else(|e| e.into_inner()).clone()
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
        self.settings = settings;
        if resolution_changed {
            self.allocate_grid(settings.resolution);
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

    /// Sets how many triangles the vertex buffer holds, replacing the budget derived from the
    /// resolution (`None` returns to it). Past the budget, triangles are dropped and `stats` says so.
    pub fn set_max_triangles(&mut self, max_triangles: Option<u32>) -> Result<(), ParamError> {
        if let Some(n) = max_triangles {
            let fits = (storage_limit(&self.device) / (3 * VERTEX_BYTES)).min(u32::MAX as u64 / 3) as u32;
            params::check_u32("triangle budget", n, 1, fits)?;
        }
        self.budget_override = max_triangles;
        self.allocate_grid(self.settings.resolution);
        Ok(())
    }

    fn allocate_grid(&mut self, cells_per_axis: u32) {
        let grid = Grid { cells_per_axis };
        self.field.set_grid(&self.device, &self.scene_buffers, grid);
        let max_vertices = match self.budget_override {
            Some(triangles) => triangles * 3,
            None => vertex_budget(&self.device, cells_per_axis),
        };
        self.marching.set_grid(&self.device, &self.scene_buffers, self.field.field(), grid, max_vertices);
    }

    fn write_uniforms(&self) {
        let grid = Grid { cells_per_axis: self.settings.resolution };
        let spheres = self.scene.spheres();
        let grid_uniform = GridUniform {
            box_min: [-BOX_HALF_EXTENT; 3],
            cell_size: grid.cell_size(),
            iso: self.settings.iso,
            cells_per_axis: grid.cells_per_axis,
            sphere_count: spheres.len() as u32,
            max_vertices: self.marching.max_vertices(),
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

    /// Runs the field and marching-cubes passes into `encoder`.
    fn encode_extraction(&self, encoder: &mut wgpu::CommandEncoder) {
        self.field.encode(encoder);
        self.marching.encode(encoder);
    }

    /// Draws one frame into `view` (a texture of this renderer's format and size). Never waits on the
    /// GPU: statistics come back asynchronously through `stats`.
    pub fn render(&mut self, view: &wgpu::TextureView) {
        self.collect_stats();
        self.write_uniforms();
        self.frame += 1;
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("frame: encoder") });
        self.encode_extraction(&mut encoder);
        self.shade.encode(&mut encoder, view, self.marching.vertices(), self.marching.draw_args());
        // With every staging buffer still in flight, this frame's figures are skipped.
        let slot = self.stats_slots.iter_mut().find(|s| s.state.load(Ordering::Acquire) == SLOT_FREE);
        if let Some(slot) = &slot {
            encoder.copy_buffer_to_buffer(self.marching.counters(), 0, &slot.buffer, 0, None);
        }
        self.queue.submit([encoder.finish()]);
        if let Some(slot) = slot {
            slot.frame = self.frame;
            slot.max_triangles = self.marching.max_vertices() / 3;
            slot.state.store(SLOT_PENDING, Ordering::Release);
            let state = slot.state.clone();
            slot.buffer.map_async(wgpu::MapMode::Read, .., move |result| {
                state.store(if result.is_ok() { SLOT_READY } else { SLOT_FREE }, Ordering::Release);
            });
        }
    }

    /// Reads the statistics whose buffers have been mapped since the last call.
    fn collect_stats(&mut self) {
        #[cfg(not(target_arch = "wasm32"))]
        let _ = self.device.poll(wgpu::PollType::Poll);
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
            let requested = counters.vertices_requested / 3;
            let stats = FrameStats {
                frame: slot.frame,
                triangles: requested.min(slot.max_triangles),
                triangles_requested: requested,
                max_triangles: slot.max_triangles,
            };
            if self.latest_stats.is_none_or(|s| s.frame < stats.frame) {
                self.latest_stats = Some(stats);
            }
        }
    }

    /// Waits until the statistics of every submitted frame are in (tests and tools).
    pub async fn flush_stats(&mut self) {
        for slot in &self.stats_slots {
            if slot.state.load(Ordering::Acquire) == SLOT_PENDING {
                let (sender, receiver) = futures_channel::oneshot::channel::<()>();
                // Queue work done implies earlier map callbacks have run.
                self.queue.on_submitted_work_done(move || {
                    let _ = sender.send(());
                });
                #[cfg(not(target_arch = "wasm32"))]
                let _ = self.device.poll(wgpu::PollType::wait_indefinitely());
                let _ = receiver.await;
                break;
            }
        }
        self.collect_stats();
    }

    /// Extracts the surface for the current state and reads the mesh back. Waits for the GPU: for tests
    /// and tools, not the frame loop.
    pub async fn extract_mesh(&mut self) -> Mesh {
        self.write_uniforms();
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("extract: encoder") });
        self.encode_extraction(&mut encoder);
        self.queue.submit([encoder.finish()]);
        let counters = crate::gpu::read_buffer(
            &self.device,
            &self.queue,
            self.marching.counters(),
            0,
            std::mem::size_of::<Counters>() as u64,
        )
        .await;
        let counters: Counters = bytemuck::pod_read_unaligned(&counters);
        let vertex_count = counters.vertices_requested.min(self.marching.max_vertices());
        let bytes = crate::gpu::read_buffer(
            &self.device,
            &self.queue,
            self.marching.vertices(),
            0,
            vertex_count as u64 * VERTEX_BYTES,
        )
        .await;
        let floats: &[[f32; 6]] = bytemuck::cast_slice(&bytes);
        Mesh {
            positions: floats.iter().map(|v| Vec3::new(v[0], v[1], v[2])).collect(),
            normals: floats.iter().map(|v| Vec3::new(v[3], v[4], v[5])).collect(),
            edge_ids: Vec::new(),
        }
    }

    /// The field values of the current state, `(resolution + 1)³`, x fastest (tests and tools).
    pub async fn extract_field(&mut self) -> Vec<f32> {
        self.write_uniforms();
        let mut encoder = self.device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("field readback: encoder"),
        });
        self.field.encode(&mut encoder);
        self.queue.submit([encoder.finish()]);
        let bytes = crate::gpu::read_buffer(
            &self.device,
            &self.queue,
            self.field.field(),
            0,
            field_bytes(self.settings.resolution),
        )
        .await;
        bytemuck::cast_slice(&bytes).to_vec()
    }
}

fn log_error(message: &str) {
    #[cfg(target_arch = "wasm32")]
    web_sys::console::error_1(&format!("GPU error: {message}").into());
    #[cfg(not(target_arch = "wasm32"))]
    eprintln!("GPU error: {message}");
}

fn storage_limit(device: &wgpu::Device) -> u64 {
    let limits = device.limits();
    limits.max_storage_buffer_binding_size.min(limits.max_buffer_size)
}

/// The vertex buffer's capacity at a resolution: `TRIANGLES_PER_FACE_CELL` per cell of a face, within the
/// device's largest storage binding.
fn vertex_budget(device: &wgpu::Device, cells_per_axis: u32) -> u32 {
    let wanted = TRIANGLES_PER_FACE_CELL * (cells_per_axis as u64).pow(2);
    let fits = storage_limit(device) / (3 * VERTEX_BYTES);
    (wanted.min(fits).min(u32::MAX as u64 / 3) * 3) as u32
}

/// The largest resolution whose field fits the device.
pub fn max_resolution(device: &wgpu::Device) -> u32 {
    (MIN_RESOLUTION..=MAX_RESOLUTION)
        .rev()
        .find(|&n| resolution_fits(device, n).is_ok())
        .unwrap_or(MIN_RESOLUTION)
}

fn resolution_fits(device: &wgpu::Device, cells_per_axis: u32) -> Result<(), String> {
    let limits = device.limits();
    let needed = field_bytes(cells_per_axis);
    if needed > storage_limit(device) {
        return Err(format!(
            "its field needs {:.1} MiB but the device's max_storage_buffer_binding_size is {:.1} MiB",
            needed as f64 / 1048576.0,
            storage_limit(device) as f64 / 1048576.0
        ));
    }
    let groups = workgroups(cells_per_axis + 1);
    if groups > limits.max_compute_workgroups_per_dimension {
        return Err(format!(
            "it needs {groups} workgroups per axis but the device's max_compute_workgroups_per_dimension is {}",
            limits.max_compute_workgroups_per_dimension
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
