//! The engine in a real browser: headless Chromium's WebGPU (SwiftShader) against the CPU oracle, and
//! the renderer drawing offscreen.
#![cfg(target_arch = "wasm32")]

#[path = "common/conditioning.rs"]
mod conditioning;

use conditioning::conditioned_iso;
use metaballs::extract::reference::{self, Grid};
use metaballs::{Renderer, Settings};
use wasm_bindgen_test::*;

wasm_bindgen_test_configure!(run_in_browser);

const FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8UnormSrgb;

async fn device() -> (wgpu::Device, wgpu::Queue) {
    let mut desc = wgpu::InstanceDescriptor::new_without_display_handle();
    desc.backends = wgpu::Backends::BROWSER_WEBGPU;
    let instance = wgpu::Instance::new(desc);
    let (_, device, queue) = metaballs::device::request_device(&instance, None)
        .await
        .unwrap_or_else(|e| panic!("browser tests need WebGPU: {e}"));
    (device, queue)
}

#[wasm_bindgen_test]
async fn gpu_mesh_matches_the_oracle_in_the_browser() {
    let (device, queue) = device().await;
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let mut renderer = Renderer::new(device.clone(), queue, FORMAT, 16, 16, Settings::default()).unwrap();
    for (seed, count, resolution) in [(11, 1, 16), (12, 5, 24), (13, 16, 32)] {
        renderer
            .set_settings(Settings { seed, sphere_count: count, resolution, iso: 1.0, ..Settings::default() })
            .unwrap();
        let spheres = renderer.scene().spheres().to_vec();
        let iso = conditioned_iso(&spheres, 1.0, resolution);
        renderer.set_iso(iso).unwrap();
        let grid = Grid { cells_per_axis: resolution };
        let gpu = renderer.extract_mesh().await.to_soup();
        let cpu = reference::extract(&spheres, iso, grid);
        assert!(cpu.triangle_count() > 0);
        if let Err(e) = gpu.matches(&cpu, 1e-4 * grid.cell_size(), 0.01f32.to_radians()) {
            panic!("seed {seed}, {count} spheres, {resolution} cells: {e}");
        }
    }
    assert!(scope.pop().await.is_none(), "validation error");
    assert_eq!(renderer.gpu_error(), None);
}

#[wasm_bindgen_test]
async fn the_renderer_draws_a_non_blank_image_offscreen() {
    let (device, queue) = device().await;
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let (width, height) = (128u32, 96u32);
    let mut renderer =
        Renderer::new(device.clone(), queue.clone(), FORMAT, width, height, Settings::default()).unwrap();
    let texture = metaballs::device::render_target(&device, width, height, FORMAT);
    renderer.render(&texture.create_view(&Default::default()));
    let bytes = metaballs::device::read_texture(&device, &queue, &texture).await;
    let pixels: Vec<&[u8]> = bytes.chunks(4).collect();
    // The surface is red; the background blue-grey.
    let surface = pixels.iter().filter(|p| p[0] as i32 > p[2] as i32 + 30).count();
    let fraction = surface as f32 / pixels.len() as f32;
    assert!(fraction > 0.02, "the surface covers {:.2}% of the image", fraction * 100.0);
    assert!(pixels.iter().any(|p| p[..3].iter().all(|&c| c > 200)), "no specular highlight");
    renderer.flush_stats().await;
    assert!(renderer.stats().is_some_and(|s| s.triangles > 0 && !s.overflowed()));
    assert!(scope.pop().await.is_none(), "validation error");
}

#[wasm_bindgen_test]
fn cpu_mesher_equals_the_oracle_in_wasm() {
    use metaballs::extract::cpu::mesher::CpuMesher;
    use metaballs::extract::kernel::Terms;
    use metaballs::extract::reference::Construction;
    use metaballs::scene::params::view::{Blend, CaseTable, Interpolation, Kernel};
    // The wasm build vectorises the field loops (simd128): the results must still be the oracle's, bit
    // for bit. Seeded scenes, one mesher reused, three constructions and the two other kernels (below
    // iso 3, where theirs have a surface).
    let mut mesher = CpuMesher::new();
    for (seed, count, resolution, iso) in
        [(11, 1, 16, 1.0), (12, 5, 29, 0.4), (13, 16, 32, 1.0), (14, 64, 40, 3.0)]
    {
        let mut scene = metaballs::Scene::new(seed, count).unwrap();
        scene.step(1.7).unwrap();
        for construction in [
            Construction::default(),
            Construction {
                interpolation: Interpolation::Midpoint,
                terms: Terms { blend: Blend::Max, ..Terms::default() },
                case_table: CaseTable::Decider,
                ..Construction::default()
            },
            Construction { case_table: CaseTable::Mc33, ..Construction::default() },
            Construction {
                terms: Terms { kernel: Kernel::Blinn, ..Terms::default() },
                ..Construction::default()
            },
            Construction {
                terms: Terms { kernel: Kernel::Wyvill, ..Terms::default() },
                ..Construction::default()
            },
        ]
        .into_iter()
        .filter(|c| iso < 3.0 || c.terms.kernel == Kernel::InverseSquare)
        {
            let grid = Grid { cells_per_axis: resolution };
            mesher.mesh(scene.spheres(), iso, grid, construction);
            let oracle = reference::extract_with(scene.spheres(), iso, grid, construction);
            let ours = mesher.to_indexed().to_soup();
            assert!(oracle.triangle_count() > 0);
            if let Err(e) = ours.matches(&oracle, 0.0, 1e-3) {
                panic!("seed {seed}, {count} spheres, {resolution} cells, {construction:?}: {e}");
            }
        }
    }
}

#[wasm_bindgen_test]
async fn the_renderer_meshes_on_the_cpu_when_asked() {
    let (device, queue) = device().await;
    let scope = device.push_error_scope(wgpu::ErrorFilter::Validation);
    let settings = Settings { seed: 5, sphere_count: 6, resolution: 32, ..Settings::default() }
        .with_parameter("mesher", "cpu")
        .unwrap();
    let mut renderer = Renderer::new(device.clone(), queue, FORMAT, 16, 16, settings).unwrap();
    let mesh = renderer.extract_mesh().await.to_soup();
    let oracle = reference::extract(renderer.scene().spheres(), settings.iso, Grid { cells_per_axis: 32 });
    assert_eq!(renderer.mesh_source(), "cpu");
    mesh.matches(&oracle, 0.0, 1e-3).unwrap();
    assert_eq!(renderer.stats().map(|s| s.triangles as usize), Some(oracle.triangle_count()));
    assert!(scope.pop().await.is_none(), "validation error");
}
