//! What each critical point does to the blobs as the iso level falls past its value: its Hessian's
//! signature (how many directions the field falls in), where the field's gradient flow leads from it,
//! and, from those, the merge tree of the blobs and the cavities' bookkeeping (two union–find passes).

use super::interval::{Source, derivatives};
use glam::DVec3;

/// The Hessian's eigenvalues, smallest first, with unit eigenvectors.
pub fn eigen(h: [[f64; 3]; 3]) -> ([f64; 3], [DVec3; 3]) {
    let p1 = h[0][1].powi(2) + h[0][2].powi(2) + h[1][2].powi(2);
    let q = (h[0][0] + h[1][1] + h[2][2]) / 3.0;
    let p2 = (h[0][0] - q).powi(2) + (h[1][1] - q).powi(2) + (h[2][2] - q).powi(2) + 2.0 * p1;
    let p = (p2 / 6.0).sqrt();
    if p <= 1e-14 * q.abs().max(f64::MIN_POSITIVE) {
        return ([q; 3], [DVec3::X, DVec3::Y, DVec3::Z]);
    }
    let b = |i: usize, j: usize| (h[i][j] - if i == j { q } else { 0.0 }) / p;
    let det = b(0, 0) * (b(1, 1) * b(2, 2) - b(1, 2) * b(2, 1))
        - b(0, 1) * (b(1, 0) * b(2, 2) - b(1, 2) * b(2, 0))
        + b(0, 2) * (b(1, 0) * b(2, 1) - b(1, 1) * b(2, 0));
    let phi = (det / 2.0).clamp(-1.0, 1.0).acos() / 3.0;
    let largest = q + 2.0 * p * phi.cos();
    let smallest = q + 2.0 * p * (phi + 2.0 * std::f64::consts::FRAC_PI_3).cos();
    let values = [smallest, 3.0 * q - largest - smallest, largest];
    (values, values.map(|l| eigenvector(h, l)))
}

/// A unit vector of the null space of H − λI: the longest cross product of two of its rows.
fn eigenvector(h: [[f64; 3]; 3], l: f64) -> DVec3 {
    let row = |i: usize| {
        DVec3::new(h[i][0], h[i][1], h[i][2])
            - DVec3::from_array(std::array::from_fn(|j| if i == j { l } else { 0.0 }))
    };
    let (a, b, c) = (row(0), row(1), row(2));
    [a.cross(b), a.cross(c), b.cross(c)]
        .into_iter()
        .max_by(|u, v| u.length_squared().total_cmp(&v.length_squared()))
        .map(|v| v.normalize_or(DVec3::X))
        .unwrap_or(DVec3::X)
}

/// Where the gradient flow from a saddle ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum End {
    /// At sphere `i`'s centre (f → +∞ for an adding sphere, −∞ for a subtracting one).
    Sphere(usize),
    /// At critical point `k` (a maximum going up, a minimum going down).
    Point(usize),
    /// Out of the searched domain going down: the region around the spheres, where f → 0.
    Outside,
    /// Nowhere the flow could be followed to (reported, never guessed).
    Lost,
}

/// Follows the gradient (up) or against it (down) from `start` until a sphere's centre, one of the
/// `extrema` (maxima going up, minima going down; `(index, position)`) or, going down, out of the cube
/// of half-width `limit`.
pub fn flow(sources: &[Source], start: DVec3, up: bool, extrema: &[(usize, DVec3)], limit: f64) -> End {
    let sign = if up { 1.0 } else { -1.0 };
    let mut p = start;
    for _ in 0..40_000 {
        if p.abs().max_element() > limit {
            return if up { End::Lost } else { End::Outside };
        }
        let (_, g, _) = derivatives(sources, p);
        let mut nearest = f64::INFINITY;
        for (i, s) in sources.iter().enumerate() {
            let d = p - s.centre;
            let dist = d.length();
            nearest = nearest.min(dist);
            // Within the sphere's radius of a centre that draws this way, where its own term outweighs
            // the rest fourfold: the flow runs straight into it.
            if s.weight * sign > 0.0 && dist * dist < s.weight.abs() {
                let own = d * (-2.0 * s.weight / dist.powi(4));
                if 2.0 * s.weight.abs() / dist.powi(3) > 4.0 * (g - own).length() {
                    return End::Sphere(i);
                }
            }
        }
        let h = (0.2 * nearest).clamp(1e-7, 0.05);
        if let Some(&(k, _)) = extrema.iter().find(|(_, q)| q.distance(p) <= 2.0 * h) {
            return End::Point(k);
        }
        if g.length_squared() == 0.0 || !g.is_finite() {
            return End::Lost;
        }
        let mid = p + g.normalize() * (0.5 * h * sign);
        let (_, g2, _) = derivatives(sources, mid);
        if g2.length_squared() == 0.0 || !g2.is_finite() {
            return End::Lost;
        }
        p += g2.normalize() * (h * sign);
    }
    End::Lost
}

/// A small union–find over `n` elements.
pub struct Sets(Vec<usize>);

impl Sets {
    pub fn new(n: usize) -> Self {
        Sets((0..n).collect())
    }

    pub fn root(&mut self, mut a: usize) -> usize {
        while self.0[a] != a {
            self.0[a] = self.0[self.0[a]];
            a = self.0[a];
        }
        a
    }

    /// Joins the sets of `a` and `b`; false when they were one already.
    pub fn join(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.root(a), self.root(b));
        self.0[ra] = rb;
        ra != rb
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn eigen_pairs_satisfy_the_matrix() {
        let h = [[2.0, 0.5, -0.3], [0.5, -1.0, 0.2], [-0.3, 0.2, 0.4]];
        let (values, vectors) = eigen(h);
        assert!(values[0] <= values[1] && values[1] <= values[2]);
        for (l, v) in values.iter().zip(vectors) {
            let hv = DVec3::new(
                h[0][0] * v.x + h[0][1] * v.y + h[0][2] * v.z,
                h[1][0] * v.x + h[1][1] * v.y + h[1][2] * v.z,
                h[2][0] * v.x + h[2][1] * v.y + h[2][2] * v.z,
            );
            assert!((hv - v * *l).length() < 1e-12, "{l} {v}");
        }
    }
}
