//! Topology as the figure reports it (`View.topology`, the HUD): components, genus, closed. Two
//! spheres are two blobs until the frame the oracle's mesh joins them; a ring of spheres has one hole;
//! and the counts agree with an independent count on the exported mesh, read back by `tobj`.

use crate::common;

use common::*;
use glam::Vec3;
use metaballs::export::{MeshFormat, encode};
use metaballs::extract::mesh::ShapeSummary;
use metaballs::extract::reference::{self, Grid};
use metaballs::{Scene, Settings, Sphere};
use std::collections::{HashMap, HashSet};

/// Components and Euler characteristic of an OBJ file's mesh, counted here from its faces alone:
/// vertices joined by faces (union-find), V − E + F per component.
fn independent_count(obj: &[u8]) -> (usize, Vec<i64>) {
    let options = tobj::LoadOptions { single_index: true, ..Default::default() };
    let (models, _) = tobj::load_obj_buf(&mut std::io::Cursor::new(obj), &options, |_| {
        Err(tobj::LoadError::OpenFileFailed)
    })
    .expect("tobj reads the OBJ");
    let indices: Vec<u32> = models.iter().flat_map(|m| m.mesh.indices.clone()).collect();
    let vertices = models.iter().map(|m| m.mesh.positions.len() / 3).sum::<usize>();
    let mut parent: Vec<usize> = (0..vertices).collect();
    fn root(parent: &mut [usize], v: usize) -> usize {
        let mut r = v;
        while parent[r] != r {
            r = parent[r];
        }
        parent[v] = r;
        r
    }
    let mut edges = HashSet::new();
    for t in indices.chunks_exact(3) {
        for k in 0..3 {
            let (a, b) = (t[k] as usize, t[(k + 1) % 3] as usize);
            edges.insert((a.min(b), a.max(b)));
            let (ra, rb) = (root(&mut parent, a), root(&mut parent, b));
            parent[ra] = rb;
        }
    }
    let mut per: HashMap<usize, [i64; 3]> = HashMap::new();
    let used: HashSet<usize> = indices.iter().map(|&i| i as usize).collect();
    for &v in &used {
        per.entry(root(&mut parent, v)).or_default()[0] += 1;
    }
    for &(a, _) in &edges {
        per.entry(root(&mut parent, a)).or_default()[1] += 1;
    }
    for t in indices.chunks_exact(3) {
        per.entry(root(&mut parent, t[0] as usize)).or_default()[2] += 1;
    }
    let mut euler: Vec<i64> = per.values().map(|[v, e, f]| v - e + f).collect();
    euler.sort();
    (per.len(), euler)
}

fn two_spheres(gap: f32) -> Vec<Sphere> {
    let at = |x: f32| sphere([x, 0.03, -0.02], 0.3);
    vec![at(-0.3 - gap / 2.0), at(0.3 + gap / 2.0)]
}

/// The figure's shape for `spheres`, on the extractor `name`, and its mesh.
fn figure_shape(o: &mut metaballs::offscreen::Offscreen, spheres: &[Sphere]) -> ShapeSummary {
    o.renderer.set_scene(Scene::from_spheres(spheres.to_vec()).unwrap());
    let mesh = pollster::block_on(o.renderer.mesh_readback().finish()).expect("mesh");
    mesh.shape()
}

#[test]
fn two_spheres_become_one_blob_at_the_step_the_oracle_joins_them() {
    let grid = Grid { cells_per_axis: 48 };
    for name in ["gpu", "cpu"] {
        let settings = Settings { resolution: 48, iso: 1.0, ..Settings::default() };
        with_renderer(settings, 32, 32, |o| {
            o.renderer.pin_extractor(Some(name)).unwrap();
            let mut joined_at = None;
            // The gap closes by about an eighth of a cell a step, from wide apart to well joined.
            for step in 0..60 {
                let gap = 0.4 - step as f32 * 0.005;
                let spheres = two_spheres(gap);
                let ours = figure_shape(o, &spheres);
                let oracle = reference::extract(&spheres, 1.0, grid).weld_by_edge().shape();
                assert_eq!(ours, oracle, "{name}, gap {gap}");
                assert_eq!(ours.genus, 0, "{name}, gap {gap}");
                assert!(ours.closed && ours.manifold, "{name}, gap {gap}: {ours:?}");
                if step == 0 {
                    assert_eq!(ours.components, 2, "{name}: apart at first");
                }
                if ours.components == 1 && joined_at.is_none() {
                    joined_at = Some(step);
                    // Merged blobs stay merged as the gap keeps closing.
                }
                if joined_at.is_some() {
                    assert_eq!(ours.components, 1, "{name}, gap {gap}: split again");
                }
            }
            let step = joined_at.unwrap_or_else(|| panic!("{name}: the spheres never merged"));
            println!("{name}: one blob from step {step} (gap {:.3})", 0.4 - step as f32 * 0.005);
            assert!(step > 0);
        });
    }
}

#[test]
fn a_ring_of_spheres_has_one_hole_and_the_exported_mesh_agrees() {
    let ring: Vec<Sphere> = (0..8)
        .map(|k| {
            let angle = k as f32 * std::f32::consts::TAU / 8.0;
            sphere([0.55 * angle.cos(), 0.55 * angle.sin(), 0.0], 0.2)
        })
        .collect();
    // The ring's middle is outside (8 · 0.2² / 0.55² ≈ 1.06 < 1.5), the gaps between spheres inside.
    let iso = 1.5;
    let middle = reference::field_at(&ring, Vec3::ZERO);
    assert!(middle < iso, "the ring's middle reads {middle}");
    let settings = Settings { resolution: 64, iso, ..Settings::default() };
    with_renderer(settings, 32, 32, |o| {
        for name in ["gpu", "cpu"] {
            o.renderer.pin_extractor(Some(name)).unwrap();
            let shape = figure_shape(o, &ring);
            assert_eq!(
                (shape.components, shape.genus, shape.closed, shape.manifold),
                (1, 1, true, true),
                "{name}"
            );
            let mesh = pollster::block_on(o.renderer.mesh_readback().finish()).unwrap();
            let (components, euler) = independent_count(&encode(&mesh, MeshFormat::Obj, 1.0));
            assert_eq!((components, euler), (1, vec![0]), "{name}: a torus has χ = 0");
        }
        // And two separate spheres: two components of χ = 2 each.
        let mesh = {
            o.renderer.set_scene(Scene::from_spheres(two_spheres(0.5)).unwrap());
            pollster::block_on(o.renderer.mesh_readback().finish()).unwrap()
        };
        let shape = mesh.shape();
        assert_eq!((shape.components, shape.genus), (2, 0));
        assert_eq!(independent_count(&encode(&mesh, MeshFormat::Obj, 1.0)), (2, vec![2, 2]));
    });
}
