//! Level selection and the LOD mesh on the CPU: balance, tiling, closedness, the oracle's triangles in
//! the finest blocks.

use super::mesher::{LodMesher, TRANSITION};
use super::select::{BALANCED_RATIO, BLOCK_CELLS, Eye, Rule, Selection, select, select_by};
use super::select_for_surface;
use crate::extract::kernel::Terms;
use crate::extract::mesh::Mesh;
use crate::extract::reference::{self, Construction, Grid};
use crate::scene::{BOX_HALF_EXTENT, Scene};
use glam::{UVec3, Vec3};

/// An eye at `position` looking at the box's centre, 480 pixels high, 45° field of view.
pub(crate) fn eye_at(position: Vec3, lod_pixels: f32) -> Eye {
    let fov = 45f32.to_radians();
    let projection = glam::camera::rh::proj::directx::perspective(fov, 4.0 / 3.0, 0.05, 100.0);
    let view = glam::camera::rh::view::look_at_mat4(position, Vec3::ZERO, Vec3::Y);
    Eye {
        position,
        view_projection: projection * view,
        pixels_per_unit: 480.0 / (2.0 * (fov / 2.0).tan()),
        orthographic: false,
        lod_pixels,
        cull: false,
    }
}

/// The eight cameras of the closedness tests: inside a corner of the box, near, far, grazing a face.
pub(crate) fn cameras() -> [Vec3; 8] {
    [
        Vec3::new(0.9, 0.85, 0.8),
        Vec3::new(-0.7, -0.9, 0.95),
        Vec3::new(1.3, 0.6, 2.2),
        Vec3::new(0.0, 0.3, 1.6),
        Vec3::new(-3.5, 1.2, 2.4),
        Vec3::new(12.0, 8.0, -14.0),
        Vec3::new(2.5, 1.02, 0.0),
        Vec3::new(0.2, -1.05, -2.0),
    ]
}

fn world(selection: &Selection, p: UVec3) -> Vec3 {
    Vec3::splat(-BOX_HALF_EXTENT) + p.as_vec3() * (2.0 * BOX_HALF_EXTENT / selection.resolution as f32)
}

/// Each finest cell's block, or a failure where blocks overlap or leave a gap.
fn owners(selection: &Selection) -> Vec<u32> {
    let n = selection.resolution as usize;
    let mut owner = vec![u32::MAX; n * n * n];
    for (i, b) in selection.blocks.iter().enumerate() {
        let o = b.origin.as_usizevec3();
        let w = b.width() as usize;
        for z in o.z..o.z + w {
            for y in o.y..o.y + w {
                for x in o.x..o.x + w {
                    let cell = &mut owner[x + n * (y + n * z)];
                    assert_eq!(*cell, u32::MAX, "blocks overlap at {x},{y},{z}");
                    *cell = i as u32;
                }
            }
        }
    }
    assert!(!owner.contains(&u32::MAX), "blocks leave a gap");
    owner
}

#[test]
fn blocks_tile_the_box_and_neighbours_differ_by_at_most_one_level() {
    let mut all_levels = std::collections::BTreeSet::new();
    for position in cameras() {
        let selection = select(128, &eye_at(position, 8.0), &|_, _, _| true);
        assert!(selection.levels >= 4, "{} levels", selection.levels);
        let owner = owners(&selection);
        let n = 128i32;
        let level = |p: [i32; 3]| {
            (p.iter().all(|&c| (0..n).contains(&c)))
                .then(|| selection.blocks[owner[(p[0] + n * (p[1] + n * p[2])) as usize] as usize].level)
        };
        let mut seen_levels = std::collections::BTreeSet::new();
        for b in &selection.blocks {
            seen_levels.insert(b.level);
            let o = b.origin.as_ivec3();
            let w = b.width() as i32;
            // Every cell just outside the block, across faces, edges and corners.
            for z in o.z - 1..=o.z + w {
                for y in o.y - 1..=o.y + w {
                    for x in o.x - 1..=o.x + w {
                        let outside = [x, y, z].iter().zip(o.to_array()).any(|(&c, o)| c < o || c >= o + w);
                        if let Some(l) = level([x, y, z]).filter(|_| outside) {
                            assert!(l.abs_diff(b.level) <= 1, "{position}: level {} beside {l}", b.level);
                        }
                    }
                }
            }
            // Transition faces are exactly those with a finer block beyond.
            for face in 0..6 {
                let (axis, side) = (face / 2, face % 2);
                let mut p = o.to_array();
                p[axis] = if side == 0 { p[axis] - 1 } else { p[axis] + w };
                let finer = level(p).is_some_and(|l| l < b.level);
                assert_eq!(b.transitions & (1 << face) != 0, finer, "{position}: face {face} of {b:?}");
            }
        }
        all_levels.extend(seen_levels);
    }
    assert!(all_levels.len() >= 4, "levels in use: {all_levels:?}");
}

#[test]
fn the_finest_blocks_surround_a_camera_inside_the_box_and_levels_grow_with_distance() {
    let position = Vec3::new(0.6, 0.5, 0.55);
    let selection = select(256, &eye_at(position, 8.0), &|_, _, _| true);
    let n = selection.resolution;
    let finest = 2.0 * BOX_HALF_EXTENT / n as f32;
    let here = ((position + BOX_HALF_EXTENT) / finest).as_uvec3();
    let holding = |p: UVec3| {
        selection.blocks.iter().find(|b| (p.cmpge(b.origin) & p.cmplt(b.origin + b.width())).all()).unwrap()
    };
    assert_eq!(holding(here).level, 0);
    // Along the line of sight, blocks only get coarser.
    let mut last = 0;
    for k in 0..200 {
        let p = position + (Vec3::ZERO - position).normalize() * (k as f32 * 0.01);
        let id = ((p + BOX_HALF_EXTENT) / finest).as_uvec3().min(UVec3::splat(n - 1));
        let level = holding(id).level;
        assert!(level >= last, "level {level} after {last} at {p}");
        last = level;
    }
    assert!(last >= 1, "the far side is at level {last}");
    let _ = world(&selection, here);
}

#[test]
fn culling_keeps_only_blocks_in_view_and_each_projects_within_lod_pixels() {
    let whole = eye_at(Vec3::new(0.0, 0.2, 2.4), 2.0);
    let culled = Eye { cull: true, ..whole };
    let all = select(512, &whole, &|_, _, _| true);
    let selection = select(512, &culled, &|_, _, _| true);
    let finest = 2.0 * BOX_HALF_EXTENT / 512.0;
    let mut finest_count = 0;
    for b in &selection.blocks {
        let (low, high) = (world(&selection, b.origin), world(&selection, b.origin + b.width()));
        let distance = (culled.position.clamp(low, high) - culled.position).length();
        let cell = finest * b.step() as f32;
        assert!(culled.sees(low, high), "{b:?} is out of view");
        assert!(
            b.level == 0 || culled.projected(cell, distance) <= culled.lod_pixels,
            "{b:?} looks too coarse"
        );
        finest_count += (b.level == 0) as usize;
    }
    // Culling drops blocks and never changes a kept block's level or faces.
    let kept: std::collections::HashSet<_> = all.blocks.iter().collect();
    assert!(selection.blocks.iter().all(|b| kept.contains(b)));
    assert!(selection.blocks.len() < all.blocks.len(), "nothing culled");
    let uniform_blocks = (512 / BLOCK_CELLS as usize).pow(3);
    assert!(all.blocks.len() * 2 < uniform_blocks, "{} blocks of {uniform_blocks}", all.blocks.len());
    assert!(finest_count > 0);
}

/// A small deterministic generator for the random cameras below.
pub(crate) struct Random(u64);

impl Random {
    pub(crate) fn new(seed: u64) -> Self {
        Self(seed.wrapping_mul(0x9e37_79b9_7f4a_7c15) | 1)
    }

    /// Uniform in `low..high`.
    pub(crate) fn range(&mut self, low: f32, high: f32) -> f32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        low + (high - low) * ((self.0 >> 40) as f32 / (1u64 << 24) as f32)
    }

    /// An eye anywhere from inside the box to well outside it, looking near the centre, with a random
    /// field of view and image height.
    pub(crate) fn eye(&mut self, lod_pixels: f32) -> Eye {
        let position = Vec3::new(self.range(-3.0, 3.0), self.range(-3.0, 3.0), self.range(-3.0, 3.0));
        let target = Vec3::new(self.range(-0.5, 0.5), self.range(-0.5, 0.5), self.range(-0.5, 0.5));
        let fov = self.range(10.0, 100.0).to_radians();
        let height = self.range(200.0, 1200.0);
        let projection = glam::camera::rh::proj::directx::perspective(fov, 1.5, 0.05, 100.0);
        let view = glam::camera::rh::view::look_at_mat4(position, target, Vec3::Y);
        Eye {
            position,
            view_projection: projection * view,
            pixels_per_unit: height / (2.0 * (fov / 2.0).tan()),
            orthographic: false,
            lod_pixels,
            cull: false,
        }
    }
}

/// The largest level difference between touching blocks of a selection that tiles the box.
fn largest_step(selection: &Selection) -> u32 {
    let owner = owners(selection);
    let n = selection.resolution as i32;
    let mut largest = 0;
    for b in &selection.blocks {
        let o = b.origin.as_ivec3();
        let w = b.width() as i32;
        for z in (o.z - 1).max(0)..=(o.z + w).min(n - 1) {
            for y in (o.y - 1).max(0)..=(o.y + w).min(n - 1) {
                for x in (o.x - 1).max(0)..=(o.x + w).min(n - 1) {
                    let other = selection.blocks[owner[(x + n * (y + n * z)) as usize] as usize];
                    largest = largest.max(other.level.abs_diff(b.level));
                }
            }
        }
    }
    largest
}

#[test]
fn levels_from_distance_alone_differ_by_one_at_the_bound_and_not_always_below_it() {
    let mut random = Random::new(48);
    let mut broken = 0;
    for _ in 0..200 {
        // As large a cell as asked: clamped to the bound, where the proof is tightest.
        let eye = random.eye(1000.0);
        assert!(eye.cell_pixels() < eye.lod_pixels);
        let ratio = eye.pixels_per_unit / (BLOCK_CELLS as f32 * eye.cell_pixels());
        assert!((ratio - BALANCED_RATIO).abs() < 1e-3 && ratio >= 3f32.sqrt(), "ratio {ratio}");
        let at_bound = select(128, &eye, &|_, _, _| true);
        assert!(largest_step(&at_bound) <= 1, "{eye:?}");
        // The same rule with cells four times as large on screen: the bound is what balance needs.
        let mut rule = Rule::new(128, &eye, 0);
        for d in rule.split_below.iter_mut().filter(|d| **d > 0.0) {
            *d /= 16.0;
        }
        broken += usize::from(largest_step(&select_by(&rule, &eye, &|_, _, _| true)) > 1);
    }
    assert!(broken > 0, "no camera broke balance below the bound");
}

/// The LOD mesh of `scene` seen from `position` at `resolution`.
fn lod_mesh(scene: &Scene, resolution: u32, position: Vec3, lod_pixels: f32) -> (LodMesher, Selection) {
    let eye = eye_at(position, lod_pixels);
    let selection = select_for_surface(scene.spheres(), 1.0, Terms::default(), resolution, &eye);
    let mut mesher = LodMesher::new();
    mesher.mesh(scene.spheres(), 1.0, Construction::default(), &selection);
    (mesher, selection)
}

#[test]
fn lod_meshes_are_closed_oriented_manifolds_wherever_levels_meet() {
    let mut most_levels = 0;
    for seed in 1..=12u64 {
        let scene = Scene::new(seed, [3, 8, 16][seed as usize % 3]).unwrap();
        let resolution = 128;
        let mut used_levels = 0;
        for (c, position) in cameras().into_iter().enumerate() {
            // Large cells on screen, so that many levels meet (up to 40 pixels a cell, near the
            // bound on balance).
            let (mesher, selection) = lod_mesh(&scene, resolution, position, 40.0);
            let levels = selection.blocks_per_level();
            used_levels = used_levels.max(levels.iter().filter(|&&n| n > 0).count());
            let topology = mesher.to_indexed().topology();
            let what = format!("seed {seed}, camera {c} {position}, blocks per level {levels:?}");
            assert_eq!(topology.open_or_nonmanifold_edges, 0, "{what}: open or non-manifold edges");
            assert_eq!(topology.misoriented_edges, 0, "{what}: inconsistent orientation");
            // So coarse a mesh may join or drop small blobs, but each component is a closed
            // orientable surface: χ = 2 − 2g is even.
            assert!(
                topology.component_euler.iter().all(|x| x % 2 == 0),
                "{what}: {:?}",
                topology.component_euler
            );
        }
        assert!(used_levels >= 2, "seed {seed}: at most {used_levels} levels in use");
        most_levels = most_levels.max(used_levels);
    }
    assert!(most_levels >= 3, "at most {most_levels} levels in use");
}

#[test]
fn lod_meshes_have_the_uniform_meshs_topology_and_volume() {
    for seed in 1..=12u64 {
        let scene = Scene::new(seed, [3, 8, 16][seed as usize % 3]).unwrap();
        let resolution = 128;
        let oracle =
            reference::extract(scene.spheres(), 1.0, Grid { cells_per_axis: resolution }).weld_by_edge();
        let volume = oracle.enclosed_volume();
        let expected: Vec<i64> =
            oracle.topology().components.iter().filter(|c| c.1 > 16).map(|c| c.0).collect();
        for (c, position) in cameras().into_iter().enumerate() {
            let (mesher, selection) = lod_mesh(&scene, resolution, position, 1.0);
            let mesh = mesher.to_indexed();
            let what = format!(
                "seed {seed}, camera {c} {position}, blocks per level {:?}",
                selection.blocks_per_level()
            );
            let topology = mesh.topology();
            assert_eq!(topology.open_or_nonmanifold_edges, 0, "{what}: open or non-manifold edges");
            assert_eq!(topology.misoriented_edges, 0, "{what}: inconsistent orientation");
            // Where a surface barely crosses into a finer block, the fine side holds a sliver the
            // coarse side cannot see, closed by its transition cells in the seam's plane: a component
            // of a few vertices. Apart from those, the components are the oracle's.
            let euler: Vec<i64> = topology.components.iter().filter(|c| c.1 > 16).map(|c| c.0).collect();
            assert_eq!(euler, expected, "{what}: Euler characteristic per component");
            let ours = mesh.enclosed_volume();
            assert!((ours - volume).abs() < 0.01 * volume, "{what}: volume {ours} against {volume}");
        }
    }
}

#[test]
fn the_finest_blocks_hold_the_oracles_triangles() {
    let scene = Scene::new(5, 16).unwrap();
    let resolution = 128;
    let (mesher, selection) = lod_mesh(&scene, resolution, Vec3::new(0.3, 0.2, 1.4), 16.0);
    let finest_blocks: Vec<_> = selection.blocks.iter().filter(|b| b.level == 0).collect();
    assert!(finest_blocks.len() > 100 && finest_blocks.len() < selection.blocks.len());
    let cell_size = 2.0 * BOX_HALF_EXTENT / resolution as f32;
    let in_finest = |t: [Vec3; 3]| {
        let cell = (((t[0] + t[1] + t[2]) / 3.0 + BOX_HALF_EXTENT) / cell_size).as_uvec3();
        finest_blocks.iter().any(|b| (cell.cmpge(b.origin) & cell.cmplt(b.origin + b.width())).all())
    };
    let oracle = reference::extract(scene.spheres(), 1.0, Grid { cells_per_axis: resolution });
    let mut expected = Mesh::default();
    for k in (0..oracle.triangle_count()).filter(|&k| in_finest(oracle.triangle(k))) {
        expected.positions.extend_from_slice(&oracle.positions[3 * k..3 * k + 3]);
        expected.normals.extend_from_slice(&oracle.normals[3 * k..3 * k + 3]);
    }
    let soup = mesher.to_indexed().to_soup();
    let mut ours = Mesh::default();
    for (k, &level) in mesher.triangle_levels.iter().enumerate() {
        if level == 0 {
            ours.positions.extend_from_slice(&soup.positions[3 * k..3 * k + 3]);
            ours.normals.extend_from_slice(&soup.normals[3 * k..3 * k + 3]);
        }
    }
    assert!(mesher.triangle_levels.iter().any(|&l| l & TRANSITION != 0));
    assert!(ours.triangle_count() > 1000, "{} triangles", ours.triangle_count());
    ours.matches(&expected, 0.0, 1e-6).unwrap();
}

/// Distance from `p` to the surface f = `iso`, by Newton steps along the gradient:
/// p ← p − (f(p) − iso) ∇f / |∇f|².
fn distance_to_surface(spheres: &[crate::scene::Sphere], iso: f32, p: Vec3) -> f32 {
    let mut q = p.as_dvec3();
    for _ in 0..8 {
        let (mut f, mut g) = (0.0f64, glam::DVec3::ZERO);
        for s in spheres {
            let d = q - s.center.as_dvec3();
            let d2 = d.length_squared().max(1e-20);
            let r2 = (s.radius as f64).powi(2);
            f += r2 / d2;
            g -= 2.0 * r2 * d / (d2 * d2);
        }
        let step = (f - iso as f64) / g.length_squared().max(1e-30);
        q -= step * g;
    }
    (q - p.as_dvec3()).length() as f32
}

#[test]
fn in_the_finest_blocks_vertices_lie_as_close_to_the_exact_surface_as_the_uniform_grids() {
    let scene = Scene::new(7, 16).unwrap();
    let resolution = 256;
    let (mesher, selection) = lod_mesh(&scene, resolution, Vec3::new(0.4, 0.5, 1.5), 2.0);
    let cell = 2.0 * BOX_HALF_EXTENT / resolution as f32;
    let finest: Vec<_> = selection.blocks.iter().filter(|b| b.level == 0).collect();
    let in_finest = |p: Vec3| {
        let id = ((p + BOX_HALF_EXTENT) / cell).as_uvec3();
        finest.iter().any(|b| (id.cmpge(b.origin) & id.cmplt(b.origin + b.width())).all())
    };
    let rms = |points: &mut dyn Iterator<Item = Vec3>| {
        let (mut sum, mut n) = (0.0f64, 0usize);
        for p in points {
            // Vertices on the walls lie on the caps, not on f = iso.
            if p.abs().max_element() < BOX_HALF_EXTENT - 1e-4 {
                sum += (distance_to_surface(scene.spheres(), 1.0, p) / cell).powi(2) as f64;
                n += 1;
            }
        }
        ((sum / n.max(1) as f64).sqrt(), n)
    };
    let mesh = mesher.to_indexed();
    let lod_vertices: std::collections::BTreeSet<u32> = mesh
        .triangles
        .iter()
        .zip(&mesher.triangle_levels)
        .filter(|(_, l)| **l & 0x7f == 0)
        .flat_map(|(t, _)| *t)
        .collect();
    let (lod_rms, lod_n) =
        rms(&mut lod_vertices.iter().map(|&i| mesh.positions[i as usize]).filter(|&p| in_finest(p)));
    let oracle = reference::extract(scene.spheres(), 1.0, Grid { cells_per_axis: resolution }).weld_by_edge();
    let (uniform_rms, uniform_n) = rms(&mut oracle.positions.iter().copied().filter(|&p| in_finest(p)));
    println!(
        "finest blocks at {resolution}³: RMS distance to the exact surface {lod_rms:.5} cells over {lod_n} LOD \
         vertices, {uniform_rms:.5} over {uniform_n} uniform ones"
    );
    assert!(lod_n > 1000 && uniform_n > 1000);
    assert!((lod_rms - uniform_rms).abs() <= 0.1 * uniform_rms, "{lod_rms} against {uniform_rms}");
    // Linear interpolation of this field puts vertices a few hundredths of a cell from the surface.
    assert!(uniform_rms < 0.1, "{uniform_rms}");
}
