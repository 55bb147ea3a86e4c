//! The GPU-free parts of extraction (`metaballs::extract` re-exports them):
//!
//! - [`tables`]: the 256-case marching-cubes tables, once, for the GPU and every CPU path.
//! - [`decider`]: the triangles of cells whose ambiguous faces the asymptotic decider resolves.
//! - [`interior`]: the joins inside a cell that MC33 makes (tunnels between loops).
//! - [`reference`]: the CPU oracle every extractor must equal exactly.
//! - [`kernel`]: the spheres' terms (kernel and blend), once, for every CPU path.
//! - [`field`]: the field on the CPU as the passes evaluate it (bounds, rows of samples), in vectors
//!   of four lanes where it can (`lanes`).
//! - [`mesh`]: triangle meshes and the properties the tests hold them to.
//! - [`tetra`]: marching tetrahedra's splits and cases, and its oracle.
//! - [`cpu`]: the CPU meshers (marching cubes, the dual methods and marching tetrahedra).

pub mod cpu;
pub mod decider;
pub mod field;
pub mod interior;
pub mod kernel;
mod lanes;
pub mod mesh;
pub mod reference;
pub mod tables;
pub mod tetra;
