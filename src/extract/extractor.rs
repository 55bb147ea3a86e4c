//! The interface every extractor implements: what it can do, the frame's problem, where the mesh
//! goes, and how it is counted.

use super::buffers::MeshBuffers;
use super::gpu::scene_buffers::SceneBuffers;
use super::lod::select::Eye;
use super::mesh::IndexedMesh;
pub use super::mesh::Viewpoint;
use super::reference::{Construction, Grid};
use super::uniforms::Counters;
use crate::device::timing::Timing;
use crate::scene::Sphere;
use crate::scene::params::view::Method;

/// What an extractor can do. The renderer chooses by these (and by name only for the `mesher`
/// setting), never by type.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Capabilities {
    /// Runs in compute shaders, so on the device (not on WebGL2, and emulated on a software adapter).
    pub needs_compute: bool,
    /// Fills the active-block and active-cell lists and the per-block field values and cases that the
    /// teaching views read.
    pub cell_lists: bool,
    /// Keeps its latest mesh on the CPU, so exports and tests need no readback.
    pub cpu_copy: bool,
    /// Meshes a level-of-detail selection (`lod=on`) rather than the uniform grid.
    pub lod: bool,
    /// How it joins the field's crossings into a mesh (`extractor`).
    pub method: Method,
}

/// One frame's extraction problem: the surface f = `iso` of `spheres` on `grid`.
#[derive(Clone, Copy, Debug)]
pub struct Job<'a> {
    pub spheres: &'a [Sphere],
    pub iso: f32,
    pub grid: Grid,
    pub construction: Construction,
    /// With `lod=on`: the camera the levels follow.
    pub lod: Option<LodJob>,
    /// The frame's views read what only a mesher of this thread keeps of its mesh (dual contouring's
    /// ranks and crossings), which a mesh made elsewhere lacks.
    pub teaching: bool,
}

/// A mesh made elsewhere (the page's mesher worker) from a packed job (`cpu::elsewhere::pack`): vertices (position, then outward normal) and indices as the CPU
/// meshers make them, with what the mesher counted.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct GivenMesh {
    /// The packed job it was made for.
    pub job: Vec<f32>,
    pub vertices: Vec<f32>,
    pub indices: Vec<u32>,
    /// Blocks the bounds kept and cells the surface crosses.
    pub counts: [u32; 2],
}

impl GivenMesh {
    /// The grid the mesh was made on.
    pub fn grid(&self) -> Grid {
        Grid { cells_per_axis: self.job.get(2).map_or(1, |&n| n as u32) }
    }
}

/// What level-of-detail extraction needs beyond the uniform grid's problem.
#[derive(Clone, Copy, Debug)]
pub struct LodJob {
    pub eye: Eye,
    /// Keep the selection of the last frame whatever the camera does (`lod_freeze`).
    pub freeze: bool,
}

/// What a LOD frame held, level by level (finest first), for the HUD and the statistics.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LodSummary {
    /// The finest level's cells per axis: the resolution of a uniform grid as fine.
    pub resolution: u32,
    /// Selected blocks per level.
    pub blocks: Vec<u32>,
    /// Triangles per level, where the extractor counts them on the CPU.
    pub triangles: Option<Vec<u32>>,
    /// Cells meshed: regular cells of the blocks the bounds kept and their transition cells, where
    /// the extractor counts them on the CPU.
    pub cells_processed: Option<u64>,
}

/// Where a frame's mesh goes: the shared buffers, the scene as the device reads it and the frame's
/// command encoder.
pub struct Output<'a> {
    pub device: &'a wgpu::Device,
    pub queue: &'a wgpu::Queue,
    /// The grid and spheres as the compute passes read them.
    pub scene: &'a SceneBuffers,
    pub encoder: &'a mut wgpu::CommandEncoder,
    pub buffers: &'a MeshBuffers,
    /// Timestamp queries for the stages, when a timed frame asks for them.
    pub timing: Option<&'a Timing>,
    /// Where the mesh is seen from, when nothing but the shading pass reads this frame's index buffer
    /// and the eye is outside the box: an extractor whose mesh is closed may then leave out the
    /// triangles facing away, which the shading pass would cull anyway.
    pub front_faces: Option<Viewpoint>,
}

/// How a frame's mesh is counted.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MeshCount {
    /// On the device: the buffers' counters and indirect draw arguments hold it, and the renderer
    /// reads the counters a frame or two later (nothing waits).
    OnDevice,
    /// Known at once.
    Known {
        /// What the surface needed (vertices, indices, active blocks and cells), even past capacity.
        needed: Counters,
        /// Indices of the mesh written, at most the index buffer's capacity.
        indices: u32,
        /// Indices to draw: fewer than `indices` where the triangles facing away were left out.
        drawn: u32,
    },
}

/// One way of making the mesh. Each renderer holds its own instance of every extractor the device
/// can run ([`Extractor::fresh`] from the device's compiled one). Natively, as wgpu's objects, they may
/// move between threads and be shared (renderers on one device in several threads).
pub trait Extractor: wgpu::WasmNotSendSync {
    /// Its word in the `mesher` setting and the HUD (`gpu`, `cpu`).
    fn name(&self) -> &'static str;

    /// What it can do.
    fn capabilities(&self) -> Capabilities;

    /// A new instance for one renderer, sharing what was compiled for the device.
    fn fresh(&self) -> Box<dyn Extractor>;

    /// The buffers were made anew (grown, or for a new resolution), or another extractor made the last
    /// frame's mesh in them: whatever was bound to the old ones is bound again, and whatever was
    /// written into them is written again, on the next [`Extractor::write`].
    fn buffers_changed(&mut self) {}

    /// Pipeline sets compiled for the device so far (shared by every renderer's instance): an extractor
    /// compiles its pipelines on the first frame that needs them.
    fn pipeline_sets(&self) -> usize {
        0
    }

    /// Does whatever work happens on the CPU and returns the room it needs in the buffers, so they
    /// can grow before [`Extractor::write`]; `None` when only the device will know.
    fn prepare(&mut self, job: &Job) -> Option<Counters>;

    /// Puts this frame's mesh into the buffers: records compute passes into the encoder, or uploads
    /// what `prepare` made. Never writes past the buffers' capacity.
    fn write(&mut self, output: Output) -> MeshCount;

    /// A mesh made elsewhere for the next frame's job (a CPU mesher takes it in place of meshing when
    /// the job is still the frame's; others make their own).
    fn give_mesh(&mut self, _mesh: GivenMesh) {}

    /// The next frame meshes anew even when its job is the last one's, which an extractor that keeps
    /// its mesh would draw again (benchmarks time the meshing itself).
    fn forget_mesh(&mut self) {}

    /// Where the crossings of the grid's edges (point, normal) lie after the mesh's vertices in the
    /// vertex buffer, for `display=normals` with dual contouring; `None` without them.
    fn crossings(&self) -> Option<Crossings> {
        None
    }

    /// The latest mesh as written (clamped as the buffers held it), where it is kept on the CPU.
    fn cpu_mesh(&self) -> Option<IndexedMesh> {
        None
    }

    /// The latest level-of-detail selection and what each level holds, for a LOD extractor.
    fn lod_summary(&self) -> Option<LodSummary> {
        None
    }
}

/// Where an extractor wrote dual contouring's crossings, after the mesh's vertices.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Crossings {
    /// These vertex records (a mesh made on the CPU).
    Listed(std::ops::Range<u32>),
    /// As many as the device counted (`crossings` in the counters), from the mesh's last vertex on.
    Counted,
}
