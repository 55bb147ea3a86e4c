//! Every extractor in `extract::EXTRACTORS`, run through the renderer, against the CPU oracle on the
//! scenes the GPU and CPU tests use. A new marching-cubes or marching-tetrahedra extractor of the
//! uniform grid added to that list is held to the same scenes (and its method's oracle) without a line
//! here; level-of-detail extractors, whose cells follow
//! the camera, are held to the oracle in their finest blocks and to each other in `tests/suite/lod.rs`,
//! and surface nets, another method, to its own properties in `tests/suite/surface_nets.rs`.

use crate::common;

use common::scenes::oracle_scenes;
use common::*;
use metaballs::extract::reference::{self, Grid};
use metaballs::extract::tetra::extract_tetrahedra;
use metaballs::extract::{EXTRACTORS, compile_all};
use metaballs::scene::params::view::{Method, Split};
use metaballs::{Scene, Settings};

#[test]
fn the_renderer_holds_every_extractor_the_list_builds_on_this_device() {
    let (_, device, _) = device();
    let names: Vec<&str> = compile_all(&device).iter().map(|e| e.name()).collect();
    // The adapter at hand has compute shaders, so every extractor can run on it.
    assert_eq!(names.len(), EXTRACTORS.len(), "extractors built here: {names:?}");
    let mut unique = names.clone();
    unique.sort();
    unique.dedup();
    assert_eq!(unique.len(), names.len(), "two extractors share a name: {names:?}");
    with_renderer(settings(1, 3, 16, 1.0), 16, 16, |o| {
        assert_eq!(o.renderer.extractor_names(), names);
        let error = o.renderer.pin_extractor(Some("fpga")).unwrap_err().to_string();
        assert!(error.contains("fpga") && names.iter().all(|n| error.contains(n)), "{error}");
    });
}

#[test]
fn every_extractor_in_the_list_matches_the_oracle() {
    let scenes = oracle_scenes(40);
    let (_, device, _) = device();
    let marching = [Method::MarchingCubes, Method::MarchingTetrahedra];
    let uniform: Vec<(&str, Method)> = compile_all(&device)
        .iter()
        .map(|e| (e.capabilities(), e.name()))
        .filter(|(c, _)| !c.lod && marching.contains(&c.method))
        .map(|(c, name)| (name, c.method))
        .collect();
    assert!(uniform.len() >= 4, "{uniform:?}");
    with_renderer(settings(1, 1, 16, 1.0), 16, 16, |o| {
        for (name, method) in uniform {
            o.renderer.pin_extractor(Some(name)).unwrap();
            let mut with_surface = 0;
            for (k, scene) in scenes.iter().enumerate() {
                // Marching tetrahedra cuts the cells one way, then the other.
                let construction = reference::Construction { split: Split::ALL[k % 2], ..scene.construction };
                let what = format!("{name}: {} ({:?})", scene.what, construction.split);
                let iso =
                    conditioned_level(&scene.spheres, scene.iso, scene.resolution, scene.construction.terms);
                let mut settings = Settings { resolution: scene.resolution, iso, ..Settings::default() };
                settings.view.interpolation = scene.construction.interpolation;
                scene.construction.terms.set_in(&mut settings.view);
                settings.view.case_table = scene.construction.case_table;
                settings.view.method = method;
                settings.view.split = construction.split;
                o.renderer.set_settings(settings).unwrap();
                o.renderer.set_scene(Scene::from_spheres(scene.spheres.clone()).unwrap());
                let ours = pollster::block_on(o.renderer.extract_mesh());
                assert_eq!(o.renderer.mesh_source(), name, "{what}: another extractor ran");
                let grid = Grid { cells_per_axis: scene.resolution };
                let oracle = match method {
                    Method::MarchingTetrahedra => extract_tetrahedra(&scene.spheres, iso, grid, construction),
                    _ => reference::extract_with(&scene.spheres, iso, grid, construction),
                };
                assert_eq!(ours.triangles.len(), oracle.triangle_count(), "{what}: triangle counts differ");
                let tolerance = 1e-4 * grid.cell_size();
                if let Err(e) =
                    ours.to_soup().matches(&oracle, tolerance, normal_tolerance(scene.construction.terms))
                {
                    panic!("{what}: {e}");
                }
                let welded = oracle.weld_by_edge();
                assert_eq!(
                    ours.positions.len(),
                    welded.positions.len(),
                    "{what}: one vertex per crossed edge (or diagonal)"
                );
                with_surface += (oracle.triangle_count() > 0) as u32;
            }
            println!("{name}: {} scenes equal the oracle, {with_surface} with a surface", scenes.len());
            assert!(with_surface >= 60, "{name}: only {with_surface} scenes had a surface");
        }
    });
}
