//! The step-through of the march (`march=x,y,z`): at every cell of a small scene, the GPU's passes and
//! the CPU's mesher draw exactly the oracle's triangles of the cells marched so far, and the oracle's
//! march is its whole mesh cut where the march stands.

use crate::common;

use common::*;
use metaballs::extract::reference::{self, Construction, Grid};
use metaballs::scene::params::view::{CaseTable, March};

#[test]
fn every_step_of_the_march_draws_the_oracles_triangles_of_the_cells_reached_on_gpu_and_cpu() {
    let n = 8;
    let grid = Grid { cells_per_axis: n };
    with_renderer(settings(4, 3, n, 1.0), 16, 16, |o| {
        let spheres = o.renderer.scene().spheres().to_vec();
        let iso = conditioned_iso(&spheres, 1.0, n);
        o.renderer.set_iso(iso).unwrap();
        for case_table in [CaseTable::Classic, CaseTable::Mc33] {
            o.renderer.set_parameter("table", case_table.word()).unwrap();
            let whole = Construction { case_table, ..Construction::default() };
            let all = reference::extract_with(&spheres, iso, grid, whole);
            assert!(all.triangle_count() > 20, "too small a surface: {}", all.triangle_count());
            let cells: Vec<[u32; 3]> = (0..n * n * n).map(|k| [k % n, k / n % n, k / (n * n)]).collect();
            // The oracle walks the cells in the march's order: its mesh so far is the start of its
            // whole mesh, and the last step is all of it.
            let steps: Vec<_> = cells
                .iter()
                .map(|&cell| {
                    reference::extract_with(&spheres, iso, grid, Construction { march: Some(cell), ..whole })
                })
                .collect();
            let mut grew = 0;
            for (k, step) in steps.iter().enumerate() {
                let t = step.triangle_count();
                let before = if k == 0 { 0 } else { steps[k - 1].triangle_count() };
                assert!(t >= before, "step {k}: the mesh shrank");
                assert_eq!(
                    step.positions[..],
                    all.positions[..3 * t],
                    "step {k}: not the whole mesh's start"
                );
                grew += (t > before) as u32;
            }
            assert_eq!(steps.last().unwrap().triangle_count(), all.triangle_count());
            for name in ["gpu", "cpu"] {
                o.renderer.pin_extractor(Some(name)).unwrap();
                for (cell, oracle) in cells.iter().zip(&steps) {
                    let what = format!("{name}, {case_table:?}, march at {cell:?}");
                    o.renderer.set_parameter("march", &March::text(Some(*cell))).unwrap();
                    let ours = pollster::block_on(o.renderer.extract_mesh());
                    assert_eq!(o.renderer.mesh_source(), name, "{what}: another extractor ran");
                    assert_eq!(
                        ours.triangles.len(),
                        oracle.triangle_count(),
                        "{what}: triangle counts differ"
                    );
                    if let Err(e) =
                        ours.to_soup().matches(oracle, 1e-4 * grid.cell_size(), 0.01f32.to_radians())
                    {
                        panic!("{what}: {e}");
                    }
                }
            }
            println!(
                "{case_table:?}: {} triangles appear over {grew} steps of {} cells",
                all.triangle_count(),
                n * n * n
            );
            assert!(grew > 10, "{case_table:?}: the mesh grew at only {grew} steps");
        }
        // A cell past the grid stands for the last cell on that axis, on both paths.
        let construction = Construction { march: Some([2, n - 1, 3]), ..Construction::default() };
        let oracle = reference::extract_with(&spheres, iso, grid, construction);
        o.renderer.set_parameter("table", "classic").unwrap();
        o.renderer.set_parameter("march", "2,99,3").unwrap();
        for name in ["gpu", "cpu"] {
            o.renderer.pin_extractor(Some(name)).unwrap();
            let ours = pollster::block_on(o.renderer.extract_mesh());
            assert_eq!(ours.triangles.len(), oracle.triangle_count(), "{name}: march past the grid");
        }
        o.renderer.set_parameter("march", "off").unwrap();
        o.renderer.pin_extractor(None).unwrap();
    });
}

#[test]
fn the_march_reads_a_cell_or_off_and_explains_anything_else() {
    assert_eq!(March::parse(" 3, 4 ,5 ").unwrap(), Some([3, 4, 5]));
    assert_eq!(March::parse("off").unwrap(), None);
    assert_eq!(March::text(Some([0, 1, 2])), "0,1,2");
    for bad in ["1,2", "1,2,3,4", "-1,0,0", "a,b,c", "1.5,0,0", "9999,0,0"] {
        let error = March::parse(bad).unwrap_err().to_string();
        assert!(error.contains("x,y,z"), "{bad}: {error}");
    }
    // x fastest, then y, then z.
    assert!(March::reached(Some([1, 2, 3]), [5, 1, 3]));
    assert!(March::reached(Some([1, 2, 3]), [1, 2, 3]));
    assert!(!March::reached(Some([1, 2, 3]), [2, 2, 3]));
    assert!(!March::reached(Some([1, 2, 3]), [0, 0, 4]));
    assert!(March::reached(None, [9, 9, 9]));
}
