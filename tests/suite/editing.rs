//! Editing the scene by hand, natively: the sphere under a pixel is the one pointed at, dragging moves
//! it in the plane facing the camera inside the box until two surfaces merge, adding puts a sphere at
//! the box centre's depth, and refused edits leave the scene as it was.

use crate::common;

use common::*;
use glam::Vec3;
use metaballs::{Scene, Settings};

const SIZE: (u32, u32) = (320, 240);

fn two_apart() -> Scene {
    Scene::from_spheres(vec![sphere([-0.5, 0.0, 0.0], 0.25), sphere([0.5, 0.0, 0.0], 0.25)]).unwrap()
}

#[test]
fn the_sphere_under_the_pointer_is_picked_and_dragging_it_merges_the_surfaces() {
    let settings = Settings { resolution: 40, ..Settings::default() };
    with_renderer(settings, SIZE.0, SIZE.1, |o| {
        let r = &mut o.renderer;
        r.set_scene(two_apart());
        let [x0, y0, radius0] = r.sphere_on_screen(0).unwrap();
        let [x1, y1, _] = r.sphere_on_screen(1).unwrap();
        assert!(radius0 > 10.0, "a sphere of radius 0.25 covers {radius0} pixels");
        assert_eq!(r.pick_sphere(x0, y0), Some(0));
        assert_eq!(r.pick_sphere(x1, y1), Some(1));
        assert_eq!(r.pick_sphere(2.0, 2.0), None, "the background picks nothing");

        let components = |r: &mut metaballs::Renderer| {
            pollster::block_on(r.extract_mesh()).topology().component_euler.len()
        };
        assert_eq!(components(r), 2);
        // Drag sphere 1 onto sphere 0 in small steps, as a pointer would.
        let forward = -r.settings().camera.eye().normalize();
        let start = r.scene().spheres()[1].center;
        let steps = 20;
        for k in 0..steps {
            let t = |k: usize| k as f32 / steps as f32;
            let at = |t: f32| (x1 + (x0 - x1) * t * 0.8, y1 + (y0 - y1) * t * 0.8);
            r.move_sphere(1, at(t(k)), at(t(k + 1))).unwrap();
        }
        let moved = r.scene().spheres()[1].center;
        assert!((moved - start).dot(forward).abs() < 1e-4, "moved in the plane facing the camera");
        let [x, y, _] = r.sphere_on_screen(1).unwrap();
        let (ex, ey) = (x1 + (x0 - x1) * 0.8, y1 + (y0 - y1) * 0.8);
        assert!((x - ex).abs() < 0.5 && (y - ey).abs() < 0.5, "the sphere followed the pointer: ({x}, {y})");
        assert_eq!(components(r), 1, "the two surfaces merged");

        // Far past the wall, it stops inside the box.
        r.move_sphere(1, (x0, y0), (x0 + 5000.0, y0)).unwrap();
        let c = r.scene().spheres()[1].center;
        assert!(c.abs().max_element() <= 0.75 + 1e-6, "{c}");
        assert!(r.move_sphere(7, (0.0, 0.0), (1.0, 1.0)).is_err());
    });
}

#[test]
fn adding_and_removing_spheres_by_hand() {
    with_renderer(Settings { resolution: 32, ..Settings::default() }, SIZE.0, SIZE.1, |o| {
        let r = &mut o.renderer;
        r.set_scene(two_apart());
        let index = r.add_sphere(SIZE.0 as f32 / 2.0, SIZE.1 as f32 / 2.0).unwrap();
        assert_eq!(index, 2);
        assert_eq!(r.settings().sphere_count, 3);
        let added = r.scene().spheres()[2];
        assert!(
            added.center.length() < 1e-3,
            "the middle of the view at the box centre's depth: {}",
            added.center
        );
        assert_eq!(added.velocity, Vec3::ZERO);
        assert_eq!(added.radius, 0.25, "sized like the others");
        let [x, y, _] = r.sphere_on_screen(2).unwrap();
        assert!((x - SIZE.0 as f32 / 2.0).abs() < 1.0 && (y - SIZE.1 as f32 / 2.0).abs() < 1.0);

        r.edit(|scene| scene.remove_sphere(0)).unwrap();
        r.edit(|scene| scene.remove_sphere(0)).unwrap();
        assert_eq!(r.scene().spheres().len(), 1);
        let before = r.scene().spheres().to_vec();
        let e = r.edit(|scene| scene.remove_sphere(0)).unwrap_err().to_string();
        assert_eq!(e, "a scene keeps at least one sphere");
        let e =
            r.edit(|scene| scene.set_sphere(0, metaballs::Sphere { radius: -1.0, ..before[0] })).unwrap_err();
        assert!(
            e.to_string().contains("sphere 1.radius: sphere radius must be between 0.01 and 1, got -1"),
            "{e}"
        );
        assert_eq!(r.scene().spheres(), before, "refused edits change nothing");
        // A larger radius pulls the centre back inside the box.
        r.edit(|scene| {
            scene.set_sphere(0, metaballs::Sphere { center: Vec3::new(0.7, 0.0, 0.0), ..before[0] })?;
            scene.set_sphere(0, metaballs::Sphere { radius: 0.5, ..scene.spheres()[0] })
        })
        .unwrap();
        assert_eq!(r.scene().spheres()[0].center.x, 0.5);
        for _ in 0..63 {
            r.add_sphere(10.0, 10.0).unwrap();
        }
        assert_eq!(r.add_sphere(10.0, 10.0).unwrap_err().to_string(), "a scene holds at most 64 spheres");
        assert_eq!(r.settings().sphere_count, 64);
    });
}
