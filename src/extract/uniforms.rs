//! The compute passes' uniform and storage blocks as the shaders read them: `#[repr(C)]` mirrors of the
//! WGSL structs in `shaders/common.wgsl`, with their sizes checked at compile time.

use bytemuck::{Pod, Zeroable};

/// The grid, iso level and buffer capacities, for the compute passes (`Grid` in `shaders/common.wgsl`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct GridUniform {
    pub box_min: [f32; 3],
    pub cell_size: f32,
    pub iso: f32,
    pub cells_per_axis: u32,
    pub sphere_count: u32,
    pub max_blocks: u32,
    pub max_vertices: u32,
    pub max_indices: u32,
    pub max_cells: u32,
    /// Bit 0: vertices at edge midpoints; bit 1: blend by max; bit 2: ambiguous faces by the asymptotic
    /// decider; bit 3: MC33; bits 4 and 5: the kernel's index (`FLAG_*` and `KERNEL_SHIFT` in
    /// `shaders/common.wgsl`); bit 6: marching tetrahedra's five-way split; bit 7: dual contouring (else surface nets) on the
    /// GPU's dual pass.
    pub flags: u32,
    /// The step-through of the march: only cells up to this one (x fastest, then y, then z) give
    /// triangles; `u32::MAX` on each axis when the march is off.
    pub march: [u32; 3],
    /// Blinn's kernel's B.
    pub blobbiness: f32,
}
const _: () = assert!(std::mem::size_of::<GridUniform>() == 64);

/// The counts the passes append with (`Counters` in `shaders/common.wgsl`); a count above its
/// capacity means that buffer overflowed.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq, Eq)]
pub struct Counters {
    pub active_blocks: u32,
    pub vertices: u32,
    pub indices: u32,
    pub active_cells: u32,
}
const _: () = assert!(std::mem::size_of::<Counters>() == 16);

/// Levels whose triangles the counters block counts (`LEVEL_SLOTS` in `shaders/extract/lod.wgsl`).
pub const LEVEL_SLOTS: usize = 12;
/// Where the per-level triangle counts start in the counters buffer: a storage binding's offset must
/// be a multiple of 256.
pub const LEVEL_COUNTS_OFFSET: u64 = 256;

/// Where the mesh's measures start in the counters buffer.
pub const MEASURES_OFFSET: u64 = 512;
/// Bins of the triangles' shape histogram.
pub const QUALITY_BINS: usize = 10;
/// A squared error's units in the measures' sum: cells² / 2²⁰ (`SQUARES_SCALE` in
/// `shaders/draw/measure.wgsl`).
pub const SQUARES_SCALE: f64 = 1_048_576.0;

/// What the measures pass (`shaders/draw/measure.wgsl`) sums over the mesh.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable, PartialEq, Eq)]
pub struct Measures {
    /// Σ error² in `SQUARES_SCALE` units, low and high words.
    pub squares: [u32; 2],
    /// The largest error's `f32` bits, in cells.
    pub largest: u32,
    /// Vertices measured.
    pub measured: u32,
    /// Triangles per tenth of the shape measure, from slivers (0) to equilateral (9).
    pub quality: [u32; QUALITY_BINS],
    pub _pad: [u32; 2],
}

/// The whole counters buffer: the counters, then (with level of detail) what the selection passes
/// report, triangles and blocks per level, then the mesh's measures (`LodCounters` in
/// `shaders/extract/lod.wgsl`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable, PartialEq, Eq)]
pub struct CounterBlock {
    pub counters: Counters,
    /// Nonzero when level selection ran out of room: the frame kept the mesh it had.
    pub lod_overflowed: u32,
    /// Levels at or below it were held back from splitting, after a frame ran out of room.
    pub lod_floor: u32,
    /// Dual contouring's crossings on the GPU, written after the mesh's vertices (for
    /// `display=normals`).
    pub crossings: u32,
    pub _pad: [u32; 57],
    pub level_triangles: [u32; LEVEL_SLOTS],
    pub level_blocks: [u32; LEVEL_SLOTS],
    pub _pad_measures: [u32; 40],
    pub measures: Measures,
}

/// What a level-of-detail frame counted per level, and how its selection fared.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LevelCounts {
    /// Triangles per level, finest first.
    pub triangles: [u32; LEVEL_SLOTS],
    /// Blocks selected per level, where the device selected them (zero where the CPU did).
    pub blocks: [u32; LEVEL_SLOTS],
    /// Levels at or below it were held back from splitting.
    pub floor: u32,
    /// The selection ran out of room and the frame kept the mesh it had.
    pub overflowed: bool,
}

impl CounterBlock {
    /// Its level-of-detail counts.
    pub fn levels(&self) -> LevelCounts {
        LevelCounts {
            triangles: self.level_triangles,
            blocks: self.level_blocks,
            floor: self.lod_floor,
            overflowed: self.lod_overflowed != 0,
        }
    }
}
const _: () = assert!(std::mem::offset_of!(CounterBlock, level_triangles) == LEVEL_COUNTS_OFFSET as usize);
const _: () = assert!(std::mem::offset_of!(CounterBlock, measures) == MEASURES_OFFSET as usize);

impl Default for CounterBlock {
    fn default() -> Self {
        Self::zeroed()
    }
}
