//! The uniform and storage buffers every compute pass reads: grid parameters and spheres.

use crate::extract::uniforms::GridUniform;
use crate::scene::params::MAX_SPHERES;

pub struct SceneBuffers {
    pub grid: wgpu::Buffer,
    pub spheres: wgpu::Buffer,
}

impl SceneBuffers {
    pub fn new(device: &wgpu::Device) -> Self {
        Self {
            grid: device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("scene: grid uniforms"),
                size: std::mem::size_of::<GridUniform>() as u64,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }),
            spheres: device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("scene: spheres"),
                size: MAX_SPHERES as u64 * 16,
                usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }),
        }
    }
}
