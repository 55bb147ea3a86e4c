//! The shading uniforms as `shaders/draw/shade.wgsl` reads them: `#[repr(C)]` mirrors of its WGSL
//! structs, with their sizes checked at compile time.

use crate::device::wgsl;
use bytemuck::{Pod, Zeroable};

/// `shaders/draw/shade.wgsl`, whose structs these mirror: the shading pass, and what the teaching views
/// compose after `shaders/common.wgsl`.
pub(crate) const SHADE_WGSL: &str = wgsl!("draw/shade.wgsl");

/// One light (`Light` in `shaders/draw/shade.wgsl`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct LightUniform {
    /// Where a point or spot light sits.
    pub position: [f32; 3],
    /// `LIGHT_*` in `shaders/draw/shade.wgsl`: 0 off, 1 point, 2 directional, 3 spot.
    pub kind: u32,
    /// Where a directional or spot light shines, unit length.
    pub direction: [f32; 3],
    /// Cosine of the spot cone's half-angle, where the light ends.
    pub cos_outer: f32,
    /// Linear RGB.
    pub color: [f32; 3],
    /// Cosine of the angle inside which the spot shines fully.
    pub cos_inner: f32,
}
const _: () = assert!(std::mem::size_of::<LightUniform>() == 48);

/// Camera, lights, material and view options for the shading pass (`Shading` in
/// `shaders/draw/shade.wgsl`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq)]
pub struct ShadingUniform {
    pub view_proj: [[f32; 4]; 4],
    /// World to camera (the axis gizmo uses its rotation).
    pub view: [[f32; 4]; 4],
    pub camera_position: [f32; 3],
    pub ambient: f32,
    /// The direction the camera looks, unit length.
    pub camera_forward: [f32; 3],
    /// 1 for an orthographic camera.
    pub orthographic: u32,
    pub base_color: [f32; 3],
    pub diffuse: f32,
    pub specular: f32,
    pub shininess: f32,
    pub encode_srgb: u32,
    pub box_half_extent: f32,
    /// `Display::index`.
    pub display: u32,
    /// `ColorBy::index`.
    pub color_by: u32,
    /// `GridView::index`.
    pub grid_view: u32,
    pub cells_per_axis: u32,
    /// Output size in pixels.
    pub viewport: [f32; 2],
    pub cell_size: f32,
    pub iso: f32,
    /// 0, 1, 2 for x, y, z; 3 without a slice.
    pub slice_axis: u32,
    /// The grid plane the slice lies on.
    pub slice_plane: u32,
    /// 1 while a cell is selected.
    pub selected: u32,
    /// Opacity of the lattice's lines.
    pub lattice_alpha: f32,
    pub selected_cell: [u32; 3],
    /// Where the LOD blocks start in the mesh's `lod_data`, in words.
    pub lod_blocks_offset: u32,
    /// The lattice's slab: the axis across it, its first and last grid planes, then padding.
    pub lattice_slab: [u32; 4],
    pub lights: [LightUniform; 3],
    /// The background's gradient, linear RGB: top, then bottom.
    pub background_top: [f32; 3],
    /// `Compare::index`: 0 none, 1 split, 2 overlay.
    pub compare: u32,
    pub background_bottom: [f32; 3],
    /// With `compare=split`, where the exact half starts, as a fraction of the width.
    pub divider: f32,
    /// Clip space to world, for the exact view's rays.
    pub inverse_view_proj: [[f32; 4]; 4],
    /// `Saddle::index`: how the slice's contour joins a saddle square.
    pub saddle: u32,
    pub _padding: [u32; 3],
}
const _: () = assert!(std::mem::size_of::<ShadingUniform>() == 528);
