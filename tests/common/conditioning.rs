//! Choosing iso levels at which the GPU and the oracle must agree exactly (shared with the browser
//! tests).

use metaballs::Sphere;
use metaballs::extract::reference::{Grid, sample_field};

/// How far the GPU's field may be from the oracle's, relative: WGSL rounds a division within 2.5 ulp
/// and may fuse multiply-adds, so a sum of 16 positive terms can differ by a few times 1e-7.
pub const FIELD_RELATIVE_TOLERANCE: f32 = 2e-6;

/// True when no grid sample lies so close to `iso` that the GPU and the oracle could classify it
/// differently within `FIELD_RELATIVE_TOLERANCE`.
pub fn well_conditioned(spheres: &[Sphere], iso: f32, resolution: u32) -> bool {
    sample_field(spheres, Grid { cells_per_axis: resolution })
        .iter()
        .all(|&f| (f - iso).abs() > FIELD_RELATIVE_TOLERANCE * iso)
}

/// `iso`, or the nearest level above it (in steps of 1e-4) at which the scene is well conditioned.
pub fn conditioned_iso(spheres: &[Sphere], iso: f32, resolution: u32) -> f32 {
    (0..100)
        .map(|k| iso * (1.0 + 1e-4 * k as f32))
        .find(|&level| well_conditioned(spheres, level, resolution))
        .expect("no well-conditioned iso level near the requested one")
}
