//! The exact surface (`display=exact`, `compare=split|overlay`): the device's ray caster against a
//! brute-force CPU one at many pixels, and the silhouettes of the exact surface and of the 128³ mesh
//! as drawn, pixel for pixel.

use crate::common;

use common::*;
use metaballs::extract::kernel::Terms;
use metaballs::extract::reference::exact_hit;
use metaballs::scene::params::view::{Blend, Compare, Display, Kernel};
use metaballs::{Scene, Settings, Sphere};

const W: u32 = 160;
const H: u32 = 120;

fn scenes() -> Vec<(&'static str, Vec<Sphere>, Terms)> {
    let seeded = Scene::new(7, 6).unwrap().spheres().to_vec();
    let terms = |kernel, blend| Terms { kernel, blend, ..Terms::default() };
    vec![
        ("seeded", seeded.clone(), Terms::default()),
        ("seeded, blend by max", seeded.clone(), terms(Kernel::InverseSquare, Blend::Max)),
        ("seeded, Blinn's kernel", seeded.clone(), terms(Kernel::Blinn, Blend::Sum)),
        ("seeded, Wyvill's kernel", seeded, terms(Kernel::Wyvill, Blend::Sum)),
        ("dented", scenes::dented(), Terms::default()),
        ("dented, Wyvill's kernel", scenes::dented(), terms(Kernel::Wyvill, Blend::Sum)),
        ("touching the walls", scenes::touching_walls(), Terms::default()),
    ]
}

#[test]
fn the_exact_view_hits_where_a_cpu_ray_caster_does() {
    for (what, spheres, terms) in scenes() {
        let mut settings = Settings { resolution: 128, iso: 1.0, ..Settings::default() };
        settings.view.display = Display::Exact;
        terms.set_in(&mut settings.view);
        with_renderer(settings, W, H, |o| {
            o.renderer.set_scene(Scene::from_spheres(spheres.clone()).unwrap());
            let pixels: Vec<[f32; 2]> = (0..32 * 24)
                .map(|k| [(k % 32) as f32 * W as f32 / 32.0 + 2.3, (k / 32) as f32 * H as f32 / 24.0 + 2.7])
                .collect();
            let gpu = pollster::block_on(o.renderer.exact_hits(&pixels));
            let (mut hits, mut disagree, mut worst) = (0, 0, 0.0f32);
            for (pixel, gpu) in pixels.iter().zip(&gpu) {
                let (origin, direction) = o.renderer.ray(pixel[0], pixel[1]);
                let cpu = exact_hit(&spheres, 1.0, terms, origin, direction);
                match (gpu, cpu) {
                    (Some(a), Some(b)) => {
                        hits += 1;
                        worst = worst.max((a - b).abs());
                    }
                    (None, None) => {}
                    // A ray grazing the surface can touch it between the CPU's steps: allow a few.
                    _ => disagree += 1,
                }
            }
            println!("{what}: {hits} hits, {disagree} disagreements, largest depth difference {worst:.2e}");
            assert!(hits >= 20, "{what}: only {hits} pixels hit the surface");
            assert!(disagree <= 2, "{what}: {disagree} pixels disagree on hitting the surface");
            // Within 1e-3 of the box's size (2).
            assert!(worst <= 2e-3, "{what}: depth differs by {worst}");
        });
    }
}

/// The pixels that differ from an empty frame (a sphere too small to show, same camera).
fn foreground(o: &mut metaballs::offscreen::Offscreen, spheres: &[Sphere], empty: &[u8]) -> Vec<bool> {
    o.renderer.set_scene(Scene::from_spheres(spheres.to_vec()).unwrap());
    let rgba = o.render_rgba();
    rgba.chunks_exact(4)
        .zip(empty.chunks_exact(4))
        .map(|(a, b)| a.iter().zip(b).any(|(x, y)| x.abs_diff(*y) > 24))
        .collect()
}

/// Pixels of `a` unlike `b` with no pixel of `b`'s other side within `reach` pixels: where the two
/// silhouettes are further apart than `reach`.
fn apart(a: &[bool], b: &[bool], reach: i32) -> usize {
    let at = |x: i32, y: i32| b[(y.clamp(0, H as i32 - 1) * W as i32 + x.clamp(0, W as i32 - 1)) as usize];
    (0..(W * H) as i32)
        .filter(|&i| {
            let (x, y) = (i % W as i32, i / W as i32);
            a[i as usize] != b[i as usize]
                && !(-reach..=reach).any(|dy| (-reach..=reach).any(|dx| at(x + dx, y + dy) == a[i as usize]))
        })
        .count()
}

#[test]
fn the_exact_silhouette_lies_within_two_pixels_of_the_mesh_at_128_cells() {
    let tiny = vec![sphere([0.0, 0.0, 0.0], 1e-3)];
    for (what, spheres, terms) in scenes().into_iter().filter(|s| s.2.blend == Blend::Sum) {
        let mut settings = Settings { resolution: 128, iso: 1.0, antialiasing: false, ..Settings::default() };
        terms.set_in(&mut settings.view);
        let mesh = with_renderer(settings, W, H, |o| {
            o.renderer.set_scene(Scene::from_spheres(tiny.clone()).unwrap());
            let empty = o.render_rgba();
            foreground(o, &spheres, &empty)
        });
        settings.view.display = Display::Exact;
        let exact = with_renderer(settings, W, H, |o| {
            o.renderer.set_scene(Scene::from_spheres(tiny.clone()).unwrap());
            let empty = o.render_rgba();
            foreground(o, &spheres, &empty)
        });
        let covered = exact.iter().filter(|&&e| e).count();
        let differ = mesh.iter().zip(&exact).filter(|(a, b)| a != b).count();
        println!("{what}: {covered} pixels of exact surface, {differ} differ from the mesh's");
        assert!(covered > 400, "{what}: the exact surface covers {covered} pixels");
        assert_eq!(apart(&mesh, &exact, 2), 0, "{what}: mesh pixels over 2 px from the exact silhouette");
        assert_eq!(apart(&exact, &mesh, 2), 0, "{what}: exact pixels over 2 px from the mesh's silhouette");
    }
}

#[test]
fn split_and_overlay_show_mesh_and_exact_surface_together() {
    let mut settings = Settings { resolution: 24, iso: 1.0, antialiasing: false, ..Settings::default() };
    settings.view.compare = Compare::Split;
    settings.view.divider = 0.5;
    let spheres = Scene::new(3, 4).unwrap().spheres().to_vec();
    let frame = |settings: Settings| {
        with_renderer(settings, W, H, |o| {
            o.renderer.set_scene(Scene::from_spheres(spheres.clone()).unwrap());
            o.render_rgba()
        })
    };
    let split = frame(settings);
    let mesh = frame(Settings {
        view: metaballs::scene::params::ViewOptions { compare: Compare::None, ..settings.view },
        ..settings
    });
    let exact = frame(Settings {
        view: metaballs::scene::params::ViewOptions {
            compare: Compare::None,
            display: Display::Exact,
            ..settings.view
        },
        ..settings
    });
    // Left of the divider the split frame is the mesh's, right of it the exact surface's; a coarse
    // 24³ mesh is visibly unlike the exact surface.
    let pixel = |frame: &[u8], x: u32, y: u32| frame[4 * (y * W + x) as usize..][..4].to_vec();
    let (mut left_as_mesh, mut right_as_exact, mut mesh_unlike_exact) = (0, 0, 0);
    for y in 0..H {
        for x in 0..W {
            if x < W / 2 - 1 {
                left_as_mesh += (pixel(&split, x, y) == pixel(&mesh, x, y)) as u32;
            } else if x > W / 2 + 2 {
                right_as_exact += (pixel(&split, x, y) == pixel(&exact, x, y)) as u32;
            }
            mesh_unlike_exact += (pixel(&mesh, x, y) != pixel(&exact, x, y)) as u32;
        }
    }
    let half = (W / 2 - 3) * H;
    assert!(left_as_mesh >= half * 99 / 100, "left: {left_as_mesh} of {half} as the mesh");
    assert!(right_as_exact >= half * 99 / 100, "right: {right_as_exact} of {half} as the exact surface");
    assert!(
        mesh_unlike_exact > 200,
        "the 24³ mesh and the exact surface differ in {mesh_unlike_exact} pixels"
    );
    // The divider: a light column at the split.
    let column = (0..H).filter(|&y| pixel(&split, W / 2, y)[0] > 200).count();
    assert!(column as u32 >= H * 9 / 10, "divider column: {column}");

    let overlay = frame(Settings {
        view: metaballs::scene::params::ViewOptions { compare: Compare::Overlay, ..settings.view },
        ..settings
    });
    let outlined = (0..W * H).filter(|&i| {
        let p = pixel(&overlay, i % W, i / W);
        p != pixel(&mesh, i % W, i / W) && p[2] > 200 && p[0] < 140
    });
    let outlined = outlined.count();
    assert!(outlined > 100, "the outline covers {outlined} pixels");
}
