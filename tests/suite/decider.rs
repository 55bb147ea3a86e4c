//! Ambiguous faces joined by the asymptotic decider (`table=decider`): the mesh meets every cell
//! face as the bilinear interpolant of its four samples does, closed and oriented, and the GPU's equals
//! the oracle's triangle for triangle.

use crate::common;

use common::*;
use metaballs::extract::mesh::{IndexedMesh, Mesh};
use metaballs::extract::reference::{self, Construction, Grid};
use metaballs::scene::params::view::CaseTable;
use metaballs::{Scene, Settings};

pub(crate) fn oracle(scene: &Scene, iso: f32, resolution: u32, case_table: CaseTable) -> Mesh {
    let construction = Construction { case_table, ..Construction::default() };
    reference::extract_with(scene.spheres(), iso, Grid { cells_per_axis: resolution }, construction)
}

pub(crate) fn gpu(scene: &Scene, iso: f32, resolution: u32, case_table: CaseTable) -> IndexedMesh {
    let mut settings =
        Settings { resolution, iso, ..Settings::default() }.with_parameter("mesher", "gpu").unwrap();
    settings.view.case_table = case_table;
    with_renderer(settings, 16, 16, |o| {
        o.renderer.set_scene(scene.clone());
        pollster::block_on(o.renderer.extract_mesh())
    })
}

pub(crate) fn assert_closed(mesh: &IndexedMesh, what: &str) {
    let t = mesh.topology();
    assert_eq!(t.open_or_nonmanifold_edges, 0, "{what}: open or non-manifold edges");
    assert_eq!(t.misoriented_edges, 0, "{what}: inconsistent winding");
    assert!(t.component_euler.iter().all(|&x| x <= 2 && x % 2 == 0), "{what}: {:?}", t.component_euler);
}

/// Seed 11, 64 spheres, 128³, iso 1.5: scikit-image's classic marching cubes gives 54,404 triangles in
/// 58 blobs, as our classic table does; its Lewiner method (MC33, the interpolant's topology) gives
/// 54,408 triangles in 57 blobs, two of the classic blobs joined across a face. The decider finds that
/// face and makes the same mesh.
#[test]
fn the_decider_joins_the_blobs_the_interpolant_joins_where_the_classic_table_splits_them() {
    let scene = Scene::new(11, 64).unwrap();
    let classic = oracle(&scene, 1.5, 128, CaseTable::Classic).weld_by_edge();
    let decided = oracle(&scene, 1.5, 128, CaseTable::Decider);
    let gpu = gpu(&scene, 1.5, 128, CaseTable::Decider);
    let tolerance = 1e-4 * Grid { cells_per_axis: 128 }.cell_size();
    gpu.to_soup().matches(&decided, tolerance, 0.01f32.to_radians()).unwrap_or_else(|e| panic!("GPU: {e}"));
    let decided = decided.weld_by_edge();
    for (mesh, what, triangles, blobs) in
        [(&classic, "classic", 54_404, 58), (&decided, "decider", 54_408, 57)]
    {
        assert_closed(mesh, what);
        assert_eq!(mesh.triangles.len(), triangles, "{what}: triangles");
        assert_eq!(mesh.topology().component_euler.len(), blobs, "{what}: blobs");
    }
}

/// On seeded scenes of 16 and 64 spheres at two iso levels, the decider's meshes are closed, oriented
/// surfaces welded by position alone, and the GPU's equal the oracle's; the two tables differ on most
/// of them.
#[test]
fn decider_meshes_are_closed_by_position_and_the_gpu_equals_the_oracle() {
    let mut differing = 0;
    let mut scenes = 0;
    for seed in 1..=6 {
        for count in [16, 64] {
            for iso in [1.0, 1.5] {
                let scene = Scene::new(seed, count).unwrap();
                let what = format!("seed {seed}, {count} spheres, iso {iso}");
                let decided = oracle(&scene, iso, 40, CaseTable::Decider);
                if decided.triangle_count() == 0 {
                    continue;
                }
                scenes += 1;
                assert_closed(&decided.weld_by_position(), &what);
                let classic = oracle(&scene, iso, 40, CaseTable::Classic);
                differing += (classic.positions != decided.positions) as u32;
                let gpu = gpu(&scene, iso, 40, CaseTable::Decider);
                let tolerance = 1e-4 * Grid { cells_per_axis: 40 }.cell_size();
                gpu.to_soup()
                    .matches(&decided, tolerance, 0.01f32.to_radians())
                    .unwrap_or_else(|e| panic!("{what}: {e}"));
            }
        }
    }
    assert!(scenes >= 20, "{scenes} scenes with a surface");
    assert!(differing * 4 >= scenes, "the tables differ on only {differing} of {scenes} scenes");
}
