//! Meshing in slabs, as the page's pool of mesher workers does: a job cut across z into slabs of
//! whole blocks, each meshed on its own from the packed job (`Meshers::mesh_slab`), and the pieces
//! joined by the edges their vertices lie on, is the mesh one mesher makes of the whole grid — vertex
//! for vertex and triangle for triangle, seams included — on the scenes every extractor is held to,
//! cut into two, three and four slabs. (The page joins them in `www/lib/engine/slabs.js`, held to
//! the same by `tests/e2e/slabs.test.js`.)

use crate::common;

use common::scenes::{
    OracleScene, on_grid_point, overlapping, random_scenes, subtractive_scenes, touching_walls,
};
use metaballs::Scene;
use metaballs::extract::cpu::elsewhere::{Meshers, pack};
use metaballs::extract::extractor::{GivenMesh, Job};
use metaballs::extract::mesh::IndexedMesh;
use metaballs::extract::reference::{Construction, Grid};
use metaballs::scene::params::view::Method;
use std::collections::HashMap;

/// Up to `pieces` slabs of whole blocks (4 cells) covering a grid of `n` cells per axis.
fn slab_ranges(n: u32, pieces: u32) -> Vec<(u32, u32)> {
    let blocks = n.div_ceil(4);
    let pieces = pieces.min(blocks);
    let at = |k: u32| (blocks * k / pieces * 4).min(n);
    (0..pieces).map(|k| (at(k), at(k + 1))).collect()
}

/// The mesh of `packed` from `pieces` slabs, each meshed by a mesher of its own, joined by edge: a
/// vertex on an edge a slab before it made a vertex on is that vertex.
fn in_slabs(packed: &[f32], pieces: u32) -> GivenMesh {
    let mut joined = GivenMesh { job: packed.to_vec(), ..GivenMesh::default() };
    let mut made: HashMap<u32, u32> = HashMap::new();
    for (from, to) in slab_ranges(packed[2] as u32, pieces) {
        let mut meshers = Meshers::default();
        let slab = meshers.mesh_slab(packed, from, to).unwrap();
        let remap: Vec<u32> = slab
            .keys
            .iter()
            .enumerate()
            .map(|(i, &key)| {
                *made.entry(key).or_insert_with(|| {
                    joined.vertices.extend_from_slice(&slab.vertices[6 * i..6 * i + 6]);
                    (joined.vertices.len() / 6 - 1) as u32
                })
            })
            .collect();
        joined.indices.extend(slab.indices.iter().map(|&i| remap[i as usize]));
        joined.counts = [joined.counts[0] + slab.counts[0], joined.counts[1] + slab.counts[1]];
    }
    joined
}

fn area(mesh: &IndexedMesh) -> f64 {
    mesh.triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize].as_dvec3());
            (b - a).cross(c - a).length() / 2.0
        })
        .sum()
}

fn check(scene: &OracleScene) -> bool {
    let job = scene.job();
    let packed = pack(Method::MarchingCubes, &job);
    let whole = Meshers::default().mesh(&packed).unwrap();
    let mesh = IndexedMesh::from_interleaved(&whole.vertices, &whole.indices);
    for pieces in 2..=4 {
        let what = format!("{} in {pieces} slabs", scene.what);
        let joined = in_slabs(&packed, pieces);
        let ours = IndexedMesh::from_interleaved(&joined.vertices, &joined.indices);
        assert_eq!(ours.triangles.len(), mesh.triangles.len(), "{what}: triangle counts");
        assert_eq!(ours.shape().closed, mesh.shape().closed, "{what}: closed");
        assert_eq!(
            ours.to_soup().weld_by_position().positions.len(),
            mesh.to_soup().weld_by_position().positions.len(),
            "{what}: vertices welded by position"
        );
        assert!((area(&ours) - area(&mesh)).abs() <= 1e-6 * area(&mesh).max(1.0), "{what}: areas");
        let (v, w) = (ours.enclosed_volume(), mesh.enclosed_volume());
        assert!((v - w).abs() <= 1e-6 * w.abs().max(1.0), "{what}: volumes {v} and {w}");
        // Exactly the whole grid's mesh: the seams' vertices shared, none made twice.
        assert_eq!(joined, whole, "{what}");
    }
    !whole.indices.is_empty()
}

#[test]
fn meshes_joined_from_slabs_are_the_whole_grids_mesh() {
    let mut scenes = random_scenes(40);
    scenes.extend(subtractive_scenes(12));
    for (what, spheres) in
        [("walls", touching_walls()), ("overlapping", overlapping()), ("grid point", on_grid_point())]
    {
        for resolution in [13, 16, 32] {
            scenes.push(OracleScene {
                what: format!("{what} at {resolution}³"),
                spheres: spheres.clone(),
                iso: 1.0,
                resolution,
                construction: Construction::default(),
            });
        }
    }
    let large = Scene::new(7, 16).unwrap();
    scenes.push(OracleScene {
        what: "16 spheres at 128³".into(),
        spheres: large.spheres().to_vec(),
        iso: 1.0,
        resolution: 128,
        construction: Construction::default(),
    });
    let with_surface = scenes.iter().filter(|s| check(s)).count();
    assert!(
        with_surface >= scenes.len() * 3 / 4,
        "only {with_surface} of {} scenes had a surface",
        scenes.len()
    );
}

#[test]
fn slabs_that_do_not_fit_are_refused_with_what_is_wrong() {
    let job = Job {
        spheres: &touching_walls(),
        iso: 1.0,
        grid: Grid { cells_per_axis: 16 },
        construction: Construction::default(),
        lod: None,
        teaching: false,
    };
    let mut meshers = Meshers::default();
    let packed = pack(Method::MarchingCubes, &job);
    assert!(meshers.mesh_slab(&packed, 8, 4).err().unwrap().contains("not within"));
    assert!(meshers.mesh_slab(&packed, 0, 17).err().unwrap().contains("not within"));
    let nets = pack(Method::SurfaceNets, &job);
    assert!(meshers.mesh_slab(&nets, 0, 8).err().unwrap().contains("only marching cubes"));
}
