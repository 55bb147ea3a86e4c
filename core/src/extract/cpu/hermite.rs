//! Hermite data for dual contouring: where the field itself (not the linear interpolation of its
//! samples) crosses the iso level on a grid edge, and the field's outward normal there.

use crate::extract::reference::{self, Construction, blended_field_at};
use crate::scene::Sphere;
use crate::scene::params::view::Interpolation;
use glam::Vec3;

/// Regula falsi steps (Illinois) that move a crossing from the samples' interpolation onto the field,
/// at most: they stop once the bracket is narrower than [`CROSSING_TOLERANCE`] of the edge.
const CROSSING_STEPS: u32 = 12;
const CROSSING_TOLERANCE: f32 = 1e-5;

/// A crossing as dual contouring reads it, Hermite data: where the field itself equals `iso` on the
/// edge, and the field's outward normal there. With midpoint placement, or where an end is on the
/// box's wall (which reads outside whatever the field), the crossing is `surface_vertex`'s.
pub fn hermite(
    spheres: &[Sphere],
    iso: f32,
    construction: Construction,
    a: (Vec3, f32, bool),
    b: (Vec3, f32, bool),
) -> (Vec3, Vec3) {
    if construction.interpolation == Interpolation::Midpoint || a.2 || b.2 {
        return reference::surface_vertex(spheres, iso, construction, a, b);
    }
    let at = |t: f32| blended_field_at(spheres, a.0 + (b.0 - a.0) * t, construction.terms) - iso;
    let (mut t0, mut g0, mut t1, mut g1) = (0.0f32, a.1 - iso, 1.0f32, b.1 - iso);
    let mut t = construction.edge_parameter(iso, a.1, b.1);
    // Which end the last step replaced: when the same end is replaced twice running, the other end's
    // value is halved (the Illinois rule), so that the bracket shrinks from both sides.
    let mut last = 0;
    for step in 0..CROSSING_STEPS {
        if step > 0 {
            t = (t0 * g1 - t1 * g0) / (g1 - g0);
            if !t.is_finite() || t <= t0 || t >= t1 {
                t = 0.5 * (t0 + t1);
            }
        }
        let g = at(t);
        if g == 0.0 || t1 - t0 < CROSSING_TOLERANCE {
            break;
        }
        if (g > 0.0) == (g0 > 0.0) {
            (t0, g0) = (t, g);
            if last == -1 {
                g1 *= 0.5;
            }
            last = -1;
        } else {
            (t1, g1) = (t, g);
            if last == 1 {
                g0 *= 0.5;
            }
            last = 1;
        }
    }
    let p = a.0 + (b.0 - a.0) * t.clamp(reference::EDGE_MARGIN, 1.0 - reference::EDGE_MARGIN);
    let outward = if a.1 > iso { b.0 - a.0 } else { a.0 - b.0 };
    let gradient = reference::outward_gradient(spheres, p, construction.terms);
    (p, gradient.try_normalize().unwrap_or(outward.normalize()))
}
