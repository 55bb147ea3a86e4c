//! The field, its gradient and its Hessian at a point (`f64`), and bounds on them over a box by
//! interval arithmetic: what the search for critical points proves with. Every bound is widened by a
//! margin far above `f64` rounding, so a bound that excludes zero excludes it for the exact values.

use glam::DVec3;

/// One term's source: centre and weight `charge · r²`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Source {
    pub centre: DVec3,
    pub weight: f64,
}

/// A closed interval `[lo, hi]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Interval {
    pub lo: f64,
    pub hi: f64,
}

impl Interval {
    pub const ZERO: Interval = Interval { lo: 0.0, hi: 0.0 };

    pub fn new(lo: f64, hi: f64) -> Self {
        Interval { lo, hi }
    }

    pub fn point(v: f64) -> Self {
        Interval { lo: v, hi: v }
    }

    pub fn contains_zero(self) -> bool {
        self.lo <= 0.0 && self.hi >= 0.0
    }

    /// The largest magnitude in the interval.
    pub fn magnitude(self) -> f64 {
        self.lo.abs().max(self.hi.abs())
    }

    pub fn plus(self, o: Interval) -> Interval {
        Interval::new(self.lo + o.lo, self.hi + o.hi)
    }

    pub fn times(self, o: Interval) -> Interval {
        let p = [self.lo * o.lo, self.lo * o.hi, self.hi * o.lo, self.hi * o.hi];
        Interval::new(
            p.iter().copied().fold(f64::INFINITY, f64::min),
            p.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        )
    }

    pub fn scale(self, k: f64) -> Interval {
        if k >= 0.0 {
            Interval::new(self.lo * k, self.hi * k)
        } else {
            Interval::new(self.hi * k, self.lo * k)
        }
    }

    /// x² over the interval (tight: zero when it straddles zero).
    pub fn square(self) -> Interval {
        if self.contains_zero() {
            Interval::new(0.0, self.magnitude() * self.magnitude())
        } else {
            let (a, b) = (self.lo * self.lo, self.hi * self.hi);
            Interval::new(a.min(b), a.max(b))
        }
    }

    /// 1/x over a positive interval.
    pub fn recip_positive(self) -> Interval {
        Interval::new(1.0 / self.hi, 1.0 / self.lo)
    }

    /// Widened on both sides by `margin`.
    pub fn widen(self, margin: f64) -> Interval {
        Interval::new(self.lo - margin, self.hi + margin)
    }
}

/// An axis-aligned box, as three intervals.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cube {
    pub low: DVec3,
    pub high: DVec3,
}

impl Cube {
    pub fn centre(&self) -> DVec3 {
        0.5 * (self.low + self.high)
    }

    pub fn half(&self) -> DVec3 {
        0.5 * (self.high - self.low)
    }

    pub fn axis(&self, a: usize) -> Interval {
        Interval::new(self.low[a], self.high[a])
    }

    pub fn contains(&self, p: DVec3) -> bool {
        (0..3).all(|a| p[a] >= self.low[a] && p[a] <= self.high[a])
    }

    /// The eight boxes splitting this one on every axis, a little off its centre (so that the centre
    /// of a symmetric scene, often a critical point, falls inside a piece, not on the cut).
    pub fn split(&self) -> [Cube; 8] {
        let m = self.low + SPLIT * (self.high - self.low);
        std::array::from_fn(|k| {
            let pick = |a: usize| if k >> a & 1 == 0 { (self.low[a], m[a]) } else { (m[a], self.high[a]) };
            let (x, y, z) = (pick(0), pick(1), pick(2));
            Cube { low: DVec3::new(x.0, y.0, z.0), high: DVec3::new(x.1, y.1, z.1) }
        })
    }
}

/// Where a box is cut along each axis, as a fraction of its width.
const SPLIT: f64 = 0.4870135;

/// Relative margin added to every bound: rounding in a sum of at most a few hundred `f64` terms is
/// below 1e-13 of the sum of their magnitudes.
const MARGIN: f64 = 1e-10;

/// f, ∇f and the Hessian at `p`.
pub fn derivatives(sources: &[Source], p: DVec3) -> (f64, DVec3, [[f64; 3]; 3]) {
    let (mut f, mut g, mut h) = (0.0, DVec3::ZERO, [[0.0; 3]; 3]);
    for s in sources {
        let d = p - s.centre;
        let s2 = d.length_squared();
        let w = s.weight;
        f += w / s2;
        g += d * (-2.0 * w / (s2 * s2));
        let (a, b) = (8.0 * w / (s2 * s2 * s2), 2.0 * w / (s2 * s2));
        for (i, row) in h.iter_mut().enumerate() {
            for (j, v) in row.iter_mut().enumerate() {
                *v += a * d[i] * d[j] - if i == j { b } else { 0.0 };
            }
        }
    }
    (f, g, h)
}

/// The field at `p`.
pub fn value(sources: &[Source], p: DVec3) -> f64 {
    sources.iter().map(|s| s.weight / (p - s.centre).length_squared()).sum()
}

/// Bounds on one term's pieces over a box: the offset's intervals and 1/s, 1/s², 1/s³ (s = |p − c|²),
/// or `None` where the box may hold the centre.
struct TermBox {
    d: [Interval; 3],
    inv: [Interval; 3],
}

fn term_box(s: &Source, cube: &Cube) -> Option<TermBox> {
    let d: [Interval; 3] =
        std::array::from_fn(|a| Interval::new(cube.low[a] - s.centre[a], cube.high[a] - s.centre[a]));
    let s2 = d[0].square().plus(d[1].square()).plus(d[2].square());
    if s2.lo <= 0.0 {
        return None;
    }
    let r = s2.recip_positive();
    let r2 = Interval::new(r.lo * r.lo, r.hi * r.hi);
    Some(TermBox { d, inv: [r, r2, Interval::new(r2.lo * r.lo, r2.hi * r.hi)] })
}

/// Bounds on f over the box; `None` where it holds a centre.
pub fn value_bounds(sources: &[Source], cube: &Cube) -> Option<Interval> {
    let (mut f, mut size) = (Interval::ZERO, 0.0);
    for s in sources {
        let t = term_box(s, cube)?;
        let term = t.inv[0].scale(s.weight);
        size += term.magnitude();
        f = f.plus(term);
    }
    Some(f.widen(MARGIN * size))
}

/// Bounds on ∇f over the box, leaving out the term of `skip` (a source whose centre the box may hold:
/// [`dominated`] bounds it on its own); `None` where another term's centre may lie in the box.
pub fn gradient_bounds(sources: &[Source], cube: &Cube, skip: Option<usize>) -> Option<[Interval; 3]> {
    let (mut g, mut size) = ([Interval::ZERO; 3], 0.0);
    for (i, s) in sources.iter().enumerate() {
        if Some(i) == skip {
            continue;
        }
        let t = term_box(s, cube)?;
        for (component, d) in g.iter_mut().zip(t.d) {
            let term = d.times(t.inv[1]).scale(-2.0 * s.weight);
            size += term.magnitude();
            *component = component.plus(term);
        }
    }
    Some(g.map(|c| c.widen(MARGIN * size)))
}

/// Bounds on the Hessian over the box; `None` where it may hold a centre.
pub fn hessian_bounds(sources: &[Source], cube: &Cube) -> Option<[[Interval; 3]; 3]> {
    let (mut h, mut size) = ([[Interval::ZERO; 3]; 3], 0.0);
    for s in sources {
        let t = term_box(s, cube)?;
        for (i, row) in h.iter_mut().enumerate() {
            for (j, entry) in row.iter_mut().enumerate() {
                let dd = if i == j { t.d[i].square() } else { t.d[i].times(t.d[j]) };
                let mut term = dd.times(t.inv[2]).scale(8.0 * s.weight);
                if i == j {
                    term = term.plus(t.inv[1].scale(-2.0 * s.weight));
                }
                size += term.magnitude();
                *entry = entry.plus(term);
            }
        }
    }
    Some(h.map(|row| row.map(|c| c.widen(MARGIN * size))))
}

/// True when the box holds no zero of ∇f because the term of source `i` outweighs every other term's
/// gradient there: its own gradient has magnitude 2|w|/|p − c|³, at least 2|w|/ρ³ with ρ the farthest
/// the box reaches from its centre.
pub fn dominated(sources: &[Source], cube: &Cube, i: usize) -> bool {
    let s = &sources[i];
    let far = (0..3)
        .map(|a| (cube.low[a] - s.centre[a]).abs().max((cube.high[a] - s.centre[a]).abs()))
        .map(|v| v * v)
        .sum::<f64>()
        .sqrt();
    let own = 2.0 * s.weight.abs() / (far * far * far);
    match gradient_bounds(sources, cube, Some(i)) {
        Some(rest) => own * (1.0 - 1e-9) > rest.iter().map(|c| c.magnitude().powi(2)).sum::<f64>().sqrt(),
        None => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sources() -> Vec<Source> {
        vec![
            Source { centre: DVec3::new(0.1, -0.2, 0.3), weight: 0.04 },
            Source { centre: DVec3::new(-0.4, 0.25, 0.0), weight: 0.09 },
            Source { centre: DVec3::new(0.3, 0.4, -0.5), weight: -0.02 },
        ]
    }

    /// Every bound holds the values, gradients and Hessians sampled in its box.
    #[test]
    fn bounds_hold_the_samples_in_their_box() {
        let s = sources();
        let cube = Cube { low: DVec3::new(0.5, -0.9, 0.55), high: DVec3::new(0.8, -0.6, 0.9) };
        let (f, g, h) = (
            value_bounds(&s, &cube).unwrap(),
            gradient_bounds(&s, &cube, None).unwrap(),
            hessian_bounds(&s, &cube).unwrap(),
        );
        let inside = |v: f64, i: Interval| i.lo <= v && v <= i.hi;
        for k in 0..1000 {
            let t = DVec3::new((k % 10) as f64, (k / 10 % 10) as f64, (k / 100) as f64) / 9.0;
            let p = cube.low + t * (cube.high - cube.low);
            let (fv, gv, hv) = derivatives(&s, p);
            assert!(inside(fv, f));
            for a in 0..3 {
                assert!(inside(gv[a], g[a]), "gradient {a} at {p}");
                for b in 0..3 {
                    assert!(inside(hv[a][b], h[a][b]), "Hessian {a}{b} at {p}");
                }
            }
        }
    }

    /// A box about a centre is passed over by dominance once it is small, never while it is large.
    #[test]
    fn a_small_box_about_a_centre_is_dominated() {
        let s = sources();
        let around =
            |h: f64| Cube { low: s[1].centre - DVec3::splat(h), high: s[1].centre + DVec3::splat(h) };
        assert!(dominated(&s, &around(0.01), 1));
        assert!(!dominated(&s, &around(0.6), 1));
    }
}
