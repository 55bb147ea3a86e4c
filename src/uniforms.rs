//! Uniform blocks as the shaders read them: `#[repr(C)]` mirrors of the WGSL structs, with their sizes
//! checked at compile time.

use bytemuck::{Pod, Zeroable};

/// The grid and iso level, for the field and marching-cubes passes (`Grid` in `shaders/common.wgsl`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct GridUniform {
    pub box_min: [f32; 3],
    pub cell_size: f32,
    pub iso: f32,
    pub cells_per_axis: u32,
    pub sphere_count: u32,
    /// Capacity of the vertex buffer; the pass writes no vertex past it.
    pub max_vertices: u32,
}
const _: () = assert!(std::mem::size_of::<GridUniform>() == 32);

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

/// The counter block the marching-cubes pass appends with (`Counters` in `shaders/marching_cubes.wgsl`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct Counters {
    pub vertices_requested: u32,
}
const _: () = assert!(std::mem::size_of::<Counters>() == 4);
