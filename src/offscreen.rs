//! Native offscreen rendering: a `Renderer` drawing into a texture that is read back as RGBA pixels, for
//! the PNG renderer, tests and benchmarks.

use crate::device;
use crate::{GpuContext, Renderer, Settings};
use std::path::Path;

/// The format offscreen frames are drawn in.
pub const OFFSCREEN_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

/// A renderer with its own device and target texture.
pub struct Offscreen {
    pub renderer: Renderer,
    pub adapter: wgpu::Adapter,
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    texture: wgpu::Texture,
    view: wgpu::TextureView,
}

impl Offscreen {
    /// Gets a device and builds a renderer for `width` × `height` frames.
    pub async fn new(
        settings: Settings,
        width: u32,
        height: u32,
    ) -> Result<Self, Box<dyn std::error::Error>> {
        let instance = device::native_instance();
        let (adapter, device, queue) = device::request_device(&instance, None).await?;
        let offscreen = Self::with_device(adapter, device, queue, settings, width, height)?;
        // `auto` meshing follows the adapter's kind (tests on a shared device choose explicitly).
        let software = offscreen.adapter.get_info().device_type == wgpu::DeviceType::Cpu;
        offscreen.renderer.context().set_software(software);
        Ok(offscreen)
    }

    /// Builds a renderer for `width` × `height` frames on a device the caller already has.
    pub fn with_device(
        adapter: wgpu::Adapter,
        device: wgpu::Device,
        queue: wgpu::Queue,
        settings: Settings,
        width: u32,
        height: u32,
    ) -> Result<Self, crate::ParamError> {
        Self::on_context(adapter, &GpuContext::new(device, queue), settings, width, height)
    }

    /// Builds a renderer for `width` × `height` frames on a device shared with other renderers (its
    /// pipelines built once for all of them).
    pub fn on_context(
        adapter: wgpu::Adapter,
        context: &GpuContext,
        settings: Settings,
        width: u32,
        height: u32,
    ) -> Result<Self, crate::ParamError> {
        let renderer = Renderer::on_context(context, OFFSCREEN_FORMAT, width, height, settings)?;
        let (device, queue) = (context.device().clone(), context.queue().clone());
        let (texture, view) = target(&device, width, height);
        Ok(Self { renderer, adapter, device, queue, texture, view })
    }

    /// Blocking form of `new`.
    pub fn blocking(settings: Settings, width: u32, height: u32) -> Result<Self, Box<dyn std::error::Error>> {
        pollster::block_on(Self::new(settings, width, height))
    }

    /// Follows a new frame size.
    pub fn resize(&mut self, width: u32, height: u32) -> Result<(), crate::ParamError> {
        self.renderer.resize(width, height)?;
        (self.texture, self.view) = target(&self.device, width, height);
        Ok(())
    }

    /// Draws a frame into the target without reading it back.
    pub fn render(&mut self) {
        self.renderer.render(&self.view);
    }

    /// Draws a frame, with timestamp queries where timing is on, without waiting
    /// (`Renderer::render_for_timing`).
    pub fn render_for_timing(&mut self) {
        self.renderer.render_for_timing(&self.view);
    }

    /// Draws a frame and waits for its GPU time per stage (`Renderer::render_timed`).
    pub async fn render_timed(&mut self) -> Option<crate::device::timing::StageTimes> {
        self.renderer.render_timed(&self.view).await
    }

    /// Draws a frame and returns its pixels, RGBA8 (sRGB), rows top to bottom.
    pub fn render_rgba(&mut self) -> Vec<u8> {
        self.render();
        self.last_frame_rgba()
    }

    /// Returns the pixels of the frame drawn last, RGBA8 (sRGB), rows top to bottom.
    pub fn last_frame_rgba(&mut self) -> Vec<u8> {
        pollster::block_on(device::read_texture(&self.device, &self.queue, &self.texture))
    }
}

fn target(device: &wgpu::Device, width: u32, height: u32) -> (wgpu::Texture, wgpu::TextureView) {
    let texture = device::render_target(device, width, height, OFFSCREEN_FORMAT);
    let view = texture.create_view(&wgpu::TextureViewDescriptor::default());
    (texture, view)
}

/// Writes RGBA8 sRGB pixels as a PNG file.
pub fn write_png(
    path: &Path,
    width: u32,
    height: u32,
    rgba: &[u8],
) -> Result<(), Box<dyn std::error::Error>> {
    let file = std::io::BufWriter::new(std::fs::File::create(path)?);
    let mut encoder = png::Encoder::new(file, width, height);
    encoder.set_color(png::ColorType::Rgba);
    encoder.set_depth(png::BitDepth::Eight);
    encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
    let mut writer = encoder.write_header()?;
    writer.write_image_data(rgba)?;
    writer.finish()?;
    Ok(())
}

/// Reads a PNG file as RGBA8 pixels: (width, height, pixels).
pub fn read_png(path: &Path) -> Result<(u32, u32, Vec<u8>), Box<dyn std::error::Error>> {
    let mut decoder = png::Decoder::new(std::io::BufReader::new(std::fs::File::open(path)?));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::ALPHA);
    let mut reader = decoder.read_info()?;
    let mut pixels = vec![0; reader.output_buffer_size().ok_or("PNG too large")?];
    let info = reader.next_frame(&mut pixels)?;
    pixels.truncate(info.buffer_size());
    if info.color_type != png::ColorType::Rgba || info.bit_depth != png::BitDepth::Eight {
        return Err(format!(
            "{}: expected 8-bit RGBA, found {:?} {:?}",
            path.display(),
            info.color_type,
            info.bit_depth
        )
        .into());
    }
    Ok((info.width, info.height, pixels))
}
