//! The CPU meshers (`metaballs::extract::cpu` re-exports them and uploads their meshes): marching
//! cubes ([`CpuMesher`]), surface nets, and which triangles face the viewer.

pub mod facing;
pub mod mesher;
pub mod surface_nets;

pub use mesher::CpuMesher;
pub use surface_nets::SurfaceNetsMesher;
