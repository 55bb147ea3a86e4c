//! Marching cubes of merging spheres on the GPU, shaded with Blinn-Phong.
//!
//! The folders are the stages of a frame, and each imports only those listed before it
//! (`docs/architecture.md`):
//!
//! - [`scene`]: the spheres, their motion, the parameter table, scene files. No GPU.
//! - [`device`]: wgpu helpers every GPU stage uses (devices, shader modules, readback, timestamps).
//! - [`extract`]: isosurface extraction behind one [`extract::Extractor`] interface: the tables, the
//!   CPU oracle, the CPU mesher, and the GPU's compute passes (blocks → field → marching cubes).
//! - [`teach`]: what the teaching views explain, computed on the CPU (case classes, the picked cell).
//! - [`view`]: the camera on an output, on the CPU: pixels to rays and back, picking a cell or a
//!   sphere, moving and adding spheres by pointer.
//! - [`draw`]: shading the mesh into a view, the teaching views, the field slice.
//! - [`renderer`]: one [`Renderer`] orders a frame (update the scene → extract → draw) into any
//!   texture view; renderers on one device share a [`GpuContext`].
//! - `web` (wasm only): the handle the page drives. Beside `main.rs`, the native tools: [`export`]
//!   (mesh files, also used by the page), [`offscreen`], [`record`] (animated GIF and APNG clips),
//!   [`bench`] and [`manifest`] (the element's description for editors, written from the parameter
//!   table).

/// The spheres and settings: the `metaballs-scene` crate (`scene/`).
pub use metaballs_scene as scene;

/// The field's critical points and the topology along the iso level (`metaballs-core`).
pub use metaballs_core::critical;

pub mod device;

pub mod extract;

pub mod teach;

pub mod view;

pub mod draw;

pub mod renderer;

#[cfg(not(target_arch = "wasm32"))]
pub mod bench;
pub mod export;
#[cfg(not(target_arch = "wasm32"))]
pub mod manifest;
#[cfg(not(target_arch = "wasm32"))]
pub mod offscreen;
#[cfg(not(target_arch = "wasm32"))]
pub mod record;
#[cfg(target_arch = "wasm32")]
mod web;

pub use renderer::context::GpuContext;
pub use renderer::{FrameStats, Renderer};
pub use scene::params::{Camera, Material, ParamError, Settings};
pub use scene::{Scene, Sphere};
