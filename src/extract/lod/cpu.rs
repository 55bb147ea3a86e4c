//! Level of detail on the CPU: the frame's selection meshed by the [`LodMesher`] and uploaded into the
//! shared buffers, as the uniform CPU mesher's mesh is. Software adapters and WebGL2 get LOD this way.

use super::mesher::LodMesher;
use super::select::{Eye, Selection};
use super::{LodSummary, eye_of, select_for_surface};
use crate::extract::extractor::{Capabilities, Extractor, Job, MeshCount, Output};
use crate::extract::facing::front_faces;
use crate::extract::mesh::IndexedMesh;
use crate::extract::uniforms::Counters;
use crate::scene::params::view::Method;

/// The LOD mesher and the selection it last meshed.
#[derive(Default)]
pub struct LodCpuExtractor {
    mesher: LodMesher,
    selection: Selection,
    /// The eye while the selection is frozen.
    frozen: Option<Eye>,
    /// Indices of the mesh the latest `write` uploaded (or would have, before leaving out back faces).
    written: u32,
    /// The indices of the triangles facing the viewer, when only those are drawn.
    front: Vec<u32>,
}

impl LodCpuExtractor {
    /// Runs anywhere: there is nothing to compile.
    pub fn compile(_device: &wgpu::Device) -> Option<Box<dyn Extractor>> {
        Some(Box::<Self>::default())
    }
}

impl Extractor for LodCpuExtractor {
    fn name(&self) -> &'static str {
        "lod-cpu"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            needs_compute: false,
            cell_lists: false,
            cpu_copy: true,
            lod: true,
            method: Method::MarchingCubes,
        }
    }

    fn fresh(&self) -> Box<dyn Extractor> {
        Box::<Self>::default()
    }

    fn prepare(&mut self, job: &Job) -> Option<Counters> {
        if let Some(eye) = eye_of(&mut self.frozen, job) {
            let terms = job.construction.terms;
            self.selection = select_for_surface(job.spheres, job.iso, terms, job.grid.cells_per_axis, &eye);
        }
        self.mesher.mesh(job.spheres, job.iso, job.construction, &self.selection);
        let stats = self.mesher.stats();
        Some(Counters {
            active_blocks: stats.active_blocks,
            vertices: self.mesher.vertex_count(),
            indices: self.mesher.indices.len() as u32,
            active_cells: stats.active_cells + stats.transition_cells,
        })
    }

    fn write(&mut self, output: Output) -> MeshCount {
        let mesher = &self.mesher;
        let stats = mesher.stats();
        let needed = Counters {
            active_blocks: stats.active_blocks,
            vertices: mesher.vertex_count(),
            indices: mesher.indices.len() as u32,
            active_cells: stats.active_cells + stats.transition_cells,
        };
        // The mesh is closed (transition cells stitch every seam), so from outside the box its back
        // faces never show; nothing but the shading pass reads the buffers when it is asked to leave
        // them out.
        let drawn = match output.front_faces {
            Some(viewpoint) if output.buffers.holds(needed.vertices, needed.indices) => {
                front_faces(&mesher.vertices, &mesher.indices, viewpoint, &mut self.front);
                self.written = needed.indices;
                output.buffers.upload(output.queue, &mesher.vertices, &self.front)
            }
            _ => {
                self.written = output.buffers.upload(output.queue, &mesher.vertices, &mesher.indices);
                self.written
            }
        };
        let buffers = output.buffers;
        // The views colour by level and count what to draw from the device's copies.
        let lod_data = &buffers.lod_data;
        if lod_data.size() >= 4 * (self.written as u64 / 3) && self.written > 0 {
            let levels: Vec<u32> =
                mesher.triangle_levels[..self.written as usize / 3].iter().map(|&l| l as u32).collect();
            output.queue.write_buffer(lod_data, 0, bytemuck::cast_slice(&levels));
        }
        let kept = mesher.kept_blocks.len().min(buffers.capacity.blocks as usize);
        let at = 4 * buffers.lod_blocks_offset() as u64;
        if kept > 0 && lod_data.size() >= at + 16 * kept as u64 {
            output.queue.write_buffer(lod_data, at, bytemuck::cast_slice(&mesher.kept_blocks[..kept]));
        }
        if buffers.counters.usage().contains(wgpu::BufferUsages::STORAGE) {
            let counts = Counters { indices: self.written, ..needed };
            output.queue.write_buffer(&buffers.counters, 0, bytemuck::bytes_of(&counts));
        }
        MeshCount::Known { needed, indices: self.written, drawn }
    }

    fn cpu_mesh(&self) -> Option<IndexedMesh> {
        let mut mesh = self.mesher.to_indexed();
        mesh.triangles.truncate(self.written as usize / 3);
        Some(mesh)
    }

    fn lod_summary(&self) -> Option<LodSummary> {
        let stats = self.mesher.stats();
        Some(LodSummary {
            resolution: self.selection.resolution,
            blocks: stats.blocks.clone(),
            triangles: Some(stats.triangles.clone()),
            cells_processed: Some(stats.cells_processed),
        })
    }
}
