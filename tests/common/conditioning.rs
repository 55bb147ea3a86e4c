//! Choosing iso levels at which the GPU and the oracle must agree exactly (shared with the browser
//! tests).

use metaballs::Sphere;
use metaballs::extract::kernel::Terms;
use metaballs::extract::reference::{Grid, sample_blended_field};
use metaballs::scene::params::view::Kernel;

/// How far the GPU's field may be from the oracle's, relative: WGSL rounds a division within 2.5 ulp
/// and may fuse multiply-adds, so a sum of 16 positive terms can differ by a few times 1e-7.
pub const FIELD_RELATIVE_TOLERANCE: f32 = 2e-6;

/// The same for Blinn's kernel: WGSL's `exp` is within 3 + 2|x| ulp, and the exponent B (1 − d²/r²)
/// carries the division's rounding times B d²/r².
const EXP_RELATIVE_TOLERANCE: f32 = 2e-5;

/// True when no sample lies so close to `iso` (within `tolerance` of it, relative) that the GPU and the
/// oracle could classify it differently.
fn level_clear_of(values: &[f32], iso: f32, tolerance: f32) -> bool {
    values.iter().all(|&f| (f - iso).abs() > tolerance * iso)
}

/// `iso`, or the nearest level above it (in steps of 1e-4) at which the scene is well conditioned.
pub fn conditioned_iso(spheres: &[Sphere], iso: f32, resolution: u32) -> f32 {
    conditioned_level(spheres, iso, resolution, Terms::default())
}

/// [`conditioned_iso`] for the field of `terms`.
pub fn conditioned_level(spheres: &[Sphere], iso: f32, resolution: u32, terms: Terms) -> f32 {
    let values = sample_blended_field(spheres, Grid { cells_per_axis: resolution }, terms);
    let tolerance =
        if terms.kernel == Kernel::Blinn { EXP_RELATIVE_TOLERANCE } else { FIELD_RELATIVE_TOLERANCE };
    (0..100)
        .map(|k| iso * (1.0 + 1e-4 * k as f32))
        .find(|&level| level_clear_of(&values, level, tolerance))
        .expect("no well-conditioned iso level near the requested one")
}
