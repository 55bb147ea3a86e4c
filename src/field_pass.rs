//! The field pass: f at every grid point into a storage buffer (`shaders/field.wgsl`).

use crate::reference::Grid;

/// WGSL shared by the field and marching-cubes passes.
pub(crate) const COMMON_WGSL: &str = include_str!("../shaders/common.wgsl");

/// Invocations per workgroup along each axis (`@workgroup_size(4, 4, 4)` in the shaders).
pub(crate) const WORKGROUP_EDGE: u32 = 4;

/// Bytes of one field value.
pub(crate) const FIELD_VALUE_BYTES: u64 = 4;

/// The uniform and storage buffers every compute pass reads: grid parameters and spheres.
pub struct SceneBuffers {
    pub grid: wgpu::Buffer,
    pub spheres: wgpu::Buffer,
}

/// Owns the field pipeline and, for the current resolution, the field buffer.
pub struct FieldPass {
    pipeline: wgpu::ComputePipeline,
    field: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    grid: Grid,
}

/// Workgroups along each axis to cover `items` invocations.
pub(crate) fn workgroups(items: u32) -> u32 {
    items.div_ceil(WORKGROUP_EDGE)
}

impl FieldPass {
    pub fn new(device: &wgpu::Device, scene: &SceneBuffers, grid: Grid) -> Self {
        let source = format!("{COMMON_WGSL}\n{}", include_str!("../shaders/field.wgsl"));
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("field: shader"),
            source: wgpu::ShaderSource::Wgsl(source.into()),
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("field: pipeline"),
            layout: None,
            module: &module,
            entry_point: Some("evaluate_field"),
            compilation_options: Default::default(),
            cache: None,
        });
        let (field, bind_group) = Self::allocate(device, &pipeline, scene, grid);
        Self { pipeline, field, bind_group, grid }
    }

    fn allocate(
        device: &wgpu::Device,
        pipeline: &wgpu::ComputePipeline,
        scene: &SceneBuffers,
        grid: Grid,
    ) -> (wgpu::Buffer, wgpu::BindGroup) {
        let field = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("field: values"),
            size: field_bytes(grid.cells_per_axis),
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("field: bind group"),
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry { binding: 0, resource: scene.grid.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 1, resource: scene.spheres.as_entire_binding() },
                wgpu::BindGroupEntry { binding: 2, resource: field.as_entire_binding() },
            ],
        });
        (field, bind_group)
    }

    /// Replaces the field buffer for a new grid; the old one is freed.
    pub fn set_grid(&mut self, device: &wgpu::Device, scene: &SceneBuffers, grid: Grid) {
        self.field.destroy();
        (self.field, self.bind_group) = Self::allocate(device, &self.pipeline, scene, grid);
        self.grid = grid;
    }

    /// The field values, `(cells_per_axis + 1)³` f32s, x fastest.
    pub fn field(&self) -> &wgpu::Buffer {
        &self.field
    }

    pub fn encode(&self, encoder: &mut wgpu::CommandEncoder) {
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("field: pass"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &self.bind_group, &[]);
        let groups = workgroups(self.grid.points_per_axis());
        pass.dispatch_workgroups(groups, groups, groups);
    }
}

/// Bytes of the field buffer at `cells_per_axis`.
pub fn field_bytes(cells_per_axis: u32) -> u64 {
    (cells_per_axis as u64 + 1).pow(3) * FIELD_VALUE_BYTES
}
