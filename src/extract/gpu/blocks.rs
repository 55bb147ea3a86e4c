//! The block pass (`shaders/extract/blocks.wgsl`): bound the field over blocks of 4³ cells, keep the blocks the
//! surface may cross, and size the per-block passes' indirect dispatch to them.

use crate::device::{bind_buffers, bindings, compute_module, compute_pipeline, wgsl};
use crate::extract::buffers::{BLOCK_CELLS, MeshBuffers};
use crate::extract::gpu::scene_buffers::SceneBuffers;

/// Owns the block classification pipelines and their bind groups for the current buffers.
#[derive(Clone)]
pub struct BlockPass {
    classify: wgpu::ComputePipeline,
    plan: wgpu::ComputePipeline,
    groups: Option<[wgpu::BindGroup; 2]>,
}

impl BlockPass {
    pub fn new(device: &wgpu::Device) -> Self {
        let module = compute_module(device, "blocks: shader", wgsl!("extract/blocks.wgsl"));
        Self {
            classify: compute_pipeline(device, "blocks: classify pipeline", &module, "classify_blocks"),
            plan: compute_pipeline(device, "blocks: plan pipeline", &module, "plan_dispatch"),
            groups: None,
        }
    }

    /// Binds the pass to new buffers.
    pub fn bind(&mut self, device: &wgpu::Device, scene: &SceneBuffers, mesh: &MeshBuffers) {
        self.groups = Some([
            bind_buffers(
                device,
                "blocks: classify bind group",
                &self.classify,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::SPHERES, &scene.spheres),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::ACTIVE_BLOCKS, &mesh.active_blocks),
                    (bindings::BLOCK_SLOTS, &mesh.block_slots),
                ],
            ),
            bind_buffers(
                device,
                "blocks: plan bind group",
                &self.plan,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::BLOCK_DISPATCH, &mesh.dispatch),
                ],
            ),
        ]);
    }

    pub fn encode(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        timestamp_writes: Option<wgpu::ComputePassTimestampWrites>,
    ) {
        let [classify, plan] = self.groups.as_ref().expect("BlockPass::bind before encode");
        encoder.clear_buffer(&mesh.counters, 0, None);
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("blocks: pass"),
            timestamp_writes,
        });
        pass.set_pipeline(&self.classify);
        pass.set_bind_group(0, classify, &[]);
        let blocks = mesh.grid.cells_per_axis.div_ceil(BLOCK_CELLS).pow(3);
        pass.dispatch_workgroups(blocks.div_ceil(64), 1, 1);
        pass.set_pipeline(&self.plan);
        pass.set_bind_group(0, plan, &[]);
        pass.dispatch_workgroups(1, 1, 1);
    }
}
