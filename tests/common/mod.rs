//! Helpers shared by the native GPU tests.
#![allow(dead_code)]

pub mod conditioning;
pub mod pictures;
pub mod scenes;

#[allow(unused_imports)]
pub use conditioning::*;
use glam::{UVec3, Vec3};
use metaballs::extract::reference::{Grid, sample_field};
use metaballs::offscreen::Offscreen;
use metaballs::{GpuContext, Settings, Sphere};
#[allow(unused_imports)]
pub use pictures::*;
use std::sync::OnceLock;

/// Every file under `dir` (in its folders too) whose name ends in `.{extension}`.
pub fn files_under(dir: &std::path::Path, extension: &str) -> Vec<std::path::PathBuf> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            found.extend(files_under(&path, extension));
        } else if path.extension().is_some_and(|e| e == extension) {
            found.push(path);
        }
    }
    found
}

/// A device of its own from the adapter at hand (lavapipe in CI), for tests of the device itself: its
/// memory counts, its limits, its loss. Fails, never skips, when there is none.
pub fn device() -> (wgpu::Adapter, wgpu::Device, wgpu::Queue) {
    let instance = metaballs::device::native_instance();
    pollster::block_on(metaballs::device::request_device(&instance, None))
        .unwrap_or_else(|e| panic!("GPU tests need an adapter: {e}"))
}

/// The device every other GPU test draws on, with its pipelines, made by the first test that asks:
/// a test's renderer owns only its buffers, targets and scene, as a figure's does on a page.
pub fn shared_device() -> &'static (wgpu::Adapter, GpuContext) {
    static SHARED: OnceLock<(wgpu::Adapter, GpuContext)> = OnceLock::new();
    SHARED.get_or_init(|| {
        let (adapter, device, queue) = device();
        (adapter, GpuContext::new(device, queue))
    })
}

/// Runs `f` with an offscreen renderer on the shared device inside a validation error scope: any
/// validation error, in setup or in the frames, fails the test. (Error scopes are the calling
/// thread's: tests running beside it on the device neither catch its errors nor give it theirs.)
pub fn with_renderer<T>(
    settings: Settings,
    width: u32,
    height: u32,
    f: impl FnOnce(&mut Offscreen) -> T,
) -> T {
    let (adapter, context) = shared_device();
    let scope = context.device().push_error_scope(wgpu::ErrorFilter::Validation);
    let offscreen =
        Offscreen::on_context(adapter.clone(), context, settings, width, height).expect("renderer");
    checked(offscreen, scope, f)
}

/// `with_renderer` on a device of its own, for tests that count the device's memory.
pub fn with_own_renderer<T>(
    settings: Settings,
    width: u32,
    height: u32,
    f: impl FnOnce(&mut Offscreen) -> T,
) -> T {
    let (adapter, device, queue) = device();
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let offscreen =
        Offscreen::with_device(adapter, device, queue, settings, width, height).expect("renderer");
    checked(offscreen, scope, f)
}

fn checked<T>(
    mut offscreen: Offscreen,
    scope: wgpu::ErrorScopeGuard,
    f: impl FnOnce(&mut Offscreen) -> T,
) -> T {
    let result = f(&mut offscreen);
    let _ = offscreen.device.poll(wgpu::PollType::wait_indefinitely());
    if let Some(error) = pollster::block_on(scope.pop()) {
        panic!("validation error: {error}");
    }
    assert_eq!(offscreen.renderer.gpu_error(), None, "GPU error outside the scope");
    result
}

/// Settings for a scene of `count` seeded spheres.
pub fn settings(seed: u64, count: u32, resolution: u32, iso: f32) -> Settings {
    Settings { seed, sphere_count: count, resolution, iso, ..Settings::default() }
}

/// True when every sample next to the box's faces is below `iso`, so the surface stays inside the box
/// and no wall closes it.
pub fn surface_inside_box(spheres: &[Sphere], iso: f32, resolution: u32) -> bool {
    let grid = Grid { cells_per_axis: resolution };
    let f = sample_field(spheres, grid);
    let n = resolution;
    (1..n).all(|z| {
        (1..n).all(|y| {
            (1..n).all(|x| {
                let id = UVec3::new(x, y, z);
                let near_wall = id.min_element() == 1 || id.max_element() == n - 1;
                !near_wall || f[grid.point_index(id)] < iso
            })
        })
    })
}

/// A sphere at rest.
pub fn sphere(center: [f32; 3], radius: f32) -> Sphere {
    Sphere { center: Vec3::from_array(center), radius, velocity: Vec3::ZERO, charge: 1.0 }
}

/// A scratch folder under the system's temporary folder, one per name and test process.
pub fn scratch_dir(name: &str) -> std::path::PathBuf {
    let dir = std::env::temp_dir().join(format!("{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Runs the `metaballs` command line: its exit status, standard output and standard error.
pub fn cli(args: &[&str]) -> (i32, String, String) {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_metaballs"))
        .args(args)
        .output()
        .expect("run the binary");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into(),
        String::from_utf8_lossy(&out.stderr).into(),
    )
}

/// How far apart the GPU's and the oracle's vertex normals may point, in radians: 0.01°, or 0.1° with
/// Blinn's kernel, whose `exp` rounding the gradient's cancelling terms magnify (measured up to 0.1°).
pub fn normal_tolerance(terms: metaballs::extract::kernel::Terms) -> f32 {
    use metaballs::scene::params::view::Kernel;
    if terms.kernel == Kernel::Blinn { 0.1f32.to_radians() } else { 0.01f32.to_radians() }
}
