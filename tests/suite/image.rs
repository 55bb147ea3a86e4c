//! What a person sees: a reference frame compared perceptually (FLIP), and the checks one would make
//! by eye — not blank, the lit side brighter, a specular highlight where the light reflects.

use crate::common;

use common::*;
use glam::Vec3;
use metaballs::offscreen::write_png;
use metaballs::{Camera, Scene, Settings};

#[test]
fn five_spheres_match_the_reference_image() {
    let (width, height) = (320, 240);
    let settings = Settings { seed: 1, sphere_count: 5, resolution: 64, ..Settings::default() };
    let pixels = with_renderer(settings, width, height, |o| {
        o.renderer.update(2.0).unwrap();
        o.render_rgba()
    });
    assert_matches_reference("five_spheres", width, height, &pixels);
}

/// One sphere seen head-on with the light to the right: where is it, how bright is each side, and
/// where is the highlight?
#[test]
fn a_lit_sphere_looks_lit_round_and_glossy() {
    let (width, height) = (256, 256);
    let radius = 0.5;
    let camera = Camera { yaw_degrees: 0.0, pitch_degrees: 0.0, distance: 4.0, fov_y_degrees: 40.0 };
    let light = Vec3::new(4.0, 0.0, 4.0);
    let settings = Settings { resolution: 96, camera, light_position: light, ..Settings::default() };
    let pixels = with_renderer(settings, width, height, |o| {
        o.renderer.set_scene(Scene::from_spheres(vec![sphere([0.0, 0.0, 0.0], radius)]).unwrap());
        o.render_rgba()
    });
    write_png(&output_dir().join("lit_sphere.png"), width, height, &pixels).unwrap();

    // The surface is red; the background and box are grey-blue.
    let pixel = |x: u32, y: u32| &pixels[((y * width + x) * 4) as usize..][..4];
    let on_surface = |x: u32, y: u32| {
        let p = pixel(x, y);
        p[0] as i32 > p[2] as i32 + 30
    };
    let surface: Vec<(u32, u32)> = (0..height)
        .flat_map(|y| (0..width).map(move |x| (x, y)))
        .filter(|&(x, y)| on_surface(x, y))
        .collect();

    // Not blank, and the disc has the size and place perspective gives it.
    let half_fov = (camera.fov_y_degrees / 2.0).to_radians();
    let angular_radius = (radius / camera.distance).asin();
    let disc_radius = angular_radius.tan() / half_fov.tan() * height as f32 / 2.0;
    let expected_area = std::f32::consts::PI * disc_radius * disc_radius;
    let area = surface.len() as f32;
    assert!(
        (area / expected_area - 1.0).abs() < 0.06,
        "surface covers {area} px, a sphere would cover {expected_area}"
    );
    let centroid =
        surface.iter().fold(glam::Vec2::ZERO, |c, &(x, y)| c + glam::Vec2::new(x as f32, y as f32)) / area;
    assert!(
        centroid.distance(glam::Vec2::new(width as f32 / 2.0, height as f32 / 2.0)) < 2.0,
        "centroid {centroid}"
    );

    // The side facing the light (+x, the right) is brighter than the far side.
    let mean = |pred: &dyn Fn(u32) -> bool| {
        let side: Vec<f32> =
            surface.iter().filter(|&&(x, _)| pred(x)).map(|&(x, y)| luminance(pixel(x, y))).collect();
        side.iter().sum::<f32>() / side.len() as f32
    };
    let (left, right) = (mean(&|x| x < width / 2), mean(&|x| x >= width / 2));
    assert!(right > 1.4 * left, "lit side {right:.1}, far side {left:.1}");

    // A white highlight where the halfway vector meets the sphere.
    let (&(hx, hy), peak) =
        surface.iter().map(|p| (p, luminance(pixel(p.0, p.1)))).max_by(|a, b| a.1.total_cmp(&b.1)).unwrap();
    let white = pixel(hx, hy);
    assert!(white[..3].iter().all(|&c| c > 215), "brightest surface pixel {white:?} is not a highlight");
    let eye = camera.eye();
    let halfway = ((light - Vec3::ZERO).normalize() + (eye - Vec3::ZERO).normalize()).normalize();
    let on_sphere = halfway * radius;
    let to_screen = |p: Vec3| {
        let depth = camera.distance - p.z;
        let scale = height as f32 / 2.0 / half_fov.tan() / depth;
        glam::Vec2::new(width as f32 / 2.0 + p.x * scale, height as f32 / 2.0 - p.y * scale)
    };
    let predicted = to_screen(on_sphere);
    let found = glam::Vec2::new(hx as f32, hy as f32);
    assert!(
        found.distance(predicted) < 0.15 * disc_radius,
        "highlight at {found}, expected near {predicted} (peak {peak})"
    );
}
