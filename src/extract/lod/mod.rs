//! Level of detail: fine cells near the camera, coarse far away, and no cracks between them.
//!
//! - [`select`]: the camera-driven, 2:1-balanced octree of blocks, one function for every path.
//! - [`transition`]: Transvoxel transition cells over the published tables.
//! - [`mesher`]: the LOD mesh on the CPU; [`cpu`] puts it behind the extraction interface.
//! - [`gpu`]: the same mesh in compute shaders.

pub mod cpu;
pub mod gpu;
pub mod mesher;
pub mod select;
pub mod transition;

#[cfg(test)]
mod tests;

pub use super::extractor::LodSummary;

use super::extractor::Job;
use super::field::Spheres;
use crate::scene::Sphere;
use crate::scene::params::view::Blend;
use select::{Eye, Selection};

/// The selection for `job`, or `None` to keep `current` (frozen, and made for the same resolution).
/// Blocks are refined only where the field's exact bounds let the surface cross, as the meshers
/// skip blocks.
pub fn next_selection(current: &Selection, job: &Job) -> Option<Selection> {
    let lod = job.lod?;
    let resolution = job.grid.cells_per_axis;
    if lod.freeze && current.resolution == resolution && !current.blocks.is_empty() {
        return None;
    }
    Some(select_for_surface(job.spheres, job.iso, job.construction.blend, resolution, &lod.eye))
}

/// [`select::select`] refining only where the surface f = `iso` of `spheres` may cross.
pub fn select_for_surface(
    spheres: &[Sphere],
    iso: f32,
    blend: Blend,
    resolution: u32,
    eye: &Eye,
) -> Selection {
    let mut bounds = Spheres::default();
    bounds.set(spheres);
    let by_max = blend == Blend::Max;
    select::select(resolution, eye, &|low, high, walls| bounds.straddles(low, high, walls, iso, by_max))
}
