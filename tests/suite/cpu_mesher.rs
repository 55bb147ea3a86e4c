//! The CPU mesher against the oracle (the same scenes the GPU is held to), and the renderer drawing its
//! mesh: the same picture as the GPU's, the choice `auto` makes, and a long soak switching meshers.

use crate::common;

use common::scenes::{alternate, on_grid_point, overlapping, random_scenes, touching_walls};
use common::*;
use metaballs::extract::cpu::mesher::CpuMesher;
use metaballs::extract::kernel::Terms;
use metaballs::extract::reference::{self, Construction, Grid};
use metaballs::offscreen::OFFSCREEN_FORMAT;
use metaballs::scene::params::view::{Blend, Interpolation, Kernel, MeshOn};
use metaballs::{GpuContext, Renderer, Scene, Settings, Sphere};
use rand::{RngExt, SeedableRng};

/// Meshes with `mesher` (reused, as in the frame loop) and checks the oracle's triangles come out:
/// same count, bit-identical positions, the same normals, every vertex shared by its edge's cells.
fn assert_equals_oracle(
    mesher: &mut CpuMesher,
    spheres: &[Sphere],
    iso: f32,
    resolution: u32,
    construction: Construction,
    what: &str,
) -> usize {
    let grid = Grid { cells_per_axis: resolution };
    mesher.mesh(spheres, iso, grid, construction);
    let oracle = reference::extract_with(spheres, iso, grid, construction);
    let ours = mesher.to_indexed();
    assert_eq!(ours.triangles.len(), oracle.triangle_count(), "{what}: triangle counts differ");
    if let Err(e) = ours.to_soup().matches(&oracle, 0.0, 1e-3) {
        panic!("{what}: {e}");
    }
    let welded = oracle.weld_by_edge();
    assert_eq!(ours.positions.len(), welded.positions.len(), "{what}: one vertex per crossed edge");
    oracle.triangle_count()
}

#[test]
fn seeded_random_scenes_equal_the_oracle() {
    // The draws of the GPU's test (tests/suite/gpu_matches_oracle.rs), one mesher reused throughout.
    let mut mesher = CpuMesher::new();
    let mut with_surface = 0;
    for s in random_scenes(60) {
        let triangles =
            assert_equals_oracle(&mut mesher, &s.spheres, s.iso, s.resolution, s.construction, &s.what);
        with_surface += (triangles > 0) as u32;
    }
    assert!(with_surface >= 45, "only {with_surface} of 60 scenes had a surface");
}

#[test]
fn walls_overlaps_extreme_levels_and_constructions_equal_the_oracle() {
    let (touching_walls, overlapping, on_grid_point) = (touching_walls(), overlapping(), on_grid_point());
    let mut mesher = CpuMesher::new();
    let mut tables = 0;
    for (name, spheres) in [
        ("touching walls", &touching_walls),
        ("overlapping", &overlapping),
        ("on a grid point", &on_grid_point),
    ] {
        for iso in [0.05, 0.3, 1.0, 4.0, 20.0] {
            for interpolation in [Interpolation::Linear, Interpolation::Midpoint] {
                for blend in [Blend::Sum, Blend::Max] {
                    for resolution in [32, 37] {
                        // The three tables, and the three kernels, in turn.
                        tables += 1;
                        let terms = Terms { blend, kernel: Kernel::ALL[tables / 3 % 3], ..Terms::default() };
                        let what =
                            format!("{name}, iso {iso}, {interpolation:?}, {terms:?}, {resolution} cells");
                        let construction = Construction {
                            interpolation,
                            terms,
                            case_table: alternate(tables),
                            ..Construction::default()
                        };
                        assert_equals_oracle(&mut mesher, spheres, iso, resolution, construction, &what);
                    }
                }
            }
        }
    }
    let mesh = mesher.to_indexed();
    assert!(mesh.positions.iter().chain(&mesh.normals).all(|v| v.is_finite()));
}

#[test]
fn the_mesh_is_closed_and_a_sphere_at_iso_one_is_its_own_sphere() {
    let mut mesher = CpuMesher::new();
    let scene = Scene::from_spheres(vec![sphere([0.05, -0.1, 0.02], 0.5)]).unwrap();
    mesher.mesh(scene.spheres(), 1.0, Grid { cells_per_axis: 64 }, Construction::default());
    let mesh = mesher.to_indexed();
    let topology = mesh.topology();
    assert_eq!(topology.open_or_nonmanifold_edges, 0);
    assert_eq!(topology.misoriented_edges, 0);
    assert_eq!(topology.component_euler, vec![2]);
    let centre = scene.spheres()[0].center;
    let worst = mesh.positions.iter().map(|p| (p.distance(centre) - 0.5).abs()).fold(0.0, f32::max);
    assert!(worst < 0.01 * 2.0 / 64.0 * 10.0, "a vertex lies {worst} off the sphere");
    let stats = mesher.stats();
    assert!(stats.active_blocks < stats.total_blocks / 2, "{stats:?}: empty space not skipped");
}

fn renderer_settings(mesher: MeshOn) -> Settings {
    let mut settings = Settings { seed: 3, sphere_count: 6, resolution: 48, ..Settings::default() };
    settings.view.mesh_on = mesher;
    settings
}

#[test]
fn the_cpu_mesh_draws_the_gpu_mesh_picture_without_its_back_faces() {
    let (width, height) = (320, 240);
    let mut pictures = Vec::new();
    for mesher in [MeshOn::Gpu, MeshOn::Cpu] {
        let pixels = with_renderer(renderer_settings(mesher), width, height, |o| {
            o.renderer.update(0.4).unwrap();
            let pixels = o.render_rgba();
            let expected = match mesher {
                MeshOn::Cpu => "cpu",
                _ => "gpu",
            };
            assert_eq!(o.renderer.mesh_source(), expected);
            pollster::block_on(o.renderer.flush_stats());
            let stats = o.renderer.stats().unwrap();
            assert!(stats.triangles > 1000 && !stats.overflowed, "{stats:?}");
            if mesher == MeshOn::Cpu {
                // The CPU's closed mesh, seen from outside the box, draws without its back faces.
                let drawn = o.renderer.triangles_drawn().expect("the CPU counts what it draws");
                let share = drawn as f32 / stats.triangles as f32;
                assert!((0.3..0.7).contains(&share), "drew {drawn} of {} triangles", stats.triangles);
            }
            (pixels, stats.triangles)
        });
        pictures.push(pixels);
    }
    assert_eq!(pictures[0].1, pictures[1].1, "both meshers report the same triangle count");
    let (mean, _) = flip(width, height, &pictures[0].0, &pictures[1].0);
    println!("mean FLIP error between the GPU and CPU meshes' pictures: {mean:.5}");
    assert!(mean < 0.005, "the CPU mesh looks different from the GPU mesh: FLIP {mean}");
    let lit = pictures[1].0.chunks(4).filter(|p| luminance(p) > 60.0).count();
    assert!(lit > (width * height / 20) as usize, "the CPU mesh drew little: {lit} bright pixels");
}

#[test]
fn auto_picks_the_cpu_on_software_adapters_and_views_take_the_gpu() {
    let (_, device, queue) = device();
    let context = GpuContext::new(device, queue);
    let draw = |renderer: &mut Renderer| {
        let texture = metaballs::device::render_target(context.device(), 64, 64, OFFSCREEN_FORMAT);
        renderer.render(&texture.create_view(&Default::default()));
        renderer.mesh_source()
    };
    let mut renderer =
        Renderer::on_context(&context, OFFSCREEN_FORMAT, 64, 64, renderer_settings(MeshOn::Auto)).unwrap();
    assert_eq!(draw(&mut renderer), "gpu", "auto on a hardware adapter");
    context.set_software(true);
    assert_eq!(draw(&mut renderer), "cpu", "auto on a software adapter");
    let forced = renderer.settings().with_parameter("mesher", "gpu").unwrap();
    renderer.set_settings(forced).unwrap();
    assert_eq!(draw(&mut renderer), "gpu", "mesher=gpu on a software adapter");
    let cpu_with_view =
        forced.with_parameter("mesher", "cpu").unwrap().with_parameter("grid", "cells").unwrap();
    renderer.set_settings(cpu_with_view).unwrap();
    assert_eq!(draw(&mut renderer), "gpu", "the cells view reads the compute passes' lists");
    assert!(renderer.settings().with_parameter("mesher", "fpga").is_err());
}

#[test]
fn five_thousand_frames_of_random_changes_and_switched_meshers() {
    let mut rng = rand_pcg::Pcg32::seed_from_u64(5000);
    let base = Settings { antialiasing: false, ..renderer_settings(MeshOn::Auto) };
    with_renderer(base, 48, 32, |o| {
        let memory = |o: &mut metaballs::offscreen::Offscreen| {
            let _ = o.device.poll(wgpu::PollType::wait_indefinitely());
            o.renderer.gpu_bytes()
        };
        let reference_settings =
            |mesher| Settings { resolution: 32, sphere_count: 5, ..renderer_settings(mesher) };
        o.renderer.set_settings(reference_settings(MeshOn::Gpu)).unwrap();
        o.render();
        let at_start = memory(o);
        let mut sources = [0u32; 2];
        for frame in 0..5000 {
            if frame % 7 == 0 {
                let mut settings = *o.renderer.settings();
                match rng.random_range(0..4) {
                    0 => settings.sphere_count = rng.random_range(1..=64),
                    1 => settings.iso = 10f32.powf(rng.random_range(-1.0..1.0)),
                    2 => settings.resolution = rng.random_range(8..=40),
                    _ => settings.view.mesh_on = [MeshOn::Gpu, MeshOn::Cpu][rng.random_range(0..2)],
                }
                o.renderer.set_settings(settings).unwrap();
            }
            o.renderer.update(1.0 / 60.0).unwrap();
            o.render();
            sources[(o.renderer.mesh_source() == "cpu") as usize] += 1;
            if frame % 500 == 0 {
                let _ = o.device.poll(wgpu::PollType::wait_indefinitely());
            }
        }
        assert!(sources.iter().all(|&n| n > 1000), "frames per mesher (gpu, cpu): {sources:?}");
        for mesher in [MeshOn::Cpu, MeshOn::Gpu] {
            o.renderer.set_settings(reference_settings(mesher)).unwrap();
            o.render();
        }
        // The buffers grow for the largest surface seen; the same settings from a fresh start.
        o.renderer.set_resolution(33).unwrap();
        o.renderer.set_settings(reference_settings(MeshOn::Gpu)).unwrap();
        o.render();
        assert_eq!(memory(o), at_start, "GPU memory for the same settings after the soak");
    });
}
