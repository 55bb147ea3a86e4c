//! Surface nets, the second extractor, chosen by `extractor=surface_nets` and run through the renderer
//! on the scenes every extractor meets: a closed surface, one vertex per crossed cell inside that
//! cell, the same blobs as marching cubes, and the volume marching cubes encloses.

use crate::common;

use common::scenes::oracle_scenes;
use common::*;
use glam::UVec3;
use metaballs::extract::reference::{self, Grid};
use metaballs::extract::tables::CORNER_OFFSETS;
use metaballs::scene::params::view::Method;
use metaballs::{Scene, Settings};

/// The cells whose corners lie on both sides of `iso`, counted on the oracle's samples.
fn crossed_cells(values: &[f32], iso: f32, grid: Grid) -> usize {
    let n = grid.cells_per_axis;
    let mut crossed = 0;
    for z in 0..n {
        for y in 0..n {
            for x in 0..n {
                let inside = CORNER_OFFSETS
                    .iter()
                    .filter(|o| values[grid.point_index(UVec3::new(x, y, z) + UVec3::from_array(**o))] > iso)
                    .count();
                crossed += (inside % 8 != 0) as usize;
            }
        }
    }
    crossed
}

#[test]
fn surface_nets_make_one_vertex_per_crossed_cell_and_closed_surfaces() {
    let scenes = oracle_scenes(30);
    with_renderer(settings(1, 1, 16, 1.0), 16, 16, |o| {
        let mut with_surface = 0;
        let mut counts = Vec::new();
        for scene in &scenes {
            let what = &scene.what;
            let iso = conditioned_iso(&scene.spheres, scene.iso, scene.resolution);
            let mut settings = Settings { resolution: scene.resolution, iso, ..Settings::default() };
            settings.view.interpolation = scene.construction.interpolation;
            settings.view.blend = scene.construction.blend;
            settings.view.case_table = scene.construction.case_table;
            settings.view.method = Method::SurfaceNets;
            o.renderer.set_settings(settings).unwrap();
            o.renderer.set_scene(Scene::from_spheres(scene.spheres.clone()).unwrap());
            let nets = pollster::block_on(o.renderer.extract_mesh());
            assert_eq!(o.renderer.mesh_source(), "surface-nets", "{what}");
            let grid = Grid { cells_per_axis: scene.resolution };
            let values = reference::sample_blended_field(&scene.spheres, grid, scene.construction.blend);
            assert_eq!(nets.positions.len(), crossed_cells(&values, iso, grid), "{what}: vertices");
            // Each vertex is a mean of crossings on its cell's edges, so it lies in the cell's box.
            let cell = grid.cell_size();
            for p in &nets.positions {
                let rel = (*p - grid.point(UVec3::ZERO)) / cell;
                assert!(rel.min_element() >= -1e-3 && rel.max_element() <= scene.resolution as f32 + 1e-3);
            }
            let shape = nets.shape();
            assert!(shape.closed, "{what}: open surface nets mesh {shape:?}");
            let oracle = reference::extract_with(&scene.spheres, iso, grid, scene.construction);
            let cubes = oracle.weld_by_edge();
            // One vertex per cell joins the sheets an ambiguous cell separates in marching cubes, so
            // surface nets may join blobs but never split one.
            assert!(shape.components <= cubes.shape().components, "{what}: blobs");
            if oracle.triangle_count() > 0 {
                with_surface += 1;
                let (v_nets, v_cubes) = (nets.enclosed_volume(), cubes.enclosed_volume());
                // Both approximate the same solid to within a few cells' worth of its surface.
                assert!(v_nets > 0.0, "{what}: volume {v_nets}");
                let area_cells = cubes.positions.len() as f64 * (cell as f64).powi(3);
                assert!((v_nets - v_cubes).abs() <= area_cells, "{what}: volume {v_nets} against {v_cubes}");
                // Two triangles per crossed edge, where marching cubes puts one vertex.
                assert_eq!(
                    nets.triangles.len(),
                    2 * cubes.positions.len(),
                    "{what}: a quad per crossed edge"
                );
                counts.push((
                    nets.positions.len(),
                    nets.triangles.len(),
                    cubes.positions.len(),
                    oracle.triangle_count(),
                ));
            }
        }
        let total = counts.iter().fold([0; 4], |t, c| [t[0] + c.0, t[1] + c.1, t[2] + c.2, t[3] + c.3]);
        println!(
            "surface nets: {} vertices, {} triangles; marching cubes: {} vertices, {} triangles",
            total[0], total[1], total[2], total[3]
        );
        assert!(with_surface >= 40, "only {with_surface} scenes had a surface");
    });
}

#[test]
fn surface_nets_follow_the_setting_and_leave_level_of_detail_to_marching_cubes() {
    with_renderer(settings(3, 4, 32, 1.0), 32, 32, |o| {
        let mut settings = *o.renderer.settings();
        settings.view.method = Method::SurfaceNets;
        o.renderer.set_settings(settings).unwrap();
        o.render();
        assert_eq!(o.renderer.mesh_source(), "surface-nets");
        settings.view.lod = true;
        o.renderer.set_settings(settings).unwrap();
        o.render();
        assert!(o.renderer.mesh_capabilities().lod, "lod=on meshes with transition cells");
        settings.view.lod = false;
        settings.view.method = Method::MarchingCubes;
        o.renderer.set_settings(settings).unwrap();
        o.render();
        assert_ne!(o.renderer.mesh_source(), "surface-nets");
    });
}
