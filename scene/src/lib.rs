//! What is drawn, before any GPU is involved: the spheres and their motion, the parameters a person
//! sets (one table feeding links, attributes, the panel and scene files), and scenes as files.
//! Nothing here knows of wgpu; every other layer may import it.
//!
//! Inside, each module imports only those above it in this list: `math` (sines, powers),
//! `number` (reading decimals), `decimal` (writing them), `checks` (range checks), `sphere` (one sphere, its checks, the link form), `params` (the parameter
//! table and settings), `motion` (a seeded layout moving in the box), `file` (scene documents).

pub mod checks;
pub mod decimal;
pub mod file;
pub mod json;
pub mod math;
pub mod motion;
pub mod number;
pub mod params;
pub mod sphere;

pub use motion::{MAX_STEP_SECONDS, Scene, nominal_radius};
pub use sphere::{BOX_HALF_EXTENT, MAX_SPHERES, SceneError, Sphere};
