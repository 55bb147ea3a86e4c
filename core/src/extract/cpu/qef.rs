//! The quadratic error function of dual contouring (Ju, Losasso, Schaefer and Warren 2002): the point
//! of a cell nearest, in the least-squares sense, to every plane through a crossing on its edges with
//! the field's normal there. E(x) = Σᵢ (nᵢ · (x − pᵢ))².
//!
//! Its normal matrix AᵀA = Σᵢ nᵢ nᵢᵀ is symmetric, so its singular value decomposition is its
//! eigen-decomposition, found here by Jacobi rotations ([`symmetric_eigen`]): a dozen lines, where a
//! general linear-algebra library's decomposition costs kilobytes of the page's WebAssembly, which
//! holds a download budget of 200 KB gzipped. `tests` holds it to the definition (A v = λ v,
//! orthonormal v) on random matrices. Directions whose singular value (the square root
//! of the eigenvalue) is under [`TRUNCATION`] of the largest are left out, as the paper does: along
//! them E barely changes, and the solution stays at the crossings' mean (the mass point) instead of
//! running off along a plane or an edge. The directions kept are the rank: 1 where the crossings'
//! planes agree (a face), 2 where two families meet (an edge, a crease), 3 at a corner.

use glam::{Mat3, Vec3};

/// Singular values under this fraction of the largest are truncated.
pub const TRUNCATION: f32 = 0.1;

/// Weight of the pull towards the mass point in the box-constrained minimisation, relative to the
/// normal matrix's trace (the sum of its eigenvalues): enough to choose among equal minimisers, too
/// little to move a well-determined one.
const MASS_BIAS: f32 = 1e-3;

/// A cell's QEF: the normal matrix AᵀA, Aᵀb about the mass point, and the mass point.
pub struct Qef {
    ata: Mat3,
    atb: Vec3,
    mass: Vec3,
}

/// A cell's QEF solved: where its vertex goes, how many directions fixed it, and whether the
/// minimiser nearest the mass point lay outside the cell.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Solved {
    pub point: Vec3,
    /// 1 (a face), 2 (an edge) or 3 (a corner).
    pub rank: u8,
    pub strayed: bool,
}

impl Qef {
    /// The QEF of `crossings` (point, unit normal): E(x) = Σ (nᵢ · (x − pᵢ))².
    pub fn new(crossings: &[(Vec3, Vec3)]) -> Qef {
        let count = crossings.len().max(1) as f32;
        let mass = crossings.iter().map(|c| c.0).sum::<Vec3>() / count;
        let (mut ata, mut atb) = (Mat3::ZERO, Vec3::ZERO);
        for &(p, n) in crossings {
            ata += Mat3::from_cols(n * n.x, n * n.y, n * n.z);
            atb += n * n.dot(p - mass);
        }
        Qef { ata, atb, mass }
    }

    /// The minimiser nearest the mass point, with the small singular values truncated, and its rank.
    pub fn minimiser(&self) -> (Vec3, u8) {
        let (values, vectors) = symmetric_eigen(self.ata.to_cols_array_2d());
        let largest = values.iter().fold(0.0f32, |a, &b| a.max(b));
        // σ < TRUNCATION·σ_max, with σ² the eigenvalues.
        let floor = TRUNCATION * TRUNCATION * largest;
        let mut offset = Vec3::ZERO;
        let mut rank = 0;
        for (value, v) in values.iter().zip(vectors) {
            if *value > floor && *value > 0.0 {
                let v = Vec3::from_array(v);
                offset += v * (v.dot(self.atb) / value);
                rank += 1;
            }
        }
        (self.mass + offset, rank.max(1))
    }

    /// The vertex of the cell from `low` to `high`, kept within `slack` of it: the truncated
    /// minimiser where it lies there; else the exact minimiser of the QEF plus a slight pull towards
    /// the mass point over that box. That point lies on the box's boundary as near every plane as the
    /// box allows (where an edge crosses the box, on the edge up to the pull), not where clamping
    /// each coordinate would put it. `strayed`: the minimiser lay outside the cell itself.
    pub fn solve_in(&self, low: Vec3, high: Vec3, slack: f32) -> Solved {
        let (point, rank) = self.minimiser();
        let outside = |low: Vec3, high: Vec3| {
            let margin = 1e-4 * (high - low).max_element();
            point.cmplt(low - margin).any() || point.cmpgt(high + margin).any()
        };
        let strayed = outside(low, high);
        let (low, high) = (low - slack, high + slack);
        if !outside(low, high) {
            return Solved { point: point.clamp(low, high), rank, strayed };
        }
        // y = x − mass. The QEF plus the pull is convex, so its minimiser over the box is the
        // stationary point of one of the box's faces (each coordinate free, or at its lower or upper
        // bound) that lies in the box and has the least energy: all 27 are tried.
        let a = self.ata
            + Mat3::from_diagonal(Vec3::splat(
                MASS_BIAS
                    * (self.ata.x_axis.x + self.ata.y_axis.y + self.ata.z_axis.z).max(f32::MIN_POSITIVE),
            ));
        let (from, to) = (low - self.mass, high - self.mass);
        let energy = |y: Vec3| y.dot(a * y) - 2.0 * y.dot(self.atb);
        let mut best = ((point - self.mass).clamp(from, to), f32::INFINITY);
        for face in 0..27u32 {
            // 0: free, 1: at the lower bound, 2: at the upper bound, per axis. The system is A's rows
            // for the free coordinates and, for the others, the bound they are held at: one 3 × 3
            // solve, never singular as A (with the pull) is positive definite.
            let at = [face % 3, face / 3 % 3, face / 9];
            let mut m = [a.row(0), a.row(1), a.row(2)];
            let mut r = self.atb;
            for i in 0..3 {
                if at[i] > 0 {
                    m[i] = Vec3::AXES[i];
                    r[i] = if at[i] == 1 { from[i] } else { to[i] };
                }
            }
            // `m` holds the system's rows: transposed into columns for glam.
            let system = Mat3::from_cols(m[0], m[1], m[2]).transpose();
            let y = system.inverse() * r;
            let margin = 1e-6 * (to - from).max_element();
            if y.is_finite()
                && y.cmpge(from - margin).all()
                && y.cmple(to + margin).all()
                && energy(y) < best.1
            {
                best = (y.clamp(from, to), energy(y));
            }
        }
        let y = best.0;
        Solved { point: self.mass + y, rank, strayed }
    }
}

/// Jacobi sweeps at most: each at least halves the off-diagonal's digits, and a sweep that rotates
/// nothing ends them; a 3 × 3 matrix in `f32` needs a few.
const JACOBI_SWEEPS: u32 = 8;

/// The eigenvalues of the symmetric matrix `a` (columns) and their unit eigenvectors, by the cyclic
/// Jacobi method: rotations in each coordinate plane in turn that zero the off-diagonal entry.
fn symmetric_eigen(mut a: [[f32; 3]; 3]) -> ([f32; 3], [[f32; 3]; 3]) {
    // The rotations' product: its columns become the eigenvectors.
    let mut v = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    for _ in 0..JACOBI_SWEEPS {
        let mut rotated = false;
        for (p, q) in [(0, 1), (0, 2), (1, 2)] {
            let off = a[q][p];
            if off.abs() <= f32::EPSILON * 1e-3 * (a[p][p].abs() + a[q][q].abs()) {
                continue;
            }
            rotated = true;
            // The rotation angle's tangent, the smaller root of t² + 2θt − 1 = 0.
            let theta = (a[q][q] - a[p][p]) / (2.0 * off);
            let t = theta.signum() / (theta.abs() + (theta * theta + 1.0).sqrt());
            let c = 1.0 / (t * t + 1.0).sqrt();
            let s = t * c;
            let rotate = |m: &mut [[f32; 3]; 3]| {
                for column in m.iter_mut() {
                    let (x, y) = (column[p], column[q]);
                    column[p] = c * x - s * y;
                    column[q] = s * x + c * y;
                }
            };
            // A ← JᵀAJ, column by column and then row by row (A is symmetric); V ← VJ.
            rotate(&mut a);
            let (cp, cq) = (a[p], a[q]);
            for k in 0..3 {
                a[p][k] = c * cp[k] - s * cq[k];
                a[q][k] = s * cp[k] + c * cq[k];
            }
            let (vp, vq) = (v[p], v[q]);
            for k in 0..3 {
                v[p][k] = c * vp[k] - s * vq[k];
                v[q][k] = s * vp[k] + c * vq[k];
            }
        }
        if !rotated {
            break;
        }
    }
    ([a[0][0], a[1][1], a[2][2]], v)
}

/// The minimiser of Σ (nᵢ · (x − pᵢ))² over `crossings` (point, unit normal) nearest their mean
/// among the minimisers with the small singular values truncated, and its rank.
pub fn solve(crossings: &[(Vec3, Vec3)]) -> (Vec3, u8) {
    Qef::new(crossings).minimiser()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plane(p: Vec3, n: Vec3) -> (Vec3, Vec3) {
        (p, n.normalize())
    }

    #[test]
    fn the_eigen_decomposition_meets_its_definition() {
        // Random symmetric matrices, Σ n nᵀ of random directions as the QEF makes them, and
        // degenerate ones (a plane's, an edge's).
        let mut seed = 12345u32;
        let mut random = || {
            seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (seed >> 8) as f32 / (1 << 24) as f32 * 2.0 - 1.0
        };
        for k in 0..200 {
            let count = 1 + k % 6;
            let mut a = Mat3::ZERO;
            for _ in 0..count {
                let n = Vec3::new(random(), random(), random()).normalize_or(Vec3::X);
                a += Mat3::from_cols(n * n.x, n * n.y, n * n.z);
            }
            let (values, vectors) = symmetric_eigen(a.to_cols_array_2d());
            let scale = values.iter().fold(0.0f32, |m, v| m.max(v.abs())).max(1.0);
            for (i, (&value, v)) in values.iter().zip(vectors).enumerate() {
                let v = Vec3::from_array(v);
                assert!((v.length() - 1.0).abs() < 1e-5, "matrix {k}: |v{i}| = {}", v.length());
                let residual = (a * v - v * value).length();
                assert!(residual < 1e-5 * scale, "matrix {k}: A v{i} − λ v{i} = {residual}");
                for w in &vectors[i + 1..] {
                    assert!(v.dot(Vec3::from_array(*w)).abs() < 1e-5, "matrix {k}: v{i} not orthogonal");
                }
            }
        }
    }

    #[test]
    fn three_planes_meet_at_their_corner() {
        let corner = Vec3::new(0.3, -0.2, 0.1);
        let crossings = [
            plane(corner + Vec3::new(0.0, 0.4, 0.1), Vec3::X),
            plane(corner + Vec3::new(0.0, -0.1, 0.3), Vec3::X),
            plane(corner + Vec3::new(0.2, 0.0, 0.1), Vec3::Y),
            plane(corner + Vec3::new(-0.3, 0.0, 0.2), Vec3::Y),
            plane(corner + Vec3::new(0.1, 0.3, 0.0), Vec3::Z),
        ];
        let (point, rank) = solve(&crossings);
        assert_eq!(rank, 3);
        assert!(point.distance(corner) < 1e-5, "{point}");
    }

    #[test]
    fn two_planes_give_the_point_of_their_edge_nearest_the_mass_point() {
        // The planes x = 0 and y = 0 meet along z; the crossings' mean has z = 0.25.
        let crossings = [
            plane(Vec3::new(0.0, 0.2, 0.0), Vec3::X),
            plane(Vec3::new(0.0, 0.4, 0.5), Vec3::X),
            plane(Vec3::new(0.3, 0.0, 0.0), Vec3::Y),
            plane(Vec3::new(0.1, 0.0, 0.5), Vec3::Y),
        ];
        let (point, rank) = solve(&crossings);
        assert_eq!(rank, 2);
        assert!(point.distance(Vec3::new(0.0, 0.0, 0.25)) < 1e-5, "{point}");
    }

    #[test]
    fn a_vertex_outside_its_box_is_the_qef_minimiser_over_the_box() {
        // The edge x = y = 0 runs along z; the mass point's foot on it is at z = 0.25, above the box.
        let crossings = [
            plane(Vec3::new(0.0, 0.05, 0.2), Vec3::X),
            plane(Vec3::new(0.0, -0.05, 0.3), Vec3::X),
            plane(Vec3::new(0.05, 0.0, 0.2), Vec3::Y),
            plane(Vec3::new(-0.05, 0.0, 0.3), Vec3::Y),
        ];
        let solved = Qef::new(&crossings).solve_in(Vec3::splat(-0.1), Vec3::splat(0.1), 0.0);
        assert!(solved.strayed && solved.rank == 2);
        assert!(solved.point.distance(Vec3::new(0.0, 0.0, 0.1)) < 1e-5, "{}", solved.point);
        // A corner outside the box: the vertex is the box's point nearest the three planes.
        let crossings = [
            plane(Vec3::new(0.2, 0.0, 0.0), Vec3::X),
            plane(Vec3::new(0.0, 0.0, 0.0), Vec3::Y),
            plane(Vec3::new(0.0, 0.0, 0.0), Vec3::Z),
        ];
        let solved = Qef::new(&crossings).solve_in(Vec3::splat(-0.1), Vec3::splat(0.1), 0.05);
        assert!(solved.strayed && solved.rank == 3);
        assert!(solved.point.distance(Vec3::new(0.15, 0.0, 0.0)) < 1e-4, "{}", solved.point);
        // A minimiser within the slack stays where it is, though it strayed; one inside, too.
        let solved = Qef::new(&crossings).solve_in(Vec3::splat(-0.1), Vec3::splat(0.1), 0.1);
        assert!(solved.strayed && solved.point.distance(Vec3::new(0.2, 0.0, 0.0)) < 1e-5);
        let solved = Qef::new(&crossings).solve_in(Vec3::splat(-0.3), Vec3::splat(0.3), 0.0);
        assert!(!solved.strayed && solved.point.distance(Vec3::new(0.2, 0.0, 0.0)) < 1e-5);
    }

    #[test]
    fn nearly_parallel_planes_keep_the_vertex_at_the_mass_point_along_them() {
        // Normals a degree apart: the second singular value is truncated, so the vertex moves only
        // across the planes, not far along them.
        let tilt = Vec3::new(0.0, 1.0_f32.to_radians().sin(), 0.0);
        let crossings = [
            plane(Vec3::new(0.0, 0.0, 0.0), Vec3::X),
            plane(Vec3::new(0.01, 0.5, 0.0), Vec3::X + tilt),
            plane(Vec3::new(0.0, 0.0, 0.5), Vec3::X),
        ];
        let (point, rank) = solve(&crossings);
        assert_eq!(rank, 1);
        let mass = crossings.iter().map(|c| c.0).sum::<Vec3>() / 3.0;
        let along = point - mass;
        assert!(along.y.abs() < 1e-3 && along.z.abs() < 1e-5, "{point} from {mass}");
    }
}
