//! MC33 (`table=mc33`): the faces as the asymptotic decider joins them and a tunnel through a cell
//! where its trilinear interpolant joins two of its loops inside it (`extract::interior`). The meshes
//! are closed, oriented surfaces welded by position alone; the GPU's equal the oracle's triangle for
//! triangle; and where the interior joins loops, the blob count and genus follow the interpolant.

use crate::common;

use common::*;
use metaballs::extract::mesh::{IndexedMesh, Mesh};
use metaballs::extract::reference::{self, Construction, Grid};
use metaballs::scene::params::view::CaseTable;
use metaballs::{Scene, Settings};

fn oracle(scene: &Scene, iso: f32, resolution: u32, case_table: CaseTable) -> Mesh {
    let construction = Construction { case_table, ..Construction::default() };
    reference::extract_with(scene.spheres(), iso, Grid { cells_per_axis: resolution }, construction)
}

fn gpu(scene: &Scene, iso: f32, resolution: u32) -> IndexedMesh {
    let settings = Settings { resolution, iso, ..Settings::default() }
        .with_parameter("mesher", "gpu")
        .and_then(|s| s.with_parameter("table", "mc33"))
        .unwrap();
    with_renderer(settings, 16, 16, |o| {
        o.renderer.set_scene(scene.clone());
        pollster::block_on(o.renderer.extract_mesh())
    })
}

fn assert_closed(mesh: &IndexedMesh, what: &str) {
    let t = mesh.topology();
    assert_eq!(t.open_or_nonmanifold_edges, 0, "{what}: open or non-manifold edges");
    assert_eq!(t.misoriented_edges, 0, "{what}: inconsistent winding");
}

/// On seeded scenes of 16 and 64 spheres at iso levels near merges and coarse grids, MC33's meshes
/// are closed and oriented by position; the GPU's equal the oracle's; and the scenes hold tunnels (a
/// band of four more triangles than the decider's two fills).
#[test]
fn mc33_meshes_are_closed_by_position_and_the_gpu_equals_the_oracle() {
    let (mut scenes, mut tunnels) = (0, 0);
    for seed in 1..=6 {
        for count in [16, 64] {
            for (iso, resolution) in [(1.0, 24), (1.5, 40), (2.5, 17)] {
                let scene = Scene::new(seed, count).unwrap();
                let what = format!("seed {seed}, {count} spheres, iso {iso}, {resolution}³");
                let mc33 = oracle(&scene, iso, resolution, CaseTable::Mc33);
                if mc33.triangle_count() == 0 {
                    continue;
                }
                scenes += 1;
                assert_closed(&mc33.weld_by_position(), &what);
                let decided = oracle(&scene, iso, resolution, CaseTable::Decider);
                tunnels += (mc33.triangle_count() - decided.triangle_count()) / 4;
                let gpu = gpu(&scene, iso, resolution);
                let tolerance = 1e-4 * Grid { cells_per_axis: resolution }.cell_size();
                gpu.to_soup()
                    .matches(&mc33, tolerance, 0.01f32.to_radians())
                    .unwrap_or_else(|e| panic!("{what}: {e}"));
            }
        }
    }
    eprintln!("{scenes} scenes, {tunnels} tunnels");
    assert!(scenes >= 30, "{scenes} scenes with a surface");
    assert!(tunnels > 0, "no scene has a tunnel");
}

/// Two spheres on the ends of one cell's body diagonal at 9³, their field above the level all the way
/// between them, and no face with two inside corners: the classic table and the decider leave the
/// blobs apart, MC33 joins them through the cell as the field does, on the GPU as in the oracle (the
/// lecture's figure).
#[test]
fn two_spheres_on_a_cells_body_diagonal_are_one_blob_only_under_mc33() {
    let spheres = vec![sphere([-0.106, -0.106, -0.106], 0.14), sphere([0.116, 0.116, 0.116], 0.14)];
    let midpoint = reference::field_at(&spheres, glam::Vec3::splat(0.005));
    assert!(midpoint > 1.0, "the field joins them: {midpoint} at the midpoint");
    let scene = Scene::from_spheres(spheres).unwrap();
    for (case_table, blobs) in [(CaseTable::Classic, 2), (CaseTable::Decider, 2), (CaseTable::Mc33, 1)] {
        let mesh = oracle(&scene, 1.0, 9, case_table).weld_by_position();
        assert_closed(&mesh, &format!("{case_table:?}"));
        assert_eq!(mesh.topology().component_euler.len(), blobs, "{case_table:?}: blobs");
    }
    let mc33 = oracle(&scene, 1.0, 9, CaseTable::Mc33);
    let tolerance = 1e-4 * Grid { cells_per_axis: 9 }.cell_size();
    gpu(&scene, 1.0, 9).to_soup().matches(&mc33, tolerance, 0.01f32.to_radians()).unwrap();
}
