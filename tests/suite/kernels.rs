//! The kernels (`kernel=inverse_square|blinn|wyvill`, with `blend=sum|max`): each one's mesh at 128³ on
//! the GPU encloses the volume a fine grid finds, closed and manifold; Wyvill's compact support lets the
//! bounds pass over every block out of the spheres' reach.

use crate::common;

use common::*;
use metaballs::extract::field::{Spheres, sample_run};
use metaballs::extract::kernel::Terms;
use metaballs::scene::BOX_HALF_EXTENT;
use metaballs::scene::params::view::{Blend, Kernel};
use metaballs::{Scene, Settings, Sphere};

/// The volume of {f > iso} in the box by the midpoint rule on an `n`³ grid of cells (each cell's
/// centre inside or not), sampled a row at a time as the CPU mesher samples.
fn fine_volume(spheres: &[Sphere], iso: f32, terms: Terms, n: u32) -> f64 {
    let mut arrays = Spheres::default();
    arrays.set(spheres);
    let h = 2.0 * BOX_HALF_EXTENT / n as f32;
    let centres: Vec<f32> = (0..n).map(|i| -BOX_HALF_EXTENT + (i as f32 + 0.5) * h).collect();
    let mut row = vec![0.0f32; n as usize];
    let mut inside = 0u64;
    for &z in &centres {
        for &y in &centres {
            sample_run(&mut row, &centres, y, z, &arrays, terms);
            inside += row.iter().filter(|&&f| f > iso).count() as u64;
        }
    }
    inside as f64 * f64::from(h).powi(3)
}

/// At 128³ the GPU's mesh of every kernel (with each blend) encloses the volume that the midpoint rule
/// finds on a 384³ grid to 0.5 %, and is closed and manifold. Blinn's Gaussian at the largest
/// blobbiness (8) is held to closed and manifold only: it falls so steeply across a cell that the
/// vertices' linear interpolation overshoots it, by 0.8 % of the volume at 128³.
#[test]
fn each_kernel_meshes_the_volume_a_fine_grid_finds() {
    let mut spheres = Scene::new(5, 7).unwrap().spheres().to_vec();
    spheres[2].charge = -1.0;
    for terms in Terms::every() {
        let mut settings = Settings { resolution: 128, iso: 1.0, ..Settings::default() };
        terms.set_in(&mut settings.view);
        let mesh = with_renderer(settings, 16, 16, |o| {
            o.renderer.set_scene(Scene::from_spheres(spheres.clone()).unwrap());
            pollster::block_on(o.renderer.extract_mesh())
        });
        let topology = mesh.topology();
        assert_eq!(topology.open_or_nonmanifold_edges, 0, "{terms:?}: open or non-manifold edges");
        assert_eq!(topology.misoriented_edges, 0, "{terms:?}: inconsistent orientation");
        let (volume, reference) = (mesh.enclosed_volume(), fine_volume(&spheres, 1.0, terms, 384));
        println!(
            "{terms:?}: {} triangles, volume {volume:.5}, 384³ midpoint rule {reference:.5}",
            mesh.triangles.len()
        );
        if terms.blobbiness > 2.0 {
            continue;
        }
        assert!(reference > 0.01, "{terms:?}: the scene has almost no volume ({reference})");
        assert!((volume / reference - 1.0).abs() < 0.005, "{terms:?}: volume {volume} against {reference}");
    }
}

/// Wyvill's kernel is 0 from twice a sphere's radius on, so however low the iso level, every block
/// out of reach of every sphere is passed over: the blocks kept all lie within reach. (Its mesh is the
/// oracle's: the shared scenes in `extractors.rs` check every kernel; and no block the surface crosses
/// is passed over: `the_blocks_left_out_hold_no_crossed_cell` in core/src/extract/cpu/blocks.rs.)
#[test]
fn the_compact_kernel_skips_every_block_out_of_reach() {
    let (resolution, block) = (64u32, 4u32);
    for iso in [0.05, 0.3, 1.0] {
        let mut settings = settings(9, 6, resolution, iso);
        Terms { kernel: Kernel::Wyvill, blend: Blend::Sum, ..Terms::default() }.set_in(&mut settings.view);
        let (stats, spheres) = with_renderer(settings, 16, 16, |o| {
            o.render();
            pollster::block_on(o.renderer.flush_stats());
            (o.renderer.stats().expect("stats after a frame"), o.renderer.scene().spheres().to_vec())
        });
        // Blocks whose ball meets some sphere's support (radius 2r).
        let side = 2.0 * BOX_HALF_EXTENT * block as f32 / resolution as f32;
        let blocks = resolution / block;
        let within = (0..blocks.pow(3))
            .filter(|&b| {
                let at = [b % blocks, b / blocks % blocks, b / (blocks * blocks)];
                let centre = glam::Vec3::from_array(at.map(|i| -BOX_HALF_EXTENT + (i as f32 + 0.5) * side));
                let h = 0.5 * 3f32.sqrt() * side;
                spheres.iter().any(|s| (centre - s.center).length() - h < 2.0 * s.radius)
            })
            .count() as u32;
        let kept = stats.active_blocks;
        println!("iso {iso}: {kept} of {} blocks kept, {within} within reach", stats.total_blocks);
        assert!(kept > 0 && kept <= within, "iso {iso}: {kept} blocks kept, {within} within reach");
    }
}
