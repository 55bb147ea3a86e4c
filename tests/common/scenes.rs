//! The scenes every extractor is held to against the oracle: the seeded random draws of the GPU and
//! CPU tests, spheres against the walls, overlapping and on a grid point at extreme iso levels, with
//! both vertex placements, every kernel, both blends and each way of joining ambiguous faces.

use super::sphere;
use metaballs::extract::extractor::Job;
use metaballs::extract::kernel::Terms;
use metaballs::extract::reference::{Construction, Grid};
use metaballs::scene::params::view::{Blend, CaseTable, Interpolation, Kernel};
use metaballs::{Scene, Sphere};
use rand::{RngExt, SeedableRng};

/// One extraction problem, named for messages.
pub struct OracleScene {
    pub what: String,
    pub spheres: Vec<Sphere>,
    pub iso: f32,
    pub resolution: u32,
    pub construction: Construction,
}

impl OracleScene {
    /// The scene as an extractor's job on its uniform grid.
    pub fn job(&self) -> Job<'_> {
        Job {
            spheres: &self.spheres,
            iso: self.iso,
            grid: Grid { cells_per_axis: self.resolution },
            construction: self.construction,
            lod: None,
            teaching: false,
        }
    }
}

/// `how_many` scenes drawn from a fixed seed (sphere count, resolution, iso level, layout and time), so
/// runs repeat: the draws of `tests/suite/gpu_matches_oracle.rs`, every other one with its ambiguous
/// faces resolved by the asymptotic decider.
pub fn random_scenes(how_many: usize) -> Vec<OracleScene> {
    let mut rng = rand_pcg::Pcg32::seed_from_u64(0x6d65_7461);
    (0..how_many)
        .map(|case| {
            let count = rng.random_range(1..=64);
            let resolution = rng.random_range(8..=48);
            let iso = 10f32.powf(rng.random_range(-1.0..1.0));
            let seed = rng.random_range(0..1_000_000);
            let time = rng.random_range(0.0..20.0);
            let mut scene = Scene::new(seed, count).unwrap();
            scene.step(time).unwrap();
            OracleScene {
                what: format!(
                    "case {case}: seed {seed}, {count} spheres, {resolution} cells, iso {iso}, {:?}",
                    alternate(case)
                ),
                spheres: scene.spheres().to_vec(),
                iso,
                resolution,
                construction: Construction { case_table: alternate(case), ..Construction::default() },
            }
        })
        .collect()
}

/// `how_many` seeded random scenes in which about a third of the spheres subtract (charge −1), with
/// both placements, every kernel and both blends: the exact bounds must keep every crossed cell with
/// negative terms.
pub fn subtractive_scenes(how_many: usize) -> Vec<OracleScene> {
    let mut rng = rand_pcg::Pcg32::seed_from_u64(0x6e65_6761);
    (0..how_many)
        .map(|case| {
            let count = rng.random_range(2..=32);
            let resolution = rng.random_range(8..=40);
            let iso = 10f32.powf(rng.random_range(-1.0..0.7));
            let seed = rng.random_range(0..1_000_000);
            let mut scene = Scene::new(seed, count).unwrap();
            scene.step(rng.random_range(0.0..20.0)).unwrap();
            let mut spheres = scene.spheres().to_vec();
            for s in spheres.iter_mut().skip(1) {
                if rng.random_bool(0.35) {
                    s.charge = -1.0;
                }
            }
            let negative = spheres.iter().filter(|s| s.is_subtractive()).count();
            let interpolation = if case % 2 == 0 { Interpolation::Linear } else { Interpolation::Midpoint };
            let blend = if case % 4 < 2 { Blend::Sum } else { Blend::Max };
            let terms = Terms { blend, kernel: Kernel::ALL[case % 3], ..Terms::default() };
            OracleScene {
                what: format!(
                    "subtractive case {case}: seed {seed}, {count} spheres ({negative} negative), \
                     {resolution} cells, iso {iso}, {interpolation:?}, {terms:?}, {:?}",
                    alternate(case / 4)
                ),
                spheres,
                iso,
                resolution,
                construction: Construction {
                    interpolation,
                    terms,
                    case_table: alternate(case / 4),
                    ..Construction::default()
                },
            }
        })
        .collect()
}

/// The classic table, the asymptotic decider and MC33 in turn.
pub fn alternate(k: usize) -> CaseTable {
    [CaseTable::Classic, CaseTable::Decider, CaseTable::Mc33][k % 3]
}

/// A sphere with a subtracting sphere inside it, off its centre: a dented blob.
pub fn dented() -> Vec<Sphere> {
    let mut hole = sphere([0.25, 0.1, 0.0], 0.3);
    hole.charge = -1.0;
    vec![sphere([0.0, 0.0, 0.0], 0.5), hole]
}

/// `random` seeded random scenes (the generator of `tests/suite/gpu_matches_oracle.rs`) and as many with
/// subtracting spheres, then the walls, overlaps, grid-point and dented scenes at five iso levels, two
/// placements and two blends, the kernels and case tables in turn.
pub fn oracle_scenes(random: usize) -> Vec<OracleScene> {
    let mut scenes = random_scenes(random);
    scenes.extend(subtractive_scenes(random.min(30)));
    for (name, spheres) in [
        ("touching walls", touching_walls()),
        ("overlapping", overlapping()),
        ("on a grid point", on_grid_point()),
        ("dented", dented()),
    ] {
        for iso in [0.05, 0.3, 1.0, 4.0, 20.0] {
            for interpolation in [Interpolation::Linear, Interpolation::Midpoint] {
                for blend in [Blend::Sum, Blend::Max] {
                    let case_table = alternate(scenes.len());
                    // Above iso 2 the compact and Gaussian kernels' few spheres have no surface left.
                    let kernel =
                        if iso > 2.0 { Kernel::InverseSquare } else { Kernel::ALL[scenes.len() / 3 % 3] };
                    let terms = Terms { blend, kernel, ..Terms::default() };
                    scenes.push(OracleScene {
                        what: format!("{name}, iso {iso}, {interpolation:?}, {terms:?}, {case_table:?}"),
                        spheres: spheres.clone(),
                        iso,
                        resolution: 32,
                        construction: Construction {
                            interpolation,
                            terms,
                            case_table,
                            ..Construction::default()
                        },
                    });
                }
            }
        }
    }
    scenes
}

/// Three spheres pressed against the walls of the box.
pub fn touching_walls() -> Vec<Sphere> {
    vec![sphere([-0.7, 0.0, 0.0], 0.3), sphere([0.0, 0.75, 0.0], 0.25), sphere([0.55, -0.55, 0.55], 0.45)]
}

/// Four spheres on top of each other, two with the same centre.
pub fn overlapping() -> Vec<Sphere> {
    vec![
        sphere([0.0, 0.0, 0.0], 0.3),
        sphere([0.05, 0.0, 0.0], 0.3),
        sphere([0.0, 0.0, 0.0], 0.2),
        sphere([0.2, 0.1, -0.1], 0.25),
    ]
}

/// One sphere centred at the origin, a grid point at even resolutions, where |p - c| = 0.
pub fn on_grid_point() -> Vec<Sphere> {
    vec![sphere([0.0, 0.0, 0.0], 0.4)]
}
