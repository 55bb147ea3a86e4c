//! The browser side: a `Gpu` (one adapter, device and pipeline set, shared by every view on a page) and
//! a `View` (one canvas with its own renderer, scene and buffers). Every setter validates and returns an
//! error with a message for the page to show; a refused value leaves the view running as it was.

use crate::renderer::{FrameStats, Renderer};
use crate::scene::Scene;
use crate::scene::Sphere;
use crate::scene::params::Settings;
use glam::Vec3;
use std::cell::RefCell;
use std::rc::Rc;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

mod editing;
mod gpu;
mod memory;
mod meshing;
mod parameters;
mod picture;
mod teaching;

pub use gpu::Gpu;

#[wasm_bindgen]
extern "C" {
    /// Reports a panic to the page (defined by the page's script before the module starts).
    #[wasm_bindgen(js_namespace = globalThis, js_name = metaballsShowPanic)]
    fn show_panic(message: &str);
}

#[wasm_bindgen(start)]
fn start() {
    std::panic::set_hook(Box::new(|info| {
        console_error_panic_hook::hook(info);
        show_panic(&info.to_string());
    }));
    // The marching-cubes tables are made now, once, rather than by whichever frame first meshes.
    crate::extract::decider::variant_table();
}

/// Resolves in a later browser task (a zero-delay timer), letting the browser run in between.
async fn next_task() {
    let promise = js_sys::Promise::new(&mut |resolve, _| {
        if let Some(window) = web_sys::window() {
            let _ = window.set_timeout_with_callback_and_timeout_and_arguments_0(&resolve, 0);
        }
    });
    let _ = wasm_bindgen_futures::JsFuture::from(promise).await;
}

/// Polls a WebGL2 device between browser tasks until dropped, so that buffer mappings and
/// submitted-work callbacks on it resolve (WebGPU resolves them by itself; nothing is polled there).
struct Polling(Rc<std::cell::Cell<bool>>);

impl Polling {
    fn start(device: &wgpu::Device) -> Polling {
        let stop = Rc::new(std::cell::Cell::new(false));
        if !crate::device::has_compute(device) {
            let (device, stop) = (device.clone(), stop.clone());
            wasm_bindgen_futures::spawn_local(async move {
                while !stop.get() {
                    let _ = device.poll(wgpu::PollType::Poll);
                    next_task().await;
                }
            });
        }
        Polling(stop)
    }
}

impl Drop for Polling {
    fn drop(&mut self) {
        self.0.set(true);
    }
}

/// Spheres as the page passes them: 7 numbers each (centre, radius with the charge's sign, velocity).
fn pack_spheres(spheres: &[Sphere]) -> Vec<f32> {
    spheres
        .iter()
        .flat_map(|s| {
            [s.center.x, s.center.y, s.center.z, s.signed_radius(), s.velocity.x, s.velocity.y, s.velocity.z]
        })
        .collect()
}

fn unpack_spheres(packed: &[f32]) -> Result<Vec<Sphere>, JsError> {
    if !packed.len().is_multiple_of(7) {
        return Err(js_error("spheres come as 7 numbers each (centre, radius, velocity)"));
    }
    Ok(packed
        .chunks(7)
        .map(|s| Sphere::from_signed(Vec3::new(s[0], s[1], s[2]), s[3], Vec3::new(s[4], s[5], s[6])))
        .collect())
}

fn js_error(error: impl std::fmt::Display) -> JsError {
    JsError::new(&error.to_string())
}

/// Figures from the GPU about a recent frame.
#[wasm_bindgen]
#[derive(Clone, Copy)]
pub struct Stats {
    /// Frame the figures are for.
    pub frame: f64,
    /// Triangles drawn.
    pub triangles: u32,
    /// Triangles the surface needed (more than `max_triangles` on overflow).
    pub triangles_requested: u32,
    /// Capacity of the index buffer in triangles.
    pub max_triangles: u32,
    /// True when triangles were dropped because the budget was full.
    pub overflowed: bool,
}

impl From<FrameStats> for Stats {
    fn from(s: FrameStats) -> Self {
        Self {
            frame: s.frame as f64,
            triangles: s.triangles,
            triangles_requested: s.triangles_requested,
            max_triangles: s.max_triangles,
            overflowed: s.overflowed(),
        }
    }
}

/// A view: one canvas, its renderer, scene and buffers, on a shared `Gpu`.
#[wasm_bindgen]
pub struct View {
    renderer: Renderer,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    device: wgpu::Device,
    /// The first GPU error this view's frames raised (caught in error scopes around each frame).
    error: Rc<RefCell<Option<String>>>,
    /// A copy of a frame asked for, for the picture in print.
    picture: picture::FramePicture,
}

#[wasm_bindgen]
impl View {
    /// Starts drawing on `canvas` (sized by the page beforehand) with the given scene settings;
    /// material and camera follow through their setters.
    pub fn create(
        gpu: &Gpu,
        canvas: HtmlCanvasElement,
        names: Vec<String>,
        texts: Vec<String>,
    ) -> Result<View, JsError> {
        // The settings it starts with, by name (those the table takes at creation), over the defaults.
        if names.len() != texts.len() {
            return Err(JsError::new("View.create takes as many texts as names"));
        }
        let pairs: Vec<(&str, &str)> =
            names.iter().map(String::as_str).zip(texts.iter().map(String::as_str)).collect();
        let settings = Settings::default().with_parameters(&pairs).map_err(js_error)?;
        let (width, height) = (canvas.width().max(1), canvas.height().max(1));
        let surface = gpu.surface_for(canvas)?;
        let capabilities = surface.get_capabilities(&gpu.adapter);
        let format =
            *capabilities.formats.first().ok_or_else(|| js_error("the canvas offers no texture format"))?;
        let device = gpu.context.device().clone();
        // Frames are copied for print where the canvas allows it: every WebGPU canvas does (wgpu
        // reports only what all its backends' surfaces allow).
        let copyable = gpu.adapter.get_info().backend == wgpu::Backend::BrowserWebGpu
            || capabilities.usages.contains(wgpu::TextureUsages::COPY_SRC);
        let picture = picture::FramePicture::new(copyable);
        // Drawn through an sRGB view of the canvas's texture, so the blending hardware encodes the
        // colours (the canvas offers only linear formats): a software rasteriser then runs no encoding
        // of its own for every pixel.
        let drawn = format.add_srgb_suffix();
        let config = wgpu::SurfaceConfiguration {
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT | picture.usage(),
            format,
            width,
            height,
            present_mode: wgpu::PresentMode::Fifo,
            desired_maximum_frame_latency: 2,
            alpha_mode: wgpu::CompositeAlphaMode::Opaque,
            view_formats: if drawn == format { vec![] } else { vec![drawn] },
            color_space: wgpu::SurfaceColorSpace::Auto,
        };
        let renderer =
            Renderer::on_context(&gpu.context, drawn, width, height, settings).map_err(js_error)?;
        surface.configure(&device, &config);
        Ok(View { renderer, surface, config, device, error: Rc::default(), picture })
    }

    /// Advances the animation by `dt` seconds and draws a frame on the canvas.
    pub fn frame(&mut self, dt: f32) -> Result<(), JsError> {
        self.renderer.update(dt).map_err(js_error)?;
        let texture = match self.surface.get_current_texture() {
            wgpu::CurrentSurfaceTexture::Success(t) | wgpu::CurrentSurfaceTexture::Suboptimal(t) => t,
            wgpu::CurrentSurfaceTexture::Outdated | wgpu::CurrentSurfaceTexture::Lost => {
                self.surface.configure(&self.device, &self.config);
                return Ok(());
            }
            _ => return Ok(()),
        };
        let validation = self.device.push_error_scope(wgpu::ErrorFilter::Validation);
        let memory = self.device.push_error_scope(wgpu::ErrorFilter::OutOfMemory);
        let format = self.config.view_formats.first().copied();
        let view = texture.texture.create_view(&wgpu::TextureViewDescriptor { format, ..Default::default() });
        self.renderer.render(&view);
        self.picture.frame_drawn(&self.device, self.renderer.queue(), &texture.texture);
        self.renderer.queue().present(texture);
        let (memory, validation) = (memory.pop(), validation.pop());
        let sink = self.error.clone();
        wasm_bindgen_futures::spawn_local(async move {
            let error = match memory.await {
                Some(error) => Some(error),
                None => validation.await,
            };
            if let Some(error) = error {
                web_sys::console::error_1(&format!("GPU error: {error}").into());
                sink.borrow_mut().get_or_insert(error.to_string());
            }
        });
        Ok(())
    }

    /// Takes in the GPU's figures for past frames without drawing (a paused view).
    pub fn poll(&mut self) {
        self.renderer.poll_stats();
    }

    /// True when the next frame would differ even with nothing changed (the buffers are growing).
    pub fn needs_redraw(&self) -> bool {
        self.renderer.needs_redraw()
    }

    /// Follows a new canvas size in device pixels.
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), JsError> {
        self.renderer.resize(width, height).map_err(js_error)?;
        if (width, height) != (self.config.width, self.config.height) {
            self.config.width = width;
            self.config.height = height;
            self.surface.configure(&self.device, &self.config);
        }
        Ok(())
    }

    /// The spheres as they are now, 7 numbers each (centre, radius, velocity), so a view rebuilt on a
    /// new device carries on from where it was.
    pub fn spheres(&self) -> Vec<f32> {
        pack_spheres(self.renderer.scene().spheres())
    }

    /// Puts back spheres saved by `spheres`.
    pub fn set_spheres(&mut self, packed: Vec<f32>) -> Result<(), JsError> {
        let spheres = unpack_spheres(&packed)?;
        let seed = self.renderer.settings().seed;
        let scene = Scene::from_spheres(spheres).map_err(js_error)?.with_seed(seed);
        self.renderer.set_scene(scene);
        Ok(())
    }

    /// Where the latest frame's mesh came from: `gpu` (compute passes) or `cpu` (the CPU mesher).
    pub fn mesh_source(&self) -> String {
        self.renderer.mesh_source().into()
    }

    /// Runs mesh generation alone (no drawing), for the benchmark.
    pub fn extract(&mut self) {
        self.renderer.extract();
    }

    /// A promise that resolves when the GPU has finished all work submitted so far. WebGPU reports it
    /// by itself; a WebGL2 device is polled (between browser tasks) until it does.
    pub fn work_done(&self) -> js_sys::Promise {
        let (sender, receiver) = futures_channel::oneshot::channel::<()>();
        self.renderer.queue().on_submitted_work_done(move || {
            let _ = sender.send(());
        });
        let polling = Polling::start(&self.device);
        wasm_bindgen_futures::future_to_promise(async move {
            let _polling = polling;
            receiver.await.map_err(|_| JsValue::from_str("the GPU queue was dropped"))?;
            Ok(JsValue::UNDEFINED)
        })
    }

    /// Active blocks and cells of the newest figures, as fractions of the grid: [blocks, cells].
    pub fn active_fractions(&self) -> Vec<f64> {
        self.renderer.stats().map_or(vec![0.0, 0.0], |s| {
            vec![
                s.active_blocks as f64 / s.total_blocks.max(1) as f64,
                s.active_cells as f64 / s.total_cells.max(1) as f64,
            ]
        })
    }

    /// Lets level of detail's cells look up to `factor` (1 or more) times `lod-pixels` on screen from
    /// the next frame on: the page's budget raises it while frames run long (see
    /// `www/lib/figure/detail.js`); throws with what is accepted.
    pub fn set_lod_coarsening(&mut self, factor: f32) -> Result<(), JsError> {
        self.renderer.set_lod_coarsening(factor).map_err(js_error)
    }

    /// With level of detail, the finest resolution, then blocks and triangles of each level in use
    /// (finest first, triangles from the newest figures): `[resolution, blocks₀, triangles₀, …]`;
    /// empty for a uniform grid.
    pub fn lod_levels(&self) -> Vec<u32> {
        let Some(summary) = self.renderer.lod_summary() else { return Vec::new() };
        let triangles = self.renderer.stats().map(|s| s.level_triangles).unwrap_or_default();
        let used = summary.blocks.iter().rposition(|&b| b > 0).map_or(0, |last| last + 1);
        let mut out = vec![summary.resolution];
        for level in 0..used {
            out.push(summary.blocks[level]);
            out.push(triangles.get(level).copied().unwrap_or(0));
        }
        out
    }

    /// With level of detail, the largest a cell may look on screen as the selection uses it, in
    /// pixels: `lod-pixels` times the coarsening, held down where larger cells would let touching
    /// blocks differ by more than one level; 0 without level of detail.
    pub fn lod_cell_pixels(&self) -> f32 {
        self.renderer.lod_cell_pixels().unwrap_or(0.0)
    }

    /// The mesh's measures while `color_by` is `error` or `quality`: `[frame, RMS error, largest error
    /// (cells), vertices measured, then triangles in ten shape bins, slivers first]`; empty otherwise.
    pub fn measures(&self) -> Vec<f64> {
        let Some(m) = self.renderer.measures() else { return Vec::new() };
        let mut out = vec![m.frame as f64, m.rms_error as f64, m.max_error as f64, m.vertices as f64];
        out.extend(m.quality.iter().map(|&n| n as f64));
        out
    }

    /// GPU memory held by the mesh buffers, in bytes.
    pub fn mesh_bytes(&self) -> f64 {
        self.renderer.mesh_bytes() as f64
    }

    /// GPU memory held by this view's buffers and targets, in bytes.
    pub fn gpu_bytes(&self) -> f64 {
        self.renderer.gpu_bytes() as f64
    }

    /// The newest figures the GPU reported, if any yet.
    pub fn stats(&self) -> Option<Stats> {
        self.renderer.stats().map(Stats::from)
    }

    /// Frames drawn so far: `stats().frame` equals it once the newest frame's figures are read back.
    pub fn frames_rendered(&self) -> f64 {
        self.renderer.frames_rendered() as f64
    }

    /// The first GPU error this view's frames raised, if any.
    pub fn gpu_error(&self) -> Option<String> {
        self.error.borrow().clone()
    }

    /// The largest resolution this device holds.
    pub fn max_resolution(&self) -> u32 {
        self.renderer.max_resolution()
    }

    pub fn sphere_count(&self) -> u32 {
        self.renderer.settings().sphere_count
    }

    pub fn iso(&self) -> f32 {
        self.renderer.settings().iso
    }

    pub fn resolution(&self) -> u32 {
        self.renderer.settings().resolution
    }

    pub fn seed(&self) -> u32 {
        self.renderer.settings().seed as u32
    }
}
