//! What the device holds: the largest grid, buffer and output sizes, the checks that say so, and the
//! capacity the mesh buffers start from (grown with the surface, or a fixed triangle budget).

use super::Renderer;
use super::stage::Sizing;
use crate::device::compute_within;
use crate::extract::buffers::{BLOCK_CELLS, Capacity};
use crate::extract::reference::Grid;
use crate::scene::decimal::Fixed;
use crate::scene::params::{self, MAX_UNIFORM_RESOLUTION, MIN_RESOLUTION, ParamError};

/// The largest buffer the mesh passes bind: a storage binding, or without compute shaders (where the
/// CPU mesher fills plain vertex and index buffers) any buffer.
pub(super) fn storage_limit(limits: &wgpu::Limits) -> u64 {
    if compute_within(limits) {
        limits.max_storage_buffer_binding_size.min(limits.max_buffer_size)
    } else {
        limits.max_buffer_size
    }
}

/// The largest buffers a device of `limits` binds for `grid`.
pub(super) fn largest_capacity(limits: &wgpu::Limits, grid: Grid) -> Capacity {
    Capacity::largest(grid, storage_limit(limits))
}

/// Starting capacity for `grid` (uniform, or with `lod` the finest level's); without compute shaders
/// only vertices and indices are stored on the device. Level of detail keeps its blocks and cells in
/// lists that start small and grow.
pub(super) fn automatic_capacity(limits: &wgpu::Limits, grid: Grid, lod: bool, compute: bool) -> Capacity {
    let sized_by = Grid { cells_per_axis: grid.cells_per_axis.min(MAX_UNIFORM_RESOLUTION) };
    let mut capacity = Capacity::for_grid(sized_by).min(Capacity::largest(sized_by, storage_limit(limits)));
    if lod {
        capacity.blocks = capacity.blocks.min(LOD_STARTING_BLOCKS);
        capacity.cells = capacity.cells.min(16 * LOD_STARTING_BLOCKS);
    }
    if compute { capacity } else { Capacity { blocks: 0, cells: 0, ..capacity } }
}

/// Active blocks the level-of-detail lists start with room for.
const LOD_STARTING_BLOCKS: u32 = 4096;

/// The largest resolution a device of `limits` can run: its block table must fit one storage binding
/// and its block pass one dispatch.
pub fn max_resolution(limits: &wgpu::Limits) -> u32 {
    (MIN_RESOLUTION..=MAX_UNIFORM_RESOLUTION)
        .rev()
        .find(|&n| resolution_fits(limits, n).is_ok())
        .unwrap_or(MIN_RESOLUTION)
}

fn resolution_fits(limits: &wgpu::Limits, cells_per_axis: u32) -> Result<(), String> {
    if !compute_within(limits) {
        return Ok(());
    }
    let blocks = (cells_per_axis.div_ceil(BLOCK_CELLS) as u64).pow(3);
    let needed = blocks * 4;
    if needed > storage_limit(limits) {
        return Err(format!(
            "its block table needs {} MiB but the device's max_storage_buffer_binding_size is {} MiB",
            Fixed(needed as f64 / 1048576.0, 1),
            Fixed(storage_limit(limits) as f64 / 1048576.0, 1)
        ));
    }
    let groups = blocks.div_ceil(64);
    let max_groups = limits.max_compute_workgroups_per_dimension as u64;
    if groups > max_groups {
        return Err(format!(
            "it needs {groups} workgroups in one dispatch but the device's max_compute_workgroups_per_dimension \
             is {max_groups}"
        ));
    }
    Ok(())
}

pub(super) fn check_resolution_fits(limits: &wgpu::Limits, cells_per_axis: u32) -> Result<(), ParamError> {
    params::check_resolution(cells_per_axis)?;
    resolution_fits(limits, cells_per_axis).map_err(|detail| ParamError::DeviceLimit {
        name: "resolution",
        value: cells_per_axis.to_string(),
        detail: format!("{detail}; the largest resolution it holds is {}", max_resolution(limits)),
    })
}

pub(super) fn check_size(limits: &wgpu::Limits, width: u32, height: u32) -> Result<(), ParamError> {
    let max = limits.max_texture_dimension_2d;
    params::check_u32("output width (pixels)", width, 1, max)?;
    params::check_u32("output height (pixels)", height, 1, max)?;
    Ok(())
}

impl Renderer {
    /// Fixes the triangle budget (`None` returns to buffers that grow with the surface). Past a fixed
    /// budget, triangles are dropped and `stats` says so.
    pub fn set_max_triangles(&mut self, max_triangles: Option<u32>) -> Result<(), ParamError> {
        self.stage.sizing = match max_triangles {
            Some(n) => {
                let fits = Capacity::largest(self.grid(), storage_limit(self.context.limits())).indices / 3;
                Sizing::FixedTriangles(params::check_u32("triangle budget", n, 1, fits)?)
            }
            None => Sizing::Automatic,
        };
        self.reallocate(self.starting_capacity());
        Ok(())
    }

    /// Fixes the blocks the buffers hold (`None` returns to buffers that grow with the surface): a
    /// level-of-detail frame that selects more keeps the mesh it had, and the next frames use larger
    /// cells until there is room. For tests and tools that provoke it.
    pub fn set_max_blocks(&mut self, max_blocks: Option<u32>) -> Result<(), ParamError> {
        self.stage.sizing = match max_blocks {
            Some(n) => Sizing::FixedBlocks(params::check_u32("block budget", n, 1, u32::MAX)?),
            None => Sizing::Automatic,
        };
        self.reallocate(self.starting_capacity());
        Ok(())
    }

    pub(super) fn starting_capacity(&self) -> Capacity {
        let lod = self.settings.view.lod;
        let automatic =
            automatic_capacity(self.context.limits(), self.grid(), lod, self.context.has_compute());
        match self.stage.sizing {
            Sizing::Automatic => automatic,
            Sizing::FixedBlocks(blocks) => Capacity { blocks, ..automatic },
            // Everything but the index buffer holds the whole grid, so only triangles overflow.
            Sizing::FixedTriangles(n) => {
                let largest = Capacity::largest(self.grid(), storage_limit(self.context.limits()));
                Capacity { vertices: largest.vertices.min(3 * largest.cells), indices: 3 * n, ..largest }
            }
        }
    }
}
