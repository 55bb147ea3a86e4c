//! The browser handle the page drives: a canvas, a device and a `Renderer`, kept alive together for as
//! long as the page holds the `App`. Every setter validates and returns an error with a message for the
//! page to show; a refused value leaves the demo running as it was.

use crate::params::Camera;
use crate::{FrameStats, Renderer, Settings};
use glam::Vec3;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

#[wasm_bindgen]
extern "C" {
    /// Shows a panic's message over the canvas (defined by the page before the module starts).
    #[wasm_bindgen(js_namespace = globalThis, js_name = metaballsShowPanic)]
    fn show_panic(message: &str);
}

#[wasm_bindgen(start)]
fn start() {
    std::panic::set_hook(Box::new(|info| {
        console_error_panic_hook::hook(info);
        show_panic(&info.to_string());
    }));
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
    /// Capacity of the vertex buffer in triangles.
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

/// The demo on one canvas.
#[wasm_bindgen]
pub struct App {
    renderer: Renderer,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    device: wgpu::Device,
    adapter: String,
}

#[wasm_bindgen]
impl App {
    /// Starts WebGPU on `canvas` (sized by the page beforehand). Rejects with a message saying what is
    /// missing when the browser has no WebGPU or no adapter.
    pub async fn create(canvas: HtmlCanvasElement) -> Result<App, JsError> {
        let (width, height) = (canvas.width().max(1), canvas.height().max(1));
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = wgpu::Backends::BROWSER_WEBGPU;
        let instance = wgpu::Instance::new(desc);
        let surface = instance
            .create_surface(wgpu::SurfaceTarget::Canvas(canvas))
            .map_err(|e| js_error(format!("cannot draw on the canvas with WebGPU: {e}")))?;
        let (adapter, device, queue) =
            crate::gpu::request_device(&instance, Some(&surface)).await.map_err(js_error)?;
        let capabilities = surface.get_capabilities(&adapter);
        let format =
            *capabilities.formats.first().ok_or_else(|| js_error("the canvas offers no texture format"))?;
        let config = wgpu::SurfaceConfiguration {
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            format,
            width,
            height,
            present_mode: wgpu::PresentMode::Fifo,
            desired_maximum_frame_latency: 2,
            alpha_mode: wgpu::CompositeAlphaMode::Opaque,
            view_formats: vec![],
            color_space: wgpu::SurfaceColorSpace::Auto,
        };
        surface.configure(&device, &config);
        let info = adapter.get_info();
        let adapter_name = [info.name.as_str(), info.driver.as_str(), info.driver_info.as_str()]
            .iter()
            .filter(|s| !s.is_empty())
            .copied()
            .collect::<Vec<_>>()
            .join(" · ");
        let adapter_name =
            if adapter_name.is_empty() { format!("{:?}", info.device_type) } else { adapter_name };
        let renderer = Renderer::new(device.clone(), queue, format, width, height, Settings::default())
            .map_err(js_error)?;
        Ok(App { renderer, surface, config, device, adapter: format!("WebGPU · {adapter_name}") })
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
        let view = texture.texture.create_view(&wgpu::TextureViewDescriptor::default());
        self.renderer.render(&view);
        self.renderer.queue().present(texture);
        Ok(())
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

    pub fn set_sphere_count(&mut self, count: u32) -> Result<(), JsError> {
        self.renderer.set_sphere_count(count).map_err(js_error)
    }

    pub fn set_iso(&mut self, iso: f32) -> Result<(), JsError> {
        self.renderer.set_iso(iso).map_err(js_error)
    }

    pub fn set_resolution(&mut self, cells_per_axis: u32) -> Result<(), JsError> {
        self.renderer.set_resolution(cells_per_axis).map_err(js_error)
    }

    pub fn set_seed(&mut self, seed: u32) -> Result<(), JsError> {
        self.renderer.set_seed(seed as u64).map_err(js_error)
    }

    /// Orbit angles in degrees and distance in box half-widths.
    pub fn set_camera(&mut self, yaw: f32, pitch: f32, distance: f32) -> Result<(), JsError> {
        let camera =
            Camera { yaw_degrees: yaw, pitch_degrees: pitch, distance, ..self.renderer.settings().camera };
        self.renderer.set_camera(camera).map_err(js_error)
    }

    pub fn set_field_of_view(&mut self, degrees: f32) -> Result<(), JsError> {
        let camera = Camera { fov_y_degrees: degrees, ..self.renderer.settings().camera };
        self.renderer.set_camera(camera).map_err(js_error)
    }

    pub fn set_shininess(&mut self, shininess: f32) -> Result<(), JsError> {
        let material = crate::Material { shininess, ..self.renderer.settings().material };
        self.renderer.set_material(material).map_err(js_error)
    }

    /// Base colour as linear RGB in [0, 1].
    pub fn set_color(&mut self, r: f32, g: f32, b: f32) -> Result<(), JsError> {
        let material =
            crate::Material { base_color: Vec3::new(r, g, b), ..self.renderer.settings().material };
        self.renderer.set_material(material).map_err(js_error)
    }

    /// 4× multisampling on or off (software adapters draw much faster without it).
    pub fn set_antialiasing(&mut self, on: bool) -> Result<(), JsError> {
        self.renderer.set_antialiasing(on).map_err(js_error)
    }

    pub fn set_light_position(&mut self, x: f32, y: f32, z: f32) -> Result<(), JsError> {
        self.renderer.set_light_position(Vec3::new(x, y, z)).map_err(js_error)
    }

    /// Runs mesh generation alone (no drawing), for the benchmark.
    pub fn extract(&mut self) {
        self.renderer.extract();
    }

    /// A promise that resolves when the GPU has finished all work submitted so far.
    pub fn work_done(&self) -> js_sys::Promise {
        let (sender, receiver) = futures_channel::oneshot::channel::<()>();
        self.renderer.queue().on_submitted_work_done(move || {
            let _ = sender.send(());
        });
        wasm_bindgen_futures::future_to_promise(async move {
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

    /// GPU memory held by the mesh buffers, in bytes.
    pub fn mesh_bytes(&self) -> f64 {
        self.renderer.mesh_bytes() as f64
    }

    /// The newest figures the GPU reported, if any yet.
    pub fn stats(&self) -> Option<Stats> {
        self.renderer.stats().map(Stats::from)
    }

    /// The first GPU error seen, if any.
    pub fn gpu_error(&self) -> Option<String> {
        self.renderer.gpu_error()
    }

    /// What the page is drawing with.
    pub fn adapter(&self) -> String {
        self.adapter.clone()
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
