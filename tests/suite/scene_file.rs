//! Scene documents: saved and loaded they give the same scene and the same mesh; every bad document is
//! refused with a message naming the field and the value (the page keeps its scene: tests/e2e).

use crate::common;

use common::*;
use glam::Vec3;
use metaballs::extract::cpu::mesher::CpuMesher;
use metaballs::extract::reference::{Construction, Grid};
use metaballs::scene::file::SceneFile;
use metaballs::scene::params::Value;
use metaballs::scene::sphere::{parse_spheres_text, spheres_text};
use metaballs::{Settings, Sphere};
use rand::{RngExt, SeedableRng};

fn mesh(spheres: &[Sphere], settings: &Settings) -> (Vec<f32>, Vec<u32>) {
    let mut mesher = CpuMesher::new();
    let grid = Grid { cells_per_axis: settings.resolution };
    mesher.mesh(spheres, settings.iso, grid, Construction::default());
    (mesher.vertices.clone(), mesher.indices.clone())
}

fn a_scene() -> SceneFile {
    let mut rng = rand_pcg::Pcg32::seed_from_u64(11);
    let spheres = (0..7)
        .map(|_| {
            let radius: f32 = rng.random_range(0.1..0.3);
            let limit = 1.0 - radius;
            let mut c = || rng.random_range(-limit..limit);
            let center = Vec3::new(c(), c(), c());
            let velocity = Vec3::new(rng.random_range(-0.5..0.5), 0.0, rng.random_range(-0.5..0.5));
            Sphere { center, radius, velocity, charge: 1.0 }
        })
        .collect();
    let text = |s: &str| Value::Text(s.into());
    let settings = vec![
        ("iso", Value::Number(0.85)),
        ("resolution", Value::Number(40.0)),
        ("speed", Value::Number(0.5)),
        ("paused", Value::Boolean(true)),
        ("yaw", Value::Number(-42.5)),
        ("color", text("#3366cc")),
        ("display", text("wireframe")),
        ("light", text("point,spot")),
        ("slice", text("z:0.25")),
    ];
    SceneFile { spheres, settings }
}

#[test]
fn a_saved_scene_loads_as_the_same_scene_and_mesh() {
    let scene = a_scene();
    let json = scene.to_json();
    let back = SceneFile::parse(&json).unwrap();
    assert_eq!(back, scene, "identical spheres (bit for bit) and settings");
    assert_eq!(back.to_json(), json, "and the same document again");

    let settings = scene.applied_to(Settings::default()).unwrap();
    assert_eq!(settings.iso, 0.85);
    assert_eq!(settings.resolution, 40);
    assert_eq!(settings.sphere_count, 7);
    assert_eq!(settings.camera.yaw_degrees, -42.5);
    assert!((settings.material.base_color - Vec3::new(0.0331, 0.1329, 0.6038)).abs().max_element() < 1e-3);
    assert_eq!(back.applied_to(Settings::default()).unwrap(), settings);
    let (a, b) = (mesh(&scene.spheres, &settings), mesh(&back.spheres, &settings));
    assert!(!a.1.is_empty());
    assert_eq!(a, b, "identical mesh");

    // Many random spheres round-trip exactly too: numbers are written as short as they read back.
    let mut rng = rand_pcg::Pcg32::seed_from_u64(3);
    for _ in 0..200 {
        let radius: f32 = rng.random_range(0.01..0.9);
        let limit = 1.0 - radius;
        let s = Sphere {
            center: Vec3::new(rng.random_range(-limit..limit), rng.random_range(-limit..limit), 0.0),
            radius,
            velocity: Vec3::new(rng.random_range(-99.0..99.0), 0.0, 0.0),
            charge: if rng.random_bool(0.3) { -1.0 } else { 1.0 },
        };
        let file = SceneFile { spheres: vec![s], settings: vec![] };
        assert_eq!(SceneFile::parse(&file.to_json()).unwrap().spheres, vec![s]);
    }
}

#[test]
fn the_link_form_carries_hand_built_spheres() {
    let spheres = vec![sphere([-0.3, 0.0, 0.0], 0.35), sphere([0.4, 0.1, -0.2], 0.3)];
    let text = spheres_text(&spheres);
    assert_eq!(text, "-0.3,0,0,0.35;0.4,0.1,-0.2,0.3");
    assert_eq!(parse_spheres_text(&text).unwrap(), spheres);
    let value =
        metaballs::scene::params::parse_parameter("balls", " -0.3,0,0,0.35 ; 0.4,0.1,-0.2,0.3 ").unwrap();
    assert_eq!(value, Value::Text(text));
    let e = metaballs::scene::params::parse_parameter("balls", "0,0,0,1.5").unwrap_err().to_string();
    assert!(e.contains("sphere radius must be between 0.01 and 1, got 1.5"), "{e}");
    // A negative radius is a subtracting sphere.
    let dented = parse_spheres_text("0,0,0,0.5;0.2,0,0,-0.25").unwrap();
    assert_eq!((dented[1].charge, dented[1].radius), (-1.0, 0.25));
    assert_eq!(spheres_text(&dented), "0,0,0,0.5;0.2,0,0,-0.25");
}

#[test]
fn scene_files_carry_the_charge_and_files_without_it_add() {
    let doc = |sphere: &str| format!(r#"{{"format":"metaballs-scene","version":1,"spheres":[{sphere}]}}"#);
    let plain = SceneFile::parse(&doc(r#"{"center":[0,0,0],"radius":0.3}"#)).unwrap();
    assert_eq!(plain.spheres[0].charge, 1.0);
    assert!(!plain.to_json().contains("charge"), "an adding sphere is written as before");
    let mut hole = sphere([0.1, 0.0, 0.0], 0.2);
    hole.charge = -1.0;
    let file = SceneFile { spheres: vec![sphere([0.0, 0.0, 0.0], 0.5), hole], settings: vec![] };
    let json = file.to_json();
    assert!(json.contains(r#""charge": -1"#), "{json}");
    assert_eq!(SceneFile::parse(&json).unwrap().spheres, file.spheres);
    let e = SceneFile::parse(&doc(r#"{"center":[0,0,0],"radius":0.3,"charge":0.5}"#)).unwrap_err();
    assert!(
        e.to_string().contains("spheres[0].charge: a sphere's charge is 1 (adds) or -1 (subtracts), got 0.5"),
        "{e}"
    );
    let e = SceneFile::parse(&doc(r#"{"center":[0,0,0],"radius":0.3,"charge":"minus"}"#)).unwrap_err();
    assert!(e.to_string().contains("spheres[0].charge must be a number"), "{e}");
}

#[test]
fn bad_documents_are_refused_with_the_field_and_value_and_change_nothing() {
    let good = a_scene().to_json();
    let sphere = r#"{"center":[0,0,0],"radius":0.3}"#;
    let doc = |spheres: &str, rest: &str| {
        format!(r#"{{"format":"metaballs-scene","version":1,"spheres":[{spheres}]{rest}}}"#)
    };
    let many = vec![sphere; 10_000].join(",");
    let huge = format!(r#"{},"padding":"{}"}}"#, &good[..good.len() - 1], "x".repeat(5 << 20));
    let cases: Vec<(&str, String, &str)> = vec![
        ("invalid JSON", "{ spheres: [] }".into(), "not valid JSON: key must be a string at line 1 column 3"),
        ("truncated", good[..good.len() / 2].into(), "the file ends early (is it cut short?)"),
        ("not an object", "[1, 2]".into(), "a scene is a JSON object, got [1,2]"),
        ("no format", r#"{"version":1}"#.into(), "format is missing"),
        (
            "another format",
            r#"{"format":"gltf","version":1}"#.into(),
            "format must be \"metaballs-scene\", got \"gltf\"",
        ),
        (
            "unknown version",
            good.replace("\"version\": 1", "\"version\": 2"),
            "version 2 is not one this build reads (it reads version 1)",
        ),
        ("no version", r#"{"format":"metaballs-scene"}"#.into(), "version is missing"),
        ("no spheres", r#"{"format":"metaballs-scene","version":1}"#.into(), "spheres is missing"),
        ("no spheres at all", doc("", ""), "spheres: a scene holds 1 to 64 spheres, got 0"),
        ("10 000 spheres", doc(&many, ""), "spheres: a scene holds 1 to 64 spheres, got 10000"),
        ("missing radius", doc(r#"{"center":[0,0,0]}"#, ""), "spheres[0].radius is missing"),
        ("missing centre", doc(r#"{"radius":0.3}"#, ""), "spheres[0].center is missing"),
        (
            "NaN as a string",
            doc(r#"{"center":[0,0,0],"radius":"NaN"}"#, ""),
            "spheres[0].radius must be a number, got \"NaN\"",
        ),
        (
            "negative radius",
            doc(&format!(r#"{sphere},{{"center":[0,0,0],"radius":-0.2}}"#), ""),
            "spheres[1].radius: sphere radius must be between 0.01 and 1, got -0.2",
        ),
        (
            "outside the box",
            doc(r#"{"center":[0,0.9,0],"radius":0.3}"#, ""),
            "spheres[0].center[1]: centre coordinate (inside the box for this radius) must be between -0.7 and 0.7, got 0.9",
        ),
        (
            "short centre",
            doc(r#"{"center":[0,0],"radius":0.3}"#, ""),
            "spheres[0].center must be three numbers [x, y, z], got [0,0]",
        ),
        (
            "velocity huge",
            doc(r#"{"center":[0,0,0],"radius":0.3,"velocity":[0,1e9,0]}"#, ""),
            "spheres[0].velocity[1]: velocity must be between -100 and 100, got 1000000000",
        ),
        (
            "iso out of range",
            doc(sphere, r#","settings":{"iso":25}"#),
            "settings.iso: iso level must be between 0.05 and 20, got 25",
        ),
        (
            "iso NaN as a string",
            doc(sphere, r#","settings":{"iso":"NaN"}"#),
            "settings.iso: iso level must be a number, got NaN",
        ),
        (
            "resolution not whole",
            doc(sphere, r#","settings":{"resolution":64.5}"#),
            "settings.resolution: resolution (cells per axis) must be a whole number from 8 to 2048, got \"64.5\"",
        ),
        (
            "unknown setting",
            doc(sphere, r#","settings":{"wobble":1}"#),
            "settings.wobble: not a setting a scene holds",
        ),
        (
            "page-only setting",
            doc(sphere, r#","settings":{"controls":"all"}"#),
            "settings.controls: not a setting a scene holds",
        ),
        (
            "setting of the wrong kind",
            doc(sphere, r#","settings":{"display":[1]}"#),
            "settings.display must be a number, true/false or text, got [1]",
        ),
        (
            "bad choice",
            doc(sphere, r#","settings":{"display":"sketch"}"#),
            "settings.display: display must be one of",
        ),
        ("5 MB", huge, "the file is 5.0 MB; a scene file is at most 1 MB"),
    ];
    for (what, text, expected) in &cases {
        match SceneFile::parse(text) {
            Ok(file) => panic!("{what}: accepted {file:?}"),
            Err(e) => {
                let message = e.to_string();
                assert!(message.contains(expected), "{what}: {message:?} should contain {expected:?}");
                assert!(message.len() < 300, "{what}: a message a person reads: {message}");
            }
        }
    }
}

#[test]
fn a_scene_with_level_of_detail_past_512_loads_whatever_the_order_of_its_settings() {
    let mut scene = a_scene();
    scene.settings.retain(|(name, _)| *name != "resolution");
    scene.settings.insert(0, ("resolution", Value::Number(1024.0)));
    scene.settings.push(("lod", Value::Boolean(true)));
    scene.settings.push(("lod_pixels", Value::Number(3.0)));
    let read = SceneFile::parse(&scene.to_json()).unwrap();
    let settings = read.applied_to(Settings::default()).unwrap();
    assert_eq!((settings.resolution, settings.view.lod, settings.view.lod_pixels), (1024, true, 3.0));
    scene.settings.retain(|(name, _)| *name != "lod");
    let error = scene.applied_to(Settings::default()).unwrap_err().to_string();
    assert!(error.contains("settings.resolution") && error.contains("lod=on goes up to 2048"), "{error}");
}
