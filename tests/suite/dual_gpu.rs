//! The dual methods in compute shaders (`shaders/extract/dual.wgsl`) against their CPU meshers
//! (`core/src/extract/cpu/dual.rs`, the methods' reference) on the scenes every extractor meets: the
//! same vertex in each crossed cell, the same quads facing the same way, split along the same diagonal
//! but where the two are as long to rounding. The QEF's marks are compared as the rank view draws them
//! (`dual::dual_contourings_views_show_…`).

use crate::common;

use common::scenes::oracle_scenes;
use common::*;
use metaballs::extract::cpu::{DualContouringMesher, SurfaceNetsMesher};
use metaballs::extract::mesh::IndexedMesh;
use metaballs::extract::reference::Grid;
use metaballs::scene::params::view::{MeshOn, Method};
use metaballs::{Scene, Settings};
use std::collections::HashSet;

/// For each vertex of `ours`, the vertex of `theirs` nearest it, and how far it lies.
fn nearest(ours: &IndexedMesh, theirs: &IndexedMesh) -> Vec<(usize, f32)> {
    ours.positions
        .iter()
        .map(|p| {
            theirs
                .positions
                .iter()
                .enumerate()
                .map(|(k, q)| (k, p.distance(*q)))
                .fold((usize::MAX, f32::INFINITY), |a, b| if b.1 < a.1 { b } else { a })
        })
        .collect()
}

/// Each quad of a dual mesh (two triangles sharing the diagonal the split chose) as its four corners,
/// turned so that the least comes first: the same whichever diagonal split it, and only if it faces the
/// same way.
fn quads(triangles: &[[u32; 3]]) -> Vec<[u32; 4]> {
    let mut quads: Vec<[u32; 4]> = triangles
        .chunks_exact(2)
        .map(|pair| {
            let [a, b, c] = pair[0];
            let [d, e, f] = pair[1];
            // (a, b, c) + (a, c, d) or (a, b, d) + (b, c, d).
            let quad = if d == a { [a, b, c, f] } else { [a, b, e, f] };
            let first = (0..4).min_by_key(|&i| quad[i]).unwrap();
            std::array::from_fn(|i| quad[(first + i) % 4])
        })
        .collect();
    quads.sort_unstable();
    quads
}

/// A triangle turned so that its least corner comes first (the same triangle, facing the same way).
fn turned(t: [u32; 3]) -> [u32; 3] {
    let first = (0..3).min_by_key(|&i| t[i]).unwrap();
    std::array::from_fn(|i| t[(first + i) % 3])
}

#[test]
fn the_dual_methods_on_the_gpu_equal_their_cpu_meshers() {
    let scenes = oracle_scenes(40);
    with_renderer(settings(1, 1, 16, 1.0), 16, 16, |o| {
        for (method, name) in
            [(Method::SurfaceNets, "gpu-surface-nets"), (Method::DualContouring, "gpu-dual-contouring")]
        {
            let (mut with_surface, mut largest, mut ties) = (0, 0.0f32, 0);
            for scene in &scenes {
                let what = format!("{name}: {}", scene.what);
                let terms = scene.construction.terms;
                let iso = conditioned_level(&scene.spheres, scene.iso, scene.resolution, terms);
                let mut settings = Settings { resolution: scene.resolution, iso, ..Settings::default() };
                settings.view.interpolation = scene.construction.interpolation;
                terms.set_in(&mut settings.view);
                settings.view.method = method;
                settings.view.mesh_on = MeshOn::Gpu;
                o.renderer.set_settings(settings).unwrap();
                o.renderer.set_scene(Scene::from_spheres(scene.spheres.clone()).unwrap());
                let ours = pollster::block_on(o.renderer.extract_mesh());
                assert_eq!(o.renderer.mesh_source(), name, "{what}: another extractor ran");
                let grid = Grid { cells_per_axis: scene.resolution };
                let theirs = if method == Method::SurfaceNets {
                    let mut mesher = SurfaceNetsMesher::default();
                    mesher.mesh(&scene.spheres, iso, grid, scene.construction);
                    mesher.to_indexed()
                } else {
                    let mut mesher = DualContouringMesher::default();
                    mesher.mesh(&scene.spheres, iso, grid, scene.construction);
                    mesher.to_indexed()
                };
                assert_eq!(ours.positions.len(), theirs.positions.len(), "{what}: vertices");
                assert_eq!(ours.triangles.len(), theirs.triangles.len(), "{what}: triangles");
                with_surface += !theirs.triangles.is_empty() as u32;
                let cell = grid.cell_size();
                let matched = nearest(&ours, &theirs);
                for (i, &(k, d)) in matched.iter().enumerate() {
                    largest = largest.max(d / cell);
                    assert!(d <= 2e-3 * cell, "{what}: vertex {i} {} cells from the CPU's", d / cell);
                    let (n, m) = (ours.normals[i], theirs.normals[k]);
                    assert!(n.dot(m) > 0.9999, "{what}: vertex {i}'s normal {n} against {m}");
                }
                let mut seen = vec![false; theirs.positions.len()];
                for &(k, _) in &matched {
                    assert!(
                        !std::mem::replace(&mut seen[k], true),
                        "{what}: two vertices on one of the CPU's"
                    );
                }
                let apart = matched.iter().fold(0.0f32, |m, &(_, d)| m.max(d));
                let mapped: Vec<[u32; 3]> =
                    ours.triangles.iter().map(|t| t.map(|i| matched[i as usize].0 as u32)).collect();
                assert_eq!(quads(&mapped), quads(&theirs.triangles), "{what}: the quads differ");
                // Each quad split along the CPU's diagonal, unless its diagonals are as long to rounding.
                let split: HashSet<[u32; 3]> = theirs.triangles.iter().map(|t| turned(*t)).collect();
                for pair in mapped.chunks_exact(2) {
                    if !pair.iter().all(|t| split.contains(&turned(*t))) {
                        let [a, b, c, d] = quads(pair)[0].map(|i| theirs.positions[i as usize]);
                        // With each corner within δ of the CPU's, |ac|² − |bd|² moves by at most
                        // 4δ (|ac| + |bd|) + 8δ².
                        let (ac, bd) = (a.distance(c), b.distance(d));
                        let bound = 4.0 * apart * (ac + bd) + 8.0 * apart * apart + 1e-6 * cell * cell;
                        assert!((ac * ac - bd * bd).abs() <= bound, "{what}: a quad split the other way");
                        ties += 1;
                    }
                }
            }
            println!(
                "{name}: {with_surface} scenes with a surface; vertices at most {largest:.2e} cells apart; \
                 {ties} quads split the other way at a tie"
            );
            assert!(with_surface >= 30, "{name}: only {with_surface} scenes had a surface");
        }
    });
}

#[test]
fn dual_contouring_on_the_gpu_keeps_the_crease_sharp() {
    // The union of two spheres at 32³, as `dual::dual_contouring_keeps_the_crease_…` meshes it on the CPU.
    let spheres = crate::dual::crease_spheres();
    let crease = crate::dual::Crease::of(
        (spheres[0].center, spheres[0].radius),
        (spheres[1].center, spheres[1].radius),
    );
    with_renderer(settings(1, 2, 32, 1.0), 16, 16, |o| {
        o.renderer.set_scene(Scene::from_spheres(spheres.to_vec()).unwrap());
        let mut errors = Vec::new();
        for method in ["marching_cubes", "dual_contouring"] {
            let settings = ["blend=max", &format!("method={method}"), "mesh-on=gpu"]
                .iter()
                .filter_map(|pair| pair.split_once('='))
                .fold(*o.renderer.settings(), |s, (key, value)| s.with_parameter(key, value).unwrap());
            o.renderer.set_settings(settings).unwrap();
            let mesh = pollster::block_on(o.renderer.extract_mesh());
            let error = crate::dual::crease_error(&mesh, &crease, Grid { cells_per_axis: 32 }.cell_size());
            println!("{}: largest distance along the crease {error:.4} cells", o.renderer.mesh_source());
            assert!(mesh.shape().closed);
            errors.push(error);
        }
        assert!(errors[1] <= 0.1 && errors[1] <= 0.5 * errors[0], "{errors:?}");
    });
}
