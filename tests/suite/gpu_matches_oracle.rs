//! The GPU passes against the CPU oracle: same field, same triangles.

use crate::common;

use common::scenes::{overlapping, touching_walls};
use common::*;
use metaballs::extract::reference::{self, Grid};
use metaballs::{Scene, Settings};
use rand::{RngExt, SeedableRng};

/// Checks the GPU mesh of the renderer's current scene against the oracle: equal triangle counts, and
/// the same triangles with vertices within 1e-4 of a cell and normals within 0.01°.
fn assert_gpu_matches_oracle(offscreen: &mut metaballs::offscreen::Offscreen, what: &str) -> usize {
    let settings = *offscreen.renderer.settings();
    let spheres = offscreen.renderer.scene().spheres().to_vec();
    let grid = Grid { cells_per_axis: settings.resolution };
    let iso = conditioned_iso(&spheres, settings.iso, settings.resolution);
    if iso != settings.iso {
        println!("{what}: iso {} moved to {iso}, away from samples that round differently", settings.iso);
    }
    offscreen.renderer.set_iso(iso).unwrap();
    let gpu = pollster::block_on(offscreen.renderer.extract_mesh()).to_soup();
    let cpu = reference::extract(&spheres, iso, grid);
    assert_eq!(gpu.triangle_count(), cpu.triangle_count(), "{what}: triangle counts differ");
    let tolerance = 1e-4 * grid.cell_size();
    if let Err(e) = gpu.matches(&cpu, tolerance, 0.01f32.to_radians()) {
        panic!("{what}: {e}");
    }
    cpu.triangle_count()
}

#[test]
fn gpu_field_matches_the_oracle() {
    // 16 spheres, so up to 16 rounded divisions and additions per sample.
    with_renderer(settings(5, 16, 48, 1.0), 16, 16, |o| {
        let grid = Grid { cells_per_axis: 48 };
        let gpu = pollster::block_on(o.renderer.extract_field());
        let cpu = reference::sample_field(o.renderer.scene().spheres(), grid);
        assert!(gpu.len() > 1000, "only {} points evaluated", gpu.len());
        let mut worst = 0.0f32;
        for (id, g) in gpu {
            let c = cpu[grid.point_index(id)];
            let relative = if c == 0.0 { g.abs() } else { (g - c).abs() / c.abs() };
            assert!(relative <= FIELD_RELATIVE_TOLERANCE, "point {id}: GPU {g}, oracle {c}");
            worst = worst.max(relative);
        }
        println!("largest relative difference: {worst:e}");
    });
}

#[test]
fn gpu_mesh_matches_the_oracle_across_scenes_and_resolutions() {
    for resolution in [16, 48, 96] {
        with_renderer(settings(11, 1, resolution, 1.0), 16, 16, |o| {
            for (seed, count) in [(11, 1), (12, 3), (13, 5), (14, 16)] {
                o.renderer.set_seed(seed).unwrap();
                o.renderer.set_sphere_count(count).unwrap();
                o.renderer.set_iso(1.0).unwrap();
                let triangles = assert_gpu_matches_oracle(
                    o,
                    &format!("seed {seed}, {count} spheres, {resolution} cells"),
                );
                println!("{count:>2} spheres, {resolution:>3} cells: {triangles} triangles match");
            }
        });
    }
}

#[test]
fn gpu_mesh_matches_the_oracle_while_spheres_move() {
    with_renderer(settings(21, 5, 40, 1.0), 16, 16, |o| {
        for step in 0..4 {
            o.renderer.update(0.37).unwrap();
            assert_gpu_matches_oracle(o, &format!("after step {step}"));
        }
    });
}

#[test]
fn gpu_mesh_matches_the_oracle_against_walls_overlaps_and_extreme_levels() {
    let touching_walls = Scene::from_spheres(touching_walls()).unwrap();
    let overlapping = Scene::from_spheres(overlapping()).unwrap();
    with_renderer(settings(1, 1, 32, 1.0), 16, 16, |o| {
        for (name, scene) in [("touching walls", &touching_walls), ("overlapping", &overlapping)] {
            for iso in [0.05, 0.3, 1.0, 4.0, 20.0] {
                o.renderer.set_scene(scene.clone());
                o.renderer.set_iso(iso).unwrap();
                assert_gpu_matches_oracle(o, &format!("{name}, iso {iso}"));
            }
        }
    });
}

#[test]
fn a_sphere_centred_on_a_grid_point_stays_finite() {
    // At 32 cells the origin is a grid point, where |p - c| = 0.
    let scene = Scene::from_spheres(vec![sphere([0.0, 0.0, 0.0], 0.4)]).unwrap();
    with_renderer(settings(1, 1, 32, 1.0), 16, 16, |o| {
        o.renderer.set_scene(scene);
        let mesh = pollster::block_on(o.renderer.extract_mesh());
        assert!(!mesh.triangles.is_empty());
        assert!(mesh.positions.iter().chain(&mesh.normals).all(|v| v.is_finite()));
        assert_gpu_matches_oracle(o, "sphere on a grid point");
    });
}

#[test]
fn seeded_random_scenes_match_the_oracle() {
    // Sphere count, iso level, resolution and animation time drawn from a fixed seed, so runs repeat.
    let mut rng = rand_pcg::Pcg32::seed_from_u64(0x6d65_7461);
    let mut with_surface = 0;
    with_renderer(settings(1, 1, 16, 1.0), 16, 16, |o| {
        for case in 0..40 {
            let count = rng.random_range(1..=64);
            let resolution = rng.random_range(8..=48);
            let iso = 10f32.powf(rng.random_range(-1.0..1.0));
            let seed = rng.random_range(0..1_000_000);
            let time = rng.random_range(0.0..20.0);
            o.renderer
                .set_settings(Settings { seed, sphere_count: count, resolution, iso, ..Settings::default() })
                .unwrap();
            o.renderer.update(time).unwrap();
            let what =
                format!("case {case}: seed {seed}, {count} spheres, {resolution} cells, iso {iso}, {time} s");
            with_surface += (assert_gpu_matches_oracle(o, &what) > 0) as u32;
        }
    });
    assert!(with_surface >= 30, "only {with_surface} of 40 scenes had a surface");
}
