//! The measures pass (`shaders/draw/measure.wgsl`): each vertex's distance to the exact surface and each
//! triangle's shape, summed on the GPU into the counters buffer, which the frame statistics bring back.
//! It reads the mesh, whichever extractor made it, and writes only the measures.

use crate::device::{bind_buffers, bindings, compute_module, compute_pipeline, wgsl};
use crate::extract::buffers::MeshBuffers;
use crate::extract::gpu::scene_buffers::SceneBuffers;
use crate::extract::uniforms::{MEASURES_OFFSET, Measures};
use wgpu::util::DeviceExt;

/// Owns the measures pipelines, their small buffers and their bind groups for the current mesh buffers.
pub struct MeasurePass {
    plan: wgpu::ComputePipeline,
    measure: wgpu::ComputePipeline,
    job: wgpu::Buffer,
    dispatch: wgpu::Buffer,
    groups: Option<[wgpu::BindGroup; 2]>,
}

impl MeasurePass {
    pub fn new(device: &wgpu::Device) -> Self {
        let module = compute_module(device, "measures: shader", wgsl!("draw/measure.wgsl"));
        use wgpu::BufferUsages as U;
        Self {
            plan: compute_pipeline(device, "measures: plan pipeline", &module, "plan_measures"),
            measure: compute_pipeline(device, "measures: pipeline", &module, "measure"),
            job: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("measures: job"),
                contents: &[0; 16],
                usage: U::UNIFORM | U::COPY_DST,
            }),
            dispatch: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("measures: dispatch"),
                contents: &[0; 12],
                usage: U::STORAGE | U::INDIRECT,
            }),
            groups: None,
        }
    }

    /// Forgets the bind groups: the mesh buffers were replaced.
    pub fn unbind(&mut self) {
        self.groups = None;
    }

    /// Measures the mesh in `mesh`: `known` gives its vertex and triangle counts when it was uploaded,
    /// `None` when the compute passes counted it on the device.
    pub fn encode(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        encoder: &mut wgpu::CommandEncoder,
        scene: &SceneBuffers,
        mesh: &MeshBuffers,
        known: Option<(u32, u32)>,
    ) {
        let (vertices, triangles) = known.unwrap_or((0, 0));
        queue.write_buffer(
            &self.job,
            0,
            bytemuck::cast_slice(&[known.is_some() as u32, vertices, triangles, 0]),
        );
        let groups = self.groups.get_or_insert_with(|| {
            let (job, dispatch) =
                ((bindings::MEASURE_JOB, &self.job), (bindings::MEASURE_DISPATCH, &self.dispatch));
            [
                bind_buffers(
                    device,
                    "measures: plan bind group",
                    &self.plan,
                    &[(bindings::GRID, &scene.grid), (bindings::COUNTERS, &mesh.counters), job, dispatch],
                ),
                bind_buffers(
                    device,
                    "measures: bind group",
                    &self.measure,
                    &[
                        (bindings::GRID, &scene.grid),
                        (bindings::SPHERES, &scene.spheres),
                        (bindings::COUNTERS, &mesh.counters),
                        (bindings::VERTICES, &mesh.vertices),
                        (bindings::INDICES, &mesh.indices),
                        job,
                    ],
                ),
            ]
        });
        let size = std::mem::size_of::<Measures>() as u64;
        encoder.clear_buffer(&mesh.counters, MEASURES_OFFSET, Some(size));
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("measures: pass"),
            timestamp_writes: None,
        });
        pass.set_pipeline(&self.plan);
        pass.set_bind_group(0, &groups[0], &[]);
        pass.dispatch_workgroups(1, 1, 1);
        pass.set_pipeline(&self.measure);
        pass.set_bind_group(0, &groups[1], &[]);
        pass.dispatch_workgroups_indirect(&self.dispatch, 0);
    }
}

/// The mesh's measures as a person reads them.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct MeshMeasures {
    /// The frame they are for.
    pub frame: u64,
    /// Root mean square of the vertices' distances to the exact surface, in cells.
    pub rms_error: f32,
    /// The largest distance, in cells.
    pub max_error: f32,
    /// Vertices measured.
    pub vertices: u32,
    /// Triangles per tenth of the shape measure, slivers first.
    pub quality: [u32; crate::extract::uniforms::QUALITY_BINS],
}

impl MeshMeasures {
    /// Reads the sums the pass left.
    pub fn from_sums(frame: u64, m: &Measures) -> Self {
        let squares = (m.squares[0] as u64 | (m.squares[1] as u64) << 32) as f64
            / crate::extract::uniforms::SQUARES_SCALE;
        let n = m.measured.max(1) as f64;
        Self {
            frame,
            rms_error: (squares / n).sqrt() as f32,
            max_error: f32::from_bits(m.largest),
            vertices: m.measured,
            quality: m.quality,
        }
    }
}
