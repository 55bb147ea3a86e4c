//! The dual methods, surface nets and dual contouring, chosen by `method=` and run through the
//! renderer on the scenes every extractor meets: a closed surface, one vertex per crossed cell inside
//! the box, the same blobs as marching cubes, and the volume marching cubes encloses. Then what dual
//! contouring is for: on a union of two spheres, the crease where they meet stays sharp.

use crate::common;

use common::scenes::oracle_scenes;
use common::*;
use glam::{UVec3, Vec3};
use metaballs::extract::cpu::dual::STRAYED;
use metaballs::extract::cpu::elsewhere::Meshers;
use metaballs::extract::cpu::{DualContouringMesher, SurfaceNetsMesher};
use metaballs::extract::kernel::Terms;
use metaballs::extract::mesh::IndexedMesh;
use metaballs::extract::reference::{self, Construction, Grid};
use metaballs::extract::tables::CORNER_OFFSETS;
use metaballs::scene::Sphere;
use metaballs::scene::params::view::{Blend, MeshOn, Method};
use metaballs::{Scene, Settings};

/// The cells whose corners lie on both sides of `iso`, counted on the oracle's samples.
fn crossed_cells(values: &[f32], iso: f32, grid: Grid) -> usize {
    let n = grid.cells_per_axis;
    let mut crossed = 0;
    for z in 0..n {
        for y in 0..n {
            for x in 0..n {
                let inside = CORNER_OFFSETS
                    .iter()
                    .filter(|o| values[grid.point_index(UVec3::new(x, y, z) + UVec3::from_array(**o))] > iso)
                    .count();
                crossed += (inside % 8 != 0) as usize;
            }
        }
    }
    crossed
}

#[test]
fn surface_nets_make_one_vertex_per_crossed_cell_and_closed_surfaces() {
    dual_method_meets_the_shared_scenes(Method::SurfaceNets, MeshOn::Cpu, "surface-nets");
    dual_method_meets_the_shared_scenes(Method::SurfaceNets, MeshOn::Gpu, "gpu-surface-nets");
}

#[test]
fn dual_contouring_makes_one_vertex_per_crossed_cell_and_closed_surfaces() {
    dual_method_meets_the_shared_scenes(Method::DualContouring, MeshOn::Cpu, "dual-contouring");
    dual_method_meets_the_shared_scenes(Method::DualContouring, MeshOn::Gpu, "gpu-dual-contouring");
}

fn dual_method_meets_the_shared_scenes(method: Method, mesh_on: MeshOn, source: &str) {
    let scenes = oracle_scenes(30);
    with_renderer(settings(1, 1, 16, 1.0), 16, 16, |o| {
        let mut with_surface = 0;
        let mut counts = Vec::new();
        for scene in &scenes {
            let what = &scene.what;
            let iso =
                conditioned_level(&scene.spheres, scene.iso, scene.resolution, scene.construction.terms);
            let mut settings = Settings { resolution: scene.resolution, iso, ..Settings::default() };
            settings.view.interpolation = scene.construction.interpolation;
            scene.construction.terms.set_in(&mut settings.view);
            settings.view.case_table = scene.construction.case_table;
            settings.view.method = method;
            settings.view.mesh_on = mesh_on;
            o.renderer.set_settings(settings).unwrap();
            o.renderer.set_scene(Scene::from_spheres(scene.spheres.clone()).unwrap());
            let nets = pollster::block_on(o.renderer.extract_mesh());
            assert_eq!(o.renderer.mesh_source(), source, "{what}");
            let grid = Grid { cells_per_axis: scene.resolution };
            let values = reference::sample_blended_field(&scene.spheres, grid, scene.construction.terms);
            assert_eq!(nets.positions.len(), crossed_cells(&values, iso, grid), "{what}: vertices");
            // Each vertex is a mean of crossings on its cell's edges or within a quarter cell of its
            // cell, so it lies in the grid's box (give or take that quarter).
            let cell = grid.cell_size();
            for p in &nets.positions {
                let rel = (*p - grid.point(UVec3::ZERO)) / cell;
                assert!(rel.min_element() >= -1e-3 && rel.max_element() <= scene.resolution as f32 + 1e-3);
            }
            let shape = nets.shape();
            assert!(shape.closed, "{what}: open {source} mesh {shape:?}");
            let oracle = reference::extract_with(&scene.spheres, iso, grid, scene.construction);
            let cubes = oracle.weld_by_edge();
            // One vertex per cell joins the sheets an ambiguous cell separates in marching cubes, so
            // surface nets may join blobs but never split one.
            assert!(shape.components <= cubes.shape().components, "{what}: blobs");
            if oracle.triangle_count() > 0 {
                with_surface += 1;
                let (v_nets, v_cubes) = (nets.enclosed_volume(), cubes.enclosed_volume());
                // Both approximate the same solid to within a few cells' worth of its surface.
                assert!(v_nets > 0.0, "{what}: volume {v_nets}");
                let area_cells = cubes.positions.len() as f64 * (cell as f64).powi(3);
                assert!((v_nets - v_cubes).abs() <= area_cells, "{what}: volume {v_nets} against {v_cubes}");
                // Two triangles per crossed edge, where marching cubes puts one vertex.
                assert_eq!(
                    nets.triangles.len(),
                    2 * cubes.positions.len(),
                    "{what}: a quad per crossed edge"
                );
                counts.push((
                    nets.positions.len(),
                    nets.triangles.len(),
                    cubes.positions.len(),
                    oracle.triangle_count(),
                ));
            }
        }
        let total = counts.iter().fold([0; 4], |t, c| [t[0] + c.0, t[1] + c.1, t[2] + c.2, t[3] + c.3]);
        println!(
            "{source}: {} vertices, {} triangles; marching cubes: {} vertices, {} triangles",
            total[0], total[1], total[2], total[3]
        );
        assert!(with_surface >= 40, "only {with_surface} scenes had a surface");
    });
}

#[test]
fn surface_nets_follow_the_setting_and_leave_level_of_detail_to_marching_cubes() {
    with_renderer(settings(3, 4, 32, 1.0), 32, 32, |o| {
        let mut settings = *o.renderer.settings();
        settings.view.method = Method::SurfaceNets;
        settings.view.mesh_on = MeshOn::Cpu;
        o.renderer.set_settings(settings).unwrap();
        o.render();
        assert_eq!(o.renderer.mesh_source(), "surface-nets");
        settings.view.lod = true;
        o.renderer.set_settings(settings).unwrap();
        o.render();
        assert!(o.renderer.mesh_capabilities().lod, "lod=on meshes with transition cells");
        settings.view.lod = false;
        settings.view.method = Method::MarchingCubes;
        o.renderer.set_settings(settings).unwrap();
        o.render();
        assert_eq!(o.renderer.mesh_source(), "cpu");
        settings.view.method = Method::SurfaceNets;
        settings.view.mesh_on = MeshOn::Gpu;
        o.renderer.set_settings(settings).unwrap();
        o.render();
        assert_eq!(o.renderer.mesh_source(), "gpu-surface-nets");
    });
}

/// The circle where two overlapping balls' spheres meet: its centre, its axis (from the first ball's
/// centre to the second's) and its radius.
pub(crate) struct Crease {
    centre: Vec3,
    axis: Vec3,
    radius: f32,
}

impl Crease {
    pub(crate) fn of((ca, ra): (Vec3, f32), (cb, rb): (Vec3, f32)) -> Crease {
        let d = ca.distance(cb);
        let axis = (cb - ca) / d;
        let along = (d * d + ra * ra - rb * rb) / (2.0 * d);
        Crease { centre: ca + axis * along, axis, radius: (ra * ra - along * along).sqrt() }
    }

    fn distance(&self, p: Vec3) -> f32 {
        let q = p - self.centre;
        let h = q.dot(self.axis);
        (h * h + ((q - self.axis * h).length() - self.radius).powi(2)).sqrt()
    }
}

/// Distance from `p` to the boundary of the union of two balls (centre, radius): to the visible part
/// of either sphere, or to the circle where they meet, whichever is nearest.
fn union_distance(p: Vec3, (ca, ra): (Vec3, f32), (cb, rb): (Vec3, f32)) -> f32 {
    let mut best = Crease::of((ca, ra), (cb, rb)).distance(p);
    for ((c, r), (other, other_r)) in [((ca, ra), (cb, rb)), ((cb, rb), (ca, ra))] {
        let foot = c + (p - c).normalize() * r;
        if foot.distance(other) >= other_r {
            best = best.min((p.distance(c) - r).abs());
        }
    }
    best
}

/// The distance from `x` to the triangle `[a, b, c]`: to its plane where `x`'s foot falls inside it,
/// else to the nearest of its sides.
fn triangle_distance(x: Vec3, [a, b, c]: [Vec3; 3]) -> f32 {
    let n = (b - a).cross(c - a);
    if n.length_squared() > 0.0 {
        let n = n.normalize();
        let foot = x - n * n.dot(x - a);
        let inside = [(a, b), (b, c), (c, a)].iter().all(|&(p, q)| (q - p).cross(foot - p).dot(n) >= 0.0);
        if inside {
            return n.dot(x - a).abs();
        }
    }
    let segment = |p: Vec3, q: Vec3| {
        let t = ((x - p).dot(q - p) / (q - p).length_squared().max(f32::MIN_POSITIVE)).clamp(0.0, 1.0);
        x.distance(p + (q - p) * t)
    };
    segment(a, b).min(segment(b, c)).min(segment(c, a))
}

/// How far, in cells, the exact crease (the circle where the two spheres meet) lies from `mesh`
/// at its farthest: the largest distance from a point of the circle to the nearest triangle. Marching
/// cubes and surface nets cut across the fold, so the circle lies under their meshes.
pub(crate) fn crease_error(mesh: &IndexedMesh, crease: &Crease, cell: f32) -> f32 {
    let u = crease.axis.any_orthonormal_vector();
    let v = crease.axis.cross(u);
    let triangles: Vec<[Vec3; 3]> =
        mesh.triangles.iter().map(|t| t.map(|i| mesh.positions[i as usize])).collect();
    (0..720)
        .map(|k| {
            let angle = k as f32 / 720.0 * std::f32::consts::TAU;
            let x = crease.centre + (u * angle.cos() + v * angle.sin()) * crease.radius;
            let near = triangles.iter().filter(|t| t[0].distance(x) < 3.0 * cell);
            near.map(|&t| triangle_distance(x, t)).fold(f32::INFINITY, f32::min) / cell
        })
        .fold(0.0, f32::max)
}

/// The crease scene: two spheres off the grid's symmetries, meeting in a circle of radius 0.4.
pub(crate) fn crease_spheres() -> [Sphere; 2] {
    [
        Sphere::from_signed(Vec3::new(-0.31, 0.023, -0.017), 0.5, Vec3::ZERO),
        Sphere::from_signed(Vec3::new(0.29, 0.013, 0.031), 0.5, Vec3::ZERO),
    ]
}

#[test]
fn dual_contouring_keeps_the_crease_of_a_union_of_two_spheres_sharp() {
    // The union of the two spheres' terms (blend=max) folds where they meet; 32 cells.
    let spheres = crease_spheres();
    let balls = spheres.map(|s| (s.center, s.radius));
    let crease = Crease::of(balls[0], balls[1]);
    let grid = Grid { cells_per_axis: 32 };
    let construction =
        Construction { terms: Terms { blend: Blend::Max, ..Terms::default() }, ..Construction::default() };
    let cell = grid.cell_size();
    let cubes = reference::extract_with(&spheres, 1.0, grid, construction).weld_by_edge();
    let mut nets = SurfaceNetsMesher::default();
    nets.mesh(&spheres, 1.0, grid, construction);
    let mut dual = DualContouringMesher::default();
    dual.mesh(&spheres, 1.0, grid, construction);
    let meshes = [
        ("marching cubes", cubes),
        ("surface nets", nets.to_indexed()),
        ("dual contouring", dual.to_indexed()),
    ];
    let errors = meshes.each_ref().map(|(name, mesh)| {
        let error = crease_error(mesh, &crease, cell);
        println!(
            "{name}: {} triangles, largest distance along the crease {error:.4} cells",
            mesh.triangles.len()
        );
        assert!(mesh.shape().closed, "{name}: {:?}", mesh.shape());
        error
    });
    let [cubes, nets, dual_error] = errors;
    assert!(dual_error <= 0.1, "dual contouring strays {dual_error} cells from the crease");
    assert!(dual_error <= 0.5 * cubes && dual_error <= 0.5 * nets, "{errors:?}");
    // The crease's cells are ranked as edges: at least one per cell the circle passes through.
    let ranks = |r: u8| dual.placed.iter().filter(|&&m| m & 3 == r).count();
    let mesh = dual.to_indexed();
    let on_crease = (mesh.positions.iter().zip(&dual.placed))
        .filter(|(p, m)| *m & 3 == 2 && crease.distance(**p) < cell)
        .count();
    let strayed = dual.placed.iter().filter(|&&m| m & STRAYED != 0).count();
    println!("ranks 1/2/3: {}/{}/{}, {strayed} minimisers outside their cell", ranks(1), ranks(2), ranks(3));
    let circumference = std::f32::consts::TAU * crease.radius / cell;
    assert!(
        on_crease as f32 >= circumference,
        "{on_crease} edge vertices along a crease {circumference} cells long"
    );
    // The edge vertices lie on the surface, where marching cubes' crossings would.
    let off = (mesh.positions.iter().zip(&dual.placed))
        .filter(|(_, m)| *m & 3 == 2)
        .map(|(p, _)| union_distance(*p, balls[0], balls[1]) / cell)
        .fold(0.0, f32::max);
    println!("edge vertices at most {off:.4} cells off the surface");
    assert!(off <= 0.1, "an edge vertex {off} cells off the surface");
    // The balls themselves are faces: each of their cells' normals agree within a few degrees.
    assert!(ranks(1) > 4 * ranks(2), "{} faces", ranks(1));
}

#[test]
fn dual_contourings_views_show_its_ranks_and_crossings_on_a_fresh_renderer() {
    // On the CPU, the mesher's marks and crossings are uploaded; on the GPU, the dual pass writes them.
    let [cpu, gpu] = ["cpu", "gpu"].map(views_show_ranks_and_crossings);
    // The same marks: the two rank pictures differ in a few edge pixels at most.
    let differing = cpu.chunks(4).zip(gpu.chunks(4));
    let differing = differing.filter(|(a, b)| a.iter().zip(*b).any(|(x, y)| x.abs_diff(*y) > 24)).count();
    let share = differing as f32 / (cpu.len() / 4) as f32;
    println!("the CPU's and the GPU's rank pictures differ in {share:.4} of their pixels");
    assert!(share < 0.002, "{share} of the rank pictures differ");
}

/// The rank view's picture, after checking what each view shows.
fn views_show_ranks_and_crossings(mesh_on: &str) -> Vec<u8> {
    let blue = |p: &[u8]| p[2] as i32 > p[0] as i32 + 60 && p[2] as i32 > p[1] as i32 + 30;
    let magenta = |p: &[u8]| p[0] as i32 > p[1] as i32 + 60 && p[2] as i32 > p[1] as i32 + 60;
    let yellow = |p: &[u8]| p[0] > 170 && p[1] > 130 && (p[2] as i32) < p[1] as i32 - 60;
    let share = |pixels: &[u8], test: &dyn Fn(&[u8]) -> bool| {
        pixels.chunks(4).filter(|p| test(p)).count() as f32 / (pixels.len() / 4) as f32
    };
    let picture = |method: &str, view: &str| {
        // A renderer of its own for each picture: the views count what to draw from what this
        // mesher wrote, with nothing left from an earlier frame.
        with_renderer(settings(1, 2, 32, 1.0), 320, 240, |o| {
            o.renderer.set_scene(Scene::from_spheres(crease_spheres().to_vec()).unwrap());
            let mut settings = *o.renderer.settings();
            settings = settings.with_parameter("blend", "max").unwrap();
            settings = settings.with_parameter("method", method).unwrap();
            settings = settings.with_parameter("mesh-on", mesh_on).unwrap();
            for (key, value) in view.split('&').filter_map(|pair| pair.split_once('=')) {
                settings = settings.with_parameter(key, value).unwrap();
            }
            o.renderer.set_settings(settings).unwrap();
            let pixels = o.render_rgba();
            let mesher = method.replace('_', "-");
            let expected = if mesh_on == "gpu" { format!("gpu-{mesher}") } else { mesher };
            assert_eq!(o.renderer.mesh_source(), expected);
            let name = format!("dual_{mesh_on}_{method}_{}.png", view.replace(['=', '&'], "_"));
            metaballs::offscreen::write_png(&output_dir().join(name), 320, 240, &pixels).unwrap();
            pixels
        })
    };
    // Ranks: the balls are faces (blue), the crease between them an edge (magenta).
    let ranks = picture("dual_contouring", "color_by=rank");
    let (faces, edges) = (share(&ranks, &blue), share(&ranks, &magenta));
    println!("{mesh_on}: rank view: {faces:.3} of the picture faces, {edges:.4} edges");
    assert!(faces > 0.05 && edges > 0.001 && edges < faces / 5.0, "faces {faces}, edges {edges}");
    // Surface nets have no QEF: the view falls back to the material's colour, drawn all the same.
    let nets = picture("surface_nets", "color_by=rank&display=wireframe");
    assert_eq!(share(&nets, &magenta), 0.0);
    assert!(share(&nets, &|p: &[u8]| p[0] > 60) > 0.05, "surface nets' wireframe is drawn");
    // The crossings' normals: yellow segments, with dual contouring only.
    let crossings = share(&picture("dual_contouring", "display=normals"), &yellow);
    let none = share(&picture("surface_nets", "display=normals"), &yellow);
    println!("{mesh_on}: crossing segments: {crossings:.4} of the picture; {none:.4} with surface nets");
    assert!(crossings > 0.005 && none < crossings / 20.0, "{crossings} against {none}");
    ranks
}

#[test]
fn the_rank_view_of_a_still_figure_meshed_elsewhere_shows_the_ranks() {
    // A paused figure: its first mesh made by the mesher worker, then the rank view asked for. The
    // worker's mesh carries no ranks, so the figure meshes again on its own thread.
    let magenta = |p: &[u8]| p[0] as i32 > p[1] as i32 + 60 && p[2] as i32 > p[1] as i32 + 60;
    with_renderer(settings(1, 2, 32, 1.0), 320, 240, |o| {
        o.renderer.set_scene(Scene::from_spheres(crease_spheres().to_vec()).unwrap());
        let mut settings = *o.renderer.settings();
        settings = settings.with_parameter("blend", "max").unwrap();
        settings = settings.with_parameter("method", "dual_contouring").unwrap();
        settings = settings.with_parameter("mesh-on", "cpu").unwrap();
        o.renderer.set_settings(settings).unwrap();
        let job = o.renderer.cpu_job().expect("dual contouring is meshed on the CPU");
        o.renderer.give_mesh(Meshers::default().mesh(&job).unwrap());
        o.render();
        settings = settings.with_parameter("color_by", "rank").unwrap();
        o.renderer.set_settings(settings).unwrap();
        assert_eq!(o.renderer.cpu_job(), None, "the rank view is meshed on the figure's own thread");
        let pixels = o.render_rgba();
        let edges = pixels.chunks(4).filter(|p| magenta(p)).count();
        assert!(edges > 20, "the crease's edge vertices show in the rank view: {edges} pixels");
    });
}
