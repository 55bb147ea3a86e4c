//! The marching-cubes pass (`shaders/marching_cubes.wgsl`): classify cells, append their triangles with
//! an atomic counter, and turn the count into indirect draw arguments on the GPU.

use crate::field_pass::{COMMON_WGSL, SceneBuffers, workgroups};
use crate::reference::Grid;
use crate::tables::{CASE_TRIANGLES, EDGE_TABLE, TRI_TABLE};
use crate::uniforms::Counters;
use wgpu::util::DeviceExt;

/// Bytes of one vertex: position and normal, three f32 each.
pub const VERTEX_BYTES: u64 = 24;
/// Bytes of the indirect draw arguments.
const DRAW_ARGS_BYTES: u64 = 16;

/// Owns the marching-cubes pipelines, the tables on the GPU and, for the current grid, the vertex,
/// counter and draw-argument buffers.
pub struct MarchingCubesPass {
    kernels: Kernels,
    buffers: MeshBuffers,
}

/// What does not depend on the grid: pipelines and tables.
struct Kernels {
    march: wgpu::ComputePipeline,
    finalize: wgpu::ComputePipeline,
    case_table: wgpu::Buffer,
    triangle_table: wgpu::Buffer,
}

/// The buffers sized for one grid and triangle budget.
struct MeshBuffers {
    grid: Grid,
    max_vertices: u32,
    vertices: wgpu::Buffer,
    counters: wgpu::Buffer,
    draw_args: wgpu::Buffer,
    march_group: wgpu::BindGroup,
    finalize_group: wgpu::BindGroup,
}

/// The case table as the shader reads it: crossed-edge mask in bits 0..11, triangle count from bit 16.
pub fn packed_case_table() -> [u32; 256] {
    std::array::from_fn(|case| EDGE_TABLE[case] as u32 | (CASE_TRIANGLES[case] as u32) << 16)
}

/// The triangle table flattened to 16 `i32` per case.
pub fn flat_triangle_table() -> Vec<i32> {
    TRI_TABLE.iter().flatten().map(|&e| e as i32).collect()
}

impl MarchingCubesPass {
    pub fn new(
        device: &wgpu::Device,
        scene: &SceneBuffers,
        field: &wgpu::Buffer,
        grid: Grid,
        max_vertices: u32,
    ) -> Self {
        let kernels = Kernels::new(device);
        let buffers = MeshBuffers::new(device, &kernels, scene, field, grid, max_vertices);
        Self { kernels, buffers }
    }

    /// Replaces the mesh buffers for a new grid or budget; the old ones are freed.
    pub fn set_grid(
        &mut self,
        device: &wgpu::Device,
        scene: &SceneBuffers,
        field: &wgpu::Buffer,
        grid: Grid,
        max_vertices: u32,
    ) {
        self.buffers.destroy();
        self.buffers = MeshBuffers::new(device, &self.kernels, scene, field, grid, max_vertices);
    }

    /// Resets the counter, marches every cell and writes the draw arguments.
    pub fn encode(&self, encoder: &mut wgpu::CommandEncoder) {
        let b = &self.buffers;
        encoder.clear_buffer(&b.counters, 0, None);
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("marching cubes: pass"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&self.kernels.march);
        pass.set_bind_group(0, &b.march_group, &[]);
        let groups = workgroups(b.grid.cells_per_axis);
        pass.dispatch_workgroups(groups, groups, groups);
        pass.set_pipeline(&self.kernels.finalize);
        pass.set_bind_group(0, &b.finalize_group, &[]);
        pass.dispatch_workgroups(1, 1, 1);
    }

    /// Vertices: position and normal per vertex, three per triangle.
    pub fn vertices(&self) -> &wgpu::Buffer {
        &self.buffers.vertices
    }

    /// The counter block (`Counters`), for statistics.
    pub fn counters(&self) -> &wgpu::Buffer {
        &self.buffers.counters
    }

    /// Arguments for `draw_indirect`.
    pub fn draw_args(&self) -> &wgpu::Buffer {
        &self.buffers.draw_args
    }

    /// Capacity of the vertex buffer.
    pub fn max_vertices(&self) -> u32 {
        self.buffers.max_vertices
    }
}

impl Kernels {
    fn new(device: &wgpu::Device) -> Self {
        let source = format!("{COMMON_WGSL}\n{}", include_str!("../shaders/marching_cubes.wgsl"));
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("marching cubes: shader"),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        });
        let pipeline = |label, entry_point| {
            device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some(label),
                layout: None,
                module: &module,
                entry_point: Some(entry_point),
                compilation_options: Default::default(),
                cache: None,
            })
        };
        Self {
            march: pipeline("marching cubes: march pipeline", "march_cells"),
            finalize: pipeline("marching cubes: finalize pipeline", "finalize_draw"),
            case_table: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("marching cubes: case table"),
                contents: bytemuck::cast_slice(&packed_case_table()),
                usage: wgpu::BufferUsages::STORAGE,
            }),
            triangle_table: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("marching cubes: triangle table"),
                contents: bytemuck::cast_slice(&flat_triangle_table()),
                usage: wgpu::BufferUsages::STORAGE,
            }),
        }
    }
}

impl MeshBuffers {
    fn new(
        device: &wgpu::Device,
        kernels: &Kernels,
        scene: &SceneBuffers,
        field: &wgpu::Buffer,
        grid: Grid,
        max_vertices: u32,
    ) -> Self {
        let vertices = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("marching cubes: vertices"),
            size: max_vertices as u64 * VERTEX_BYTES,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let counters = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("marching cubes: counters"),
            size: std::mem::size_of::<Counters>() as u64,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let draw_args = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("marching cubes: draw arguments"),
            size: DRAW_ARGS_BYTES,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::INDIRECT,
            mapped_at_creation: false,
        });
        let march_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("marching cubes: march bind group"),
            layout: &kernels.march.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: scene.grid.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: scene.spheres.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 2, resource: field.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 3, resource: kernels.case_table.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 4, resource: kernels.triangle_table.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 5, resource: vertices.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 6, resource: counters.as_entire_binding() },
            ],
        });
        let finalize_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("marching cubes: finalize bind group"),
            layout: &kernels.finalize.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: scene.grid.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 6, resource: counters.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 7, resource: draw_args.as_entire_binding() },
            ],
        });
        Self { grid, max_vertices, vertices, counters, draw_args, march_group, finalize_group }
    }

    fn destroy(&self) {
        self.vertices.destroy();
        self.counters.destroy();
        self.draw_args.destroy();
    }
}
