//! The field on the CPU as the compute passes evaluate it, for the CPU meshers: the spheres in
//! separate arrays, the exact bounds of the field over a box (`straddles` in `shaders/common.wgsl`),
//! and rows of samples summed in sphere order like the oracle.

use crate::extract::reference::MIN_DISTANCE_SQUARED;
use crate::scene::Sphere;
use crate::scene::params::view::Blend;
use glam::Vec3;

/// Bounds skip a box only with this relative margin (`BOUND_MARGIN` in `shaders/common.wgsl`).
const BOUND_MARGIN: f32 = 1e-4;

/// The spheres as separate arrays of coordinates, read in the innermost loops.
#[derive(Default)]
pub struct Spheres {
    x: Vec<f32>,
    y: Vec<f32>,
    z: Vec<f32>,
    r2: Vec<f32>,
}

impl Spheres {
    /// Holds `spheres` from now on.
    pub fn set(&mut self, spheres: &[Sphere]) {
        self.x.clear();
        self.y.clear();
        self.z.clear();
        self.r2.clear();
        for sphere in spheres {
            self.x.push(sphere.center.x);
            self.y.push(sphere.center.y);
            self.z.push(sphere.center.z);
            self.r2.push(sphere.radius * sphere.radius);
        }
    }

    /// False only when the field's bounds over the box from `low` to `high` keep every point on one
    /// side of `iso` (as `classify_blocks` in `shaders/extract/blocks.wgsl` decides): no cell there can
    /// emit a triangle. A box touching the walls is never all inside, as the walls read outside.
    pub fn straddles(&self, low: Vec3, high: Vec3, touches_walls: bool, iso: f32, by_max: bool) -> bool {
        let centre = 0.5 * (low + high);
        let h = 0.5 * (high - low).length();
        let (mut lower, mut upper, mut unbounded) = (0.0f32, 0.0f32, false);
        for i in 0..self.r2.len() {
            let d = (centre - Vec3::new(self.x[i], self.y[i], self.z[i])).length();
            let low_term = self.r2[i] / ((d + h) * (d + h));
            let gap = d - h;
            let high_term = if gap <= 0.0 {
                unbounded = true;
                0.0
            } else {
                self.r2[i] / (gap * gap)
            };
            if by_max {
                lower = lower.max(low_term);
                upper = upper.max(high_term);
            } else {
                lower += low_term;
                upper += high_term;
            }
        }
        let all_outside = !unbounded && upper * (1.0 + BOUND_MARGIN) <= iso;
        let all_inside = !touches_walls && lower * (1.0 - BOUND_MARGIN) > iso;
        !all_outside && !all_inside
    }
}

/// Field values along a run of points sharing y and z: the sphere loop outside, the points inside, so
/// the inner loop has no dependence between iterations and vectorises; each point still sums its
/// spheres in order.
pub fn sample_run(run: &mut [f32], xs: &[f32], py: f32, pz: f32, s: &Spheres, blend: Blend) {
    run.fill(0.0);
    for i in 0..s.r2.len() {
        let (dy, dz, r2) = (py - s.y[i], pz - s.z[i], s.r2[i]);
        let (dy2, dz2, cx) = (dy * dy, dz * dz, s.x[i]);
        match blend {
            Blend::Sum => {
                for (f, &x) in run.iter_mut().zip(xs) {
                    let dx = x - cx;
                    let d2 = dx * dx + dy2 + dz2;
                    *f += r2 / if d2 < MIN_DISTANCE_SQUARED { MIN_DISTANCE_SQUARED } else { d2 };
                }
            }
            Blend::Max => {
                for (f, &x) in run.iter_mut().zip(xs) {
                    let dx = x - cx;
                    let d2 = dx * dx + dy2 + dz2;
                    let term = r2 / if d2 < MIN_DISTANCE_SQUARED { MIN_DISTANCE_SQUARED } else { d2 };
                    *f = if term > *f { term } else { *f };
                }
            }
        }
    }
}
