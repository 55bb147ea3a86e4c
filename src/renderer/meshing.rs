//! Where each frame's mesh comes from: the GPU's compute passes or the CPU mesher, whose result is
//! uploaded into the same vertex and index buffers. The shading pass draws either the same way.

use super::{FrameStats, Renderer, Sizing};
use crate::cpu_mesher::CpuMesher;
use crate::params::view::Mesher;
use crate::reference::Construction;
use crate::shade::DrawCount;
use crate::uniforms::Counters;
use crate::views;

/// Which mesher made a frame's mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshSource {
    /// The compute passes (block skipping, field, marching cubes).
    Gpu,
    /// The CPU mesher, uploaded with `Queue::write_buffer`.
    Cpu,
}

impl MeshSource {
    /// `gpu` or `cpu`.
    pub fn word(self) -> &'static str {
        match self {
            MeshSource::Gpu => "gpu",
            MeshSource::Cpu => "cpu",
        }
    }
}

impl Renderer {
    /// Records the extraction passes: blocks, field, marching cubes.
    pub(super) fn encode_extraction(&self, encoder: &mut wgpu::CommandEncoder, timed: bool) {
        let Some(passes) = &self.compute else { return };
        let timing = self.timing.as_ref().filter(|_| timed);
        passes.blocks.encode(encoder, &self.mesh, timing.map(|t| t.compute_writes(0)));
        passes.field.encode(encoder, &self.mesh, timing.map(|t| t.compute_writes(1)));
        passes.marching.encode(encoder, &self.mesh, timing.map(|t| t.compute_writes(2)));
    }

    /// Makes this frame's mesh where `source` says: records the compute passes, or meshes on the CPU
    /// and uploads the result into the same vertex and index buffers.
    pub(super) fn make_mesh(&mut self, encoder: &mut wgpu::CommandEncoder, timed: bool) -> DrawCount {
        self.source = self.next_source();
        match self.source {
            MeshSource::Gpu => {
                self.encode_extraction(encoder, timed);
                DrawCount::Indirect
            }
            MeshSource::Cpu => DrawCount::Direct(self.mesh_on_cpu()),
        }
    }

    /// True when the teaching views draw this frame. They read the compute passes' buffers, so a
    /// device without compute shaders shows the surface alone.
    pub(super) fn views_shown(&self) -> bool {
        self.compute.is_some() && views::needed(&self.settings.view, self.selected.is_some())
    }

    /// Where the next frame's mesh comes from: the CPU without compute shaders; the GPU while a
    /// teaching view draws from its buffers; else as `mesher` says, `auto` choosing the CPU on a
    /// software adapter (where compute passes are emulated on the CPU) and the GPU on hardware.
    pub fn next_source(&self) -> MeshSource {
        if self.compute.is_none() {
            return MeshSource::Cpu;
        }
        if self.views_shown() {
            return MeshSource::Gpu;
        }
        match self.settings.view.mesher {
            Mesher::Gpu => MeshSource::Gpu,
            Mesher::Cpu => MeshSource::Cpu,
            Mesher::Auto if self.context.is_software() => MeshSource::Cpu,
            Mesher::Auto => MeshSource::Gpu,
        }
    }

    /// Meshes the current scene on the CPU and uploads it, growing the buffers when it does not fit
    /// (a fixed triangle budget clamps instead, as on the GPU). Returns the indices to draw.
    pub(super) fn mesh_on_cpu(&mut self) -> u32 {
        let grid = self.grid();
        let view = &self.settings.view;
        let construction = Construction { interpolation: view.interpolation, blend: view.blend };
        let mesher = self.cpu.get_or_insert_with(CpuMesher::new);
        mesher.mesh(self.scene.spheres(), self.settings.iso, grid, construction);
        let (vertices, requested) = (mesher.vertex_count(), mesher.indices.len() as u32);
        let capacity = self.mesh.capacity;
        let limit = match self.sizing {
            Sizing::FixedTriangles(n) => 3 * n,
            Sizing::Automatic => u32::MAX,
        };
        if vertices > capacity.vertices || requested.min(limit) > capacity.indices {
            let need =
                Counters { active_blocks: 0, vertices, indices: requested.min(limit), active_cells: 0 };
            self.reallocate(capacity.grown_for(&need));
        }
        let Some(mesher) = self.cpu.as_ref() else { return 0 };
        let indices = requested.min(self.mesh.capacity.indices);
        if vertices > 0 {
            self.queue.write_buffer(&self.mesh.vertices, 0, bytemuck::cast_slice(&mesher.vertices));
        }
        if indices > 0 {
            let data = bytemuck::cast_slice(&mesher.indices[..indices as usize]);
            self.queue.write_buffer(&self.mesh.indices, 0, data);
        }
        let stats = mesher.stats();
        self.latest_stats = Some(FrameStats {
            frame: self.frame,
            triangles: indices / 3,
            triangles_requested: requested / 3,
            max_triangles: self.mesh.capacity.indices / 3,
            vertices,
            active_blocks: stats.active_blocks,
            total_blocks: stats.total_blocks,
            active_cells: stats.active_cells,
            total_cells: grid.cells_per_axis.pow(3),
            overflowed: indices < requested,
            mesh_bytes: self.mesh.bytes(),
        });
        self.cpu_indices = indices;
        indices
    }
}
