//! The spheres' terms: the one place that says how a sphere's term falls off with distance (the
//! kernel) and how the terms combine (the blend), read by the field, its gradient, its bounds over a
//! box, the oracle and the exact surface on the CPU. `shaders/common.wgsl` (`term`, which gives the
//! size and the slope together) evaluates the same expressions in the same order on the GPU.
//!
//! Each kernel is a function of the squared distance d² and of r², decreasing in d², and 1 at d = r:
//! - inverse-square: r² / d²;
//! - Blinn's blobby Gaussian: exp(B (1 − d² / r²)), B the blobbiness;
//! - Wyvill's soft objects: 2 C(d / 2r) with C(a) = 1 − 4/9 a⁶ + 17/9 a⁴ − 22/9 a², which in
//!   t = 1 − d² / 4r² is 2/9 t² (5 + 4 t), 0 from d = 2r on (t clamped at 0), so far from every sphere
//!   the field is exactly 0.

use crate::scene::params::ViewOptions;
use crate::scene::params::view::{Blend, Kernel};

/// Squared distances are clamped to this, so a grid point at a sphere's centre reads a huge but finite
/// inverse square. The GPU uses the same constant (`MIN_DISTANCE_SQUARED` in `shaders/common.wgsl`).
pub const MIN_DISTANCE_SQUARED: f32 = 1e-20;

/// How the spheres' terms are shaped and combined.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Terms {
    pub kernel: Kernel,
    /// Blinn's B (read only by `Kernel::Blinn`).
    pub blobbiness: f32,
    pub blend: Blend,
}

impl Default for Terms {
    fn default() -> Self {
        Self { kernel: Kernel::InverseSquare, blobbiness: DEFAULT_BLOBBINESS, blend: Blend::Sum }
    }
}

/// The `blobbiness` row's default.
pub const DEFAULT_BLOBBINESS: f32 = 2.0;

/// The steepest a Wyvill term of radius r gets, times r: max over d of |d(2 C(d / 2r))/dd| · r.
const WYVILL_STEEPEST: f32 = 1.6;

impl Terms {
    /// The terms a figure's options choose.
    pub fn of(view: &ViewOptions) -> Self {
        Self { kernel: view.kernel, blobbiness: view.blobbiness, blend: view.blend }
    }

    /// Puts these terms into a figure's options.
    pub fn set_in(self, view: &mut ViewOptions) {
        (view.kernel, view.blobbiness, view.blend) = (self.kernel, self.blobbiness, self.blend);
    }

    /// Every kernel with each blend, Blinn's at the least, the default and the largest blobbiness
    /// (the `blobbiness` row's range), for tests.
    pub fn every() -> impl Iterator<Item = Terms> {
        let kernels = [
            (Kernel::InverseSquare, DEFAULT_BLOBBINESS),
            (Kernel::Blinn, 0.25),
            (Kernel::Blinn, DEFAULT_BLOBBINESS),
            (Kernel::Blinn, 8.0),
            (Kernel::Wyvill, DEFAULT_BLOBBINESS),
        ];
        kernels.into_iter().flat_map(|(kernel, blobbiness)| {
            Blend::ALL.iter().map(move |&blend| Terms { kernel, blobbiness, blend })
        })
    }

    /// The blend by max (the union of the spheres): the largest adding term less the largest
    /// subtracting one.
    pub fn by_max(self) -> bool {
        self.blend == Blend::Max
    }

    /// The size of a term of radius² `r2` at squared distance `d2` (its sign is the sphere's
    /// charge's); infinite at the centre only for the inverse square.
    #[inline(never)]
    pub fn size(self, r2: f32, d2: f32) -> f32 {
        match self.kernel {
            Kernel::InverseSquare => r2 / d2.max(MIN_DISTANCE_SQUARED),
            Kernel::Blinn => (self.blobbiness * (1.0 - d2 / r2)).exp(),
            Kernel::Wyvill => {
                let t = (1.0 - d2 / (4.0 * r2)).max(0.0);
                2.0 / 9.0 * t * t * (5.0 + 4.0 * t)
            }
        }
    }

    /// How fast the size falls with the squared distance, −d size / d(d²), so that a term's outward
    /// gradient −∇/2 is `slope · (p − c)`.
    #[inline(never)]
    pub fn slope(self, r2: f32, d2: f32) -> f32 {
        match self.kernel {
            Kernel::InverseSquare => {
                let d2 = d2.max(MIN_DISTANCE_SQUARED);
                r2 / (d2 * d2)
            }
            Kernel::Blinn => self.blobbiness / r2 * self.size(r2, d2),
            Kernel::Wyvill => {
                let t = (1.0 - d2 / (4.0 * r2)).max(0.0);
                t * (5.0 + 6.0 * t) / (9.0 * r2)
            }
        }
    }

    /// The largest size over the points at least `gap` from the centre (`gap` ≤ 0: any point, where
    /// the inverse square's is r² / `MIN_DISTANCE_SQUARED`, so large that no bound keeps a box with
    /// it off iso).
    pub fn size_beyond(self, r2: f32, gap: f32) -> f32 {
        let gap = gap.max(0.0);
        self.size(r2, gap * gap)
    }

    /// An upper bound of a term's |∇| over the points at least `gap` from the centre of a sphere of
    /// radius² `r2`: 2 · slope · d where the slope falls monotonically (the inverse square); the
    /// steepest the term gets anywhere for the others, or the value at `gap` past the steepest point.
    pub fn steepness_beyond(self, r2: f32, gap: f32) -> f32 {
        match self.kernel {
            Kernel::InverseSquare if gap <= 0.0 => f32::INFINITY,
            Kernel::InverseSquare => 2.0 * self.slope(r2, gap * gap) * gap,
            Kernel::Blinn => {
                // d exp(−B d² / r²) is steepest at d = r / √(2B) and falls beyond.
                let d = gap.max((r2 / (2.0 * self.blobbiness)).sqrt());
                2.0 * self.slope(r2, d * d) * d
            }
            Kernel::Wyvill if gap >= 2.0 * r2.sqrt() => 0.0,
            Kernel::Wyvill => WYVILL_STEEPEST / r2.sqrt(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ALL: [Kernel; 3] = [Kernel::InverseSquare, Kernel::Blinn, Kernel::Wyvill];

    fn terms(kernel: Kernel, blobbiness: f32) -> Terms {
        Terms { kernel, blobbiness, blend: Blend::Sum }
    }

    /// Every kernel is 1 on the sphere, falls with distance, and its slope is the size's derivative.
    #[test]
    fn each_kernel_is_one_on_the_sphere_and_falls_as_its_slope_says() {
        for kernel in ALL {
            for b in [0.5, 2.0, 6.0] {
                let t = terms(kernel, b);
                for r in [0.1f32, 0.3, 0.7] {
                    let r2 = r * r;
                    assert!(
                        (t.size(r2, r2) - 1.0).abs() < 1e-5,
                        "{kernel:?} B {b} r {r}: {}",
                        t.size(r2, r2)
                    );
                    let mut last = f32::INFINITY;
                    for k in 10..400 {
                        let d = k as f32 * r / 100.0;
                        let (d2, h) = (d * d, 1e-2 * d);
                        let size = t.size(r2, d2);
                        assert!(size <= last, "{kernel:?} rises at d {d}");
                        last = size;
                        if kernel == Kernel::Wyvill && d + h >= 2.0 * r {
                            continue; // the difference would straddle the end of the support
                        }
                        let numeric = (t.size(r2, (d - h) * (d - h)) - t.size(r2, (d + h) * (d + h)))
                            / ((d + h) * (d + h) - (d - h) * (d - h));
                        let slope = t.slope(r2, d2);
                        let scale = slope.abs().max(1e-3 * t.slope(r2, r2));
                        assert!(
                            (numeric - slope).abs() <= 2e-2 * scale,
                            "{kernel:?} B {b} r {r} d {d}: slope {slope}, numerically {numeric}"
                        );
                    }
                }
            }
        }
    }

    /// Wyvill's kernel is the soft-objects polynomial and exactly 0 from twice the radius on.
    #[test]
    fn wyvill_is_the_soft_objects_polynomial_with_compact_support() {
        let t = terms(Kernel::Wyvill, 0.0);
        for k in 0..=100 {
            let a = k as f64 / 100.0;
            let c = 1.0 - 4.0 / 9.0 * a.powi(6) + 17.0 / 9.0 * a.powi(4) - 22.0 / 9.0 * a * a;
            let d = (2.0 * a * 0.4) as f32;
            assert!((f64::from(t.size(0.16, d * d)) - 2.0 * c).abs() < 1e-5, "a {a}");
        }
        for d in [0.8f32, 0.81, 1.0, 5.0] {
            assert_eq!(t.size(0.16, d * d), 0.0);
            assert_eq!(t.slope(0.16, d * d), 0.0);
        }
    }

    /// `steepness_beyond` bounds the gradient's size at every distance past the gap.
    #[test]
    fn steepness_bounds_the_gradient_past_the_gap() {
        for kernel in ALL {
            for b in [0.5, 2.0, 6.0] {
                let t = terms(kernel, b);
                let (r, r2) = (0.3f32, 0.09f32);
                for g in 0..120 {
                    let gap = g as f32 * r / 40.0;
                    let bound = t.steepness_beyond(r2, gap);
                    for k in 0..400 {
                        let d = gap + (k + 1) as f32 * r / 80.0;
                        let steep = 2.0 * t.slope(r2, d * d) * d;
                        assert!(
                            steep <= bound * (1.0 + 1e-4),
                            "{kernel:?} B {b}: gap {gap}, d {d}: {steep} > {bound}"
                        );
                    }
                }
            }
        }
    }
}
