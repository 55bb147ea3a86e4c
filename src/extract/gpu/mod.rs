//! Extraction in compute shaders, all on the device: the block pass bounds the field over blocks of 4³
//! cells and lists those the surface may cross, the field pass evaluates them and lists the crossed
//! cells, and the marching-cubes passes write shared vertices and indices. Counters feed indirect
//! dispatches and the indexed indirect draw; nothing is read back.

pub mod blocks;
pub mod field;
pub mod marching_cubes;
pub mod scene_buffers;

use super::buffers::MeshBuffers;
use super::extractor::{Capabilities, Extractor, Job, MeshCount, Output};
use super::uniforms::Counters;
use crate::device::has_compute;
use blocks::BlockPass;
use field::FieldPass;
use marching_cubes::MarchingCubesPass;
use scene_buffers::SceneBuffers;

/// The three compute passes; clones share the compiled pipelines and bind their own buffers.
#[derive(Clone)]
pub struct GpuExtractor {
    blocks: BlockPass,
    field: FieldPass,
    marching: MarchingCubesPass,
}

impl GpuExtractor {
    /// Compiles the passes, on a device with compute shaders.
    pub fn compile(device: &wgpu::Device) -> Option<Box<dyn Extractor>> {
        if !has_compute(device) {
            return None;
        }
        Some(Box::new(Self {
            blocks: BlockPass::new(device),
            field: FieldPass::new(device),
            marching: MarchingCubesPass::new(device),
        }))
    }
}

impl Extractor for GpuExtractor {
    fn name(&self) -> &'static str {
        "gpu"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities { needs_compute: true, cell_lists: true, cpu_copy: false }
    }

    fn fresh(&self) -> Box<dyn Extractor> {
        Box::new(self.clone())
    }

    fn bind(&mut self, device: &wgpu::Device, scene: &SceneBuffers, buffers: &MeshBuffers) {
        self.blocks.bind(device, scene, buffers);
        self.field.bind(device, scene, buffers);
        self.marching.bind(device, scene, buffers);
    }

    /// The passes read the scene from the uniforms the renderer uploaded: nothing to do before them.
    fn prepare(&mut self, _job: &Job) -> Option<Counters> {
        None
    }

    fn write(&mut self, output: Output) -> MeshCount {
        let Output { encoder, buffers, timing, .. } = output;
        self.blocks.encode(encoder, buffers, timing.map(|t| t.compute_writes(0)));
        self.field.encode(encoder, buffers, timing.map(|t| t.compute_writes(1)));
        self.marching.encode(encoder, buffers, timing.map(|t| t.compute_writes(2)));
        MeshCount::OnDevice
    }
}
