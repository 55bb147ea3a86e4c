//! The scene as the camera sees it on an output of some size, on the CPU: world points to pixels and
//! pixels to rays ([`camera`]), the cell or sphere under a pixel ([`pick`]), and moving or adding a
//! sphere by pointer ([`edit`]). Nothing here touches a device: the renderer asks these with its own
//! settings and size, and they are tested alone.
//!
//! Imports `scene`, `extract` (the grid and the oracle's construction) and `teach` (the ray walk
//! through the cells).

pub mod camera;
pub mod edit;
pub mod pick;

pub use camera::CameraView;
pub use pick::Picker;
