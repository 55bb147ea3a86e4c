//! The field pass (`shaders/extract/field.wgsl`): f at the 5³ grid points of every active block, then the cells
//! the surface crosses, compacted into a list with its indirect dispatch.

use crate::device::{bind_buffers, bindings, compute_module, compute_pipeline, wgsl};
use crate::extract::buffers::MeshBuffers;
use crate::extract::gpu::scene_buffers::SceneBuffers;

/// Owns the field pipeline and its bind group for the current buffers.
#[derive(Clone)]
pub struct FieldPass {
    pipeline: wgpu::ComputePipeline,
    classify: wgpu::ComputePipeline,
    plan: wgpu::ComputePipeline,
    groups: Option<[wgpu::BindGroup; 3]>,
}

impl FieldPass {
    pub fn new(device: &wgpu::Device) -> Self {
        let module = compute_module(device, "field: shader", wgsl!("extract/field.wgsl"));
        Self {
            pipeline: compute_pipeline(device, "field: pipeline", &module, "evaluate_field"),
            classify: compute_pipeline(device, "field: classify pipeline", &module, "classify_cells"),
            plan: compute_pipeline(device, "field: plan pipeline", &module, "plan_cell_dispatch"),
            groups: None,
        }
    }

    /// Binds the pass to new buffers.
    pub fn bind(&mut self, device: &wgpu::Device, scene: &SceneBuffers, mesh: &MeshBuffers) {
        self.groups = Some([
            bind_buffers(
                device,
                "field: bind group",
                &self.pipeline,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::SPHERES, &scene.spheres),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::ACTIVE_BLOCKS, &mesh.active_blocks),
                    (bindings::BLOCK_VALUES, &mesh.block_values),
                ],
            ),
            bind_buffers(
                device,
                "field: classify bind group",
                &self.classify,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::ACTIVE_BLOCKS, &mesh.active_blocks),
                    (bindings::BLOCK_VALUES, &mesh.block_values),
                    (bindings::CELL_CASES, &mesh.cell_cases),
                    (bindings::ACTIVE_CELLS, &mesh.active_cells),
                ],
            ),
            bind_buffers(
                device,
                "field: plan bind group",
                &self.plan,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::CELL_DISPATCH, &mesh.cell_dispatch),
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
        let [group, classify, plan] = self.groups.as_ref().expect("FieldPass::bind before encode");
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("field: pass"),
            timestamp_writes,
        });
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, group, &[]);
        pass.dispatch_workgroups_indirect(&mesh.dispatch, 0);
        pass.set_pipeline(&self.classify);
        pass.set_bind_group(0, classify, &[]);
        pass.dispatch_workgroups_indirect(&mesh.dispatch, 0);
        pass.set_pipeline(&self.plan);
        pass.set_bind_group(0, plan, &[]);
        pass.dispatch_workgroups(1, 1, 1);
    }
}
