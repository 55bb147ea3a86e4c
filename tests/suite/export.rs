//! Exported meshes, read back with independent readers (stl_io, tobj): the GPU mesh's triangles, a
//! closed 2-manifold, the volume it encloses; simplified exports reach their target and stay closed;
//! `metaballs export` writes them from flags or a scene file and refuses bad input.

use crate::common;

use common::*;
use glam::Vec3;
use metaballs::export::{MeshFormat, enclosed_volume, encode, simplified};
use metaballs::extract::mesh::IndexedMesh;
use metaballs::{Scene, Settings};

/// The GPU's mesh (compute passes, read back once) of `scene`.
fn gpu_mesh(scene: &Scene, resolution: u32) -> IndexedMesh {
    let settings = Settings { resolution, ..Settings::default() }.with_parameter("mesher", "gpu").unwrap();
    with_renderer(settings, 16, 16, |o| {
        o.renderer.set_scene(scene.clone());
        pollster::block_on(o.renderer.extract_mesh())
    })
}

/// Two merged spheres and one apart, all inside the box.
fn scene() -> Scene {
    Scene::from_spheres(vec![
        sphere([-0.35, 0.05, 0.0], 0.32),
        sphere([0.05, -0.05, 0.1], 0.28),
        sphere([0.45, 0.5, -0.4], 0.2),
    ])
    .unwrap()
}

/// An indexed mesh from a reader's vertices and triangles. Readers of STL weld corners by position: a
/// triangle with two corners at one point would mean two vertices of the mesh coincide.
fn from_reader(positions: Vec<Vec3>, triangles: Vec<[u32; 3]>) -> IndexedMesh {
    let flattened = triangles.iter().filter(|t| t[0] == t[1] || t[1] == t[2] || t[0] == t[2]).count();
    assert_eq!(flattened, 0, "triangles flattened by welding their corners by position");
    let normals = vec![Vec3::Y; positions.len()];
    IndexedMesh { positions, normals, triangles }
}

fn read_stl(bytes: &[u8]) -> IndexedMesh {
    let stl = stl_io::read_stl(&mut std::io::Cursor::new(bytes)).expect("stl_io reads the STL");
    let positions = stl.vertices.iter().map(|v| Vec3::new(v[0], v[1], v[2])).collect();
    let triangles = stl.faces.iter().map(|f| f.vertices.map(|i| i as u32)).collect();
    from_reader(positions, triangles)
}

fn read_obj(path: &std::path::Path) -> (IndexedMesh, Vec<Vec3>) {
    let options = tobj::LoadOptions { single_index: true, ..Default::default() };
    let (models, _) = tobj::load_obj(path, &options).expect("tobj reads the OBJ");
    assert_eq!(models.len(), 1);
    let m = &models[0].mesh;
    let positions = m.positions.chunks(3).map(Vec3::from_slice).collect();
    let normals = m.normals.chunks(3).map(Vec3::from_slice).collect();
    let triangles = m.indices.chunks(3).map(|t| [t[0], t[1], t[2]]).collect();
    (from_reader(positions, triangles), normals)
}

fn assert_closed(mesh: &IndexedMesh, what: &str) {
    let topology = mesh.topology();
    assert_eq!(topology.open_or_nonmanifold_edges, 0, "{what}: open or non-manifold edges");
    assert_eq!(topology.misoriented_edges, 0, "{what}: inconsistent winding");
    assert!(topology.component_euler.iter().all(|&e| e == 2), "{what}: {:?}", topology.component_euler);
}

#[test]
fn stl_and_obj_read_back_as_the_gpu_mesh_closed_with_its_volume() {
    let mesh = gpu_mesh(&scene(), 48);
    let triangles = mesh.triangles.len();
    assert!(triangles > 1000, "{triangles}");
    let volume = enclosed_volume(&mesh);
    // Two merged spheres and a separate one: more than the three balls' own volumes (the field's
    // tails add up), far less than the box.
    let balls: f64 =
        scene().spheres().iter().map(|s| 4.0 / 3.0 * std::f64::consts::PI * (s.radius as f64).powi(3)).sum();
    assert!(volume > balls && volume < 2.0 * balls, "volume {volume} against the balls' {balls}");

    let stl = encode(&mesh, MeshFormat::Stl, 25.0);
    assert_eq!(stl.len(), 84 + 50 * triangles);
    let read = read_stl(&stl);
    assert_eq!(read.triangles.len(), triangles, "STL triangle count");
    assert_closed(&read, "STL");
    assert_eq!(read.topology().component_euler.len(), 2, "two blobs");
    let stl_volume = enclosed_volume(&read) / 25f64.powi(3);
    assert!((stl_volume - volume).abs() < 1e-4 * volume, "STL volume {stl_volume} against {volume}");
    // Z up: the third blob (at y = 0.5) is high on the Z axis.
    let top = read.positions.iter().map(|p| p.z).fold(f32::MIN, f32::max);
    assert!((top / 25.0 - 0.7).abs() < 0.05, "the top at z = {top} mm");

    let dir = scratch_dir("metaballs-export-obj");
    let path = dir.join("blob.obj");
    std::fs::write(&path, encode(&mesh, MeshFormat::Obj, 1.0)).unwrap();
    let (read, normals) = read_obj(&path);
    assert_eq!(read.triangles.len(), triangles, "OBJ triangle count");
    assert_eq!(read.positions.len(), mesh.positions.len());
    assert_closed(&read, "OBJ");
    assert!((enclosed_volume(&read) - volume).abs() < 1e-5 * volume);
    // Each vertex keeps its normal (the reader numbers vertices in its own order).
    let by_position: std::collections::HashMap<[u32; 3], Vec3> =
        mesh.positions.iter().zip(&mesh.normals).map(|(p, n)| (p.to_array().map(f32::to_bits), *n)).collect();
    assert_eq!(normals.len(), read.positions.len());
    for (p, n) in read.positions.iter().zip(&normals) {
        let m = by_position[&p.to_array().map(f32::to_bits)];
        assert!((*n - m).length() < 1e-5, "normal {n} against {m}");
    }

    let ply = encode(&mesh, MeshFormat::Ply, 1.0);
    let text = String::from_utf8_lossy(&ply[..400]);
    assert!(text.contains(&format!("element vertex {}\n", mesh.positions.len())), "{text}");
    assert!(text.contains(&format!("element face {triangles}\n")), "{text}");
    let body = ply.windows(11).position(|w| w == b"end_header\n").unwrap() + 11;
    assert_eq!(ply.len() - body, 24 * mesh.positions.len() + 13 * triangles);
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn one_sphere_encloses_its_own_volume() {
    let radius = 0.5f32;
    let mesh = gpu_mesh(&Scene::from_spheres(vec![sphere([0.0, 0.0, 0.0], radius)]).unwrap(), 64);
    let exact = 4.0 / 3.0 * std::f64::consts::PI * (radius as f64).powi(3);
    let read = read_stl(&encode(&mesh, MeshFormat::Stl, 1.0));
    let volume = enclosed_volume(&read);
    assert!((volume - exact).abs() < 0.01 * exact, "volume {volume} against {exact}");
}

#[test]
fn simplified_exports_reach_their_target_and_stay_closed() {
    let mesh = gpu_mesh(&scene(), 64);
    let full = mesh.triangles.len();
    let volume = enclosed_volume(&mesh);
    for target in [full / 2, full / 10, 1000] {
        let simple = simplified(&mesh, target);
        let got = simple.triangles.len();
        assert!(
            (got as f64 - target as f64).abs() <= 0.05 * target as f64,
            "asked {target} of {full}, got {got}"
        );
        let read = read_stl(&encode(&simple, MeshFormat::Stl, 25.0));
        assert_closed(&read, &format!("simplified to {target}"));
        let v = enclosed_volume(&read) / 25f64.powi(3);
        assert!((v - volume).abs() < 0.05 * volume, "simplified to {target}: volume {v} against {volume}");
    }
    assert_eq!(simplified(&mesh, full + 10).triangles.len(), full);
}

#[test]
fn the_cli_exports_a_scene_file_and_refuses_bad_input() {
    let dir = scratch_dir("metaballs-export-cli");
    let scene_path = dir.join("two.json");
    let file = metaballs::scene::file::SceneFile {
        spheres: scene().spheres().to_vec(),
        settings: vec![("resolution", metaballs::scene::params::Value::Number(40.0))],
    };
    std::fs::write(&scene_path, file.to_json()).unwrap();
    let stl = dir.join("blob.stl");
    let (code, stdout, stderr) =
        cli(&["export", "--out", stl.to_str().unwrap(), "--scene", scene_path.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("closed"), "{stdout}");
    let read = read_stl(&std::fs::read(&stl).unwrap());
    assert_closed(&read, "CLI STL");
    let expected = gpu_mesh(&scene(), 40).triangles.len();
    assert_eq!(read.triangles.len(), expected, "the scene file's resolution was used");

    let obj = dir.join("small.obj");
    let (code, stdout, stderr) = cli(&[
        "export",
        "--out",
        obj.to_str().unwrap(),
        "--scene",
        scene_path.to_str().unwrap(),
        "--simplify",
        "500",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains(&format!("500 triangles (from {expected})")), "{stdout}");
    assert_closed(&read_obj(&obj).0, "CLI simplified OBJ");

    let ply = dir.join("blob.bin");
    let (code, _, stderr) =
        cli(&["export", "--out", ply.to_str().unwrap(), "--format", "ply", "--spheres", "2"]);
    assert_eq!(code, 0, "{stderr}");
    assert!(std::fs::read(&ply).unwrap().starts_with(b"ply\nformat binary_little_endian 1.0\n"));

    let bad = dir.join("bad.json");
    std::fs::write(
        &bad,
        r#"{"format":"metaballs-scene","version":1,"spheres":[{"center":[0,0,0],"radius":-1}]}"#,
    )
    .unwrap();
    let out = dir.join("never.stl");
    let cases: Vec<(Vec<&str>, String)> = vec![
        (vec!["--format", "3mf"], "mesh format must be one of stl, obj, ply, got \"3mf\"".into()),
        (vec!["--simplify", "2"], "triangle target must be between 4".into()),
        (vec!["--scale", "0"], "scale must be between".into()),
        (
            vec!["--scene", bad.to_str().unwrap()],
            "spheres[0].radius: sphere radius must be between 0.01 and 1, got -1".into(),
        ),
        (vec!["--scene", "/no/such/scene.json"], "/no/such/scene.json".into()),
        (vec!["--scene", scene_path.to_str().unwrap(), "--iso", "2"], "cannot be used with".into()),
    ];
    for (flags, expected) in &cases {
        let mut args = vec!["export", "--out", out.to_str().unwrap()];
        args.extend(flags);
        let (code, _, stderr) = cli(&args);
        assert_ne!(code, 0, "{flags:?}");
        assert!(stderr.contains(expected.as_str()), "{flags:?}: {stderr:?} should contain {expected:?}");
        assert!(!stderr.contains("panicked"), "{stderr}");
        assert!(!out.exists(), "{flags:?} wrote a file");
    }
    std::fs::remove_dir_all(dir).unwrap();
}
