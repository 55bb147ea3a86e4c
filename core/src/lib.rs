//! The GPU-free core of metaballs' extraction: the marching-cubes tables, the CPU oracle, the field's
//! bounds and rows of samples, meshes, and the CPU meshers. The `metaballs` crate re-exports each
//! module at the same path (`metaballs::extract::tables`, …), so this crate is where they are built,
//! not how they are named: the browser's build makes this crate fast (`opt-level = 3`, for the CPU
//! mesher on the page's thread) and everything else small (`Cargo.toml`, `[profile.wasm]`).

pub mod critical;
pub mod extract;

/// The spheres and settings (the `metaballs-scene` crate, `scene/`), at the path the modules here and
/// in `metaballs` name them by.
pub use metaballs_scene as scene;
