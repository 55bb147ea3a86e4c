//! The CPU meshers (`metaballs::extract::cpu` re-exports them and uploads their meshes): marching
//! cubes ([`CpuMesher`]), the dual methods (surface nets and dual contouring), and which triangles
//! face the viewer.

mod blocks;
pub mod dual;
pub mod facing;
pub mod hermite;
pub mod mesher;
mod normals;
mod planes;
pub mod qef;
mod vertices;

pub use dual::{DualContouringMesher, SurfaceNetsMesher};
pub use mesher::CpuMesher;
