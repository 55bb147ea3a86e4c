//! Exact ties: grid samples equal to the iso level. Spheres centred on grid points, with radii and iso
//! levels chosen so that f is exactly the iso level at many samples, are meshed by every extractor (the
//! oracle, the GPU passes, the CPU mesher, surface nets) and exported as STL; welded by position alone
//! (here, and by an STL reader), each mesh is a closed, consistently wound 2-manifold with no triangle
//! of zero area.

use crate::common;

use common::*;
use glam::{DVec3, UVec3, Vec3};
use metaballs::export::{MeshFormat, encode};
use metaballs::extract::reference::{self, Grid, sample_field};
use metaballs::scene::params::view::Method;
use metaballs::{Scene, Settings};
use std::collections::HashMap;

/// A scene whose samples hit `iso` exactly: one sphere on grid point `at` of a `resolution` grid (the
/// cell size is a power of two, so grid points, their differences and squared distances are exact in
/// `f32`), of radius `k` cells; f = k² / m at a sample m squared cells away.
struct Tie {
    resolution: u32,
    at: [u32; 3],
    k: f32,
    iso: f32,
}

const TIES: [Tie; 4] = [
    // 3² + 4² = 5²: 30 samples at f = 1.
    Tie { resolution: 32, at: [16, 15, 17], k: 5.0, iso: 1.0 },
    // 2² + 3² + 6² = 7²: 54 samples at f = 1.
    Tie { resolution: 64, at: [30, 33, 31], k: 7.0, iso: 1.0 },
    // f = 16 / 8 = 2 where 2² + 2² = 8.
    Tie { resolution: 32, at: [15, 16, 16], k: 4.0, iso: 2.0 },
    // f = 36 / 72 = 0.5 where 6² + 6² = 2² + 2² + 8² = 72: ties on the level set outside the sphere.
    Tie { resolution: 64, at: [32, 31, 33], k: 6.0, iso: 0.5 },
];

impl Tie {
    fn grid(&self) -> Grid {
        Grid { cells_per_axis: self.resolution }
    }

    fn scene(&self) -> Scene {
        let grid = self.grid();
        let centre = grid.point(UVec3::from_array(self.at));
        Scene::from_spheres(vec![sphere(centre.to_array(), self.k * grid.cell_size())]).unwrap()
    }

    /// How many samples equal the iso level exactly.
    fn ties(&self) -> usize {
        sample_field(self.scene().spheres(), self.grid()).iter().filter(|&&f| f == self.iso).count()
    }
}

/// Checks a triangle soup welded by position only: every triangle has three distinct corners and a
/// non-zero area, every edge is shared by exactly two triangles wound opposite ways, and the surface
/// is one sphere (χ = 2). Returns the number of distinct positions.
fn assert_closed_by_position(triangles: &[[Vec3; 3]], what: &str) -> usize {
    assert!(!triangles.is_empty(), "{what}: no triangles");
    let mut ids: HashMap<[u32; 3], u32> = HashMap::new();
    let mut welded = Vec::with_capacity(triangles.len());
    for (k, t) in triangles.iter().enumerate() {
        let corner = |p: Vec3, ids: &mut HashMap<[u32; 3], u32>| {
            let next = ids.len() as u32;
            *ids.entry(p.to_array().map(f32::to_bits)).or_insert(next)
        };
        let w = [corner(t[0], &mut ids), corner(t[1], &mut ids), corner(t[2], &mut ids)];
        assert!(
            w[0] != w[1] && w[1] != w[2] && w[0] != w[2],
            "{what}: triangle {k} has two corners at one point {t:?}"
        );
        let [a, b, c] = t.map(|p| p.as_dvec3());
        let area = (b - a).cross(c - a).length() / 2.0;
        assert!(area > 0.0, "{what}: triangle {k} has zero area {t:?}");
        welded.push(w);
    }
    let mut edges: HashMap<(u32, u32), i32> = HashMap::new();
    for t in &welded {
        for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            *edges.entry((a.min(b), a.max(b))).or_default() += if a < b { 1 } else { -1 };
        }
    }
    let mut uses: HashMap<(u32, u32), u32> = HashMap::new();
    for t in &welded {
        for (a, b) in [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])] {
            *uses.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    let bad: Vec<_> = uses.iter().filter(|(_, n)| **n != 2).collect();
    assert!(bad.is_empty(), "{what}: {} edges not in exactly two triangles", bad.len());
    assert!(edges.values().all(|&s| s == 0), "{what}: an edge's two triangles are wound the same way");
    let euler = ids.len() as i64 - edges.len() as i64 + welded.len() as i64;
    assert_eq!(euler, 2, "{what}: Euler characteristic");
    ids.len()
}

fn soup(mesh: &metaballs::extract::mesh::IndexedMesh) -> Vec<[Vec3; 3]> {
    mesh.triangles.iter().map(|t| t.map(|i| mesh.positions[i as usize])).collect()
}

#[test]
fn samples_equal_to_iso_leave_every_mesh_closed_by_position() {
    for tie in &TIES {
        let what = format!("{} cells, radius {} cells, iso {}", tie.resolution, tie.k, tie.iso);
        let ties = tie.ties();
        assert!(ties >= 12, "{what}: only {ties} samples equal the iso level");
        let scene = tie.scene();

        let oracle = reference::extract(scene.spheres(), tie.iso, tie.grid());
        let triangles: Vec<[Vec3; 3]> = (0..oracle.triangle_count()).map(|k| oracle.triangle(k)).collect();
        let positions = assert_closed_by_position(&triangles, &format!("{what}, oracle"));
        // One vertex per crossed edge: welding by position joins exactly what welding by edge joins.
        assert_eq!(positions, oracle.weld_by_edge().positions.len(), "{what}: oracle vertices");

        let base = Settings { resolution: tie.resolution, iso: tie.iso, ..Settings::default() };
        let mut runs = vec![
            ("GPU", base.with_parameter("mesher", "gpu").unwrap()),
            ("CPU mesher", base.with_parameter("mesher", "cpu").unwrap()),
        ];
        let mut nets = base;
        nets.view.method = Method::SurfaceNets;
        runs.push(("surface nets", nets));
        for (name, settings) in runs {
            let mesh = with_renderer(settings, 16, 16, |o| {
                o.renderer.set_scene(scene.clone());
                pollster::block_on(o.renderer.extract_mesh())
            });
            assert_closed_by_position(&soup(&mesh), &format!("{what}, {name}"));
            // The STL has no indices: a reader welds its corners by position.
            let stl = encode(&mesh, MeshFormat::Stl, 25.0);
            let read = stl_io::read_stl(&mut std::io::Cursor::new(&stl)).expect("stl_io reads the STL");
            let triangles: Vec<[Vec3; 3]> = read
                .faces
                .iter()
                .map(|f| {
                    f.vertices.map(|i| {
                        let v = read.vertices[i];
                        Vec3::new(v[0], v[1], v[2])
                    })
                })
                .collect();
            assert_eq!(triangles.len(), mesh.triangles.len(), "{what}, {name}: STL triangles");
            assert_closed_by_position(&triangles, &format!("{what}, {name}, STL"));
            let distinct = read.faces.iter().all(|f| {
                let [a, b, c] = f.vertices;
                a != b && b != c && a != c
            });
            assert!(
                distinct,
                "{what}, {name}: the STL reader found a triangle with two corners at one point"
            );
        }
    }
}

#[test]
fn a_vertex_keeps_off_the_ends_of_its_edge() {
    // f at the ends: exactly the iso level at one, above it at the other.
    let grid = Grid { cells_per_axis: 64 };
    let construction = reference::Construction::default();
    for (fa, fb) in [(1.0f32, 3.0f32), (3.0, 1.0), (0.999_999_9, 5.0), (1.0, 1.000_000_1)] {
        let t = construction.edge_parameter(1.0, fa, fb);
        assert!(t > 0.0 && t < 1.0, "t = {t} for {fa} → {fb}");
        let (pa, pb) = (grid.point(UVec3::new(10, 20, 30)), grid.point(UVec3::new(11, 20, 30)));
        let (p, _) = reference::surface_vertex(&[], 1.0, construction, (pa, fa, false), (pb, fb, false));
        assert!(p != pa && p != pb, "{p} on an end of {pa} → {pb}");
        let along = (p - pa).as_dvec3().dot(DVec3::X) / grid.cell_size() as f64;
        assert!((0.0..=1.0).contains(&along));
    }
}
