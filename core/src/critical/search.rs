//! Every zero of ∇f in a box, with proof: the box is halved until each piece either holds no zero
//! (a gradient component's bounds exclude 0, or one sphere's term outweighs all others there) or holds
//! exactly one (the Krawczyk test: the interval Newton image lies inside the piece), which Newton's
//! method then finds to rounding. Pieces still undecided at the finest size (a degenerate critical
//! point, where the Hessian is singular) are reported, never dropped.

use super::interval::{Cube, Interval, Source, derivatives, dominated, gradient_bounds, hessian_bounds};
use glam::{DMat3, DVec3};

/// Halvings before a piece is reported undecided: 2⁻²² of the domain.
const MAX_DEPTH: u32 = 22;
/// Pieces tried at most, so that a degenerate scene cannot take the search without end.
const MAX_PIECES: usize = 1_000_000;

/// What the search found.
#[derive(Clone, Debug, Default)]
pub struct Zeros {
    /// Each zero of ∇f, proven the only one in a piece of the domain.
    pub points: Vec<DVec3>,
    /// Pieces at the finest size where no test decided (each may hold a degenerate critical point).
    pub undecided: Vec<Cube>,
    /// Pieces examined.
    pub pieces: usize,
}

enum Krawczyk {
    None,
    Unique,
    Unknown,
}

/// Every zero of ∇f in `domain`.
pub fn zeros(sources: &[Source], domain: Cube) -> Zeros {
    let mut found = Zeros::default();
    let mut stack = vec![(domain, 0u32)];
    while let Some((cube, depth)) = stack.pop() {
        found.pieces += 1;
        match examine(sources, &cube, depth) {
            Krawczyk::None => continue,
            Krawczyk::Unique if found.keep(sources, &cube) => continue,
            Krawczyk::Unknown if depth >= 2 => {
                // A zero on the piece's boundary is never strictly inside its K: the piece grown by a
                // quarter each way is tried too (a zero in the piece is in it, so it is that one).
                let grown = Cube {
                    low: cube.low - 0.25 * (cube.high - cube.low),
                    high: cube.high + 0.25 * (cube.high - cube.low),
                };
                if let Some(hb) = hessian_bounds(sources, &grown)
                    && matches!(krawczyk(sources, &grown, &hb), Krawczyk::Unique)
                    && found.keep(sources, &grown)
                {
                    continue;
                }
            }
            _ => {}
        }
        if depth >= MAX_DEPTH || found.pieces >= MAX_PIECES {
            found.undecided.push(cube);
            continue;
        }
        stack.extend(cube.split().into_iter().map(|c| (c, depth + 1)));
    }
    found
}

impl Zeros {
    /// Newton's method in a piece proven to hold one zero; false where it does not converge there.
    fn keep(&mut self, sources: &[Source], cube: &Cube) -> bool {
        let Some(p) = newton(sources, cube.centre(), cube) else { return false };
        if !self.points.iter().any(|q| q.distance(p) <= 1e-9 * (1.0 + p.length())) {
            self.points.push(p);
        }
        true
    }
}

/// What the bounds say of the piece: no zero (a gradient component's natural bounds, or its
/// mean-value bounds ∇f(m) + H(piece)(piece − m), exclude 0; or a sphere's term outweighs the rest),
/// exactly one (the Krawczyk test, from depth 2 on), or not yet known.
fn examine(sources: &[Source], cube: &Cube, depth: u32) -> Krawczyk {
    if let Some(g) = gradient_bounds(sources, cube, None)
        && g.iter().any(|c| !c.contains_zero())
    {
        return Krawczyk::None;
    }
    // A piece holding or near a centre: that term may outweigh the rest.
    let centre = cube.centre();
    let nearest = sources
        .iter()
        .enumerate()
        .map(|(i, s)| (i, s.centre.distance(centre)))
        .min_by(|a, b| a.1.total_cmp(&b.1));
    if let Some((i, d)) = nearest
        && d <= 3.0 * cube.half().length()
        && dominated(sources, cube, i)
    {
        return Krawczyk::None;
    }
    if let Some(hb) = hessian_bounds(sources, cube) {
        let (_, g, _) = derivatives(sources, centre);
        let rounding = gradient_rounding(sources, centre);
        let r = cube.half();
        let excluded = (0..3).any(|a| {
            let spread: f64 = (0..3).map(|j| hb[a][j].magnitude() * r[j]).sum();
            g[a].abs() - rounding > spread * (1.0 + 1e-9) + 1e-300
        });
        if excluded {
            return Krawczyk::None;
        }
        if depth >= 2 {
            return krawczyk(sources, cube, &hb);
        }
        return Krawczyk::Unknown;
    }
    Krawczyk::Unknown
}

/// The Krawczyk test on the piece, given its Hessian bounds `hb`: K = m − Y∇f(m) + (I − Y·H)(piece −
/// m), Y = H(m)⁻¹. K inside the piece proves exactly one zero there; K apart from it proves none.
fn krawczyk(sources: &[Source], cube: &Cube, hb: &[[Interval; 3]; 3]) -> Krawczyk {
    let (m, r) = (cube.centre(), cube.half());
    let (_, g, h) = derivatives(sources, m);
    let hm = DMat3::from_cols_array_2d(&h).transpose();
    if hm.determinant().abs() < 1e-300 {
        return Krawczyk::Unknown;
    }
    let y = hm.inverse();
    let step = y * g;
    let rounding = gradient_rounding(sources, m);
    let mut inside = true;
    for i in 0..3 {
        let mut spread = 0.0;
        for j in 0..3 {
            // (I − Y·H)ᵢⱼ over the piece.
            let mut entry = Interval::point(if i == j { 1.0 } else { 0.0 });
            for (k, row) in hb.iter().enumerate() {
                entry = entry.plus(row[j].scale(-y.col(k)[i]));
            }
            spread += entry.magnitude() * r[j];
        }
        let centre = m[i] - step[i];
        // Rounding in ∇f(m), carried through Y, and in the step itself.
        let carried: f64 = (0..3).map(|k| y.col(k)[i].abs()).sum::<f64>() * rounding;
        let slack = carried + 1e-12 * (1.0 + m[i].abs() + step[i].abs());
        let k = Interval::new(centre - spread - slack, centre + spread + slack);
        if k.hi < cube.low[i] || k.lo > cube.high[i] {
            return Krawczyk::None;
        }
        inside &= k.lo > cube.low[i] && k.hi < cube.high[i];
    }
    if inside { Krawczyk::Unique } else { Krawczyk::Unknown }
}

/// A bound on the rounding error of ∇f at `p` as `derivatives` sums it: far above `f64`'s, against
/// the sum of the terms' magnitudes.
fn gradient_rounding(sources: &[Source], p: DVec3) -> f64 {
    1e-13 * sources.iter().map(|s| 2.0 * s.weight.abs() / (p - s.centre).length().powi(3)).sum::<f64>()
}

/// Newton's method on ∇f from `start`, kept to the piece (a little beyond it, for rounding).
fn newton(sources: &[Source], start: DVec3, cube: &Cube) -> Option<DVec3> {
    let slack = 1e-9 * (1.0 + cube.half().length());
    let around = Cube { low: cube.low - DVec3::splat(slack), high: cube.high + DVec3::splat(slack) };
    let mut p = start;
    for _ in 0..60 {
        let (_, g, h) = derivatives(sources, p);
        let hm = DMat3::from_cols_array_2d(&h).transpose();
        let step = hm.inverse() * g;
        if !step.is_finite() {
            return None;
        }
        p -= step;
        if !around.contains(p) {
            return None;
        }
        if step.length() <= 1e-15 * (1.0 + p.length()) {
            break;
        }
    }
    let (_, g, _) = derivatives(sources, p);
    // Converged when the gradient is at rounding level against its terms' sizes.
    let size: f64 = sources.iter().map(|s| 2.0 * s.weight.abs() / (p - s.centre).length().powi(3)).sum();
    (g.length() <= 1e-9 * size).then_some(p)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_equal_spheres_have_one_zero_at_their_midpoint() {
        let s = [
            Source { centre: DVec3::new(-0.3, 0.0, 0.0), weight: 0.04 },
            Source { centre: DVec3::new(0.3, 0.0, 0.0), weight: 0.04 },
        ];
        let found = zeros(&s, Cube { low: DVec3::splat(-1.0), high: DVec3::splat(1.0) });
        assert_eq!(found.points.len(), 1, "{found:?}");
        assert!(found.points[0].length() < 1e-12);
        assert!(found.undecided.is_empty());
    }
}
