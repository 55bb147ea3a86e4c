//! Level of detail: fine cells near the camera, coarse far away, and no cracks between them.
//!
//! - [`select`]: the camera-driven, 2:1-balanced octree of blocks, one function for every path.
//! - [`transition`]: Transvoxel transition cells over the published tables.
//! - [`mesher`]: the LOD mesh on the CPU.

pub mod mesher;
pub mod select;
pub mod transition;

#[cfg(test)]
mod tests;
