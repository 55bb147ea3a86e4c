//! The CPU meshers (`metaballs::extract::cpu` re-exports them and uploads their meshes): marching
//! cubes ([`CpuMesher`]), surface nets, and which triangles face the viewer.

mod blocks;
pub mod facing;
pub mod mesher;
mod normals;
mod planes;
pub mod surface_nets;
mod vertices;

pub use mesher::CpuMesher;
pub use surface_nets::SurfaceNetsMesher;
