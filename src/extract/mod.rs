//! Isosurface extraction: every way of making a frame's mesh sits behind one [`Extractor`] interface
//! and fills the same [`MeshBuffers`](buffers::MeshBuffers) (shared vertices, indices, counters), so
//! the renderer orders a frame without knowing which one ran.
//!
//! - [`tables`]: the 256-case marching-cubes tables, once, for the GPU and every CPU path.
//! - [`reference`]: the CPU oracle every extractor must equal exactly.
//! - [`decider`]: the triangles of cells whose ambiguous faces the asymptotic decider joins.
//! - [`field`]: the field on the CPU as the passes evaluate it (bounds, rows of samples).
//! - [`facing`]: which triangles of a closed mesh face the eye, for the CPU paths to draw those alone.
//! - [`gpu`]: the compute passes (blocks → field → marching cubes or tetrahedra), all on the device, no
//!   readback.
//! - [`cpu`]: the CPU mesher, uploaded into the same buffers (faster on software adapters, the only
//!   one on WebGL2).
//!   It also holds the dual methods, surface nets and dual contouring, and marching tetrahedra, to
//!   compare with.
//! - [`lod`]: level of detail: fine blocks near the camera, coarse far away, closed by transition
//!   cells.
//!
//! Imports `scene` and `device`; knows nothing of drawing.

pub mod buffers;
pub mod cpu;
pub mod extractor;
pub mod gpu;
pub mod lod;

// The GPU-free modules live in the `metaballs-core` crate (`core/`), built for speed in the browser's
// size-optimised build, and keep their paths here.
pub use metaballs_core::extract::cpu::facing;
pub use metaballs_core::extract::{decider, field, interior, kernel, mesh, reference, tables, tetra};
pub mod uniforms;

pub use extractor::{
    Capabilities, Crossings, Extractor, GivenMesh, Job, LodJob, LodSummary, MeshCount, Output, Viewpoint,
};

/// Builds an extractor on a device, compiling what every renderer on that device shares (its
/// pipelines); `None` where it cannot run there.
pub type Compile = fn(&wgpu::Device) -> Option<Box<dyn Extractor>>;

/// Every extractor, in order of preference. Adding one is a module and a line here.
pub const EXTRACTORS: &[Compile] = &[
    gpu::GpuExtractor::compile,
    cpu::CpuExtractor::compile,
    lod::gpu::LodGpuExtractor::compile,
    lod::cpu::LodCpuExtractor::compile,
    #[cfg(any(not(target_arch = "wasm32"), not(feature = "webgpu")))]
    cpu::SurfaceNetsExtractor::compile,
    #[cfg(any(not(target_arch = "wasm32"), not(feature = "webgpu")))]
    cpu::DualContouringExtractor::compile,
    gpu::GpuExtractor::compile_tetrahedra,
    #[cfg(any(not(target_arch = "wasm32"), not(feature = "webgpu")))]
    cpu::TetrahedraExtractor::compile,
    gpu::GpuExtractor::compile_surface_nets,
    gpu::GpuExtractor::compile_dual_contouring,
];

/// The extractors `device` can run, in the order of [`EXTRACTORS`].
pub fn compile_all(device: &wgpu::Device) -> Vec<Box<dyn Extractor>> {
    EXTRACTORS.iter().filter_map(|compile| compile(device)).collect()
}
