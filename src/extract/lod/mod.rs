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

use super::extractor::Job;
use select::{Eye, Selection};

/// What a LOD frame held, level by level (finest first), for the HUD and the statistics.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct LodSummary {
    /// The finest level's cells per axis: the resolution of a uniform grid as fine.
    pub resolution: u32,
    /// Selected blocks per level.
    pub blocks: Vec<u32>,
    /// Triangles per level, where the extractor counts them on the CPU.
    pub triangles: Option<Vec<u32>>,
    /// Cells meshed: regular cells of the blocks the bounds kept and their transition cells.
    pub cells_processed: u64,
}

/// The selection for `job`: a new one from `choose`, or `None` to keep `current` (frozen, and
/// made for the same resolution).
pub fn next_selection(
    current: &Selection,
    job: &Job,
    choose: impl Fn(u32, &Eye) -> Selection,
) -> Option<Selection> {
    let lod = job.lod?;
    let resolution = job.grid.cells_per_axis;
    if lod.freeze && current.resolution == resolution && !current.blocks.is_empty() {
        return None;
    }
    Some(choose(resolution, &lod.eye))
}
