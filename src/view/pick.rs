//! What is under a pixel: the cell the inspector shows, or the sphere a pointer grabs. Both walk the ray
//! through the grid as the oracle builds the surface, from the scene's spheres alone.

use super::CameraView;
use crate::extract::reference::{Construction, Grid};
use crate::scene::Sphere;
use crate::scene::params::view::GridView;
use crate::teach::inspect::{self, Target};
use glam::{UVec3, Vec3};

/// The surface f = `iso` of `spheres` on `grid`, as `view` shows it.
#[derive(Clone, Copy, Debug)]
pub struct Picker<'a> {
    pub view: CameraView,
    pub spheres: &'a [Sphere],
    pub iso: f32,
    pub grid: Grid,
    pub construction: Construction,
}

impl Picker<'_> {
    /// The cell under pixel (`x`, `y`): the cell whose triangles the ray from the eye meets first, or in
    /// the cells view (`grid`) the first crossed cell it enters; `None` over the background.
    pub fn cell(&self, x: f32, y: f32, grid: GridView) -> Option<UVec3> {
        let target = if grid == GridView::Cells { Target::CrossedCell } else { Target::Surface };
        self.walk(x, y, target).map(|(cell, _)| cell)
    }

    /// The sphere under pixel (`x`, `y`): the one whose term dominates the field where the ray first
    /// meets the surface, or a subtracting sphere whose ball the ray meets before that; `None` over
    /// the background.
    pub fn sphere(&self, x: f32, y: f32) -> Option<usize> {
        let (origin, direction) = self.view.ray(x, y);
        let on_surface = self.walk(x, y, Target::Surface).and_then(|(_, point)| {
            Some(((point - origin).length(), inspect::dominant_sphere(self.spheres, point)?))
        });
        // A subtracting sphere has no surface of its own: it is picked where the ray meets its ball.
        let subtracting = self
            .spheres
            .iter()
            .enumerate()
            .filter(|(_, sphere)| sphere.is_subtractive())
            .filter_map(|(i, sphere)| Some((ball_hit(sphere, origin, direction)?, i)))
            .min_by(|a, b| a.0.total_cmp(&b.0));
        match (on_surface, subtracting) {
            (Some(hit), Some(ball)) => Some(if ball.0 < hit.0 { ball.1 } else { hit.1 }),
            (hit, ball) => hit.or(ball).map(|h| h.1),
        }
    }

    fn walk(&self, x: f32, y: f32, target: Target) -> Option<(UVec3, Vec3)> {
        let (origin, direction) = self.view.ray(x, y);
        inspect::pick(self.spheres, self.iso, self.grid, self.construction, origin, direction, target)
    }
}

/// How far along the ray (`origin`, unit `direction`) it first meets `sphere`'s ball, ahead of the
/// origin by its centre; `None` when it passes by.
fn ball_hit(sphere: &Sphere, origin: Vec3, direction: Vec3) -> Option<f32> {
    let to_centre = sphere.center - origin;
    let along = to_centre.dot(direction);
    let miss2 = to_centre.length_squared() - along * along;
    let r2 = sphere.radius * sphere.radius;
    (along > 0.0 && miss2 <= r2).then(|| along - (r2 - miss2).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::params::Settings;

    fn sphere(center: [f32; 3], radius: f32, charge: f32) -> Sphere {
        Sphere { center: Vec3::from_array(center), radius, velocity: Vec3::ZERO, charge }
    }

    fn picker(spheres: &[Sphere]) -> Picker<'_> {
        Picker {
            view: CameraView::new(&Settings::default(), (320, 240)),
            spheres,
            iso: 1.0,
            grid: Grid { cells_per_axis: 40 },
            construction: Construction::default(),
        }
    }

    #[test]
    fn a_sphere_is_picked_at_its_projected_centre_and_the_background_picks_nothing() {
        let spheres = [sphere([-0.5, 0.0, 0.0], 0.25, 1.0), sphere([0.5, 0.0, 0.0], 0.25, 1.0)];
        let picker = picker(&spheres);
        for (i, s) in spheres.iter().enumerate() {
            let pixel = picker.view.project(s.center);
            assert_eq!(picker.sphere(pixel.x, pixel.y), Some(i));
        }
        assert_eq!(picker.sphere(2.0, 2.0), None);
        assert_eq!(picker.cell(2.0, 2.0, GridView::None), None);
    }

    #[test]
    fn a_subtracting_sphere_in_front_of_a_surface_is_picked_before_it() {
        let eye = picker(&[]).view.eye();
        let toward_eye = eye.normalize() * 0.45;
        let spheres = [sphere([0.0; 3], 0.3, 1.0), sphere(toward_eye.to_array(), 0.1, -1.0)];
        let picker = picker(&spheres);
        let centre = picker.view.project(Vec3::ZERO);
        assert_eq!(picker.sphere(centre.x, centre.y), Some(1));
        let beside = picker.view.project(Vec3::new(0.0, -0.25, 0.0));
        assert_eq!(picker.sphere(beside.x, beside.y), Some(0), "the ray passes the small ball by");
    }

    #[test]
    fn the_picked_cell_holds_the_near_side_of_the_surface() {
        let spheres = [sphere([0.0; 3], 0.4, 1.0)];
        let picker = picker(&spheres);
        let centre = picker.view.project(Vec3::ZERO);
        let cell = picker.cell(centre.x, centre.y, GridView::None).expect("the ray meets the sphere");
        let grid = picker.grid;
        let middle = grid.point(cell) + Vec3::splat(grid.cell_size() / 2.0);
        let diagonal = grid.cell_size() * 3f32.sqrt();
        assert!((middle.length() - 0.4).abs() <= diagonal, "{middle} lies on the sphere");
        assert!(middle.dot(picker.view.eye()) > 0.0, "{middle} faces the eye");
        let entered = picker.cell(centre.x, centre.y, GridView::Cells).expect("a crossed cell");
        let walked = (grid.point(entered) - grid.point(cell)).length();
        assert!(walked <= 2.0 * diagonal, "the cells view picks the crossed cell the ray enters");
    }
}
