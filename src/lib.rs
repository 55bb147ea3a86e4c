//! Marching cubes of merging spheres on the GPU, shaded with Blinn-Phong.
//!
//! Every frame, compute passes evaluate the field f(p) = Σ rᵢ² / |p − cᵢ|² on a grid, run marching cubes
//! over it and append triangles whose count feeds an indirect draw; a render pass shades them. The same
//! [`Renderer`] draws into a canvas (wasm) or an offscreen texture (native tests, PNG renderer).

pub mod field_pass;
pub mod gpu;
pub mod marching_cubes;
pub mod mesh;
#[cfg(not(target_arch = "wasm32"))]
pub mod offscreen;
pub mod params;
pub mod reference;
pub mod renderer;
pub mod scene;
pub mod shade;
pub mod tables;
pub mod uniforms;
#[cfg(target_arch = "wasm32")]
mod web;

pub use params::{Camera, Material, ParamError, Settings};
pub use renderer::{FrameStats, Renderer};
pub use scene::{Scene, Sphere};
