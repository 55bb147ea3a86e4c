//! The camera framing an output: its view and projection matrices, where a world point lands in pixels,
//! and the ray through a pixel.

use crate::scene::math;
use crate::scene::params::view::Projection;
use crate::scene::params::{Camera, Settings};
use glam::{Mat4, Vec2, Vec3, Vec4};

/// Near and far planes of both projections.
const NEAR: f32 = 0.05;
const FAR: f32 = 100.0;

/// The right-handed perspective with depth from 0 (near) to 1 (far) that WebGPU takes, as glam's
/// `camera::rh::proj::directx::perspective` makes it, with the sine and cosine from
/// [`math`](crate::scene::math) (the browser's own in the browser's build).
fn perspective(vertical_fov: f32, aspect: f32) -> Mat4 {
    let h = math::cos(0.5 * vertical_fov) / math::sin(0.5 * vertical_fov);
    let depth = 1.0 / (FAR - NEAR);
    Mat4::from_cols(
        Vec4::new(h / aspect, 0.0, 0.0, 0.0),
        Vec4::new(0.0, h, 0.0, 0.0),
        Vec4::new(0.0, 0.0, -FAR * depth, -1.0),
        Vec4::new(0.0, 0.0, -NEAR * FAR * depth, 0.0),
    )
}

/// The camera looking at the box's centre, and the output it draws into: pixels count from the top
/// left of a `size.0` × `size.1` output.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraView {
    pub camera: Camera,
    pub projection: Projection,
    /// The output's width and height in pixels.
    pub size: (u32, u32),
}

impl CameraView {
    /// The camera and projection `settings` hold, on an output of `size`.
    pub fn new(settings: &Settings, size: (u32, u32)) -> Self {
        Self { camera: settings.camera, projection: settings.view.projection, size }
    }

    /// Where the eye is.
    pub fn eye(&self) -> Vec3 {
        self.camera.eye()
    }

    /// The unit direction the camera looks in, from the eye to the box's centre.
    pub fn forward(&self) -> Vec3 {
        -self.eye().normalize()
    }

    /// World to camera space: from the eye, looking at the box's centre, with y up.
    pub fn view(&self) -> Mat4 {
        glam::camera::rh::view::look_at_mat4(self.eye(), Vec3::ZERO, Vec3::Y)
    }

    /// The projection times the view: perspective, or orthographic with the same framing at the box's
    /// centre.
    pub fn view_projection(&self) -> Mat4 {
        let aspect = self.size.0 as f32 / self.size.1 as f32;
        let fov = self.camera.fov_y_degrees.to_radians();
        let projection = match self.projection {
            Projection::Perspective => perspective(fov, aspect),
            Projection::Orthographic => {
                let half_height = self.camera.distance * math::tan(fov / 2.0);
                let half_width = half_height * aspect;
                glam::camera::rh::proj::directx::orthographic(
                    -half_width,
                    half_width,
                    -half_height,
                    half_height,
                    NEAR,
                    FAR,
                )
            }
        };
        projection * self.view()
    }

    /// Pixels per world unit: at unit distance from the eye in perspective, anywhere in orthographic.
    pub fn pixels_per_unit(&self) -> f32 {
        let half_fov = math::tan(self.camera.fov_y_degrees.to_radians() / 2.0);
        let height = self.size.1 as f32;
        match self.projection {
            Projection::Perspective => height / (2.0 * half_fov),
            Projection::Orthographic => height / (2.0 * self.camera.distance * half_fov),
        }
    }

    /// Where world point `p` lands in the output, in pixels from the top left.
    pub fn project(&self, p: Vec3) -> Vec2 {
        self.ndc_to_pixel(self.view_projection().project_point3(p))
    }

    /// Where world point `p` lands in the output, or `None` when it is behind the eye.
    pub fn pixel_of(&self, p: Vec3) -> Option<Vec2> {
        let clip = self.view_projection() * p.extend(1.0);
        (clip.w > 1e-6).then(|| self.ndc_to_pixel(clip.truncate() / clip.w))
    }

    fn ndc_to_pixel(&self, ndc: Vec3) -> Vec2 {
        Vec2::new((ndc.x + 1.0) * 0.5 * self.size.0 as f32, (1.0 - ndc.y) * 0.5 * self.size.1 as f32)
    }

    /// The ray from the eye through pixel (`x`, `y`): a point on the near plane and a unit direction,
    /// for perspective and orthographic projections alike.
    pub fn ray(&self, x: f32, y: f32) -> (Vec3, Vec3) {
        let (width, height) = (self.size.0 as f32, self.size.1 as f32);
        let ndc = Vec2::new(2.0 * x / width - 1.0, 1.0 - 2.0 * y / height);
        let inverse = self.view_projection().inverse();
        let near = inverse.project_point3(ndc.extend(0.0));
        let far = inverse.project_point3(ndc.extend(1.0));
        (near, (far - near).normalize())
    }

    /// Where the ray through pixel (`x`, `y`) meets the plane through `point` facing the camera; `None`
    /// when the ray runs along the plane.
    pub fn on_plane_through(&self, x: f32, y: f32, point: Vec3) -> Option<Vec3> {
        let (origin, direction) = self.ray(x, y);
        let normal = self.forward();
        let facing = direction.dot(normal);
        (facing.abs() > 1e-6).then(|| origin + direction * ((point - origin).dot(normal) / facing))
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;
    use crate::scene::params::view::ViewOptions;

    /// The perspective is glam's, number for number, where `math` is the platform's.
    #[test]
    fn the_perspective_is_glams() {
        for (fov, aspect) in [(10.0f32, 1.5f32), (45.0, 4.0 / 3.0), (90.0, 0.5), (170.0, 2.0)] {
            let fov = fov.to_radians();
            let glams = glam::camera::rh::proj::directx::perspective(fov, aspect, NEAR, FAR);
            assert_eq!(perspective(fov, aspect), glams, "{fov} rad at {aspect}");
        }
    }

    /// A 320 × 240 view from the default camera with `projection`.
    pub(crate) fn view(projection: Projection) -> CameraView {
        let settings =
            Settings { view: ViewOptions { projection, ..ViewOptions::default() }, ..Settings::default() };
        CameraView::new(&settings, (320, 240))
    }

    const BOTH: [Projection; 2] = [Projection::Perspective, Projection::Orthographic];

    /// How far `p` lies from the ray (`origin`, `direction`).
    fn miss(p: Vec3, (origin, direction): (Vec3, Vec3)) -> f32 {
        let along = (p - origin).dot(direction);
        (p - origin - direction * along).length()
    }

    #[test]
    fn the_ray_through_the_centre_pixel_passes_through_the_box_centre() {
        for projection in BOTH {
            let view = view(projection);
            let (origin, direction) = view.ray(160.0, 120.0);
            assert!(miss(Vec3::ZERO, (origin, direction)) < 1e-4, "{projection:?}");
            assert!(direction.dot(view.forward()) > 0.9999, "{projection:?} looks at the box");
            assert!(view.project(Vec3::ZERO).distance(Vec2::new(160.0, 120.0)) < 1e-3);
        }
    }

    #[test]
    fn a_point_lies_on_the_ray_through_the_pixel_it_projects_to() {
        for projection in BOTH {
            let view = view(projection);
            for p in [Vec3::new(0.5, 0.3, -0.2), Vec3::new(-0.9, -0.7, 0.8), Vec3::new(0.0, 1.0, 1.0)] {
                let pixel = view.project(p);
                assert!(miss(p, view.ray(pixel.x, pixel.y)) < 1e-4, "{projection:?}: {p}");
            }
        }
    }

    #[test]
    fn up_in_the_world_is_up_on_the_screen_and_rays_are_parallel_only_when_orthographic() {
        for projection in BOTH {
            let view = view(projection);
            assert!(view.project(Vec3::Y).y < view.project(Vec3::ZERO).y, "{projection:?}");
        }
        let spread = |view: CameraView| view.ray(0.0, 0.0).1.dot(view.ray(320.0, 240.0).1);
        assert!(spread(view(Projection::Orthographic)) > 0.9999);
        assert!(spread(view(Projection::Perspective)) < 0.95);
    }

    #[test]
    fn a_point_behind_the_eye_has_no_pixel() {
        let view = view(Projection::Perspective);
        assert!(view.pixel_of(Vec3::ZERO).is_some());
        assert!(view.pixel_of(view.eye() * 2.0).is_none());
    }

    #[test]
    fn the_plane_through_a_point_facing_the_camera_holds_the_point_under_the_pixel() {
        for projection in BOTH {
            let view = view(projection);
            let point = Vec3::new(0.2, -0.1, 0.3);
            let hit = view.on_plane_through(40.0, 200.0, point).unwrap();
            assert!((hit - point).dot(view.forward()).abs() < 1e-4, "{projection:?}: at the point's depth");
            assert!(
                view.project(hit).distance(Vec2::new(40.0, 200.0)) < 1e-2,
                "{projection:?}: under the pixel"
            );
        }
    }

    #[test]
    fn pixels_per_unit_follow_the_output_height_and_the_field_of_view() {
        let perspective = view(Projection::Perspective);
        let half_fov = (22.5f32).to_radians().tan();
        assert!((perspective.pixels_per_unit() - 240.0 / (2.0 * half_fov)).abs() < 1e-3);
        let orthographic = view(Projection::Orthographic);
        let expected = 240.0 / (2.0 * perspective.camera.distance * half_fov);
        assert!((orthographic.pixels_per_unit() - expected).abs() < 1e-3);
    }
}
