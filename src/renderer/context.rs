//! What every renderer on one device shares: the device and queue, the extractors it runs with their
//! compiled pipelines and the shading pipelines (built once per device, not once per view), and the device's
//! error and loss reports. A page with several views holds one `GpuContext`; when its device is lost,
//! a new context is made and every view rebuilds its renderer on it from its own state.

use crate::device::compute_within;
use crate::draw::shade::ShadePipelines;
use crate::extract::{self, Extractor};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Arc, Mutex};

/// What is compiled once per device: each renderer takes fresh extractors from these (sharing their
/// GPU objects) and binds them to its own buffers.
pub(crate) struct Pipelines {
    /// The extractors this device runs (compiled once; each renderer takes a fresh instance).
    extractors: Vec<Box<dyn Extractor>>,
    /// Shading pipelines per output format and sample count, built on first use.
    shading: Mutex<Vec<((wgpu::TextureFormat, u32), ShadePipelines)>>,
}

/// A device shared by any number of renderers.
#[derive(Clone)]
pub struct GpuContext {
    device: wgpu::Device,
    queue: wgpu::Queue,
    pipelines: Arc<Pipelines>,
    /// How many shading pipeline sets (one per format and sample count) were built on this context.
    pipelines_built: Arc<AtomicUsize>,
    live_renderers: Arc<AtomicUsize>,
    /// True on a software adapter (SwiftShader, llvmpipe, any fallback adapter), where the CPU mesher
    /// is faster than compute passes emulated on the CPU.
    software: Arc<AtomicBool>,
    /// The device's limits, read once: in a browser every read goes through each limit's getter.
    limits: wgpu::Limits,
    error: Arc<Mutex<Option<String>>>,
    lost: Arc<Mutex<Option<String>>>,
}

impl GpuContext {
    /// Makes every extractor the device runs (`extract::EXTRACTORS`; each compiles its pipelines on
    /// the first frame that needs them) and starts listening for the device's errors and loss.
    pub fn new(device: wgpu::Device, queue: wgpu::Queue) -> Self {
        let error: Arc<Mutex<Option<String>>> = Arc::default();
        let sink = error.clone();
        device.on_uncaptured_error(Arc::new(move |error: wgpu::Error| {
            let message = error.to_string();
            log_error(&message);
            lock(&sink).get_or_insert(message);
        }));
        let lost: Arc<Mutex<Option<String>>> = Arc::default();
        let sink = lost.clone();
        device.set_device_lost_callback(move |reason, message| {
            let why = match reason {
                wgpu::DeviceLostReason::Destroyed => "the device was destroyed",
                _ => "the GPU was lost (driver reset or GPU process crash)",
            };
            let message = if message.is_empty() { why.to_string() } else { format!("{why}: {message}") };
            lock(&sink).get_or_insert(message);
        });
        // On wasm32 wgpu's objects are not Send: a page runs them on one thread.
        #[allow(clippy::arc_with_non_send_sync)]
        let pipelines =
            Arc::new(Pipelines { extractors: extract::compile_all(&device), shading: Mutex::default() });
        Self {
            limits: device.limits(),
            device,
            queue,
            pipelines,
            pipelines_built: Arc::default(),
            live_renderers: Arc::default(),
            software: Arc::default(),
            error,
            lost,
        }
    }

    pub fn device(&self) -> &wgpu::Device {
        &self.device
    }

    pub fn queue(&self) -> &wgpu::Queue {
        &self.queue
    }

    /// True when the device runs compute shaders (every WebGPU device; not WebGL2).
    pub fn has_compute(&self) -> bool {
        compute_within(&self.limits)
    }

    /// The device's limits.
    pub fn limits(&self) -> &wgpu::Limits {
        &self.limits
    }

    /// Says whether the adapter is a software one (natively the adapter's type tells; in a browser
    /// the page reads it from the adapter's info).
    pub fn set_software(&self, software: bool) {
        self.software.store(software, Ordering::Relaxed);
    }

    /// True on a software adapter.
    pub fn is_software(&self) -> bool {
        self.software.load(Ordering::Relaxed)
    }

    /// The extractors this device runs, as compiled for it, in order of preference.
    pub fn extractors(&self) -> &[Box<dyn Extractor>] {
        &self.pipelines.extractors
    }

    /// The shading pipelines for `format` and `sample_count`, built once per context.
    pub(crate) fn shade_pipelines(&self, format: wgpu::TextureFormat, sample_count: u32) -> ShadePipelines {
        let mut cache = lock(&self.pipelines.shading);
        if let Some((_, pipelines)) = cache.iter().find(|(key, _)| *key == (format, sample_count)) {
            return pipelines.clone();
        }
        let pipelines = ShadePipelines::new(&self.device, format, sample_count);
        cache.push(((format, sample_count), pipelines.clone()));
        self.pipelines_built.fetch_add(1, Ordering::Relaxed);
        pipelines
    }

    /// Pipeline sets built on this context so far: one for the compute passes once a frame has used
    /// them, plus one per output format and sample count in use. Views sharing a context do not add
    /// to it.
    pub fn pipeline_sets_built(&self) -> usize {
        let extractors: usize = self.pipelines.extractors.iter().map(|e| e.pipeline_sets()).sum();
        extractors + self.pipelines_built.load(Ordering::Relaxed)
    }

    /// Renderers alive on this context.
    pub fn live_renderers(&self) -> usize {
        self.live_renderers.load(Ordering::Relaxed)
    }

    pub(crate) fn renderer_token(&self) -> RendererToken {
        self.live_renderers.fetch_add(1, Ordering::Relaxed);
        RendererToken(self.live_renderers.clone())
    }

    /// The first GPU error raised outside an error scope, if any (also logged).
    pub fn gpu_error(&self) -> Option<String> {
        lock(&self.error).clone()
    }

    /// Why the device was lost, once it has been.
    pub fn lost(&self) -> Option<String> {
        lock(&self.lost).clone()
    }
}

/// Counts a renderer as alive until dropped.
pub(crate) struct RendererToken(Arc<AtomicUsize>);

impl Drop for RendererToken {
    fn drop(&mut self) {
        self.0.fetch_sub(1, Ordering::Relaxed);
    }
}

fn lock<T>(mutex: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    mutex.lock().unwrap_or_else(|e| e.into_inner())
}

fn log_error(message: &str) {
    #[cfg(target_arch = "wasm32")]
    web_sys::console::error_1(&format!("GPU error: {message}").into());
    #[cfg(not(target_arch = "wasm32"))]
    eprintln!("GPU error: {message}");
}
