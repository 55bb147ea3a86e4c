//! The critical points of the field f(p) = Σ qᵢ rᵢ² / |p − cᵢ|² (∇f = 0), found with proof, and what
//! each does to the surface f = iso as the iso level falls past its value: where blobs merge (the
//! merge tree), where tunnels open and close and where cavities form. The surface changes topology only
//! at those levels, so between two of them its blobs, cavities and genus are known exactly.
//!
//! - [`interval`]: f, ∇f and the Hessian at a point and bounded over a box.
//! - [`search`]: every zero of ∇f in a box (exclusion by bounds, uniqueness by the Krawczyk test).
//! - [`morse`]: the Hessian's signature, the gradient flow from saddles, union–find.
//!
//! Where no sphere subtracts, every critical point lies in the spheres' convex hull (outside it, the
//! field falls along any direction leaving the hull), so the box is searched. Where some subtract but
//! the adding weights Σ rᵢ² outweigh them, the field falls outward beyond a radius worked out below,
//! and the cube of that radius is searched. Otherwise the search covers eight box widths and says it
//! may be incomplete.

pub mod interval;
pub mod json;
pub mod morse;
mod roles;
pub mod search;

use crate::scene::Sphere;
use glam::DVec3;
use interval::{Cube, Source, derivatives, value, value_bounds};
use morse::{End, eigen};
use roles::{follow_saddles, merge_tree, sublevel_roles};

/// What a critical point does as the iso level falls past its value (the blobs being where f ≥ iso).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// A maximum away from the spheres' centres: a blob appears.
    Birth,
    /// A saddle (two falling directions) where two blobs join.
    Join,
    /// A saddle where a blob meets itself: a tunnel (handle) opens, genus + 1.
    Loop,
    /// A saddle (one falling direction) that closes a tunnel: genus − 1.
    Hole,
    /// A saddle that closes a pocket of outside off: a cavity appears.
    Cavity,
    /// A minimum: a cavity fills.
    Fill,
    /// A saddle whose flow could not be followed to its ends: its effect is not known.
    Unresolved,
}

impl Role {
    pub fn word(self) -> &'static str {
        match self {
            Role::Birth => "birth",
            Role::Join => "join",
            Role::Loop => "loop",
            Role::Hole => "hole",
            Role::Cavity => "cavity",
            Role::Fill => "fill",
            Role::Unresolved => "unresolved",
        }
    }
}

/// One critical point.
#[derive(Clone, Debug)]
pub struct CriticalPoint {
    pub position: DVec3,
    /// f here: the iso level at which the surface passes through it.
    pub value: f64,
    /// How many of the Hessian's eigenvalues are negative (directions the field falls in): 3 a
    /// maximum, 2 a saddle that joins, 1 a saddle that closes, 0 a minimum.
    pub index: u8,
    /// The Hessian's eigenvalues, smallest first.
    pub eigenvalues: [f64; 3],
    /// Where the gradient flow leads from a saddle, both ways along its lone direction: up from a
    /// join saddle (to the blobs it joins), down from a closing one.
    pub ends: [End; 2],
    pub role: Role,
    /// True inside the box the spheres move in.
    pub in_box: bool,
}

impl CriticalPoint {
    /// The width of a joining saddle's neck at `iso` below its value, from the quadratic part of the
    /// field: across the neck, f ≈ value + ½ λ x², so the neck spans 2 √(2 (value − iso) / |λ|) along
    /// the eigenvector of the most negative eigenvalue λ (its narrowest way).
    pub fn neck_width(&self, iso: f64) -> f64 {
        let steepest = -self.eigenvalues[0];
        if self.index != 2 || iso >= self.value || steepest <= 0.0 {
            return 0.0;
        }
        2.0 * (2.0 * (self.value - iso) / steepest).sqrt()
    }
}

/// One node of the merge tree: a blob from the level it appears (a sphere's, at +∞) down to the level
/// it joins another.
#[derive(Clone, Debug)]
pub struct TreeNode {
    /// The level the node starts at: +∞ for a sphere, a join saddle's or a maximum's value.
    pub value: f64,
    /// The nodes it joins (none for a leaf).
    pub children: Vec<usize>,
    /// The critical point (a join saddle or maximum), none for a sphere.
    pub point: Option<usize>,
    /// The adding spheres in this blob.
    pub spheres: Vec<usize>,
}

/// The surface's topology at one iso level, from the critical points above and below it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Counts {
    /// Blobs: connected pieces of f ≥ iso.
    pub blobs: usize,
    /// Cavities: pockets of f < iso closed off inside blobs (each is a piece of surface of its own).
    pub cavities: usize,
    /// The total genus (tunnels) of the surface.
    pub genus: usize,
    /// Pieces of surface: blobs and cavities.
    pub surfaces: usize,
}

/// Everything found for one set of spheres.
#[derive(Clone, Debug)]
pub struct Critical {
    /// Every critical point found, by value, highest first.
    pub points: Vec<CriticalPoint>,
    /// The merge tree; the last node is the root (or the roots, where blobs never all join).
    pub tree: Vec<TreeNode>,
    /// The searched cube's half-width.
    pub reach: f64,
    /// True where the search provably covers every critical point in space.
    pub complete: bool,
    /// Pieces of the search left undecided (degenerate critical points); 0 for a proven result.
    pub undecided: usize,
    /// Pieces of the search examined.
    pub pieces: usize,
    /// The highest f on the box's walls (from above, to 1 %): below it, the surface may reach the
    /// walls, where the mesh is closed off, so the counts are of the surface in all of space, not of
    /// the mesh.
    pub wall_level: f64,
    positive: usize,
    negative: usize,
    /// Saddles whose flow could not be followed to its ends: the counts may be off by as many.
    pub unresolved: usize,
}

impl Critical {
    /// Why the counts along the iso level cannot be trusted, or `None` where they are exact: the
    /// search must be proven complete, every piece decided and every saddle's flow followed.
    pub fn counts_unknown(&self) -> Option<&'static str> {
        if !self.complete {
            Some("the subtracting spheres outweigh the adding ones, so no bound holds every critical point")
        } else if self.undecided > 0 {
            Some("a degenerate critical point (its Hessian singular) was found")
        } else if self.unresolved > 0 {
            Some("a saddle's flow could not be followed to its ends")
        } else {
            None
        }
    }
}

/// The box's half-width (`BOX_HALF_EXTENT`).
const BOX: f64 = crate::scene::sphere::BOX_HALF_EXTENT as f64;

/// The critical points of the spheres' field, with what each does.
pub fn find(spheres: &[Sphere]) -> Critical {
    // Spheres sharing a centre are one term (their weights summed); a term whose weights cancel is
    // none. `owner[k]`: the first sphere of term k, which the results name.
    let (mut sources, mut owner) = (Vec::<Source>::new(), Vec::new());
    for (i, s) in spheres.iter().enumerate() {
        let (centre, weight) = (s.center.as_dvec3(), f64::from(s.weight()));
        match sources.iter().position(|t| t.centre == centre) {
            Some(k) => sources[k].weight += weight,
            None => {
                sources.push(Source { centre, weight });
                owner.push(i);
            }
        }
    }
    let kept: Vec<usize> = (0..sources.len()).filter(|&k| sources[k].weight != 0.0).collect();
    let sources: Vec<Source> = kept.iter().map(|&k| sources[k]).collect();
    let owner: Vec<usize> = kept.iter().map(|&k| owner[k]).collect();
    let adding: Vec<bool> = sources.iter().map(|s| s.weight > 0.0).collect();
    let (reach, complete) = reach(&sources);
    if sources.is_empty() {
        // f ≡ 0: no surface at any iso level above zero, and nothing to search.
        return Critical {
            points: vec![],
            tree: vec![],
            reach,
            complete,
            undecided: 0,
            pieces: 0,
            wall_level: 0.0,
            positive: 0,
            negative: 0,
            unresolved: 0,
        };
    }
    let domain = Cube { low: DVec3::splat(-reach), high: DVec3::splat(reach) };
    let zeros = search::zeros(&sources, domain);
    let mut points: Vec<CriticalPoint> = zeros
        .points
        .iter()
        .map(|&p| {
            let (f, _, h) = derivatives(&sources, p);
            let (eigenvalues, _) = eigen(h);
            let index = eigenvalues.iter().filter(|&&l| l < 0.0).count() as u8;
            let in_box = p.abs().max_element() <= BOX;
            CriticalPoint {
                position: p,
                value: f,
                index,
                eigenvalues,
                ends: [End::Lost; 2],
                role: Role::Unresolved,
                in_box,
            }
        })
        .collect();
    points.sort_by(|a, b| b.value.total_cmp(&a.value));
    follow_saddles(&sources, &mut points, reach);
    let positive = adding.iter().filter(|&&a| a).count();
    let mut tree = merge_tree(&adding, &mut points);
    sublevel_roles(&adding, &mut points);
    let unresolved = points.iter().filter(|p| p.role == Role::Unresolved).count();
    // Terms by the spheres they came from.
    for point in &mut points {
        for end in &mut point.ends {
            if let End::Sphere(k) = end {
                *end = End::Sphere(owner[*k]);
            }
        }
    }
    for node in &mut tree {
        for s in &mut node.spheres {
            *s = owner[*s];
        }
        node.spheres.sort_unstable();
    }
    Critical {
        wall_level: wall_level(&sources),
        points,
        tree,
        reach,
        complete,
        undecided: zeros.undecided.len(),
        pieces: zeros.pieces,
        positive,
        negative: sources.len() - positive,
        unresolved,
    }
}

/// The half-width of a cube holding every critical point, and whether that is proven. With adding
/// weight W₊ and subtracting W₋ and every centre within ρ₀ of the origin, the radial derivative at
/// distance ρ is negative when W₊/W₋ > ((ρ + ρ₀)/(ρ − ρ₀))⁵.
fn reach(sources: &[Source]) -> (f64, bool) {
    let plus: f64 = sources.iter().map(|s| s.weight.max(0.0)).sum();
    let minus: f64 = sources.iter().map(|s| (-s.weight).max(0.0)).sum();
    let rho = sources.iter().map(|s| s.centre.length()).fold(0.0, f64::max);
    if minus == 0.0 {
        return (BOX * (1.0 + 1e-6), true);
    }
    if plus > minus {
        let k = (plus / minus).powf(0.2);
        let radius = rho * (k + 1.0) / (k - 1.0) * 1.01;
        if radius <= 64.0 * BOX {
            return (radius.max(BOX * (1.0 + 1e-6)), true);
        }
    }
    (8.0 * BOX, false)
}

impl Critical {
    /// The surface's blobs, cavities and genus at `iso` (> 0). Blobs: adding spheres and maxima above
    /// `iso` less the joins above it. Pockets of f < iso: the outside, subtracting spheres and minima
    /// below it, less the joins of pockets below it; all but the outside's are cavities. The genus
    /// follows from the Euler characteristic of f ≥ iso, which each critical point above `iso`
    /// changes by (−1)^(3 − index).
    pub fn counts(&self, iso: f64) -> Counts {
        let above = |role: Role| self.points.iter().filter(|p| p.role == role && p.value > iso).count();
        let below = |pred: &dyn Fn(&CriticalPoint) -> bool| {
            self.points.iter().filter(|p| pred(p) && p.value < iso).count()
        };
        let blobs = self.positive + above(Role::Birth) - above(Role::Join);
        let pockets = 1 + self.negative + below(&|p| p.index == 0) - below(&|p| p.role == Role::Cavity);
        let cavities = pockets - 1;
        let euler = self.positive as i64
            + self
                .points
                .iter()
                .filter(|p| p.value > iso)
                .map(|p| if (3 - p.index) % 2 == 0 { 1 } else { -1 })
                .sum::<i64>();
        let genus = (blobs + cavities) as i64 - euler;
        Counts { blobs, cavities, genus: genus.max(0) as usize, surfaces: blobs + cavities }
    }

    /// The critical levels above zero, highest first, without repeats.
    pub fn levels(&self) -> Vec<f64> {
        let mut levels: Vec<f64> = self.points.iter().map(|p| p.value).filter(|&v| v > 0.0).collect();
        levels.dedup();
        levels
    }
}

/// The highest f on the box's walls, from above, to 1 %: branch and bound over pieces of each wall,
/// returning the largest upper bound left (so a level above it surely keeps the surface off the walls).
fn wall_level(sources: &[Source]) -> f64 {
    let mut best = f64::NEG_INFINITY;
    let mut stack = Vec::new();
    for axis in 0..3 {
        for side in [-BOX, BOX] {
            let (mut low, mut high) = (DVec3::splat(-BOX), DVec3::splat(BOX));
            low[axis] = side;
            high[axis] = side;
            stack.push(Cube { low, high });
        }
    }
    let mut settled = f64::NEG_INFINITY;
    let scale: f64 = sources.iter().map(|s| s.weight.abs()).sum::<f64>().max(f64::MIN_POSITIVE);
    let mut pieces = 0;
    while let Some(piece) = stack.pop() {
        pieces += 1;
        best = best.max(value(sources, piece.centre()));
        let Some(bounds) = value_bounds(sources, &piece) else { continue };
        if bounds.hi <= best + 0.01 * best.abs() + 1e-9 * scale || pieces > 100_000 {
            settled = settled.max(bounds.hi);
            continue;
        }
        let (m, mut children) = (piece.centre(), vec![piece]);
        for a in (0..3).filter(|&a| piece.high[a] > piece.low[a]) {
            children = children
                .into_iter()
                .flat_map(|c| {
                    let (mut left, mut right) = (c, c);
                    left.high[a] = m[a];
                    right.low[a] = m[a];
                    [left, right]
                })
                .collect();
        }
        stack.extend(children);
    }
    settled.max(best)
}
