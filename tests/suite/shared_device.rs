//! Several views on one device: pipelines compiled once, each renderer with its own buffers and scene,
//! memory returned when a renderer goes, and a lost device reported so views can move to a new one.

use crate::common;

use metaballs::offscreen::OFFSCREEN_FORMAT;
use metaballs::{GpuContext, Renderer, Settings};

fn context() -> GpuContext {
    let (_, device, queue) = common::device();
    GpuContext::new(device, queue)
}

fn buffer_memory(context: &GpuContext) -> (isize, isize) {
    let _ = context.device().poll(wgpu::PollType::wait_indefinitely());
    let hal = context.device().get_internal_counters().hal;
    (hal.buffer_memory.read(), hal.buffers.read())
}

fn draw(context: &GpuContext, renderer: &mut Renderer) -> Vec<u8> {
    let (width, height) = renderer.size();
    let texture = metaballs::device::render_target(context.device(), width, height, OFFSCREEN_FORMAT);
    renderer.render(&texture.create_view(&Default::default()));
    pollster::block_on(metaballs::device::read_texture(context.device(), context.queue(), &texture))
}

#[test]
fn views_on_one_device_share_pipelines_and_keep_their_own_scenes() {
    let context = context();
    let scope = context.device().push_error_scope(wgpu::ErrorFilter::Validation);
    assert_eq!(context.pipeline_sets_built(), 0, "pipelines were compiled before a view needed them");
    let settings =
        |seed, resolution| Settings { seed, resolution, antialiasing: false, ..Settings::default() };
    let mut views: Vec<Renderer> = [(1, 32), (2, 48), (3, 16), (4, 24)]
        .into_iter()
        .map(|(seed, res)| {
            Renderer::on_context(&context, OFFSCREEN_FORMAT, 96, 64, settings(seed, res)).unwrap()
        })
        .collect();
    assert_eq!(context.live_renderers(), 4);
    assert_eq!(context.pipeline_sets_built(), 1, "four views add one shading pipeline set, not four");

    // Each view draws its own scene, the same picture as a renderer alone on its own device would.
    let images: Vec<Vec<u8>> = views.iter_mut().map(|v| draw(&context, v)).collect();
    assert_eq!(context.pipeline_sets_built(), 2, "the compute passes are compiled once for four views");
    assert_ne!(images[0], images[1], "two views with different seeds drew the same picture");
    let (_, device, queue) = common::device();
    let mut alone =
        Renderer::new(device.clone(), queue.clone(), OFFSCREEN_FORMAT, 96, 64, settings(2, 48)).unwrap();
    let alone_context = alone.context().clone();
    assert_eq!(draw(&alone_context, &mut alone), images[1], "a shared view drew differently from one alone");

    // Antialiasing in one view builds the multisampled variant once.
    views[0].set_antialiasing(true).unwrap();
    views[1].set_antialiasing(true).unwrap();
    assert_eq!(context.pipeline_sets_built(), 3);
    let _ = context.device().poll(wgpu::PollType::wait_indefinitely());
    assert!(pollster::block_on(scope.pop()).is_none(), "validation error");
    assert_eq!(context.gpu_error(), None);
    assert_eq!(context.lost(), None);
}

#[test]
fn frames_meshed_on_the_cpu_compile_no_compute_passes() {
    let context = context();
    context.set_software(true);
    let settings = Settings { resolution: 32, antialiasing: false, ..Settings::default() };
    let mut view = Renderer::on_context(&context, OFFSCREEN_FORMAT, 64, 48, settings).unwrap();
    draw(&context, &mut view);
    assert_eq!(view.mesh_source(), "cpu", "a software adapter meshed on the device");
    assert_eq!(context.pipeline_sets_built(), 1, "the compute passes were compiled for a CPU mesh");
    // A teaching view reads the compute passes' cell lists: they compile when it is first shown.
    view.set_settings(settings.with_parameter("grid", "cells").unwrap()).unwrap();
    draw(&context, &mut view);
    assert_eq!(view.mesh_source(), "gpu");
    assert_eq!(context.pipeline_sets_built(), 2);
    assert_eq!(context.gpu_error(), None);
}

#[test]
fn dropping_a_view_returns_its_gpu_memory() {
    let context = context();
    let settings = Settings { resolution: 64, ..Settings::default() };
    // The allocator keeps memory blocks once made: measure after a first view has come and gone.
    let mut warm_up = Renderer::on_context(&context, OFFSCREEN_FORMAT, 64, 64, settings).unwrap();
    draw(&context, &mut warm_up);
    drop(warm_up);
    let before = buffer_memory(&context);
    let mut first = Renderer::on_context(&context, OFFSCREEN_FORMAT, 64, 64, settings).unwrap();
    draw(&context, &mut first);
    let with_one = buffer_memory(&context);
    assert!(with_one.0 > before.0, "a renderer holds no buffer memory?");
    assert!(first.gpu_bytes() >= first.mesh_bytes() && first.mesh_bytes() > 0);
    for _ in 0..3 {
        let mut second = Renderer::on_context(&context, OFFSCREEN_FORMAT, 64, 64, settings).unwrap();
        draw(&context, &mut second);
        assert!(buffer_memory(&context).0 > with_one.0);
        assert_eq!(context.live_renderers(), 2);
        drop(second);
        assert_eq!(buffer_memory(&context), with_one, "memory after removing a view");
        assert_eq!(context.live_renderers(), 1);
    }
    drop(first);
    assert_eq!(context.live_renderers(), 0);
    assert_eq!(buffer_memory(&context), before, "memory after removing every view");
}

#[test]
fn a_destroyed_device_is_reported_as_lost() {
    let context = context();
    let mut view = Renderer::on_context(&context, OFFSCREEN_FORMAT, 32, 32, Settings::default()).unwrap();
    draw(&context, &mut view);
    assert_eq!(context.lost(), None);
    context.device().destroy();
    let _ = context.device().poll(wgpu::PollType::Poll);
    let lost = context.lost().expect("the loss was not reported");
    assert!(lost.contains("destroyed"), "{lost}");
    // A view can be rebuilt on a new device from its own state.
    let scene = view.scene().clone();
    let settings = *view.settings();
    drop(view);
    let fresh = self::context();
    let mut rebuilt = Renderer::on_context(&fresh, OFFSCREEN_FORMAT, 32, 32, settings).unwrap();
    rebuilt.set_scene(scene.clone());
    assert_eq!(rebuilt.scene().spheres(), scene.spheres());
    assert!(draw(&fresh, &mut rebuilt).chunks(4).any(|p| p[0] as i32 > p[2] as i32 + 30), "no surface drawn");
}
