//! The lab: the mesh measured against the exact surface (on the GPU, every frame, no readback in the
//! frame) and against itself at other resolutions, subtracting spheres, topology.

use crate::common;

use common::*;
use metaballs::extract::kernel::Terms;
use metaballs::extract::reference::{Construction, Grid, surface_distance};
use metaballs::scene::params::view::{Blend, ColorBy, Interpolation};
use metaballs::teach::error::{error_at, fitted_slope};
use metaballs::{Scene, Settings};

#[test]
fn the_gpu_measures_each_vertex_as_a_cpu_newton_projection_does() {
    let mut scenes = vec![("seeded", Scene::new(4, 12).unwrap().spheres().to_vec())];
    scenes.push(("dented", scenes::dented()));
    for (what, spheres) in scenes {
        for (interpolation, blend) in [
            (Interpolation::Linear, Blend::Sum),
            (Interpolation::Midpoint, Blend::Sum),
            (Interpolation::Linear, Blend::Max),
        ] {
            let mut settings = Settings { resolution: 40, iso: 1.0, ..Settings::default() };
            settings.view.color_by = ColorBy::Error;
            settings.view.interpolation = interpolation;
            settings.view.blend = blend;
            let terms = Terms::of(&settings.view);
            let (measures, mesh) = with_renderer(settings, 64, 64, |o| {
                o.renderer.set_scene(Scene::from_spheres(spheres.clone()).unwrap());
                o.render();
                pollster::block_on(o.renderer.flush_stats());
                let measures = o.renderer.measures().expect("measures with color_by=error");
                (measures, pollster::block_on(o.renderer.extract_mesh()))
            });
            let grid = Grid { cells_per_axis: 40 };
            let errors: Vec<f32> =
                mesh.positions.iter().map(|&p| surface_distance(&spheres, 1.0, terms, p, grid)).collect();
            let rms = (errors.iter().map(|e| (*e as f64).powi(2)).sum::<f64>() / errors.len() as f64).sqrt();
            let max = errors.iter().cloned().fold(0.0f32, f32::max);
            let what = format!("{what}, {interpolation:?}, {blend:?}");
            println!(
                "{what}: GPU RMS {:.5} max {:.5}, CPU RMS {rms:.5} max {max:.5} cells",
                measures.rms_error, measures.max_error
            );
            assert_eq!(measures.vertices as usize, mesh.positions.len(), "{what}: every vertex measured");
            assert!(
                (measures.max_error - max).abs() < 1e-4,
                "{what}: largest {} against {max}",
                measures.max_error
            );
            assert!(
                (measures.rms_error as f64 - rms).abs() < 1e-4,
                "{what}: RMS {} against {rms}",
                measures.rms_error
            );
            assert_eq!(
                measures.quality.iter().sum::<u32>() as usize,
                mesh.triangles.len(),
                "{what}: every triangle binned"
            );
            if interpolation == Interpolation::Midpoint {
                assert!(max > 0.1, "{what}: midpoints sit off the surface");
            }
        }
    }
}

#[test]
fn the_error_falls_at_second_order_with_linear_placement_and_first_with_midpoints() {
    let resolutions = [16, 24, 32, 48, 64];
    let scenes = [
        ("one sphere", vec![sphere([0.05, -0.02, 0.03], 0.5)]),
        // Inside the box: where the walls cut the solid, the caps sit up to a cell off the wall at any
        // resolution, a first-order error whatever the placement.
        (
            "three spheres",
            vec![
                sphere([-0.25, 0.0, 0.0], 0.3),
                sphere([0.2, 0.1, 0.0], 0.28),
                sphere([0.0, -0.2, 0.2], 0.25),
            ],
        ),
        ("dented", scenes::dented()),
    ];
    for (what, spheres) in &scenes {
        for (interpolation, low, high) in
            [(Interpolation::Linear, -2.6, -1.6), (Interpolation::Midpoint, -1.35, -0.7)]
        {
            let construction = Construction { interpolation, ..Construction::default() };
            let points: Vec<_> =
                resolutions.iter().map(|&n| error_at(spheres, 1.0, construction, n)).collect();
            let slope = |f: fn(&metaballs::teach::error::ErrorPoint) -> f64| {
                fitted_slope(&points.iter().map(|p| (p.cells_per_axis as f64, f(p))).collect::<Vec<_>>())
                    .unwrap()
            };
            let (rms, max) = (slope(|p| p.rms), slope(|p| p.max));
            let triangles = slope(|p| p.triangles as f64);
            println!(
                "{what}, {interpolation:?}: RMS slope {rms:.2}, max slope {max:.2}, triangles slope {triangles:.2}"
            );
            assert!((low..high).contains(&rms), "{what}, {interpolation:?}: RMS error slope {rms}");
            assert!(
                (1.8..2.2).contains(&triangles),
                "{what}: triangles grow as the surface's cells, slope {triangles}"
            );
        }
    }
}
