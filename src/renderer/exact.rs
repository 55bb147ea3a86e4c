//! The exact surface's rays, cast on the device for listed pixels: what `display=exact` draws there,
//! as numbers. For tests and tools, never the frame loop.

use super::Renderer;
use crate::device::{bindings, read_buffer};
use wgpu::util::DeviceExt;

impl Renderer {
    /// For each pixel (from the top left of the output), the distance along [`Renderer::ray`] to the
    /// first point of the exact solid {f > iso} in the box, cast by the same shader code
    /// `display=exact` draws with; `None` where the ray misses it. Waits for the GPU; `None` in all
    /// where the device has no compute shaders.
    pub async fn exact_hits(&mut self, pixels: &[[f32; 2]]) -> Vec<Option<f32>> {
        if !self.context.has_compute() || pixels.is_empty() {
            return vec![None; pixels.len()];
        }
        self.write_uniforms();
        let pipelines = self.shade.pipelines().views(&self.device);
        let pipeline = &pipelines.exact_probe;
        let device = &self.device;
        let input = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("exact probe: pixels"),
            contents: bytemuck::cast_slice(pixels),
            usage: wgpu::BufferUsages::STORAGE,
        });
        let size = 4 * pixels.len() as u64;
        let hits = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("exact probe: hits"),
            size,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let entries = [
            (bindings::GRID, &self.scene_buffers.grid),
            (bindings::SPHERES, &self.scene_buffers.spheres),
            (bindings::SHADING, self.shade.uniform()),
            (bindings::PROBE_PIXELS, &input),
            (bindings::PROBE_HITS, &hits),
        ]
        .map(|(binding, buffer)| wgpu::BindGroupEntry { binding, resource: buffer.as_entire_binding() });
        let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("exact probe: bind group"),
            layout: &pipeline.get_bind_group_layout(0),
            entries: &entries,
        });
        let mut encoder =
            device.create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("exact probe") });
        {
            let mut pass = encoder.begin_compute_pass(&Default::default());
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, &group, &[]);
            pass.dispatch_workgroups((pixels.len() as u32).div_ceil(64), 1, 1);
        }
        self.queue.submit([encoder.finish()]);
        let bytes = read_buffer(device, &self.queue, &hits, 0, size).await;
        input.destroy();
        hits.destroy();
        bytemuck::cast_slice::<u8, f32>(&bytes).iter().map(|&t| (t >= 0.0).then_some(t)).collect()
    }
}
