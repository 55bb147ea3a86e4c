//! The field's critical points (`metaballs::critical`) against closed forms, against a brute-force
//! search of ∇f = 0 on a fine grid, and against meshes: between two critical levels, the oracle's mesh
//! (under MC33, the interpolant's topology) has the blobs, cavities and genus the critical points
//! predict.

use crate::common;

use common::*;
use glam::DVec3;
use metaballs::critical::interval::{Source, derivatives};
use metaballs::critical::morse::End;
use metaballs::critical::{self, Critical, Role};
use metaballs::extract::cpu::mesher::CpuMesher;
use metaballs::extract::reference::{self, Construction, Grid};
use metaballs::scene::params::view::CaseTable;
use metaballs::{Scene, Sphere};

fn sources(spheres: &[Sphere]) -> Vec<Source> {
    spheres.iter().map(|s| Source { centre: s.center.as_dvec3(), weight: f64::from(s.weight()) }).collect()
}

/// ∇f = 0 by brute force: every cell of an `n`³ grid over the cube of half-width `half` where each
/// gradient component takes both signs at its corners is a candidate, refined by Newton's method.
fn brute_force(spheres: &[Sphere], half: f64, n: usize) -> Vec<DVec3> {
    let s = sources(spheres);
    let at = |i: usize| -half + 2.0 * half * i as f64 / n as f64;
    let plane = |k: usize| -> Vec<DVec3> {
        (0..=n)
            .flat_map(|j| (0..=n).map(move |i| (i, j)))
            .map(|(i, j)| derivatives(&s, DVec3::new(at(i), at(j), at(k))).1)
            .collect()
    };
    let mut found: Vec<DVec3> = Vec::new();
    let mut below = plane(0);
    for k in 0..n {
        let above = plane(k + 1);
        for j in 0..n {
            for i in 0..n {
                let corners = [(i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1)];
                let g: Vec<DVec3> = corners
                    .iter()
                    .flat_map(|&(a, b)| [below[a + (n + 1) * b], above[a + (n + 1) * b]])
                    .collect();
                let straddles =
                    (0..3).all(|c| g.iter().any(|v| v[c] <= 0.0) && g.iter().any(|v| v[c] >= 0.0));
                if !straddles {
                    continue;
                }
                let mut p = DVec3::new(at(i), at(j), at(k)) + DVec3::splat(half / n as f64);
                for _ in 0..50 {
                    let (_, g, h) = derivatives(&s, p);
                    let step = glam::DMat3::from_cols_array_2d(&h).transpose().inverse() * g;
                    if !step.is_finite() {
                        break;
                    }
                    p -= step;
                }
                let (_, g, _) = derivatives(&s, p);
                let size: f64 =
                    s.iter().map(|t| 2.0 * t.weight.abs() / (p - t.centre).length().powi(3)).sum();
                let near_cell =
                    (p - DVec3::new(at(i), at(j), at(k))).abs().max_element() < 4.0 * half / n as f64;
                if g.length() <= 1e-9 * size && near_cell && !found.iter().any(|q| q.distance(p) < 1e-7) {
                    found.push(p);
                }
            }
        }
        below = above;
    }
    found
}

fn assert_found_all(found: &Critical, brute: &[DVec3], what: &str) {
    for p in brute {
        assert!(
            found.points.iter().any(|q| q.position.distance(*p) < 1e-6),
            "{what}: the brute-force search finds a critical point at {p} that the search missed; it found {:?}",
            found.points.iter().map(|q| q.position).collect::<Vec<_>>()
        );
    }
}

#[test]
fn two_equal_spheres_join_at_their_midpoint_at_two_r_squared_over_a_squared() {
    let (r, a) = (0.3f64, 0.4f64);
    let spheres = [sphere([-a as f32, 0.0, 0.0], r as f32), sphere([a as f32, 0.0, 0.0], r as f32)];
    let found = critical::find(&spheres);
    assert_eq!(found.points.len(), 1, "{:?}", found.points);
    let p = &found.points[0];
    let expected = 2.0 * (r as f32 as f64).powi(2) / (a as f32 as f64).powi(2);
    assert!((p.value - expected).abs() <= 1e-6 * expected, "saddle f = {} against {expected}", p.value);
    assert!(p.position.length() < 1e-9);
    assert_eq!((p.index, p.role), (2, Role::Join));
    let mut ends = p.ends;
    ends.sort_by_key(|e| format!("{e:?}"));
    assert_eq!(ends, [End::Sphere(0), End::Sphere(1)]);
    assert_eq!(found.counts(expected * 1.01).blobs, 2);
    assert_eq!(found.counts(expected * 0.99).blobs, 1);
    assert_eq!(found.tree.len(), 3);
    assert_eq!(found.tree[2].spheres, vec![0, 1]);
    assert!(found.complete && found.undecided == 0);
}

#[test]
fn unequal_spheres_and_one_off_the_axis_match_a_brute_force_search() {
    let spheres =
        [sphere([-0.35, 0.0, 0.0], 0.3), sphere([0.3, 0.05, 0.0], 0.2), sphere([0.0, 0.45, 0.2], 0.22)];
    let found = critical::find(&spheres);
    let brute = brute_force(&spheres, 1.0, 96);
    assert!(brute.len() >= 2, "{brute:?}");
    assert_found_all(&found, &brute, "three spheres");
    assert_eq!(found.points.len(), brute.len(), "found {:?}, brute force {brute:?}", found.points);
    // Three blobs become one at two joins.
    assert_eq!(found.points.iter().filter(|p| p.role == Role::Join).count(), 2);
    assert_eq!(found.tree.last().unwrap().spheres, vec![0, 1, 2]);
}

/// Eight spheres on a ring in the plane z = 0.
fn ring() -> Vec<Sphere> {
    (0..8)
        .map(|k| {
            let t = k as f32 * std::f32::consts::TAU / 8.0 + 0.1;
            sphere([0.5 * t.cos(), 0.5 * t.sin(), 0.02], 0.2)
        })
        .collect()
}

#[test]
fn a_ring_of_eight_closes_its_hole_at_the_saddle_in_its_middle_as_the_mesh_shows() {
    let spheres = ring();
    let found = critical::find(&spheres);
    let holes: Vec<_> = found.points.iter().filter(|p| p.role == Role::Hole).collect();
    assert_eq!(holes.len(), 1, "{:?}", found.points);
    let hole = holes[0];
    // The brute-force search finds the same point, at the ring's centre.
    let brute = brute_force(&spheres, 1.0, 80);
    assert_found_all(&found, &brute, "ring");
    assert!(brute.iter().any(|p| p.distance(hole.position) < 1e-9));
    assert!((hole.position - DVec3::new(0.0, 0.0, 0.02)).length() < 1e-6, "{}", hole.position);
    // Every join is above the hole's level, and the eighth closes the ring (a loop).
    assert_eq!(found.points.iter().filter(|p| p.role == Role::Join).count(), 7);
    assert_eq!(found.points.iter().filter(|p| p.role == Role::Loop).count(), 1);
    let lowest_join =
        found.points.iter().filter(|p| p.index == 2).map(|p| p.value).fold(f64::INFINITY, f64::min);
    assert!(lowest_join > hole.value * 1.2, "{lowest_join} {}", hole.value);
    let expect = |iso: f64, genus: u32| {
        let counts = found.counts(iso);
        assert_eq!((counts.surfaces, counts.genus), (1, genus as usize), "prediction at {iso}");
        let mut mesher = CpuMesher::new();
        mesher.mesh(&spheres, iso as f32, Grid { cells_per_axis: 256 }, Construction::default());
        let shape = mesher.to_indexed().shape();
        assert_eq!((shape.components, shape.genus), (1, genus), "256³ CPU mesh at iso {iso}");
    };
    expect(hole.value * 1.08, 1);
    expect(hole.value * 0.92, 0);
}

/// Twenty seeded scenes of 3 to 8 spheres, a third of them subtracting, drawn in towards the middle
/// (so that more of their critical levels have the surface inside the box).
fn scenes() -> Vec<Vec<Sphere>> {
    (0..20u64)
        .map(|seed| {
            let count = 3 + (seed % 6) as u32;
            let mut spheres = Scene::new(seed + 11, count).unwrap().spheres().to_vec();
            for (k, s) in spheres.iter_mut().enumerate() {
                s.center *= 0.7;
                if (k as u64 + seed) % 3 == 2 {
                    s.charge = -1.0;
                    s.radius *= 0.7;
                }
            }
            spheres
        })
        .collect()
}

#[test]
fn on_twenty_scenes_with_charges_a_brute_force_search_finds_nothing_the_search_missed() {
    let (mut total, mut in_box) = (0, 0);
    for (k, spheres) in scenes().iter().enumerate() {
        let found = critical::find(spheres);
        assert_eq!(found.undecided, 0, "scene {k}: undecided pieces");
        assert_eq!(found.unresolved, 0, "scene {k}: saddles whose flow was lost: {:?}", found.points);
        // Finely over the box, where the spheres are; coarsely over everything searched.
        let brute = brute_force(spheres, 1.0, 72);
        assert_found_all(&found, &brute, &format!("scene {k} (box)"));
        let wide = brute_force(spheres, found.reach, 48);
        assert_found_all(&found, &wide, &format!("scene {k} (all of {:.1})", found.reach));
        total += found.points.len();
        in_box += brute.len();
    }
    println!(
        "20 scenes: {total} critical points found; the brute-force search found {in_box} in the box, none missed"
    );
    assert!(total >= 40, "{total}");
}

#[test]
fn between_critical_levels_the_oracle_mesh_has_the_predicted_blobs_cavities_and_genus() {
    const N: u32 = 96;
    let cell = 2.0 / N as f64;
    let (mut checked, mut thin, mut walls) = (0, 0, 0);
    for (k, spheres) in scenes().iter().enumerate() {
        let found = critical::find(spheres);
        let levels = found.levels();
        for pair in levels.windows(2) {
            let iso = (pair[0] * pair[1]).sqrt();
            if pair[0] / pair[1] < 1.1 {
                continue;
            }
            if iso <= found.wall_level * 1.05 {
                walls += 1;
                continue;
            }
            // A neck or hole under three cells across at this level is beyond the grid's reach.
            let narrow = found.points.iter().any(|p| {
                let gap = (p.value - iso).abs();
                let curvature = p.eigenvalues.iter().map(|l| l.abs()).fold(0.0, f64::max);
                2.0 * (2.0 * gap / curvature).sqrt() < 3.0 * cell
            });
            if narrow {
                thin += 1;
                continue;
            }
            let predicted = found.counts(iso);
            let construction = Construction { case_table: CaseTable::Mc33, ..Construction::default() };
            let mesh = reference::extract_with(spheres, iso as f32, Grid { cells_per_axis: N }, construction);
            let shape = mesh.weld_by_edge().shape();
            assert!(shape.closed, "scene {k} at {iso}");
            assert_eq!(
                (shape.components as usize, shape.genus as usize),
                (predicted.surfaces, predicted.genus),
                "scene {k} at iso {iso}: the mesh against the critical points {predicted:?}"
            );
            checked += 1;
        }
    }
    println!(
        "{checked} levels agree; {thin} skipped as too thin for {N}³, {walls} where the surface reaches the walls"
    );
    assert!(checked >= 30, "{checked} levels checked");
}

#[test]
fn as_the_spheres_move_the_search_keeps_finding_what_a_brute_force_search_finds() {
    let mut scene = Scene::new(3, 6).unwrap();
    let mut spheres = scene.spheres().to_vec();
    spheres[4].charge = -1.0;
    spheres[4].radius *= 0.6;
    scene = Scene::from_spheres(spheres).unwrap();
    let mut seen = 0;
    for step in 0..5 {
        scene.step(0.3).unwrap();
        let found = critical::find(scene.spheres());
        assert!(found.complete && found.undecided == 0 && found.unresolved == 0, "step {step}");
        let brute = brute_force(scene.spheres(), 1.0, 64);
        assert_found_all(&found, &brute, &format!("step {step}"));
        seen += found.points.len();
    }
    assert!(seen >= 10, "{seen}");
}

#[test]
fn where_subtracting_spheres_outweigh_the_adding_ones_the_counts_are_not_claimed() {
    // f ≤ 0 far away: a subtracting pocket may reach infinity with no critical point on the way.
    let spheres = [sphere([-0.5, 0.0, 0.0], 0.3), Sphere { charge: -1.0, ..sphere([0.5, 0.0, 0.0], 0.4) }];
    let found = critical::find(&spheres);
    assert!(!found.complete);
    assert!(found.counts_unknown().is_some());
    let text = metaballs::critical::json::to_json(&found, 0.0);
    assert!(text.contains("\"bands\":[]") && text.contains("\"countsUnknown\":\"the subtracting"), "{text}");
}

#[test]
fn spheres_that_cancel_leave_no_field_and_nothing_to_search() {
    // An adding and a subtracting sphere of one centre and radius: f ≡ 0.
    let spheres = [sphere([0.1, 0.0, 0.0], 0.3), Sphere { charge: -1.0, ..sphere([0.1, 0.0, 0.0], 0.3) }];
    let found = critical::find(&spheres);
    assert!(found.points.is_empty() && found.tree.is_empty());
    assert_eq!(found.pieces, 0, "nothing to search");
    // Two spheres on one centre are one term: a lone sphere has no critical point.
    let found = critical::find(&[sphere([0.1, 0.0, 0.0], 0.3), sphere([0.1, 0.0, 0.0], 0.2)]);
    assert!(found.points.is_empty());
    assert_eq!(found.tree.len(), 1);
    assert_eq!(found.counts(1.0).blobs, 1);
}
