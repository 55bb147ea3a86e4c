//! Editing the scene by pointer, on the CPU from the sphere list and the camera: a dragged sphere moves
//! in the plane through its centre facing the camera, an added one lands on the plane through the box's
//! centre, and a sphere's place and size on the screen.

use super::CameraView;
use crate::scene::{Sphere, nominal_radius};
use glam::Vec3;

/// `sphere` moved as the pointer went from pixel `from` to pixel `to`, in the plane through its centre
/// facing the camera (the box's walls are the scene's to keep); `None` when that plane is seen edge-on.
pub fn dragged(view: &CameraView, sphere: Sphere, from: (f32, f32), to: (f32, f32)) -> Option<Sphere> {
    let a = view.on_plane_through(from.0, from.1, sphere.center)?;
    let b = view.on_plane_through(to.0, to.1, sphere.center)?;
    Some(Sphere { center: sphere.center + (b - a), ..sphere })
}

/// A still sphere where the ray through pixel (`x`, `y`) meets the plane through the box's centre
/// facing the camera, as large as the median of `spheres` (or the nominal radius of one more sphere
/// when there are none).
pub fn added(view: &CameraView, spheres: &[Sphere], x: f32, y: f32) -> Sphere {
    let center = view.on_plane_through(x, y, Vec3::ZERO).unwrap_or(Vec3::ZERO);
    // Radii are positive, so their bits sort as they do (as u64: the sort the topology count uses,
    // so the browser's build carries one sort, not two).
    let mut radii: Vec<u64> = spheres.iter().map(|s| s.radius.to_bits() as u64).collect();
    radii.sort_unstable();
    let median = radii.get(radii.len() / 2).map(|&bits| f32::from_bits(bits as u32));
    let radius = median.unwrap_or(nominal_radius(spheres.len() as u32 + 1));
    Sphere { center, radius, velocity: Vec3::ZERO, charge: 1.0 }
}

/// Where `sphere` appears in the output: its centre's pixel and its radius in pixels (measured across
/// the screen), or `None` when it is behind the eye.
pub fn on_screen(view: &CameraView, sphere: &Sphere) -> Option<[f32; 3]> {
    let right = view.forward().cross(Vec3::Y).normalize_or(Vec3::X);
    let centre = view.pixel_of(sphere.center)?;
    let edge = view.pixel_of(sphere.center + right * sphere.radius)?;
    Some([centre.x, centre.y, centre.distance(edge)])
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::params::Camera;
    use crate::scene::params::view::Projection;
    use crate::view::camera::tests::view;
    use glam::Vec2;

    fn ball(center: [f32; 3], radius: f32) -> Sphere {
        Sphere { center: Vec3::from_array(center), radius, velocity: Vec3::new(0.1, 0.0, 0.0), charge: 1.0 }
    }

    #[test]
    fn a_dragged_sphere_keeps_its_depth_and_follows_the_pointer() {
        for projection in [Projection::Perspective, Projection::Orthographic] {
            let view = view(projection);
            let sphere = ball([0.3, -0.2, 0.1], 0.2);
            let [x, y, _] = on_screen(&view, &sphere).unwrap();
            let moved = dragged(&view, sphere, (x, y), (x - 40.0, y + 25.0)).unwrap();
            assert!((moved.center - sphere.center).dot(view.forward()).abs() < 1e-4, "{projection:?}");
            let [mx, my, _] = on_screen(&view, &moved).unwrap();
            assert!(Vec2::new(mx, my).distance(Vec2::new(x - 40.0, y + 25.0)) < 1e-2, "{projection:?}");
            assert_eq!((moved.radius, moved.velocity, moved.charge), (sphere.radius, sphere.velocity, 1.0));
            assert_eq!(dragged(&view, sphere, (x, y), (x, y)).unwrap().center, sphere.center);
        }
    }

    #[test]
    fn an_added_sphere_lands_on_the_plane_through_the_box_centre_facing_the_camera() {
        let view = view(Projection::Perspective);
        let spheres = [ball([0.5, 0.0, 0.0], 0.1), ball([-0.5, 0.0, 0.0], 0.3), ball([0.0, 0.5, 0.0], 0.2)];
        let added = added(&view, &spheres, 100.0, 70.0);
        assert!(added.center.dot(view.forward()).abs() < 1e-4, "{}", added.center);
        assert!(view.project(added.center).distance(Vec2::new(100.0, 70.0)) < 1e-2);
        assert_eq!((added.radius, added.velocity, added.charge), (0.2, Vec3::ZERO, 1.0), "the median size");
        let centre = super::added(&view, &spheres, 160.0, 120.0).center;
        assert!(centre.length() < 1e-4, "the middle pixel adds at the box's centre: {centre}");
        assert_eq!(super::added(&view, &[], 160.0, 120.0).radius, nominal_radius(1));
    }

    #[test]
    fn a_sphere_on_screen_grows_as_the_camera_comes_closer_and_vanishes_behind_it() {
        let far = view(Projection::Perspective);
        let near = CameraView { camera: Camera { distance: 2.0, ..far.camera }, ..far };
        let sphere = ball([0.0; 3], 0.25);
        let [x, y, radius] = on_screen(&far, &sphere).unwrap();
        assert!((x - 160.0).abs() < 1e-3 && (y - 120.0).abs() < 1e-3);
        assert!(on_screen(&near, &sphere).unwrap()[2] > 1.5 * radius);
        assert!(on_screen(&far, &ball((far.eye() * 1.5).to_array(), 0.1)).is_none());
    }
}
