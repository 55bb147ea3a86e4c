//! Level selection on the device against the rule on the CPU: for hundreds of random cameras, fields of
//! view, cell sizes and sphere sets, the compute passes select the CPU's blocks, levels and transition
//! faces, and touching blocks differ by at most one level; a selection that runs out of room keeps the
//! mesh it had and coarsens the next frame.

use crate::common::*;
use metaballs::Settings;
use metaballs::extract::field::Spheres;
use metaballs::extract::kernel::Terms;
use metaballs::extract::lod::mesher::LodMesher;
use metaballs::extract::lod::select::{BLOCK_CELLS, Block, Eye, Rule, coarsest_level, select_by};
use metaballs::extract::lod::select_for_surface;
use metaballs::extract::reference::Construction;
use metaballs::scene::BOX_HALF_EXTENT;
use metaballs::scene::params::view::Blend;
use std::collections::{HashMap, HashSet};

/// A small deterministic generator.
struct Random(u64);

impl Random {
    fn range(&mut self, low: f32, high: f32) -> f32 {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        low + (high - low) * ((self.0 >> 40) as f32 / (1u64 << 24) as f32)
    }

    fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[(self.range(0.0, items.len() as f32) as usize).min(items.len() - 1)]
    }
}

fn unpack(b: [u32; 4]) -> Block {
    Block { origin: glam::UVec3::new(b[0], b[1], b[2]), level: b[3] & 0xff, transitions: (b[3] >> 8) as u8 }
}

/// True when one of the decisions that place `block` (its own, its ancestors', and its face
/// neighbours' splits) is within rounding of turning the other way: the CPU and the device compute
/// them in `f32`, in different orders.
fn near_a_tie(block: Block, eye: &Eye, rule: &Rule, bounds: &Spheres, iso: f32, terms: Terms) -> bool {
    let finest = 2.0 * BOX_HALF_EXTENT / rule.resolution as f32;
    let world = |p: glam::UVec3| glam::Vec3::splat(-BOX_HALF_EXTENT) + p.as_vec3() * finest;
    let close = |a: f32, b: f32| (a - b).abs() <= 1e-4 * b.abs().max(1e-6);
    let decision_wavers = |origin: glam::UVec3, level: u32| {
        let width = BLOCK_CELLS << level;
        let (low, high) = (world(origin), world(origin + width));
        let e = 1e-4 * width as f32 * finest;
        let wall = origin.min_element() == 0 || (origin + width).max_element() == rule.resolution;
        close(rule.distance_squared(origin, level), rule.split_below[level as usize])
            || (eye.cull && eye.sees(low - e, high + e) != eye.sees(low + e, high - e))
            || bounds.straddles(low, high, wall, iso * (1.0 + 1e-4), terms)
                != bounds.straddles(low, high, wall, iso * (1.0 - 1e-4), terms)
    };
    let mut candidates = vec![(block.origin, block.level)];
    for level in block.level + 1..=rule.top {
        let width = BLOCK_CELLS << level;
        candidates.push((block.origin / width * width, level));
    }
    let width = block.width();
    for axis in 0..3 {
        let mut low = block.origin;
        if low[axis] >= width {
            low[axis] -= width;
            candidates.push((low, block.level));
        }
        let mut high = block.origin;
        high[axis] += width;
        if high[axis] < rule.resolution {
            candidates.push((high, block.level));
        }
    }
    candidates.into_iter().any(|(origin, level)| decision_wavers(origin, level))
}

/// The largest level difference between blocks of `blocks` that touch (faces, edges or corners).
fn largest_step(blocks: &[Block], resolution: u32) -> u32 {
    let levels: HashMap<(glam::UVec3, u32), ()> = blocks.iter().map(|b| ((b.origin, b.level), ())).collect();
    let top = coarsest_level(resolution);
    let level_at = |p: glam::UVec3| {
        (0..=top).find(|&l| {
            let width = BLOCK_CELLS << l;
            levels.contains_key(&(p / width * width, l))
        })
    };
    let mut largest = 0;
    for b in blocks {
        let (o, w) = (b.origin.as_ivec3(), b.width() as i32);
        for d in 0..27 {
            let step = glam::IVec3::new(d % 3 - 1, d / 3 % 3 - 1, d / 9 - 1);
            if step == glam::IVec3::ZERO {
                continue;
            }
            let p = o + glam::IVec3::select(step.cmplt(glam::IVec3::ZERO), step, step * w);
            if p.min_element() < 0 || p.max_element() >= resolution as i32 {
                continue;
            }
            if let Some(l) = level_at(p.as_uvec3()) {
                largest = largest.max(l.abs_diff(b.level));
            }
        }
    }
    largest
}

#[test]
fn the_devices_blocks_are_the_cpu_rules_for_hundreds_of_random_cameras() {
    let mut random = Random(48);
    let base = settings(1, 8, 64, 1.0).with_parameter("lod", "on").unwrap();
    let (mut compared, mut blocks, mut ties, mut levels_seen) = (0, 0, 0, HashSet::new());
    with_renderer(base, 160, 120, |o| {
        o.renderer.pin_extractor(Some("lod-gpu")).unwrap();
        for case in 0..300 {
            let mut s = Settings {
                seed: case,
                sphere_count: random.pick(&[1, 3, 8, 16, 40, 64]),
                resolution: random.pick(&[64, 128, 256, 512, 1024]),
                ..base
            };
            s.view.lod_pixels = random.range(0.5, 10.0);
            s.camera.yaw_degrees = random.range(-180.0, 180.0);
            s.camera.pitch_degrees = random.range(-80.0, 80.0);
            s.camera.distance = random.range(1.5, 8.0);
            s.camera.fov_y_degrees = random.range(10.0, 120.0);
            if case % 7 == 0 {
                s.view.blend = Blend::Max;
            }
            o.renderer.set_settings(s.validated().unwrap()).unwrap();
            // Until the buffers have grown to hold the selection (a frame out of room keeps its mesh).
            for _ in 0..6 {
                o.render();
                pollster::block_on(o.renderer.flush_stats());
                let stats = o.renderer.stats().unwrap();
                if !stats.overflowed && stats.lod_floor == 0 {
                    break;
                }
            }
            let device: Vec<Block> =
                pollster::block_on(o.renderer.lod_blocks()).into_iter().map(unpack).collect();
            let eye = o.renderer.lod_eye();
            assert!(eye.cull, "a drawn frame leaves out what is outside the view");
            let spheres = o.renderer.scene().spheres().to_vec();
            let iso = o.renderer.settings().iso;
            let cpu = select_for_surface(&spheres, iso, Terms::of(&s.view), s.resolution, &eye).blocks;
            let what = format!("case {case}: {s:?}");
            let on_device: HashSet<Block> = device.iter().copied().collect();
            let on_cpu: HashSet<Block> = cpu.iter().copied().collect();
            assert_eq!(on_device.len(), device.len(), "{what}: a block twice");
            let rule = Rule::new(s.resolution, &eye, 0);
            let mut bounds = Spheres::default();
            bounds.set(&spheres);
            for &b in on_device.symmetric_difference(&on_cpu) {
                assert!(
                    near_a_tie(b, &eye, &rule, &bounds, iso, Terms::of(&s.view)),
                    "{what}: {b:?} is {} but no decision placing it is near a tie",
                    if on_cpu.contains(&b) { "the CPU's alone" } else { "the device's alone" }
                );
                ties += 1;
            }
            assert!(largest_step(&device, s.resolution) <= 1, "{what}: touching blocks two levels apart");
            compared += 1;
            blocks += cpu.len();
            levels_seen.extend(cpu.iter().map(|b| b.level));
        }
    });
    println!("{compared} cameras, {blocks} blocks, {ties} within rounding of a tie, levels {levels_seen:?}");
    assert!(blocks > 30_000, "{blocks} blocks in all");
    assert!(levels_seen.len() >= 5, "levels {levels_seen:?}");
    assert!(ties * 1000 <= blocks, "{ties} ties in {blocks} blocks");
}

/// Seed `seed`'s 16 spheres with level of detail at `resolution`.
fn lod_at(seed: u64, resolution: u32) -> Settings {
    let mut s = settings(seed, 16, 64, 1.0).with_parameter("lod", "on").unwrap();
    s.resolution = resolution;
    s
}

/// Bright pixels: the surface's, against the dark background.
fn covered(pixels: &[u8]) -> usize {
    pixels.chunks(4).filter(|p| luminance(p) > 40.0).count()
}

#[test]
fn a_selection_out_of_room_keeps_its_mesh_and_coarsens_the_next_frame() {
    let mut far = lod_at(4, 1024);
    far.view.lod_pixels = 1.0;
    far.camera.distance = 6.0;
    let mut near = far;
    near.camera.distance = 1.5;
    with_renderer(far.validated().unwrap(), 240, 180, |o| {
        o.renderer.pin_extractor(Some("lod-gpu")).unwrap();
        o.renderer.set_max_blocks(Some(1500)).unwrap();
        for _ in 0..2 {
            o.render();
        }
        pollster::block_on(o.renderer.flush_stats());
        let fits = o.renderer.stats().unwrap();
        assert!(!fits.overflowed && fits.lod_floor == 0 && fits.triangles > 1000, "{fits:?}");
        // Nearer, the surface needs more blocks than there is room for.
        o.renderer.set_settings(near.validated().unwrap()).unwrap();
        let kept = o.render_rgba();
        pollster::block_on(o.renderer.flush_stats());
        let out = o.renderer.stats().unwrap();
        assert!(out.overflowed && out.lod_floor == 0, "{out:?}");
        // The next frames hold the finest levels back until the blocks fit.
        let mut coarse = Vec::new();
        for _ in 0..4 {
            coarse = o.render_rgba();
            pollster::block_on(o.renderer.flush_stats());
            if !o.renderer.stats().unwrap().overflowed {
                break;
            }
        }
        let after = o.renderer.stats().unwrap();
        assert!(!after.overflowed && after.lod_floor >= 1, "{after:?}");
        assert!(after.level_blocks[..after.lod_floor as usize].iter().all(|&n| n == 0), "{after:?}");
        assert!(after.level_blocks.iter().sum::<u32>() <= 1500, "{after:?}");
        // The frame out of room drew the mesh it had: the surface, not a hole, where the next one is.
        let (a, b) = (covered(&kept), covered(&coarse));
        assert!(b > 2000 && a.abs_diff(b) * 20 < b, "{a} bright pixels while out of room, {b} after");
        // The coarsened blocks are the rule's with the finest levels held back, and mesh closed.
        let eye = o.renderer.lod_eye();
        let spheres = o.renderer.scene().spheres().to_vec();
        let iso = o.renderer.settings().iso;
        let mut bounds = Spheres::default();
        bounds.set(&spheres);
        let surface = |low, high, walls| bounds.straddles(low, high, walls, iso, Terms::default());
        let rule = Rule::new(near.resolution, &eye, after.lod_floor);
        let device: HashSet<Block> =
            pollster::block_on(o.renderer.lod_blocks()).into_iter().map(unpack).collect();
        let cpu: HashSet<Block> = select_by(&rule, &eye, &surface).blocks.into_iter().collect();
        for &b in device.symmetric_difference(&cpu) {
            assert!(
                near_a_tie(b, &eye, &rule, &bounds, iso, Terms::default()),
                "{b:?} differs from the rule's"
            );
        }
        let whole = select_by(&rule, &Eye { cull: false, ..eye }, &surface);
        let mut mesher = LodMesher::new();
        mesher.mesh(&spheres, iso, Construction::default(), &whole);
        let topology = mesher.to_indexed().topology();
        assert!(mesher.triangle_count() > 1000, "{} triangles", mesher.triangle_count());
        assert_eq!(topology.open_or_nonmanifold_edges, 0, "the coarsened mesh is open");
        // With room again (farther away), the floor comes back down.
        o.renderer.set_settings(far.validated().unwrap()).unwrap();
        for _ in 0..12 {
            o.render();
        }
        pollster::block_on(o.renderer.flush_stats());
        let back = o.renderer.stats().unwrap();
        assert_eq!(back.lod_floor, 0, "the floor stayed up: {back:?}, at first {fits:?}");
    });
}

#[test]
fn a_readback_after_frames_that_leave_out_what_is_not_in_view_meshes_the_whole_surface() {
    let mut s = lod_at(2, 512);
    s.camera.fov_y_degrees = 15.0;
    s.camera.distance = 3.0;
    with_renderer(s.validated().unwrap(), 240, 180, |o| {
        o.renderer.pin_extractor(Some("lod-gpu")).unwrap();
        for _ in 0..3 {
            o.render();
            pollster::block_on(o.renderer.flush_stats());
        }
        let drawn = o.renderer.stats().unwrap();
        assert!(o.renderer.mesh_culled() && !drawn.overflowed, "{drawn:?}");
        // What an export reads (`exportMesh()`): the whole surface, closed, or a request to try again
        // while the buffers grow to hold it; never a mesh with parts missing.
        let mut tries = 0;
        let mesh = loop {
            match pollster::block_on(o.renderer.mesh_readback().finish()) {
                Ok(mesh) => break mesh,
                Err(e) => assert!(e.contains("try again"), "{e}"),
            }
            tries += 1;
            assert!(tries < 4, "still out of room after {tries} tries");
            o.render();
            pollster::block_on(o.renderer.flush_stats());
        };
        println!(
            "whole surface after {tries} retries: {} triangles, {} drawn",
            mesh.triangles.len(),
            drawn.triangles
        );
        assert!(
            10 * mesh.triangles.len() as u32 > 11 * drawn.triangles,
            "the readback left out what is outside the view"
        );
        let topology = mesh.topology();
        assert_eq!(topology.open_or_nonmanifold_edges, 0, "the whole surface is open");
        assert_eq!(topology.misoriented_edges, 0);
    });
}
