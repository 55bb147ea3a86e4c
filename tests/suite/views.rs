//! The teaching views: each renders as its reference image shows and passes the check a person would
//! make; none changes the mesh; the overlays draw exactly what the oracle says (crossed cells, slice
//! contour); the construction toggles match the oracle run with the same choice; the inspector reads a
//! picked cell as the oracle does.

use crate::common;

use common::*;
use glam::{UVec3, Vec3};
use metaballs::draw::slice;
use metaballs::extract::decider;
use metaballs::extract::kernel::Terms;
use metaballs::extract::reference::{self, Construction, Grid};
use metaballs::offscreen::{Offscreen, write_png};
use metaballs::scene::params::view::{Blend, Interpolation, Kernel, Saddle, Slice};
use metaballs::teach::case_classes::case_classes;
use metaballs::{Scene, Settings};

const WIDTH: u32 = 320;
const HEIGHT: u32 = 240;

/// The teaching scene: five spheres at 16 cells, two seconds into their motion.
fn teaching_settings() -> Settings {
    Settings { seed: 1, sphere_count: 5, resolution: 16, ..Settings::default() }
}

/// Renders the teaching scene with parameters (name, text) applied, and writes it to tests/output.
fn render_with(o: &mut Offscreen, name: &str, parameters: &[(&str, &str)]) -> Vec<u8> {
    let mut settings = teaching_settings();
    for (key, text) in parameters {
        settings = settings.with_parameter(key, text).unwrap_or_else(|e| panic!("{key}={text}: {e}"));
    }
    o.renderer.set_settings(settings).unwrap();
    let pixels = o.render_rgba();
    write_png(&output_dir().join(format!("view_{name}.png")), WIDTH, HEIGHT, &pixels).unwrap();
    pixels
}

fn fraction(pixels: &[u8], test: impl Fn(&[u8]) -> bool) -> f32 {
    pixels.chunks(4).filter(|p| test(p)).count() as f32 / (pixels.len() / 4) as f32
}

fn differing(a: &[u8], b: &[u8]) -> f32 {
    let changed =
        a.chunks(4).zip(b.chunks(4)).filter(|(p, q)| p.iter().zip(*q).any(|(x, y)| x.abs_diff(*y) > 24));
    changed.count() as f32 / (a.len() / 4) as f32
}

const VIEWS: &[(&str, &[(&str, &str)])] = &[
    ("flat", &[("display", "flat")]),
    ("wireframe", &[("display", "wireframe")]),
    ("points", &[("display", "points")]),
    ("normals", &[("display", "normals")]),
    ("lattice", &[("grid", "lattice")]),
    ("cells", &[("grid", "cells")]),
    ("blocks", &[("grid", "blocks")]),
    ("color_area", &[("color_by", "area")]),
    ("color_quality", &[("color_by", "quality")]),
    ("color_case", &[("color_by", "case")]),
    ("slice", &[("slice", "z:0.1")]),
    ("ambiguous", &[("ambiguous", "on"), ("display", "wireframe")]),
    ("light_directional", &[("light", "directional")]),
    ("light_spot", &[("light", "spot"), ("spot_angle", "12")]),
    ("light_three", &[("light", "all"), ("ambient", "0.05"), ("specular", "1.2")]),
    ("orthographic", &[("projection", "orthographic")]),
    ("midpoint", &[("interpolation", "midpoint"), ("display", "flat")]),
    ("blend_max", &[("blend", "max")]),
];

#[test]
fn every_view_matches_its_reference_and_keeps_the_mesh() {
    with_renderer(teaching_settings(), WIDTH, HEIGHT, |o| {
        o.renderer.update(2.0).unwrap();
        let shaded = render_with(o, "shaded", &[]);
        let mesh = pollster::block_on(o.renderer.extract_mesh()).to_soup();
        for (name, parameters) in VIEWS {
            let pixels = render_with(o, name, parameters);
            assert_matches_reference(&format!("views/{name}"), WIDTH, HEIGHT, &pixels);
            assert!(differing(&shaded, &pixels) > 0.005, "{name} looks like the shaded view");
            let builds_differently = parameters.iter().any(|(k, _)| *k == "interpolation" || *k == "blend");
            if !builds_differently {
                let after = pollster::block_on(o.renderer.extract_mesh()).to_soup();
                assert_eq!(
                    after.triangle_count(),
                    mesh.triangle_count(),
                    "{name} changed the triangle count"
                );
                after.matches(&mesh, 0.0, 0.0).unwrap_or_else(|e| panic!("{name} changed the mesh: {e}"));
            }
        }
    });
}

#[test]
fn views_pass_the_checks_a_person_would_make() {
    with_renderer(teaching_settings(), WIDTH, HEIGHT, |o| {
        o.renderer.update(2.0).unwrap();
        let shaded = render_with(o, "shaded", &[]);
        let background = |p: &[u8]| p[2] >= p[0] && luminance(p) < 110.0;
        let surface = fraction(&shaded, |p| p[0] as i32 > p[2] as i32 + 30);
        assert!(surface > 0.05, "the shaded surface covers {surface}");

        // Wireframe: many thin dark lines over a paler surface, darker overall than shaded.
        let wire = render_with(o, "wireframe", &[("display", "wireframe")]);
        let on_surface: Vec<f32> = shaded
            .chunks(4)
            .zip(wire.chunks(4))
            .filter(|(s, _)| s[0] as i32 > s[2] as i32 + 30)
            .map(|(_, w)| luminance(w))
            .collect();
        let share = |test: &dyn Fn(f32) -> bool| {
            on_surface.iter().filter(|&&l| test(l)).count() as f32 / on_surface.len() as f32
        };
        let (lines, pale) = (share(&|l| l < 50.0), share(&|l| l > 90.0));
        assert!(lines > 0.15 && lines < 0.7, "{lines} of the surface is dark lines");
        assert!(pale > 0.2, "{pale} of the surface shows pale between the lines");
        assert!(mean_luminance(&wire) < mean_luminance(&shaded), "wireframe is darker than shaded");

        // Points: mostly background, with a dot per vertex.
        let points = render_with(o, "points", &[("display", "points")]);
        let empty = fraction(&points, background);
        assert!(
            empty > 0.9 && empty > fraction(&shaded, background) + 0.6 * surface,
            "{empty} is background"
        );
        assert!(fraction(&points, |p| p[0] as i32 > p[2] as i32 + 30) > 0.01, "the dots show");

        // Flat: one normal per face, so the brightness bends sharply where facets meet (a large second
        // difference along rows), where smooth shading bends gently.
        let flat = render_with(o, "flat", &[("display", "flat")]);
        let creases = |img: &[u8]| {
            (4..img.len() - 4)
                .step_by(4)
                .filter(|&i| img[i - 4] > 60 && img[i] > 60 && img[i + 4] > 60)
                .filter(|&i| (img[i - 4] as i32 - 2 * img[i] as i32 + img[i + 4] as i32).abs() > 8)
                .count()
        };
        let (faceted, smooth) = (creases(&flat), creases(&shaded));
        assert!(faceted > 2 * smooth, "creases: flat {faceted}, smooth {smooth}");

        // A spot light: narrowing its cone shrinks the lit patch; a hard edge lights more than a soft one.
        let lit = |o: &mut Offscreen, angle: &str, softness: &str| {
            let frame = render_with(
                o,
                "spot",
                &[("light", "spot"), ("spot_angle", angle), ("spot_softness", softness)],
            );
            fraction(&frame, |p| p[0] > 100)
        };
        let (narrow, wide) = (lit(o, "6", "0"), lit(o, "40", "0"));
        assert!(narrow > 0.0 && narrow < 0.7 * wide, "lit by a 6° cone {narrow}, by a 40° cone {wide}");
        let soft = lit(o, "6", "1");
        assert!(soft < narrow, "a soft edge {soft} lights less than a hard one {narrow}");
    });
}

#[test]
fn the_orthographic_camera_keeps_box_edges_parallel_and_the_framing() {
    with_renderer(teaching_settings(), WIDTH, HEIGHT, |o| {
        let edge = |r: &metaballs::Renderer, x: f32, z: f32| {
            r.project(Vec3::new(x, 1.0, z)) - r.project(Vec3::new(x, -1.0, z))
        };
        let parallel = |r: &metaballs::Renderer| {
            let (a, b) = (edge(r, -1.0, -1.0), edge(r, 1.0, 1.0));
            a.perp_dot(b).abs() / (a.length() * b.length())
        };
        let perspective_centre = o.renderer.project(Vec3::new(0.5, 0.3, 0.0) - Vec3::ZERO);
        let perspective_skew = parallel(&o.renderer);
        let settings = teaching_settings().with_parameter("projection", "orthographic").unwrap();
        o.renderer.set_settings(settings).unwrap();
        assert!(parallel(&o.renderer) < 1e-5, "vertical box edges stay parallel");
        assert!(perspective_skew > 1e-3, "in perspective they converge ({perspective_skew})");
        // The same framing: a point in the plane through the centre facing the camera stays put.
        let eye = settings.camera.eye();
        let right = Vec3::Y.cross(eye).normalize();
        let up = eye.cross(right).normalize();
        let p = 0.5 * right + 0.3 * up;
        let mut r = teaching_settings();
        r.view.projection = Default::default();
        o.renderer.set_settings(r).unwrap();
        let before = o.renderer.project(p);
        o.renderer.set_settings(settings).unwrap();
        assert!(o.renderer.project(p).distance(before) < 0.01, "{} vs {before}", o.renderer.project(p));
        let _ = perspective_centre;
    });
}

/// Count of cells the oracle finds the surface crossing.
fn oracle_crossed_cells(
    spheres: &[metaballs::Sphere],
    iso: f32,
    grid: Grid,
    construction: Construction,
) -> u32 {
    let n = grid.cells_per_axis;
    let mut count = 0;
    for z in 0..n {
        for y in 0..n {
            for x in 0..n {
                let case =
                    metaballs::teach::inspect::inspect(spheres, iso, grid, construction, UVec3::new(x, y, z))
                        .case;
                count += (case != 0 && case != 255) as u32;
            }
        }
    }
    count
}

/// The same segments, in any order and either direction, to a ten-thousandth of a cell.
fn assert_same_segments(mut actual: Vec<[Vec3; 2]>, expected: &mut [[Vec3; 2]], grid: Grid) {
    assert_eq!(actual.len(), expected.len(), "segment count");
    let key = |s: &[Vec3; 2]| {
        let m = (s[0] + s[1]) * 0.5;
        [m.x, m.y, m.z].map(|c| (c * 1e4).round() as i64)
    };
    actual.sort_by_key(key);
    expected.sort_by_key(key);
    let tolerance = 1e-4 * grid.cell_size();
    for (a, e) in actual.iter().zip(expected.iter()) {
        let same =
            |x: [Vec3; 2], y: &[Vec3; 2]| x[0].distance(y[0]) < tolerance && x[1].distance(y[1]) < tolerance;
        assert!(same(*a, e) || same([a[1], a[0]], e), "segment {a:?} vs {e:?}");
    }
}

#[test]
fn the_slice_joins_saddle_squares_by_its_rule_as_the_oracle_does() {
    with_renderer(Settings { resolution: 12, ..teaching_settings() }, WIDTH, HEIGHT, |o| {
        o.renderer.update(1.0).unwrap();
        let spheres = o.renderer.scene().spheres().to_vec();
        let grid = Grid { cells_per_axis: 12 };
        let iso = o.renderer.settings().iso;
        let rules = [Saddle::Table, Saddle::Center, Saddle::Decider];
        let contour = |slice, rule| slice::contour(&spheres, iso, grid, slice, Construction::default(), rule);
        // A plane of the grid on which the rules join some saddle square differently.
        let plane = (0..=12)
            .flat_map(|k| (0..3).map(move |axis| Slice { axis, position: k as f32 / 6.0 - 1.0 }))
            .find(|&slice| {
                let key = |s: &Vec<[Vec3; 2]>| format!("{s:?}");
                let table = key(&contour(slice, Saddle::Table));
                key(&contour(slice, Saddle::Center)) != table
                    || key(&contour(slice, Saddle::Decider)) != table
            })
            .expect("a grid plane where the saddle rules differ");
        for rule in rules {
            let text = format!("{}:{}", ["x", "y", "z"][plane.axis as usize], plane.position);
            let settings =
                o.renderer.settings().with_parameters(&[("slice", &text), ("saddle", rule.word())]).unwrap();
            o.renderer.set_settings(settings).unwrap();
            o.render();
            let readback = pollster::block_on(o.renderer.read_overlays()).expect("the views drew");
            assert_same_segments(readback.segments.clone(), &mut contour(plane, rule), grid);
        }
    });
}

#[test]
fn overlays_draw_what_the_oracle_finds() {
    with_renderer(Settings { resolution: 24, ..teaching_settings() }, WIDTH, HEIGHT, |o| {
        o.renderer.update(1.0).unwrap();
        let settings = o.renderer.settings().with_parameter("grid", "cells").unwrap();
        let settings = settings.with_parameter("slice", "y:-0.2").unwrap();
        o.renderer.set_settings(settings).unwrap();
        o.render();
        let spheres = o.renderer.scene().spheres().to_vec();
        let grid = Grid { cells_per_axis: 24 };
        let readback = pollster::block_on(o.renderer.read_overlays()).expect("the views drew");
        let cpu = reference::extract(&spheres, settings.iso, grid);
        assert_eq!(readback.draws[0].0 as usize, 3 * cpu.triangle_count(), "triangles drawn");
        let crossed = oracle_crossed_cells(&spheres, settings.iso, grid, Construction::default());
        assert_eq!(readback.draws[3], (24, crossed), "cells view: one box per crossed cell");

        // The slice's contour: marching squares on the oracle's samples of the same plane.
        let plane = Slice { axis: 1, position: -0.2 };
        let mut expected =
            slice::contour(&spheres, settings.iso, grid, plane, Construction::default(), Saddle::Table);
        assert!(expected.len() > 10);
        assert_same_segments(readback.segments.clone(), &mut expected, grid);
        let tolerance = 1e-4 * grid.cell_size();
        // On the plane, and on the surface: every endpoint is a vertex of the oracle's mesh.
        let y = grid.point(UVec3::new(0, plane.plane(24), 0)).y;
        for p in expected.iter().flatten() {
            assert_eq!(p.y, y);
            assert!(cpu.positions.iter().any(|v| v.distance(*p) < tolerance), "{p} is a mesh vertex");
        }
    });
}

#[test]
fn midpoint_vertices_blend_by_max_and_the_kernels_match_the_oracle() {
    let terms = |kernel, blend| Terms { kernel, blend, ..Terms::default() };
    for (interpolation, terms) in [
        (Interpolation::Midpoint, Terms::default()),
        (Interpolation::Linear, terms(Kernel::InverseSquare, Blend::Max)),
        (Interpolation::Linear, terms(Kernel::Blinn, Blend::Sum)),
        (Interpolation::Linear, Terms { blobbiness: 0.5, ..terms(Kernel::Blinn, Blend::Sum) }),
        (Interpolation::Linear, terms(Kernel::Wyvill, Blend::Sum)),
        (Interpolation::Midpoint, terms(Kernel::Wyvill, Blend::Max)),
    ] {
        with_renderer(settings(7, 6, 32, 1.0), 16, 16, |o| {
            o.renderer.update(0.5).unwrap();
            let mut s = *o.renderer.settings();
            s.view.interpolation = interpolation;
            terms.set_in(&mut s.view);
            let spheres = o.renderer.scene().spheres().to_vec();
            s.iso = conditioned_level(&spheres, s.iso, 32, terms);
            o.renderer.set_settings(s).unwrap();
            let grid = Grid { cells_per_axis: 32 };
            let construction = Construction { interpolation, terms, ..Construction::default() };
            let gpu = pollster::block_on(o.renderer.extract_mesh()).to_soup();
            let cpu = reference::extract_with(&spheres, s.iso, grid, construction);
            let plain = reference::extract(&spheres, s.iso, grid);
            assert_eq!(gpu.triangle_count(), cpu.triangle_count(), "{construction:?}");
            let close = gpu.matches(&cpu, 1e-4 * grid.cell_size(), normal_tolerance(terms));
            close.unwrap_or_else(|e| panic!("{construction:?}: {e}"));
            assert!(
                cpu.matches(&plain, 1e-4 * grid.cell_size(), 0.01f32.to_radians()).is_err(),
                "it changes the mesh"
            );
        });
    }
}

#[test]
fn the_inspector_reads_the_picked_cell_as_the_oracle_does() {
    let settings = Settings { resolution: 16, ..Settings::default() };
    with_renderer(settings, WIDTH, HEIGHT, |o| {
        let spheres = vec![sphere([0.1, 0.05, 0.0], 0.5), sphere([-0.45, -0.1, 0.1], 0.3)];
        o.renderer.set_scene(Scene::from_spheres(spheres.clone()).unwrap());
        let grid = Grid { cells_per_axis: 16 };
        let centre = o.renderer.project(Vec3::new(0.1, 0.05, 0.0));
        let cell = o.renderer.pick(centre.x, centre.y).expect("a cell under the sphere's centre");
        // The cell holding the first triangle the ray meets in the oracle's mesh.
        let mesh = reference::extract(&spheres, 1.0, grid);
        let eye = settings.camera.eye();
        let direction = (Vec3::new(0.1, 0.05, 0.0) - eye).normalize();
        let hit = (0..mesh.triangle_count())
            .filter_map(|k| {
                metaballs::teach::inspect::ray_triangle(eye, direction, mesh.triangle(k)).map(|t| (t, k))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .expect("the ray meets the mesh");
        let [a, b, c] = mesh.triangle(hit.1);
        let centroid = (a + b + c) / 3.0;
        let holder = ((centroid - grid.point(UVec3::ZERO)) / grid.cell_size()).floor().as_uvec3();
        assert_eq!(cell, holder, "picked the cell whose triangle is in front");

        let report = o.renderer.inspect(cell);
        let values = reference::sample_field(&spheres, grid);
        for (c, offset) in metaballs::extract::tables::CORNER_OFFSETS.iter().enumerate() {
            assert_eq!(report.corners[c], values[grid.point_index(cell + UVec3::from_array(*offset))]);
        }
        let case = (0..8).fold(0u8, |m, c| m | ((report.corners[c] > 1.0) as u8) << c);
        assert_eq!(report.case, case);
        assert_eq!(report.class, case_classes()[case as usize]);
        assert_eq!(
            report.triangles.len(),
            metaballs::extract::tables::CASE_TRIANGLES[case as usize] as usize
        );
        for e in &report.edges {
            assert!(mesh.positions.iter().any(|v| v.distance(e.vertex) < 1e-6), "edge {} vertex", e.edge);
        }
        // The background picks nothing.
        assert_eq!(o.renderer.pick(2.0, 2.0), None);
        // In the cells view a click picks the first crossed cell's box the ray enters, which is no
        // farther from the eye than the surface's cell.
        o.renderer.set_settings(o.renderer.settings().with_parameter("grid", "cells").unwrap()).unwrap();
        let boxed = o.renderer.pick(centre.x, centre.y).expect("a box under the sphere's centre");
        assert!(grid.point(boxed).distance(eye) <= grid.point(cell).distance(eye) + 1e-6);
        assert_ne!(o.renderer.inspect(boxed).case, 0);
        o.renderer.set_settings(o.renderer.settings().with_parameter("grid", "none").unwrap()).unwrap();
        // Selected, the cell is drawn highlighted; deselected, the frame is as before.
        let plain = o.render_rgba();
        o.renderer.select_cell(Some(cell));
        let highlighted = o.render_rgba();
        write_png(&output_dir().join("view_selected.png"), WIDTH, HEIGHT, &highlighted).unwrap();
        assert!(differing(&plain, &highlighted) > 0.002, "the selected cell shows");
        assert_matches_reference("views/selected", WIDTH, HEIGHT, &highlighted);
        o.renderer.select_cell(None);
        assert_eq!(differing(&plain, &o.render_rgba()), 0.0);
    });
}

/// Faces of crossed cells whose two inside corners sit on a diagonal, by the oracle, and how many of
/// them the asymptotic decider joins.
fn oracle_ambiguous_faces(spheres: &[metaballs::Sphere], iso: f32, grid: Grid) -> (usize, usize) {
    let n = grid.cells_per_axis;
    let values = reference::sample_field(spheres, grid);
    let value = |p: UVec3| values[grid.point_index(p)];
    let (mut count, mut joined) = (0, 0);
    for z in 0..n {
        for y in 0..n {
            for x in 0..n {
                let cell = UVec3::new(x, y, z);
                for axis in 0..3 {
                    for side in 0..2 {
                        let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
                        let corner = |a: u32, b: u32| {
                            let mut o = [0u32; 3];
                            o[axis] = side;
                            o[u] = a;
                            o[v] = b;
                            value(cell + UVec3::from_array(o))
                        };
                        let f = [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)];
                        let inside = f.map(|f| f > iso);
                        if inside[0] == inside[2] && inside[1] == inside[3] && inside[0] != inside[1] {
                            count += 1;
                            joined += decider::saddle_above(f, iso) as usize;
                        }
                    }
                }
            }
        }
    }
    (count, joined)
}

#[test]
fn ambiguous_faces_are_marked_where_the_oracle_finds_them() {
    // Two small spheres on diagonal corners of a cell face: the face's other two corners are outside.
    let camera = metaballs::Camera { distance: 1.6, ..Default::default() };
    let settings = Settings { resolution: 16, antialiasing: false, camera, ..Settings::default() };
    with_renderer(settings, WIDTH, HEIGHT, |o| {
        let grid = Grid { cells_per_axis: 16 };
        let magenta = |p: &[u8]| p[0] > 200 && p[2] > 170 && p[0] as i32 - p[1] as i32 > 80;
        // The joining the triangles follow: amber where the decider agrees, red where it does not.
        let amber = |p: &[u8]| p[0] > 200 && p[1] > 130 && p[2] < 60;
        let red = |p: &[u8]| p[0] > 200 && p[1] < 40 && p[2] < 40;
        let mut marked = Vec::new();
        // Apart; on two diagonal corners of a face, which the decider joins and the classic table
        // cuts; and off those corners, away from the face, each corner barely inside its sphere,
        // which the decider cuts too (the face's saddle, the mean of its values, is below the level).
        let h = grid.cell_size();
        let corner = |x, y| grid.point(UVec3::new(x, y, 8));
        let off = Vec3::new(0.5, 0.5, 0.0) * h;
        let scenes = [
            ("apart", corner(8, 8) + 0.003, corner(14, 14) + 0.003, 0.07),
            ("on corners", corner(8, 8) + 0.003, corner(9, 9) + 0.003, 0.07),
            ("off corners", corner(8, 8) - off, corner(9, 9) + off, 0.5 * 2f32.sqrt() * h * 1.02),
        ];
        for (scene, a, b, radius) in scenes {
            let spheres = vec![sphere(a.to_array(), radius), sphere(b.to_array(), radius)];
            o.renderer.set_scene(Scene::from_spheres(spheres.clone()).unwrap());
            let (faces, joined) = oracle_ambiguous_faces(&spheres, 1.0, grid);
            for table in ["classic", "decider"] {
                let settings = o.renderer.settings().with_parameter("ambiguous", "on").unwrap();
                o.renderer.set_settings(settings.with_parameter("table", table).unwrap()).unwrap();
                let pixels = o.render_rgba();
                let name = format!("view_ambiguous_{}_{table}.png", scene.replace(' ', "_"));
                write_png(&output_dir().join(name), WIDTH, HEIGHT, &pixels).unwrap();
                let seen = [magenta, amber, red].map(|test| fraction(&pixels, test));
                marked.push((scene, radius, table, faces, joined, seen));
            }
        }
        for &(scene, radius, table, faces, joined, [crosses, agreed, disagreed]) in &marked {
            let what = format!(
                "{scene}, radius {radius}, {table}: {faces} ambiguous faces, {joined} joined \
                 by the decider; crosses {crosses}, agreeing {agreed}, disagreeing {disagreed}"
            );
            assert_eq!(faces == 0, crosses == 0.0, "{what}");
            // Classic cuts every face apart: red exactly where the decider would join.
            let wrong = if table == "classic" { joined } else { 0 };
            assert_eq!(wrong > 0, disagreed > 0.0, "{what}");
            assert_eq!(faces > wrong, agreed > 0.0, "{what}");
        }
        assert_eq!(marked[0].3, 0, "separate spheres have no ambiguous face");
        assert!(
            marked[2].4 > 0 && marked[4].4 < marked[4].3,
            "the scenes hold faces the decider joins and faces it cuts: {marked:?}"
        );
    });
}
