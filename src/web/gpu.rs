//! The adapter and device a view draws with. With WebGPU one `Gpu` serves every view on a page (its
//! pipelines built once); with WebGL2 (the second build, `--features webgl`, loaded only where WebGPU
//! is missing) the device belongs to one canvas, so each view has its own.

use super::js_error;
use crate::GpuContext;
use std::cell::RefCell;
use wasm_bindgen::prelude::*;
use web_sys::HtmlCanvasElement;

/// One adapter and device, their pipelines, and what the page learns about them. Every view on a page
/// draws with the same WebGPU `Gpu`; when it is lost, the page makes a new one and the views move to it.
#[wasm_bindgen]
pub struct Gpu {
    instance: wgpu::Instance,
    pub(super) adapter: wgpu::Adapter,
    pub(super) context: GpuContext,
    /// A WebGL2 device's canvas surface, made with the device and taken by its one view.
    surface: RefCell<Option<wgpu::Surface<'static>>>,
}

impl Gpu {
    /// The surface a view draws on: the one made with a WebGL2 device, or a new one on `canvas`.
    pub(super) fn surface_for(&self, canvas: HtmlCanvasElement) -> Result<wgpu::Surface<'static>, JsError> {
        if let Some(surface) = self.surface.borrow_mut().take() {
            return Ok(surface);
        }
        self.instance
            .create_surface(wgpu::SurfaceTarget::Canvas(canvas))
            .map_err(|e| js_error(format!("cannot draw on the canvas: {e}")))
    }
}

#[wasm_bindgen]
impl Gpu {
    /// Requests a WebGPU adapter and device. Rejects with a message saying what is missing when the
    /// browser has no WebGPU or no adapter.
    pub async fn create() -> Result<Gpu, JsError> {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = wgpu::Backends::BROWSER_WEBGPU;
        let instance = wgpu::Instance::new(desc);
        let (adapter, device, queue) =
            crate::device::request_device(&instance, None).await.map_err(js_error)?;
        Ok(Gpu { instance, adapter, context: GpuContext::new(device, queue), surface: RefCell::default() })
    }

    /// Requests a WebGL2 device drawing on `canvas` (the device is bound to that canvas's context).
    /// Meshes are then made on the CPU; the shading is the same WGSL, translated for WebGL2.
    #[cfg(feature = "webgl")]
    pub async fn create_webgl(canvas: HtmlCanvasElement) -> Result<Gpu, JsError> {
        let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
        desc.backends = wgpu::Backends::GL;
        let instance = wgpu::Instance::new(desc);
        let surface = instance
            .create_surface(wgpu::SurfaceTarget::Canvas(canvas))
            .map_err(|e| js_error(format!("cannot draw on the canvas with WebGL2: {e}")))?;
        let (adapter, device, queue) =
            crate::device::request_device(&instance, Some(&surface)).await.map_err(js_error)?;
        let context = GpuContext::new(device, queue);
        Ok(Gpu { instance, adapter, context, surface: RefCell::new(Some(surface)) })
    }

    /// `webgpu` or `webgl2`.
    pub fn backend(&self) -> String {
        match self.adapter.get_info().backend {
            wgpu::Backend::Gl => "webgl2".into(),
            _ => "webgpu".into(),
        }
    }

    /// True when the browser says the adapter is a fallback (software) one.
    pub fn is_fallback(&self) -> bool {
        self.adapter.get_info().device_type == wgpu::DeviceType::Cpu
    }

    /// Tells the renderers the adapter is a software one (the page reads it from the adapter's info):
    /// `mesh-on=auto` then meshes on the CPU.
    pub fn set_software(&self, software: bool) {
        self.context.set_software(software);
    }

    /// True when the device runs compute shaders (WebGPU); without them the CPU makes every mesh and
    /// the teaching views are not drawn.
    pub fn has_compute(&self) -> bool {
        self.context.has_compute()
    }

    /// Why the device was lost, once it has been.
    pub fn lost(&self) -> Option<String> {
        self.context.lost()
    }

    /// The first GPU error raised on this device outside a view's frames, if any.
    pub fn gpu_error(&self) -> Option<String> {
        self.context.gpu_error()
    }

    /// Destroys the device, as a driver reset would (tests of recovery use it).
    pub fn destroy(&self) {
        self.context.device().destroy();
    }

    /// Renderers alive on this device (one per view that has started and not been removed).
    pub fn live_renderers(&self) -> u32 {
        self.context.live_renderers() as u32
    }

    /// Pipeline sets compiled on this device: one for the compute passes plus one per output format
    /// and sample count, however many views there are.
    pub fn pipeline_sets_built(&self) -> u32 {
        self.context.pipeline_sets_built() as u32
    }

    /// The largest resolution this device holds.
    pub fn max_resolution(&self) -> u32 {
        crate::renderer::max_resolution(self.context.limits())
    }
}
