//! The CPU meshers (`metaballs::extract::cpu` re-exports them and uploads their meshes): marching
//! cubes ([`CpuMesher`]), the dual methods (surface nets and dual contouring), and which triangles
//! face the viewer.

mod blocks;
pub mod dual;
pub mod facing;
pub mod hermite;
mod kept;
pub mod mesher;
mod normals;
mod planes;
pub mod qef;
pub mod tetra;
mod vertices;

pub use dual::{DualContouringMesher, SurfaceNetsMesher};
pub use mesher::CpuMesher;
pub use tetra::TetraMesher;
