//! Extraction on the CPU: the [`CpuMesher`] meshes the frame in `prepare`, then `write` uploads its
//! vertices and indices into the same buffers the compute passes fill (`Queue::write_buffer`), and the
//! mesh is drawn the same way. On a software adapter it beats compute passes emulated on the CPU; on
//! WebGL2 it is the only extractor.

pub mod facing;
pub mod mesher;
pub mod surface_nets;

pub use mesher::CpuMesher;
pub use surface_nets::SurfaceNetsMesher;

use super::extractor::{Capabilities, Extractor, Job, MeshCount, Output};
use super::mesh::IndexedMesh;
use super::uniforms::Counters;
use crate::scene::params::view::Method;

/// The CPU mesher and what it last uploaded.
#[derive(Default)]
pub struct CpuExtractor {
    mesher: CpuMesher,
    /// Indices of the mesh the latest `write` uploaded (or would have, before leaving out back faces).
    written: u32,
    /// The indices of the triangles facing the viewer, when only those are drawn.
    front: Vec<u32>,
}

impl CpuExtractor {
    /// Runs anywhere: there is nothing to compile.
    pub fn compile(_device: &wgpu::Device) -> Option<Box<dyn Extractor>> {
        Some(Box::<Self>::default())
    }
}

impl Extractor for CpuExtractor {
    fn name(&self) -> &'static str {
        "cpu"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            needs_compute: false,
            cell_lists: false,
            cpu_copy: true,
            lod: false,
            method: Method::MarchingCubes,
        }
    }

    fn fresh(&self) -> Box<dyn Extractor> {
        Box::<Self>::default()
    }

    /// Meshes the frame; the buffers need room for its vertices and indices only.
    fn prepare(&mut self, job: &Job) -> Option<Counters> {
        self.mesher.mesh(job.spheres, job.iso, job.grid, job.construction);
        let (vertices, indices) = (self.mesher.vertex_count(), self.mesher.indices.len() as u32);
        Some(Counters { active_blocks: 0, vertices, indices, active_cells: 0 })
    }

    fn write(&mut self, output: Output) -> MeshCount {
        let mesher = &self.mesher;
        let (vertices, requested) = (mesher.vertex_count(), mesher.indices.len() as u32);
        let fits = output.buffers.holds(vertices, requested);
        // A whole marching-cubes mesh is closed, so from outside the box its back faces never show.
        let (indices, drawn) = match output.front_faces {
            Some(viewpoint) if fits => {
                facing::front_faces(&mesher.vertices, &mesher.indices, viewpoint, &mut self.front);
                let drawn = output.buffers.upload(output.queue, &mesher.vertices, &self.front);
                (requested, drawn)
            }
            _ => {
                let written = output.buffers.upload(output.queue, &mesher.vertices, &mesher.indices);
                (written, written)
            }
        };
        self.written = indices;
        let stats = mesher.stats();
        let needed = Counters {
            active_blocks: stats.active_blocks,
            vertices,
            indices: requested,
            active_cells: stats.active_cells,
        };
        MeshCount::Known { needed, indices, drawn }
    }

    fn cpu_mesh(&self) -> Option<IndexedMesh> {
        let mut mesh = self.mesher.to_indexed();
        mesh.triangles.truncate(self.written as usize / 3);
        Some(mesh)
    }
}

/// Surface nets on the CPU, uploaded like the marching-cubes mesher's mesh (`extractor=surface_nets`).
#[derive(Default)]
pub struct SurfaceNetsExtractor {
    mesher: SurfaceNetsMesher,
    written: u32,
}

impl SurfaceNetsExtractor {
    /// Runs anywhere: there is nothing to compile.
    pub fn compile(_device: &wgpu::Device) -> Option<Box<dyn Extractor>> {
        Some(Box::<Self>::default())
    }

    fn counters(&self) -> Counters {
        let stats = self.mesher.stats();
        Counters {
            active_blocks: stats.active_blocks,
            vertices: self.mesher.vertex_count(),
            indices: self.mesher.indices.len() as u32,
            active_cells: stats.active_cells,
        }
    }
}

impl Extractor for SurfaceNetsExtractor {
    fn name(&self) -> &'static str {
        "surface-nets"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            needs_compute: false,
            cell_lists: false,
            cpu_copy: true,
            lod: false,
            method: Method::SurfaceNets,
        }
    }

    fn fresh(&self) -> Box<dyn Extractor> {
        Box::<Self>::default()
    }

    fn prepare(&mut self, job: &Job) -> Option<Counters> {
        self.mesher.mesh(job.spheres, job.iso, job.grid, job.construction);
        Some(self.counters())
    }

    fn write(&mut self, output: Output) -> MeshCount {
        let mesher = &self.mesher;
        self.written = output.buffers.upload(output.queue, &mesher.vertices, &mesher.indices);
        MeshCount::Known { needed: self.counters(), indices: self.written, drawn: self.written }
    }

    fn cpu_mesh(&self) -> Option<IndexedMesh> {
        let mut mesh = self.mesher.to_indexed();
        mesh.triangles.truncate(self.written as usize / 3);
        Some(mesh)
    }
}
