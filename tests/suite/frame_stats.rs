//! The host learns triangles emitted and overflow asynchronously, and an overflow never writes out of
//! bounds.

use crate::common;

use common::*;
use metaballs::extract::reference::{self, Grid};

#[test]
fn stats_report_the_triangles_drawn() {
    with_renderer(settings(3, 5, 40, 1.0), 64, 64, |o| {
        assert_eq!(o.renderer.stats(), None);
        let spheres = o.renderer.scene().spheres().to_vec();
        let iso = conditioned_iso(&spheres, 1.0, 40);
        o.renderer.set_iso(iso).unwrap();
        let oracle = reference::extract(&spheres, iso, Grid { cells_per_axis: 40 });
        let expected = oracle.triangle_count() as u32;
        for _ in 0..3 {
            o.render();
        }
        pollster::block_on(o.renderer.flush_stats());
        let stats = o.renderer.stats().expect("stats after flush");
        assert_eq!(stats.frame, 3);
        assert_eq!(stats.triangles, expected);
        assert_eq!(stats.triangles_requested, expected);
        assert!(!stats.overflowed());
        // Every surface vertex is computed once: as many as the oracle's grid edges that carry one.
        assert_eq!(stats.vertices as usize, oracle.weld_by_edge().positions.len());
        assert!(stats.active_blocks > 0 && stats.active_blocks < stats.total_blocks / 2, "{stats:?}");
        assert!(stats.active_cells > 0 && (stats.active_cells as u64) < stats.total_cells / 10, "{stats:?}");
        assert_eq!(stats.mesh_bytes, o.renderer.mesh_bytes());
    });
}

#[test]
fn frames_do_not_wait_for_stats() {
    // Many frames in a row: the staging buffers cycle, and stats arrive for a recent frame.
    with_renderer(settings(3, 5, 24, 1.0), 32, 32, |o| {
        for _ in 0..20 {
            o.render();
        }
        pollster::block_on(o.renderer.flush_stats());
        let stats = o.renderer.stats().expect("stats");
        assert!(stats.frame >= 18, "latest stats are for frame {}", stats.frame);
        assert!(stats.triangles > 0);
    });
}

#[test]
fn an_overflowing_budget_is_clamped_and_reported() {
    with_renderer(settings(3, 16, 40, 0.3), 64, 64, |o| {
        let spheres = o.renderer.scene().spheres().to_vec();
        let iso = conditioned_iso(&spheres, 0.3, 40);
        o.renderer.set_iso(iso).unwrap();
        let full = reference::extract(&spheres, iso, Grid { cells_per_axis: 40 });
        assert!(full.triangle_count() > 1000);
        o.renderer.set_max_triangles(Some(500)).unwrap();
        o.render();
        pollster::block_on(o.renderer.flush_stats());
        let stats = o.renderer.stats().unwrap();
        assert!(stats.overflowed());
        assert_eq!(stats.triangles, 500);
        assert_eq!(stats.max_triangles, 500);
        assert_eq!(stats.triangles_requested as usize, full.triangle_count());
        // The 500 written are real triangles of the surface (a subset of the oracle's).
        let mesh = pollster::block_on(o.renderer.extract_mesh()).to_soup();
        assert_eq!(mesh.triangle_count(), 500);
        let tolerance = 1e-4 * Grid { cells_per_axis: 40 }.cell_size();
        mesh.contained_in(&full, tolerance, 0.01f32.to_radians()).unwrap();
        // Back to automatic sizing: within a few frames the buffers have grown to hold everything.
        o.renderer.set_max_triangles(None).unwrap();
        for _ in 0..3 {
            o.render();
            pollster::block_on(o.renderer.flush_stats());
        }
        let stats = o.renderer.stats().unwrap();
        assert!(!stats.overflowed());
        assert_eq!(stats.triangles as usize, full.triangle_count());
    });
}

#[test]
fn buffers_grow_when_a_frame_overflows() {
    // At iso 0.05 the surface fills the box and the walls cap it: far more triangles than a 64-cell
    // grid starts with room for.
    with_renderer(settings(2, 5, 64, 0.05), 32, 32, |o| {
        let spheres = o.renderer.scene().spheres().to_vec();
        let iso = conditioned_iso(&spheres, 0.05, 64);
        o.renderer.set_iso(iso).unwrap();
        let expected = reference::extract(&spheres, iso, Grid { cells_per_axis: 64 }).triangle_count() as u32;
        let before = o.renderer.capacity();
        o.render();
        pollster::block_on(o.renderer.flush_stats());
        let first = o.renderer.stats().unwrap();
        assert!(first.overflowed(), "expected the first frame to overflow: {first:?}");
        assert_eq!(first.triangles_requested, expected);
        for _ in 0..2 {
            o.render();
            pollster::block_on(o.renderer.flush_stats());
        }
        let grown = o.renderer.stats().unwrap();
        assert!(!grown.overflowed(), "{grown:?}");
        assert_eq!(grown.triangles, expected);
        assert!(o.renderer.capacity().indices > before.indices);
        // No thrash: frames that fit leave the buffers as they are.
        let capacity = o.renderer.capacity();
        for _ in 0..3 {
            o.render();
        }
        pollster::block_on(o.renderer.flush_stats());
        assert_eq!(o.renderer.capacity(), capacity);
    });
}
