//! Marching tetrahedra, chosen by `method=` and cut by `split=`: on the scenes every extractor meets,
//! its mesh is closed and manifold and has the topology of the piecewise-linear interpolant of its
//! tetrahedra (which has no ambiguous case), counted on the tetrahedra themselves; the two splits give
//! different surfaces of the same field; and the GPU's and the CPU's meshes equal the oracle
//! (`tests/suite/extractors.rs`).

use crate::common;

use common::scenes::oracle_scenes;
use common::*;
use glam::UVec3;
use metaballs::extract::cpu::TetraMesher;
use metaballs::extract::kernel::Terms;
use metaballs::extract::reference::{Construction, Grid, sample_blended_field, surface_distance};
use metaballs::extract::tables::CORNER_OFFSETS;
use metaballs::extract::tetra::tetrahedra;
use metaballs::scene::params::view::{Method, Split};
use std::collections::HashSet;

/// What the interpolant's solid {f > iso} has, counted on the tetrahedra: its Euler characteristic
/// (that of the simplices whose corners all lie inside, which the solid retracts onto), and how many
/// pieces the inside and the outside corners each make, joined along the tetrahedra's edges.
struct Interpolant {
    euler: i64,
    inside_pieces: usize,
    outside_pieces: usize,
}

fn interpolant(values: &[f32], iso: f32, grid: Grid, split: Split) -> Interpolant {
    let n = grid.cells_per_axis;
    let mut simplices: [HashSet<Vec<usize>>; 4] = Default::default();
    let mut edges = HashSet::new();
    for z in 0..n {
        for y in 0..n {
            for x in 0..n {
                let point =
                    |c: usize| grid.point_index(UVec3::new(x, y, z) + UVec3::from_array(CORNER_OFFSETS[c]));
                for t in tetrahedra(split, [x, y, z]) {
                    let corners = t.map(point);
                    for mask in 1..16usize {
                        let mut face: Vec<usize> =
                            (0..4).filter(|i| mask >> i & 1 == 1).map(|i| corners[i]).collect();
                        face.sort();
                        if face.len() == 2 {
                            edges.insert((face[0], face[1]));
                        }
                        if face.iter().all(|&p| values[p] > iso) {
                            simplices[face.len() - 1].insert(face);
                        }
                    }
                }
            }
        }
    }
    let euler = simplices[0].len() as i64 - simplices[1].len() as i64 + simplices[2].len() as i64
        - simplices[3].len() as i64;
    // Pieces of each side, by union-find along the edges whose ends lie on that side.
    let mut parent: Vec<usize> = (0..values.len()).collect();
    fn root(parent: &mut [usize], mut p: usize) -> usize {
        while parent[p] != p {
            parent[p] = parent[parent[p]];
            p = parent[p];
        }
        p
    }
    for &(a, b) in &edges {
        if (values[a] > iso) == (values[b] > iso) {
            let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
            parent[ra] = rb;
        }
    }
    let (mut inside_pieces, mut outside_pieces) = (0, 0);
    for (p, value) in values.iter().enumerate() {
        if root(&mut parent, p) == p {
            if *value > iso { inside_pieces += 1 } else { outside_pieces += 1 }
        }
    }
    Interpolant { euler, inside_pieces, outside_pieces }
}

#[test]
fn the_mesh_has_the_topology_of_the_interpolant_of_its_tetrahedra_under_either_split() {
    let mut mesher = TetraMesher::default();
    let mut with_surface = 0;
    let mut with_holes_or_pieces = 0;
    for (k, scene) in oracle_scenes(12).iter().enumerate() {
        if scene.resolution > 32 {
            continue;
        }
        for split in [Split::Six, Split::Five] {
            let construction = Construction { split, ..scene.construction };
            let grid = Grid { cells_per_axis: scene.resolution };
            let what = format!("scene {k}, {}, {split:?}", scene.what);
            mesher.mesh(&scene.spheres, scene.iso, grid, construction);
            let mesh = mesher.to_indexed().to_soup().weld_by_position();
            let shape = mesh.shape();
            assert!(shape.closed && shape.manifold, "{what}: {shape:?}");
            let values = sample_blended_field(&scene.spheres, grid, construction.terms);
            let solid = interpolant(&values, scene.iso, grid, split);
            let euler: i64 = mesh.topology().component_euler.iter().sum();
            // The surface bounds the solid: twice its Euler characteristic, and one piece of surface
            // between each inside piece and the outside piece around it (the pieces nest as a tree).
            assert_eq!(euler, 2 * solid.euler, "{what}");
            if !mesh.triangles.is_empty() {
                assert_eq!(
                    shape.components as usize,
                    solid.inside_pieces + solid.outside_pieces - 1,
                    "{what}: {} pieces inside, {} outside",
                    solid.inside_pieces,
                    solid.outside_pieces
                );
                with_surface += 1;
                with_holes_or_pieces += (shape.components > 1 || shape.genus > 0) as u32;
            }
        }
    }
    println!("{with_surface} surfaces, {with_holes_or_pieces} with several pieces or holes");
    assert!(with_surface >= 80 && with_holes_or_pieces >= 10, "{with_surface}, {with_holes_or_pieces}");
}

/// From the panel's settings on the renderer: each split meshes the same field into a different closed
/// surface, with more triangles than marching cubes' (each cell's are cut by its tetrahedra) and
/// thinner ones on the whole, enclosing nearly the same volume, its vertices within twice marching
/// cubes' distance of the exact surface (those on diagonals interpolate over a longer segment).
#[test]
fn each_split_makes_its_own_closed_surface_with_more_triangles_than_marching_cubes() {
    with_renderer(settings(4, 6, 24, 1.0), 16, 16, |o| {
        let mut meshes = Vec::new();
        for (method, split) in [
            (Method::MarchingCubes, Split::Six),
            (Method::MarchingTetrahedra, Split::Six),
            (Method::MarchingTetrahedra, Split::Five),
        ] {
            let mut settings = settings(4, 6, 24, 1.0);
            settings.view.method = method;
            settings.view.split = split;
            o.renderer.set_settings(settings).unwrap();
            let mesh = pollster::block_on(o.renderer.extract_mesh());
            let shape = mesh.to_soup().weld_by_position().shape();
            assert!(shape.closed && shape.manifold, "{method:?}, {split:?}: {shape:?}");
            let grid = Grid { cells_per_axis: 24 };
            let spheres = o.renderer.scene().spheres().to_vec();
            let distance = |p: &glam::Vec3| surface_distance(&spheres, 1.0, Terms::default(), *p, grid);
            let distances: Vec<f32> = mesh.positions.iter().map(distance).collect();
            let rms = (distances.iter().map(|d| d * d).sum::<f32>() / distances.len() as f32).sqrt();
            let largest = distances.iter().fold(0f32, |m, d| m.max(d.abs()));
            // Shape quality 4√3·A / (a² + b² + c²): 1 equilateral, 0 a sliver.
            let quality = |t: &&[u32; 3]| {
                let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
                let area = (b - a).cross(c - a).length() / 2.0;
                let squares = (b - a).length_squared() + (c - b).length_squared() + (a - c).length_squared();
                4.0 * 3f32.sqrt() * area / squares
            };
            let slivers = mesh.triangles.iter().filter(|t| quality(t) < 0.1).count() as f32;
            let slivers = slivers / mesh.triangles.len() as f32;
            let mean = mesh.triangles.iter().map(|t| quality(&t)).sum::<f32>() / mesh.triangles.len() as f32;
            println!(
                "{method:?}, {split:?} at 24³: {} triangles, {} vertices, distance to the exact surface \
                 RMS {rms:.4} / largest {largest:.4} cells, mean quality {mean:.3}, {:.1}% slivers (quality under 0.1)",
                mesh.triangles.len(),
                mesh.positions.len(),
                100.0 * slivers
            );
            meshes.push((mesh.triangles.len(), mesh.enclosed_volume(), mean, rms));
        }
        let [
            (cubes, cubes_volume, cubes_quality, cubes_rms),
            (six, six_volume, six_quality, six_rms),
            (five, five_volume, five_quality, five_rms),
        ] = meshes[..]
        else {
            unreachable!()
        };
        assert!(six_quality < cubes_quality && five_quality < cubes_quality, "thinner triangles");
        assert!(six > cubes && five > cubes, "{cubes} {six} {five}");
        assert_ne!(six, five, "the splits give the same triangles");
        for (volume, rms) in [(six_volume, six_rms), (five_volume, five_rms)] {
            assert!((volume / cubes_volume - 1.0).abs() < 0.05, "{volume} against {cubes_volume}");
            assert!(rms < 2.0 * cubes_rms, "RMS distance {rms} against {cubes_rms} cells");
        }
    });
}
