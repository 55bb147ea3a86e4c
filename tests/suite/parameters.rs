//! Bad input gets a clear message, leaves the previous state running, and never panics.

use crate::common;

use common::*;
use glam::Vec3;
use metaballs::scene::params::MAX_SPHERES;
use metaballs::{Camera, Material, Settings};

const BAD_FLOATS: [f32; 3] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY];

fn assert_refused<T: std::fmt::Debug>(result: Result<T, metaballs::ParamError>, starts: &str) {
    let message = result.expect_err("should be refused").to_string();
    assert!(message.starts_with(starts), "message {message:?} should start with {starts:?}");
}

#[test]
fn every_setter_refuses_bad_values_and_keeps_the_previous_state() {
    with_renderer(Settings::default(), 32, 32, |o| {
        let r = &mut o.renderer;
        let before = *r.settings();

        assert_refused(r.set_sphere_count(0), "sphere count must be between 1 and 64, got 0");
        assert_refused(r.set_sphere_count(MAX_SPHERES + 1), "sphere count must be between 1 and 64, got 65");

        for bad in BAD_FLOATS {
            assert_refused(r.set_iso(bad), "iso level must be");
        }
        assert_refused(r.set_iso(0.0), "iso level must be between 0.05 and 20, got 0");
        assert_refused(r.set_iso(-1.0), "iso level must be between 0.05 and 20, got -1");
        assert_refused(r.set_iso(1e9), "iso level must be between");

        assert_refused(r.set_resolution(0), "resolution (cells per axis) must be between 8 and 2048, got 0");
        assert_refused(r.set_resolution(7), "resolution (cells per axis) must be between 8 and 2048, got 7");
        assert_refused(r.set_resolution(100_000), "resolution (cells per axis) must be between 8 and 2048");
        assert_refused(
            r.set_resolution(1024),
            "resolution must be at most 512 for a uniform grid (lod=on goes up to 2048)",
        );

        let material = Material::default();
        for bad in BAD_FLOATS {
            assert_refused(r.set_material(Material { shininess: bad, ..material }), "shininess must be");
            assert_refused(r.set_material(Material { ambient: bad, ..material }), "ambient strength must be");
            assert_refused(r.set_material(Material { diffuse: bad, ..material }), "diffuse strength must be");
            assert_refused(
                r.set_material(Material { specular: bad, ..material }),
                "specular strength must be",
            );
            assert_refused(
                r.set_material(Material { base_color: Vec3::new(0.5, bad, 0.5), ..material }),
                "base colour must be",
            );
            assert_refused(r.set_light_position(Vec3::new(bad, 1.0, 1.0)), "light position must be");
        }
        assert_refused(
            r.set_material(Material { shininess: 0.0, ..material }),
            "shininess must be between 1 and 1024, got 0",
        );
        assert_refused(
            r.set_material(Material { ambient: -0.5, ..material }),
            "ambient strength must be between 0 and 1",
        );
        assert_refused(
            r.set_material(Material { base_color: Vec3::splat(2.0), ..material }),
            "base colour must be between 0 and 1",
        );
        assert_refused(
            r.set_light_position(Vec3::new(1e6, 0.0, 0.0)),
            "light position must be between -100 and 100",
        );

        let camera = Camera::default();
        for bad in BAD_FLOATS {
            assert_refused(
                r.set_camera(Camera { yaw_degrees: bad, ..camera }),
                "camera yaw (degrees) must be",
            );
            assert_refused(
                r.set_camera(Camera { pitch_degrees: bad, ..camera }),
                "camera pitch (degrees) must be",
            );
            assert_refused(r.set_camera(Camera { distance: bad, ..camera }), "camera distance must be");
            assert_refused(
                r.set_camera(Camera { fov_y_degrees: bad, ..camera }),
                "field of view (degrees) must be",
            );
        }
        assert_refused(
            r.set_camera(Camera { pitch_degrees: 90.0, ..camera }),
            "camera pitch (degrees) must be between -89 and 89",
        );
        assert_refused(r.set_camera(Camera { distance: 0.0, ..camera }), "camera distance must be between");
        assert_refused(
            r.set_camera(Camera { fov_y_degrees: 180.0, ..camera }),
            "field of view (degrees) must be between 10 and 120",
        );

        assert_refused(r.resize(0, 10), "output width (pixels) must be between 1 and");
        assert_refused(r.resize(10, 1 << 30), "output height (pixels) must be between 1 and");
        assert_refused(r.update(f32::NAN), "time step (seconds) must be a number");
        assert_refused(r.update(-1.0), "time step (seconds) must be between 0 and");
        assert_refused(r.set_max_triangles(Some(0)), "triangle budget must be between 1 and");

        // A batch with one bad field changes nothing.
        assert_refused(
            r.set_settings(Settings { sphere_count: 9, iso: f32::NAN, ..before }),
            "iso level must be",
        );

        assert_eq!(*r.settings(), before, "refused values must leave the settings as they were");
        assert_eq!(r.size(), (32, 32));
        assert_eq!(r.scene().spheres().len(), before.sphere_count as usize);

        // The renderer still draws.
        let pixels = o.render_rgba();
        assert_eq!(pixels.len(), 32 * 32 * 4);
    });
}

#[test]
fn good_values_are_applied() {
    with_renderer(Settings::default(), 32, 32, |o| {
        let r = &mut o.renderer;
        r.set_sphere_count(12).unwrap();
        r.set_iso(0.8).unwrap();
        r.set_resolution(40).unwrap();
        r.set_seed(99).unwrap();
        r.set_camera(Camera {
            yaw_degrees: -120.0,
            pitch_degrees: -30.0,
            distance: 5.0,
            fov_y_degrees: 60.0,
        })
        .unwrap();
        r.set_light_position(Vec3::new(-2.0, 3.0, 1.0)).unwrap();
        r.resize(48, 24).unwrap();
        let s = *r.settings();
        assert_eq!((s.sphere_count, s.iso, s.resolution, s.seed), (12, 0.8, 40, 99));
        assert_eq!(r.scene().spheres().len(), 12);
        o.resize(48, 24).unwrap();
        assert_eq!(o.render_rgba().len(), 48 * 24 * 4);
    });
}

#[test]
fn a_resolution_beyond_the_device_names_the_limit() {
    let (adapter, device, queue) = device();
    let mut limits = adapter.limits();
    // A device granted less than the adapter can: a 256 KiB storage binding holds the block table of
    // at most 40³ blocks, 160 cells.
    limits.max_storage_buffer_binding_size = 256 << 10;
    let (small_device, small_queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
        label: Some("small device"),
        required_limits: limits,
        ..Default::default()
    }))
    .unwrap();
    drop((device, queue));
    let mut r = metaballs::Renderer::new(
        small_device,
        small_queue,
        wgpu::TextureFormat::Rgba8UnormSrgb,
        16,
        16,
        Settings { resolution: 64, ..Settings::default() },
    )
    .unwrap();
    assert_eq!(r.max_resolution(), 160);
    let message = r.set_resolution(200).unwrap_err().to_string();
    assert!(message.contains("resolution 200 is more than this device can hold"), "{message}");
    assert!(message.contains("max_storage_buffer_binding_size is 0.2 MiB"), "{message}");
    assert!(message.contains("the largest resolution it holds is 160"), "{message}");
    assert_eq!(r.settings().resolution, 64);
    r.set_resolution(160).unwrap();
}

/// An empty folder of its own for one test.
#[test]
fn every_cli_flag_refuses_bad_values_with_its_message() {
    let dir = scratch_dir("metaballs-cli");
    let out = dir.join("bad.png");
    let out = out.to_str().unwrap();
    let cases: &[(&[&str], &str)] = &[
        (&["--spheres", "0"], "sphere count must be between 1 and 64, got 0"),
        (&["--spheres", "65"], "sphere count must be between 1 and 64, got 65"),
        (&["--spheres", "many"], "invalid value 'many' for '--spheres <SPHERES>'"),
        (&["--iso", "NaN"], "iso level must be a number, got NaN"),
        (&["--iso", "inf"], "iso level must be finite, got infinity"),
        (&["--iso", "-2"], "iso level must be between 0.05 and 20, got -2"),
        (&["--resolution", "4"], "resolution (cells per axis) must be between 8 and 2048, got 4"),
        (&["--resolution", "9999"], "resolution (cells per axis) must be between 8 and 2048, got 9999"),
        (&["--resolution", "1024"], "at most 512 for a uniform grid (lod=on goes up to 2048)"),
        (&["--view", "lod=on", "--resolution", "100"], "a multiple of 8 with lod=on"),
        (&["--view", "lod_px=0"], "LOD cell size (pixels) must be between 0.25 and 32"),
        (&["--size", "0x10"], "width must be a whole number from 1 to 8192"),
        (&["--size", "640"], "size must look like 960x640"),
        (&["--size", "10x99999"], "height must be a whole number from 1 to 8192"),
        (&["--seed", "-1"], "invalid value '-1' for '--seed <SEED>'"),
        (&["--time", "-1"], "time (seconds) must be between 0 and 3600, got -1"),
        (&["--time", "NaN"], "time (seconds) must be a number, got NaN"),
    ];
    for (flags, expected) in cases {
        let mut args = vec!["render", "--out", out];
        args.extend_from_slice(flags);
        let (code, _, stderr) = cli(&args);
        assert_eq!(code, 2, "{flags:?} should exit 2; stderr: {stderr}");
        assert!(stderr.contains(expected), "{flags:?}: stderr {stderr:?} should contain {expected:?}");
        assert!(!stderr.contains("panicked"), "{flags:?} panicked: {stderr}");
        assert!(!std::path::Path::new(out).exists(), "{flags:?} wrote a file");
    }
    let (code, _, stderr) = cli(&["render"]);
    assert_eq!(code, 2);
    assert!(stderr.contains("--out <OUT>"), "{stderr}");
    let (code, _, stderr) =
        cli(&["render", "--out", dir.join("no/such/dir/x.png").to_str().unwrap(), "--size", "8x8"]);
    assert_eq!(code, 1, "{stderr}");
    assert!(stderr.contains("error: "), "{stderr}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn the_cli_writes_a_png_of_the_requested_size() {
    let dir = scratch_dir("metaballs-cli-ok");
    let out = dir.join("frame.png");
    let (code, stdout, stderr) = cli(&[
        "render",
        "--out",
        out.to_str().unwrap(),
        "--spheres",
        "3",
        "--iso",
        "0.9",
        "--resolution",
        "24",
        "--size",
        "64x48",
        "--seed",
        "5",
        "--time",
        "1.5",
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("3 spheres, iso 0.9, 24 cells per axis"), "{stdout}");
    let (w, h, pixels) = metaballs::offscreen::read_png(&out).unwrap();
    assert_eq!((w, h, pixels.len()), (64, 48, 64 * 48 * 4));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn changing_resolution_frees_the_old_buffers() {
    // The device's own memory counts: a device of its own, which no other test allocates on.
    with_own_renderer(Settings { resolution: 64, ..Settings::default() }, 32, 32, |o| {
        let memory = |o: &mut metaballs::offscreen::Offscreen| {
            o.render();
            let _ = o.device.poll(wgpu::PollType::wait_indefinitely());
            let hal = o.device.get_internal_counters().hal;
            (hal.buffer_memory.read(), hal.buffers.read())
        };
        let (bytes, buffers) = memory(o);
        assert!(bytes > 0, "this backend reports no buffer memory");
        for _ in 0..5 {
            for resolution in [32, 160, 8, 64] {
                o.renderer.set_resolution(resolution).unwrap();
                memory(o);
            }
        }
        assert_eq!(memory(o), (bytes, buffers), "buffer memory and count after 20 resolution changes");
    });
}

#[test]
fn the_benchmark_runs_and_writes_json_records() {
    let dir = scratch_dir("metaballs-bench");
    let json = dir.join("bench.json");
    let (code, stdout, stderr) = cli(&[
        "bench",
        "--frames",
        "2",
        "--resolutions",
        "8,16",
        "--spheres",
        "1,3",
        "--size",
        "32x24",
        "--json",
        json.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("frame ms"), "{stdout}");
    let records: Vec<serde_json::Value> =
        serde_json::from_str(&std::fs::read_to_string(&json).unwrap()).unwrap();
    assert_eq!(records.len(), 4);
    for (record, (resolution, spheres)) in records.iter().zip([(8, 1), (8, 3), (16, 1), (16, 3)]) {
        assert_eq!(record["resolution"], resolution);
        assert_eq!(record["spheres"], spheres);
        assert!(record["frame_ms"].as_f64().unwrap() > 0.0, "{record}");
        assert!(record["triangles"].as_u64().unwrap() > 0, "{record}");
    }
    let (code, _, stderr) = cli(&["bench", "--resolutions", "4"]);
    assert_eq!(code, 2);
    assert!(stderr.contains("resolution (cells per axis) must be between 8 and 2048, got 4"), "{stderr}");
    std::fs::remove_dir_all(&dir).unwrap();
}
