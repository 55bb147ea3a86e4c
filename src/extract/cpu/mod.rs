//! Extraction on the CPU: a mesher (marching cubes, [`CpuMesher`], surface nets or dual contouring)
//! meshes the frame in
//! `prepare`, then `write` uploads its vertices and indices into the same buffers the compute passes
//! fill (`Queue::write_buffer`), and the mesh is drawn the same way. On a software adapter it beats
//! compute passes emulated on the CPU; on WebGL2 it is the only extractor.

pub mod elsewhere;
// The meshers themselves are in the `metaballs-core` crate (`core/src/extract/cpu/`), built for speed.
pub use metaballs_core::extract::cpu::{dual, facing, mesher, tetra};

pub use dual::{DualContouringMesher, SurfaceNetsMesher};
pub use mesher::CpuMesher;
pub use tetra::TetraMesher;

use super::extractor::{Capabilities, Crossings, Extractor, GivenMesh, Job, MeshCount, Output};
use super::mesh::IndexedMesh;
use super::uniforms::Counters;
use crate::scene::params::view::Method;

/// A mesher on the CPU whose mesh [`CpuMeshExtractor`] uploads: vertices of 6 `f32` (position, then
/// outward normal) and three indices per triangle, counter-clockwise seen from outside.
pub trait CpuMeshing: Default + wgpu::WasmNotSendSync + 'static {
    /// The extractor's name (`Extractor::name`).
    const NAME: &'static str;
    /// How it joins the field's crossings into a mesh.
    const METHOD: Method;
    /// Meshes the frame's surface.
    fn mesh_job(&mut self, job: &Job);
    fn vertices(&self) -> &[f32];
    fn indices(&self) -> &[u32];
    /// Blocks the bounds kept and cells the surface crosses, in the last mesh.
    fn blocks_and_cells(&self) -> (u32, u32);
    fn to_indexed(&self) -> IndexedMesh;
    /// Takes a mesh another mesher of its kind made (the page's mesher worker) as its last mesh.
    fn install(&mut self, mesh: GivenMesh);
    /// One word per triangle for the views (`color-by=rank`), or none.
    fn triangle_marks(&self) -> Vec<u32> {
        Vec::new()
    }
    /// False when the mesh came from elsewhere and lacks the marks and crossings this mesher keeps.
    fn complete(&self) -> bool {
        true
    }
    /// Records laid out as vertices, drawn by the views after the mesh's (dual contouring's crossings,
    /// for `display=normals`), or none.
    fn crossings(&self) -> &[f32] {
        &[]
    }
}

/// Both meshers keep their mesh in `vertices` and `indices` and count blocks and cells in `stats()`.
macro_rules! cpu_meshing {
    ($mesher:ty, $name:literal, $method:expr $(, $marks:ident)?) => {
        impl CpuMeshing for $mesher {
            const NAME: &'static str = $name;
            const METHOD: Method = $method;
            fn mesh_job(&mut self, job: &Job) {
                self.mesh(job.spheres, job.iso, job.grid, job.construction);
            }
            fn vertices(&self) -> &[f32] {
                &self.vertices
            }
            fn indices(&self) -> &[u32] {
                &self.indices
            }
            fn blocks_and_cells(&self) -> (u32, u32) {
                (self.stats().active_blocks, self.stats().active_cells)
            }
            fn to_indexed(&self) -> IndexedMesh {
                <$mesher>::to_indexed(self)
            }
            fn install(&mut self, mesh: GivenMesh) {
                let grid = mesh.grid();
                <$mesher>::install(self, mesh.vertices, mesh.indices, mesh.counts, grid);
            }
            $(fn triangle_marks(&self) -> Vec<u32> {
                let $marks = <$mesher>::triangle_marks(self);
                $marks
            }
            fn crossings(&self) -> &[f32] {
                &self.crossings
            }
            fn complete(&self) -> bool {
                self.vertices.is_empty() || !self.placed.is_empty()
            })?
        }
    };
}

cpu_meshing!(CpuMesher, "cpu", Method::MarchingCubes);
cpu_meshing!(SurfaceNetsMesher, "surface-nets", Method::SurfaceNets);
cpu_meshing!(DualContouringMesher, "dual-contouring", Method::DualContouring, marks);
cpu_meshing!(TetraMesher, "cpu-tetrahedra", Method::MarchingTetrahedra);

/// Marching cubes on the CPU (`mesh-on=cpu`, and everything on WebGL2).
pub type CpuExtractor = CpuMeshExtractor<CpuMesher>;
/// Surface nets on the CPU (`method=surface_nets`), and the two below: natively and on WebGL2. The
/// WebGPU page meshes these methods in compute shaders alone, so that its WebAssembly stays small.
pub type SurfaceNetsExtractor = CpuMeshExtractor<SurfaceNetsMesher>;
/// Dual contouring on the CPU (`method=dual_contouring`).
pub type DualContouringExtractor = CpuMeshExtractor<DualContouringMesher>;
/// Marching tetrahedra on the CPU (`method=marching_tetrahedra`).
pub type TetrahedraExtractor = CpuMeshExtractor<TetraMesher>;

/// A CPU mesher and what it last uploaded.
#[derive(Default)]
pub struct CpuMeshExtractor<M> {
    mesher: M,
    /// Indices of the mesh the latest `write` uploaded (or would have, before leaving out back faces).
    written: u32,
    /// The indices of the triangles facing the viewer, when only those are drawn.
    front: Vec<u32>,
    /// A mesh made elsewhere for a frame not drawn yet.
    given: Option<GivenMesh>,
    /// The job (packed) of the mesh held, when it is whole: a frame of the same job (the camera turned,
    /// a view changed, a still figure drawn again) draws it without meshing again.
    held: Vec<f32>,
    /// The buffers hold the vertices of the mesh held: a frame drawing it again writes its indices only.
    uploaded: bool,
    /// Crossings the buffers hold after the mesh's vertices.
    crossings: u32,
    /// The frame's views read the mesher's teaching data (`Job::teaching`).
    teaching: bool,
}

impl<M: CpuMeshing> CpuMeshExtractor<M> {
    /// Runs anywhere: there is nothing to compile.
    pub fn compile(_device: &wgpu::Device) -> Option<Box<dyn Extractor>> {
        Some(Box::<Self>::default())
    }

    /// What the last mesh needs, even past the buffers' capacity.
    fn counters(&self) -> Counters {
        let (active_blocks, active_cells) = self.mesher.blocks_and_cells();
        Counters {
            active_blocks,
            vertices: (self.mesher.vertices().len() / 6) as u32,
            indices: self.mesher.indices().len() as u32,
            active_cells,
        }
    }
}

impl<M: CpuMeshing> Extractor for CpuMeshExtractor<M> {
    fn name(&self) -> &'static str {
        M::NAME
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            needs_compute: false,
            cell_lists: false,
            cpu_copy: true,
            lod: false,
            method: M::METHOD,
        }
    }

    fn fresh(&self) -> Box<dyn Extractor> {
        Box::<Self>::default()
    }

    /// Meshes the frame; the buffers need room for its vertices and indices only (it fills no block or
    /// cell lists, and asking for room in them would grow them for nothing).
    fn prepare(&mut self, job: &Job) -> Option<Counters> {
        // Part way through the march the frame meshes its cells on its own, and its mesh is not whole.
        let whole = job.construction.march.is_none();
        let packed = if whole { elsewhere::pack(M::METHOD, job) } else { Vec::new() };
        // A mesh made elsewhere lacks what the frame's teaching views read of this mesher's own.
        let complete = !job.teaching || self.mesher.complete();
        self.teaching = job.teaching;
        let kept = match self.given.take() {
            Some(given) if whole && given.job == packed && !job.teaching => {
                self.mesher.install(given);
                false
            }
            _ if whole && self.held == packed && complete => true,
            _ => {
                self.mesher.mesh_job(job);
                false
            }
        };
        self.uploaded &= kept;
        self.held = packed;
        let Counters { vertices, indices, .. } = self.counters();
        let vertices = vertices + (self.mesher.crossings().len() / 6) as u32;
        Some(Counters { active_blocks: 0, vertices, indices, active_cells: 0 })
    }

    fn write(&mut self, output: Output) -> MeshCount {
        let needed = self.counters();
        let (vertices, indices) = (self.mesher.vertices(), self.mesher.indices());
        let fits = output.buffers.holds(needed.vertices, needed.indices);
        // A whole marching-cubes or marching-tetrahedra mesh is closed, so from outside the box its back
        // faces never show.
        let front = match output.front_faces {
            Some(viewpoint) if fits && M::METHOD.closes_its_mesh() => {
                facing::front_faces(vertices, indices, viewpoint, &mut self.front);
                true
            }
            _ => false,
        };
        // The vertices of a mesh drawn again are in the buffers already; the crossings follow them
        // where there is room.
        let crossings = self.mesher.crossings();
        let count = (crossings.len() / 6) as u32;
        let room = count > 0 && output.buffers.holds(needed.vertices + count, 0);
        let joined;
        let sent = match (self.uploaded, room) {
            (true, _) => &[][..],
            (false, false) => vertices,
            (false, true) => {
                joined = [vertices, crossings].concat();
                &joined[..]
            }
        };
        let drawn = output.buffers.upload(output.queue, sent, if front { &self.front } else { indices });
        self.crossings = if room { count } else { 0 };
        let written = if front { needed.indices } else { drawn };
        self.uploaded = fits;
        self.written = written;
        let buffers = output.buffers;
        // The views count what to draw from the device's counters (no block or cell lists: this
        // extractor fills none), and `color-by=rank` reads a word per triangle where level of detail
        // keeps its levels.
        if buffers.counters.usage().contains(wgpu::BufferUsages::STORAGE) {
            let counts = Counters { indices: written, active_blocks: 0, active_cells: 0, ..needed };
            output.queue.write_buffer(&buffers.counters, 0, bytemuck::bytes_of(&counts));
            let marks = if self.teaching { self.mesher.triangle_marks() } else { Vec::new() };
            let triangles = (written as usize / 3).min(marks.len());
            if triangles > 0 && !front && buffers.lod_data.size() >= 4 * triangles as u64 {
                output.queue.write_buffer(&buffers.lod_data, 0, bytemuck::cast_slice(&marks[..triangles]));
            }
        }
        MeshCount::Known { needed, indices: written, drawn }
    }

    fn buffers_changed(&mut self) {
        self.uploaded = false;
        self.crossings = 0;
    }

    fn crossings(&self) -> Option<Crossings> {
        let first = (self.mesher.vertices().len() / 6) as u32;
        (self.crossings > 0).then_some(Crossings::Listed(first..first + self.crossings))
    }

    fn give_mesh(&mut self, mesh: GivenMesh) {
        self.given = Some(mesh);
    }

    fn forget_mesh(&mut self) {
        self.held.clear();
    }

    fn cpu_mesh(&self) -> Option<IndexedMesh> {
        let mut mesh = self.mesher.to_indexed();
        mesh.triangles.truncate(self.written as usize / 3);
        Some(mesh)
    }
}
