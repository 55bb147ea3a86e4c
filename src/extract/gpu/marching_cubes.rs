//! The marching-cubes passes (`shaders/extract/marching_cubes.wgsl`), over the active cells: vertices on the
//! edges each cell owns, then triangles as indices into them, then the indexed indirect draw's arguments.

use crate::device::{bind_buffers, bindings, compute_module, compute_pipeline, wgsl};
use crate::extract::buffers::MeshBuffers;
use crate::extract::decider::variant_table;
use crate::extract::gpu::scene_buffers::SceneBuffers;
use wgpu::util::DeviceExt;

/// Owns the marching-cubes pipelines, the tables on the GPU, and bind groups for the current buffers.
#[derive(Clone)]
pub struct MarchingCubesPass {
    vertices: wgpu::ComputePipeline,
    triangles: wgpu::ComputePipeline,
    finalize: wgpu::ComputePipeline,
    triangle_table: wgpu::Buffer,
    groups: Option<[wgpu::BindGroup; 3]>,
}

impl MarchingCubesPass {
    pub fn new(device: &wgpu::Device) -> Self {
        let module = compute_module(
            device,
            "marching cubes: shader",
            wgsl!(include_str!("../../../shaders/extract/marching_cubes.wgsl")),
        );
        Self {
            vertices: compute_pipeline(device, "marching cubes: vertex pipeline", &module, "make_vertices"),
            triangles: compute_pipeline(
                device,
                "marching cubes: triangle pipeline",
                &module,
                "make_triangles",
            ),
            finalize: compute_pipeline(device, "marching cubes: finalize pipeline", &module, "finalize_draw"),
            triangle_table: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("marching cubes: triangle table"),
                contents: bytemuck::cast_slice(variant_table()),
                usage: wgpu::BufferUsages::STORAGE,
            }),
            groups: None,
        }
    }

    /// Binds the passes to new buffers.
    pub fn bind(&mut self, device: &wgpu::Device, scene: &SceneBuffers, mesh: &MeshBuffers) {
        self.groups = Some([
            bind_buffers(
                device,
                "marching cubes: vertex bind group",
                &self.vertices,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::SPHERES, &scene.spheres),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::ACTIVE_BLOCKS, &mesh.active_blocks),
                    (bindings::BLOCK_VALUES, &mesh.block_values),
                    (bindings::EDGE_VERTICES, &mesh.edge_vertices),
                    (bindings::VERTICES, &mesh.vertices),
                    (bindings::ACTIVE_CELLS, &mesh.active_cells),
                ],
            ),
            bind_buffers(
                device,
                "marching cubes: triangle bind group",
                &self.triangles,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::ACTIVE_BLOCKS, &mesh.active_blocks),
                    (bindings::BLOCK_SLOTS, &mesh.block_slots),
                    (bindings::TRIANGLE_TABLE, &self.triangle_table),
                    (bindings::CELL_CASES, &mesh.cell_cases),
                    (bindings::EDGE_VERTICES, &mesh.edge_vertices),
                    (bindings::INDICES, &mesh.indices),
                    (bindings::ACTIVE_CELLS, &mesh.active_cells),
                ],
            ),
            bind_buffers(
                device,
                "marching cubes: finalize bind group",
                &self.finalize,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::DRAW_ARGS, &mesh.draw_args),
                ],
            ),
        ]);
    }

    /// Vertices, then triangles, then the draw arguments, over the active blocks.
    pub fn encode(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        timestamp_writes: Option<wgpu::ComputePassTimestampWrites>,
    ) {
        let [vertices, triangles, finalize] =
            self.groups.as_ref().expect("MarchingCubesPass::bind before encode");
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("marching cubes: pass"),
            timestamp_writes,
        });
        pass.set_pipeline(&self.vertices);
        pass.set_bind_group(0, vertices, &[]);
        pass.dispatch_workgroups_indirect(&mesh.cell_dispatch, 0);
        pass.set_pipeline(&self.triangles);
        pass.set_bind_group(0, triangles, &[]);
        pass.dispatch_workgroups_indirect(&mesh.cell_dispatch, 0);
        pass.set_pipeline(&self.finalize);
        pass.set_bind_group(0, finalize, &[]);
        pass.dispatch_workgroups(1, 1, 1);
    }
}
