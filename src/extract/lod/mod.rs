//! Level of detail: fine cells near the camera, coarse far away, and no cracks between them.
//!
//! - [`select`]: the rule that gives each block its level from its distance alone, and the CPU's
//!   walk by it.
//! - [`walk`]: the same walk in compute passes, level by level, with nothing sent back.
//! - [`transition`]: Transvoxel transition cells over the published tables.
//! - [`mesher`]: the LOD mesh on the CPU; [`cpu`] puts it behind the extraction interface.
//! - [`gpu`]: the same mesh in compute shaders.

pub mod cpu;
pub mod gpu;
pub mod mesher;
pub mod select;
pub mod transition;
pub mod walk;

#[cfg(test)]
mod tests;

pub use super::extractor::LodSummary;

use super::extractor::Job;
use super::field::Spheres;
use super::kernel::Terms;
use crate::scene::Sphere;
use select::{Eye, Selection};

/// The eye `job` selects by: its own, kept in `frozen`, or while the selection is frozen (`lod_freeze`)
/// the one kept there from before, culling nothing (a frozen selection is looked at from elsewhere).
/// `None` without level of detail.
pub fn eye_of(frozen: &mut Option<Eye>, job: &Job) -> Option<Eye> {
    let lod = job.lod?;
    if !lod.freeze || frozen.is_none() {
        *frozen = Some(lod.eye);
    }
    // A frozen selection is looked at from elsewhere: nothing is left out as outside its view.
    let cull = lod.eye.cull && !lod.freeze;
    Some(Eye { cull, ..(*frozen)? })
}

/// [`select::select`] keeping only the blocks the surface f = `iso` of `spheres` may cross, by the
/// field's exact bounds, as the meshers skip blocks.
pub fn select_for_surface(
    spheres: &[Sphere],
    iso: f32,
    terms: Terms,
    resolution: u32,
    eye: &Eye,
) -> Selection {
    let mut bounds = Spheres::default();
    bounds.set(spheres);
    select::select(resolution, eye, &|low, high, walls| bounds.straddles(low, high, walls, iso, terms))
}
