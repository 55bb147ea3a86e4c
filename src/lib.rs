//! Marching cubes of merging spheres on the GPU, shaded with Blinn-Phong.
//!
//! Every frame, compute passes skip the blocks of the grid the surface cannot cross, evaluate the field
//! f(p) = Σ rᵢ² / |p − cᵢ|² on the others, run marching cubes there with shared vertices, and append
//! triangles whose count feeds an indexed indirect draw; a render pass shades them. The same
//! [`Renderer`] draws into a canvas (wasm) or an offscreen texture (native tests, PNG renderer).

#[cfg(not(target_arch = "wasm32"))]
pub mod bench;
pub mod blocks;
pub mod case_classes;
pub mod context;
pub mod cpu_mesher;
pub mod export;
pub mod field_pass;
pub mod gpu;
pub mod inspect;
pub mod marching_cubes;
pub mod mesh;
pub mod mesh_buffers;
#[cfg(not(target_arch = "wasm32"))]
pub mod offscreen;
pub mod params;
pub mod reference;
pub mod renderer;
pub mod scene;
pub mod scene_buffers;
pub mod scene_file;
pub mod shade;
pub mod slice;
pub mod tables;
pub mod timing;
pub mod uniforms;
pub mod views;
#[cfg(target_arch = "wasm32")]
mod web;

pub use context::GpuContext;
pub use params::{Camera, Material, ParamError, Settings};
pub use renderer::{FrameStats, Renderer};
pub use scene::{Scene, Sphere};
