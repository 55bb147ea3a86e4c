//! Getting a device, building shader modules and pipelines every GPU stage uses, the binding numbers
//! their shaders share, and reading buffers back outside the frame loop (tests and tools). Imports only
//! `scene`.

pub mod bindings;
pub mod timing;
pub mod wgsl;

pub(crate) use wgsl::wgsl;

use std::fmt;

/// Why no device could be had.
#[derive(Debug, Clone)]
pub struct InitError(pub String);

impl fmt::Display for InitError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for InitError {}

#[cfg(not(target_arch = "wasm32"))]
const NO_ADAPTER_HINT: &str = "install a Vulkan driver; without a GPU, Mesa's software rasteriser \
     lavapipe works (Debian/Ubuntu: apt-get install mesa-vulkan-drivers)";
#[cfg(target_arch = "wasm32")]
const NO_ADAPTER_HINT: &str = "use a browser with WebGPU enabled (Chrome or Edge 113+, Firefox 141+, \
     Safari 26+), or enable it with the browser's WebGPU flag";

/// An adapter, its device and queue, with the adapter's own limits granted so that large grids fit
/// where the hardware allows.
pub async fn request_device(
    instance: &wgpu::Instance,
    compatible_surface: Option<&wgpu::Surface<'_>>,
) -> Result<(wgpu::Adapter, wgpu::Device, wgpu::Queue), InitError> {
    let adapter = instance
        .request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            compatible_surface,
            ..Default::default()
        })
        .await
        .map_err(|e| InitError(format!("no GPU adapter found ({e}): {NO_ADAPTER_HINT}")))?;
    let (device, queue) = adapter
        .request_device(&wgpu::DeviceDescriptor {
            label: Some("metaballs device"),
            required_limits: adapter.limits(),
            // Benchmarks time the stages where the adapter allows it.
            required_features: adapter.features() & wgpu::Features::TIMESTAMP_QUERY,
            ..Default::default()
        })
        .await
        .map_err(|e| InitError(format!("the GPU adapter refused a device: {e}")))?;
    Ok((adapter, device, queue))
}

/// A native instance over every backend wgpu supports here (Vulkan first, which lavapipe provides).
#[cfg(not(target_arch = "wasm32"))]
pub fn native_instance() -> wgpu::Instance {
    let mut desc = wgpu::InstanceDescriptor::new_without_display_handle_from_env();
    if std::env::var_os("WGPU_BACKEND").is_none() {
        desc.backends = wgpu::Backends::PRIMARY;
    }
    wgpu::Instance::new(desc)
}

/// Copies `size` bytes of `source` from `offset` into a mappable buffer and returns them. Waits for
/// the GPU: for tests and tools, never for the frame loop.
pub async fn read_buffer(
    device: &wgpu::Device,
    queue: &wgpu::Queue,
    source: &wgpu::Buffer,
    offset: u64,
    size: u64,
) -> Vec<u8> {
    if size == 0 {
        return Vec::new();
    }
    let staging = device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("readback: staging"),
        size,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let mut encoder =
        device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("readback: copy") });
    encoder.copy_buffer_to_buffer(source, offset, &staging, 0, size);
    queue.submit([encoder.finish()]);
    map_and_read(device, &staging).await
}

/// A texture to render frames into and read them back from (offscreen rendering and tests).
pub fn render_target(
    device: &wgpu::Device,
    width: u32,
    height: u32,
    format: wgpu::TextureFormat,
) -> wgpu::Texture {
    device.create_texture(&wgpu::TextureDescriptor {
        label: Some("offscreen: target"),
        size: wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    })
}

/// Copies a 4-byte-per-texel 2D texture (COPY_SRC) into a mappable buffer and returns its texels, rows
/// top to bottom without padding. Waits for the GPU: for tests and tools.
pub async fn read_texture(device: &wgpu::Device, queue: &wgpu::Queue, texture: &wgpu::Texture) -> Vec<u8> {
    TextureCopy::submit(device, queue, texture)
        .texels(device)
        .await
        .expect("the device was lost while reading a texture back")
}

/// A texture's texels copied into a mappable buffer: the copy is submitted at once (while the texture
/// still holds what is wanted, a canvas's frame before it is presented), the texels read later.
pub struct TextureCopy {
    buffer: wgpu::Buffer,
    row_bytes: u32,
    padded: u32,
}

impl TextureCopy {
    /// Submits the copy of `texture` (4 bytes per texel, COPY_SRC).
    pub fn submit(device: &wgpu::Device, queue: &wgpu::Queue, texture: &wgpu::Texture) -> TextureCopy {
        let (width, height) = (texture.width(), texture.height());
        let row_bytes = width * 4;
        let padded =
            row_bytes.div_ceil(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT) * wgpu::COPY_BYTES_PER_ROW_ALIGNMENT;
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback: texels"),
            size: padded as u64 * height as u64,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let mut encoder = device.create_command_encoder(&wgpu::CommandEncoderDescriptor {
            label: Some("readback: texture copy"),
        });
        encoder.copy_texture_to_buffer(
            texture.as_image_copy(),
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: 0,
                    bytes_per_row: Some(padded),
                    rows_per_image: None,
                },
            },
            wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
        );
        queue.submit([encoder.finish()]);
        TextureCopy { buffer, row_bytes, padded }
    }

    /// The texels, rows top to bottom without padding, once the GPU has made the copy; none when the
    /// device was lost first.
    pub async fn texels(self, device: &wgpu::Device) -> Option<Vec<u8>> {
        let bytes = try_map_and_read(device, &self.buffer).await?;
        let (padded, row_bytes) = (self.padded as usize, self.row_bytes as usize);
        if padded == row_bytes {
            return Some(bytes);
        }
        // Row by row (a byte at a time took tens of milliseconds of a browser's thread at a figure's size).
        let mut texels = Vec::with_capacity(bytes.len() / padded * row_bytes);
        for row in bytes.chunks(padded) {
            texels.extend_from_slice(&row[..row_bytes]);
        }
        Some(texels)
    }
}

/// Maps a MAP_READ buffer and returns its bytes.
pub async fn map_and_read(device: &wgpu::Device, buffer: &wgpu::Buffer) -> Vec<u8> {
    try_map_and_read(device, buffer).await.expect("mapping a readback buffer failed")
}

/// Maps a MAP_READ buffer and returns its bytes, or none when the mapping fails (the device was lost
/// meanwhile).
pub async fn try_map_and_read(device: &wgpu::Device, buffer: &wgpu::Buffer) -> Option<Vec<u8>> {
    let (sender, receiver) = futures_channel::oneshot::channel();
    buffer.map_async(wgpu::MapMode::Read, .., move |result| {
        let _ = sender.send(result);
    });
    #[cfg(not(target_arch = "wasm32"))]
    device
        .poll(wgpu::PollType::wait_indefinitely())
        .expect("the device was lost while reading a buffer back");
    #[cfg(target_arch = "wasm32")]
    let _ = device;
    receiver.await.ok()?.ok()?;
    let bytes = buffer.get_mapped_range(..).ok()?.to_vec();
    buffer.unmap();
    Some(bytes)
}

/// `shaders/common.wgsl`: the grid, the spheres and the field, composed before every pass's own source.
pub(crate) const COMMON_WGSL: &str = wgsl!("common.wgsl");

/// A compute shader module made of `shaders/common.wgsl` followed by a pass's own source.
pub(crate) fn compute_module(device: &wgpu::Device, label: &str, source: &str) -> wgpu::ShaderModule {
    shader_module(device, label, &[COMMON_WGSL, source])
}

/// A shader module made of `parts` in order, after the constants the crate fixes (`MAX_SPHERES`).
pub(crate) fn shader_module(device: &wgpu::Device, label: &str, parts: &[&str]) -> wgpu::ShaderModule {
    let source =
        format!("const MAX_SPHERES: u32 = {}u;\n{}", crate::scene::params::MAX_SPHERES, parts.join("\n"));
    device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(label),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    })
}

/// A compute pipeline for one entry point, its bind group layout derived from what the entry uses.
pub(crate) fn compute_pipeline(
    device: &wgpu::Device,
    label: &str,
    module: &wgpu::ShaderModule,
    entry_point: &str,
) -> wgpu::ComputePipeline {
    device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
        label: Some(label),
        layout: None,
        module,
        entry_point: Some(entry_point),
        compilation_options: Default::default(),
        cache: None,
    })
}

/// A bind group for group 0 of `pipeline`, binding whole buffers.
pub(crate) fn bind_buffers(
    device: &wgpu::Device,
    label: &str,
    pipeline: &wgpu::ComputePipeline,
    buffers: &[(u32, &wgpu::Buffer)],
) -> wgpu::BindGroup {
    bind_buffers_to(device, label, &pipeline.get_bind_group_layout(0), buffers)
}

/// A bind group for `layout`, binding whole buffers.
pub(crate) fn bind_buffers_to(
    device: &wgpu::Device,
    label: &str,
    layout: &wgpu::BindGroupLayout,
    buffers: &[(u32, &wgpu::Buffer)],
) -> wgpu::BindGroup {
    let entries: Vec<wgpu::BindGroupEntry> = buffers
        .iter()
        .map(|&(binding, buffer)| wgpu::BindGroupEntry { binding, resource: buffer.as_entire_binding() })
        .collect();
    device.create_bind_group(&wgpu::BindGroupDescriptor { label: Some(label), layout, entries: &entries })
}

/// Compute shaders with storage buffers: WebGL2 devices report no room for either.
pub fn has_compute(device: &wgpu::Device) -> bool {
    compute_within(&device.limits())
}

/// True when a device of these limits runs compute shaders.
pub fn compute_within(limits: &wgpu::Limits) -> bool {
    limits.max_compute_invocations_per_workgroup > 0 && limits.max_storage_buffers_per_shader_stage > 0
}
