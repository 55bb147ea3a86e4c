//! Uniform and storage blocks as the shaders read them: `#[repr(C)]` mirrors of the WGSL structs, with
//! their sizes checked at compile time.

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
    pub _pad: u32,
}
const _: () = assert!(std::mem::size_of::<GridUniform>() == 48);

/// Camera, light and material for the shading pass (`Shading` in `shaders/shade.wgsl`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct ShadingUniform {
    pub view_proj: [[f32; 4]; 4],
    pub camera_position: [f32; 3],
    pub ambient: f32,
    pub light_position: [f32; 3],
    pub diffuse: f32,
    pub base_color: [f32; 3],
    pub specular: f32,
    pub shininess: f32,
    pub encode_srgb: u32,
    pub box_half_extent: f32,
    pub _pad: u32,
}
const _: () = assert!(std::mem::size_of::<ShadingUniform>() == 128);

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
