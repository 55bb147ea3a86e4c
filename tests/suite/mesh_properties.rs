//! What the extracted surface must be: closed, manifold, of the right topology and shape, with exact
//! normals.

use crate::common;

use common::*;
use glam::{DVec3, Vec3};
use metaballs::extract::reference::{self, Grid};
use metaballs::{Scene, Sphere};

fn gpu_mesh(scene: &Scene, iso: f32, resolution: u32) -> metaballs::extract::mesh::IndexedMesh {
    with_renderer(settings(1, 1, resolution, iso), 16, 16, |o| {
        o.renderer.set_scene(scene.clone());
        pollster::block_on(o.renderer.extract_mesh())
    })
}

/// Checks that the GPU's indexed mesh (its vertices shared as the GPU shares them) and the oracle's
/// (welded by grid edge) are closed, consistently oriented 2-manifolds with the expected Euler
/// characteristic per component.
fn assert_closed_with_euler(scene: &Scene, iso: f32, resolution: u32, expected: &[i64]) {
    let what = format!("{} spheres, iso {iso}, {resolution} cells", scene.spheres().len());
    let gpu = gpu_mesh(scene, iso, resolution);
    let cpu = reference::extract(scene.spheres(), iso, Grid { cells_per_axis: resolution }).weld_by_edge();
    for (name, mesh) in [("GPU", gpu), ("oracle", cpu)] {
        let topology = mesh.topology();
        assert_eq!(topology.open_or_nonmanifold_edges, 0, "{what}, {name}: open or non-manifold edges");
        assert_eq!(topology.misoriented_edges, 0, "{what}, {name}: inconsistent orientation");
        assert_eq!(topology.component_euler, expected, "{what}, {name}: Euler characteristic per component");
    }
}

#[test]
fn one_sphere_is_a_closed_sphere() {
    let scene = Scene::from_spheres(vec![sphere([0.1, -0.05, 0.03], 0.5)]).unwrap();
    for resolution in [16, 48, 96] {
        assert_closed_with_euler(&scene, 1.0, resolution, &[2]);
    }
}

#[test]
fn two_merged_spheres_are_one_closed_sphere() {
    let scene =
        Scene::from_spheres(vec![sphere([-0.2, 0.0, 0.0], 0.3), sphere([0.2, 0.05, 0.0], 0.3)]).unwrap();
    assert_closed_with_euler(&scene, 1.0, 48, &[2]);
}

#[test]
fn two_far_apart_spheres_are_two_closed_spheres() {
    let scene =
        Scene::from_spheres(vec![sphere([-0.55, 0.0, 0.0], 0.25), sphere([0.55, 0.0, 0.0], 0.25)]).unwrap();
    assert_closed_with_euler(&scene, 1.0, 48, &[2, 2]);
}

#[test]
fn seeded_scenes_are_closed_manifolds_whether_or_not_walls_cut_them() {
    let mut inside = 0;
    for seed in 1..=12 {
        for count in [3, 8, 16, 64] {
            let scene = Scene::new(seed, count).unwrap();
            inside += surface_inside_box(scene.spheres(), 1.0, 40) as u32;
            let mesh = gpu_mesh(&scene, 1.0, 40);
            let topology = mesh.topology();
            assert_eq!(topology.open_or_nonmanifold_edges, 0, "seed {seed}, {count} spheres");
            assert_eq!(topology.misoriented_edges, 0, "seed {seed}, {count} spheres");
            // Each component is a closed orientable surface: χ = 2 − 2·genus.
            assert!(
                topology.component_euler.iter().all(|&x| x <= 2 && x % 2 == 0),
                "seed {seed}: {topology:?}"
            );
        }
    }
    // Both kinds were covered: surfaces inside the box and surfaces the walls cut.
    assert!((1..48).contains(&inside), "{inside} of 48 scenes stayed inside the box");
}

#[test]
fn walls_close_the_surface_where_they_cut_it() {
    // The big sphere pokes through three walls at once; the walls cap it.
    let scene =
        Scene::from_spheres(vec![sphere([0.55, 0.55, -0.55], 0.45), sphere([-0.3, 0.0, 0.2], 0.3)]).unwrap();
    assert!(!surface_inside_box(scene.spheres(), 0.5, 32));
    assert_closed_with_euler(&scene, 0.5, 32, &[2]);
}

#[test]
fn a_single_sphere_at_iso_one_is_its_own_sphere() {
    let s = sphere([0.13, -0.21, 0.07], 0.42);
    let scene = Scene::from_spheres(vec![s]).unwrap();
    for resolution in [16, 48, 96] {
        let cell = Grid { cells_per_axis: resolution }.cell_size();
        let mesh = gpu_mesh(&scene, 1.0, resolution);
        assert!(mesh.triangles.len() > 100);
        let worst =
            mesh.positions.iter().map(|p| (p.distance(s.center) - s.radius).abs()).fold(0.0, f32::max);
        assert!(worst < cell, "{resolution} cells: a vertex is {worst} from the sphere (cell {cell})");
        // Normals of a lone sphere point straight out from its centre.
        for (p, n) in mesh.positions.iter().zip(&mesh.normals) {
            assert!(n.angle_between(*p - s.center) < 1f32.to_radians());
        }
    }
}

fn field_f64(spheres: &[Sphere], p: DVec3) -> f64 {
    spheres
        .iter()
        .map(|s| {
            let r = s.radius as f64;
            r * r / (p - s.center.as_dvec3()).length_squared()
        })
        .sum()
}

#[test]
fn analytic_normals_match_a_central_difference_gradient_within_one_degree() {
    for (seed, count) in [(3, 5), (4, 16), (5, 64)] {
        let scene = Scene::new(seed, count).unwrap();
        let mesh = gpu_mesh(&scene, 1.0, 48);
        let h = 1e-5;
        let mut worst = 0.0f32;
        // Vertices within a cell of a wall belong to the caps, whose normals are the walls'.
        let away_from_walls = 1.0 - Grid { cells_per_axis: 48 }.cell_size();
        let mut checked = 0;
        for (p, n) in mesh.positions.iter().zip(&mesh.normals) {
            if p.abs().max_element() >= away_from_walls {
                continue;
            }
            checked += 1;
            let p = p.as_dvec3();
            let diff = |axis: DVec3| {
                (field_f64(scene.spheres(), p + axis * h) - field_f64(scene.spheres(), p - axis * h))
                    / (2.0 * h)
            };
            let gradient = DVec3::new(diff(DVec3::X), diff(DVec3::Y), diff(DVec3::Z));
            let outward: Vec3 = (-gradient).as_vec3();
            worst = worst.max(n.angle_between(outward));
        }
        assert!(checked > 1000, "seed {seed}: only {checked} vertices away from the walls");
        assert!(worst < 1f32.to_radians(), "seed {seed}: worst normal is {}° off", worst.to_degrees());
        assert!((mesh.normals.iter().map(|n| n.length()).fold(0.0, f32::max) - 1.0).abs() < 1e-4);
    }
}

#[test]
fn triangles_face_outwards() {
    // Signed volume of a closed surface with counter-clockwise outside faces is positive.
    let scene = Scene::new(9, 5).unwrap();
    let mesh = gpu_mesh(&scene, 1.0, 48).to_soup();
    let volume: f32 = (0..mesh.triangle_count())
        .map(|k| {
            let [a, b, c] = mesh.triangle(k);
            a.dot(b.cross(c)) / 6.0
        })
        .sum();
    assert!(volume > 0.0, "signed volume {volume}");
    // And each geometric normal agrees with the analytic ones at its corners.
    let agree = (0..mesh.triangle_count())
        .filter(|&k| {
            let [a, b, c] = mesh.triangle(k);
            let face = (b - a).cross(c - a);
            face.dot(mesh.normals[3 * k] + mesh.normals[3 * k + 1] + mesh.normals[3 * k + 2]) > 0.0
        })
        .count();
    assert_eq!(agree, mesh.triangle_count());
}

#[test]
fn a_subtracting_sphere_dents_a_blob_to_the_volume_the_field_predicts() {
    // A sphere of charge −1 inside a larger one, off its centre: a dented, still closed blob whose
    // volume is the midpoint-rule integral of {f ≥ iso} over the same cells.
    let spheres = common::scenes::dented();
    let (iso, resolution) = (1.0, 128);
    let grid = Grid { cells_per_axis: resolution };
    let h = grid.cell_size() as f64;
    let mut inside = 0u64;
    for z in 0..resolution {
        for y in 0..resolution {
            for x in 0..resolution {
                let p = grid.point(glam::UVec3::new(x, y, z)) + Vec3::splat(0.5 * grid.cell_size());
                inside += (reference::field_at(&spheres, p) >= iso) as u64;
            }
        }
    }
    let predicted = inside as f64 * h * h * h;
    let scene = Scene::from_spheres(spheres.clone()).unwrap();
    let mesh = gpu_mesh(&scene, iso, resolution);
    let topology = mesh.topology();
    assert_eq!(topology.open_or_nonmanifold_edges, 0, "open or non-manifold edges");
    assert_eq!(topology.misoriented_edges, 0, "inconsistent orientation");
    assert_eq!(topology.component_euler, [2], "one blob, no hole through it");
    let volume = mesh.enclosed_volume();
    let whole = 4.0 / 3.0 * std::f64::consts::PI * 0.5f64.powi(3);
    println!("dented volume {volume:.5}, midpoint rule {predicted:.5}, undented sphere {whole:.5}");
    assert!((volume / predicted - 1.0).abs() < 0.01, "volume {volume} against {predicted}");
    assert!(volume < 0.93 * whole, "the dent took away only {:.1} %", 100.0 * (1.0 - volume / whole));
}
