//! Spheres moving in a box: a seeded layout, Euler steps and elastic bounces off the walls.

use super::checks::{ParamError, check_f32};
use super::math;
use super::sphere::{BOX_HALF_EXTENT, MAX_SPHERES, SceneError, Sphere, check_sphere, check_sphere_count};
use glam::Vec3;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg32;

/// The longest time step `Scene::step` takes at once; longer steps (a tab left in the background) are
/// split, so that a bounce is never skipped.
pub const MAX_STEP_SECONDS: f32 = 1.0 / 30.0;

/// The per-sphere random draws of a layout, independent of how many spheres are in play.
#[derive(Clone, Copy, Debug)]
struct Seedling {
    radius_scale: f32,
    position: Vec3,
    velocity: Vec3,
}

/// Spheres inside the box. The first `count` of a seeded layout are in play; changing the count keeps
/// the others where they are.
#[derive(Clone, Debug)]
pub struct Scene {
    seed: u64,
    spheres: Vec<Sphere>,
}

/// Radius of a typical sphere when `count` are in play: the field's long tails add up, so more spheres
/// must be smaller for the surface not to swallow the box.
pub fn nominal_radius(count: u32) -> f32 {
    (0.36 / count as f32).sqrt().min(0.45)
}

impl Scene {
    /// The layout drawn from `seed`, with `count` spheres in play.
    pub fn new(seed: u64, count: u32) -> Result<Self, ParamError> {
        check_sphere_count(count)?;
        let mut rng = Pcg32::seed_from_u64(seed);
        let seedlings: Vec<Seedling> = (0..MAX_SPHERES)
            .map(|_| {
                let radius_scale = rng.random_range(0.75..1.25);
                let position = Vec3::new(rng.random(), rng.random(), rng.random());
                // A direction uniform on the sphere, and a speed in box half-widths per second.
                let z: f32 = rng.random_range(-1.0..1.0);
                let phi: f32 = rng.random_range(0.0..std::f32::consts::TAU);
                let s = (1.0 - z * z).sqrt();
                let speed: f32 = rng.random_range(0.25..0.6);
                Seedling {
                    radius_scale,
                    position,
                    velocity: speed * Vec3::new(s * math::cos(phi), s * math::sin(phi), z),
                }
            })
            .collect();
        let radius = nominal_radius(count);
        let spheres = seedlings[..count as usize]
            .iter()
            .map(|s| {
                let r = radius * s.radius_scale;
                let room = 2.0 * (BOX_HALF_EXTENT - r);
                Sphere {
                    center: Vec3::splat(-BOX_HALF_EXTENT + r) + s.position * room,
                    radius: r,
                    velocity: s.velocity,
                    charge: 1.0,
                }
            })
            .collect();
        Ok(Self { seed, spheres })
    }

    /// A scene of the given spheres, for tests and tools; each must lie inside the box.
    pub fn from_spheres(spheres: Vec<Sphere>) -> Result<Self, ParamError> {
        check_sphere_count(spheres.len() as u32)?;
        for s in &spheres {
            check_f32("sphere radius", s.radius, 1e-3, BOX_HALF_EXTENT)?;
            let limit = BOX_HALF_EXTENT - s.radius;
            for c in s.center.to_array() {
                check_f32("sphere centre coordinate", c, -limit, limit)?;
            }
            for v in s.velocity.to_array() {
                check_f32("sphere velocity", v, -100.0, 100.0)?;
            }
        }
        Ok(Self { seed: 0, spheres })
    }

    /// The same spheres, with `seed` drawing the ones added when the count grows.
    pub fn with_seed(mut self, seed: u64) -> Self {
        self.seed = seed;
        self
    }

    /// The seed this layout was drawn from (0 for hand-made scenes).
    pub fn seed(&self) -> u64 {
        self.seed
    }

    /// The spheres in play.
    pub fn spheres(&self) -> &[Sphere] {
        &self.spheres
    }

    /// Puts `count` spheres in play: the layout is drawn again for the new count, keeping where the
    /// spheres it shares with the old one are now.
    pub fn set_count(&mut self, count: u32) -> Result<(), ParamError> {
        let mut next = Scene::new(self.seed, count)?;
        let radius_ratio = nominal_radius(count) / nominal_radius(self.spheres.len() as u32);
        for (new, old) in next.spheres.iter_mut().zip(&self.spheres) {
            new.radius = old.radius * radius_ratio;
            let limit = BOX_HALF_EXTENT - new.radius;
            new.center = old.center.clamp(Vec3::splat(-limit), Vec3::splat(limit));
            new.velocity = old.velocity;
        }
        *self = next;
        Ok(())
    }

    /// Replaces sphere `index` (checked as a scene file's would be), with its centre moved back inside
    /// the box if its radius needs it.
    pub fn set_sphere(&mut self, index: usize, sphere: Sphere) -> Result<(), SceneError> {
        let slot = self.sphere_slot(index)?;
        let limit = BOX_HALF_EXTENT - sphere.radius;
        let sphere =
            Sphere { center: sphere.center.clamp(Vec3::splat(-limit), Vec3::splat(limit)), ..sphere };
        *slot = check_sphere(&format!("sphere {}", index + 1), sphere)?;
        Ok(())
    }

    /// Adds a sphere (checked, and moved inside the box); returns its index.
    pub fn add_sphere(&mut self, sphere: Sphere) -> Result<usize, SceneError> {
        if self.spheres.len() >= MAX_SPHERES as usize {
            return Err(SceneError(format!("a scene holds at most {MAX_SPHERES} spheres")));
        }
        self.spheres.push(sphere);
        let index = self.spheres.len() - 1;
        self.set_sphere(index, sphere).inspect_err(|_| {
            self.spheres.pop();
        })?;
        Ok(index)
    }

    /// Removes sphere `index`; the last sphere stays.
    pub fn remove_sphere(&mut self, index: usize) -> Result<(), SceneError> {
        self.sphere_slot(index)?;
        if self.spheres.len() == 1 {
            return Err(SceneError("a scene keeps at least one sphere".into()));
        }
        self.spheres.remove(index);
        Ok(())
    }

    fn sphere_slot(&mut self, index: usize) -> Result<&mut Sphere, SceneError> {
        let count = self.spheres.len();
        self.spheres
            .get_mut(index)
            .ok_or_else(|| SceneError(format!("there is no sphere {} (the scene has {count})", index + 1)))
    }

    /// Advances the spheres by `dt` seconds: Euler steps, reflecting off the walls so that every sphere
    /// stays inside the box and keeps its speed.
    pub fn step(&mut self, dt: f32) -> Result<(), ParamError> {
        check_f32("time step (seconds)", dt, 0.0, 3600.0)?;
        let steps = (dt / MAX_STEP_SECONDS).ceil().max(1.0) as u32;
        let h = dt / steps as f32;
        for _ in 0..steps {
            for s in &mut self.spheres {
                let limit = BOX_HALF_EXTENT - s.radius;
                let mut p = s.center + s.velocity * h;
                for axis in 0..3 {
                    if p[axis] > limit {
                        p[axis] = (2.0 * limit - p[axis]).max(-limit);
                        s.velocity[axis] = -s.velocity[axis].abs();
                    } else if p[axis] < -limit {
                        p[axis] = (-2.0 * limit - p[axis]).min(limit);
                        s.velocity[axis] = s.velocity[axis].abs();
                    }
                }
                s.center = p;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_seed_always_gives_the_same_layout() {
        let a = Scene::new(7, 16).unwrap();
        let b = Scene::new(7, 16).unwrap();
        assert_eq!(a.spheres(), b.spheres());
        assert_ne!(a.spheres(), Scene::new(8, 16).unwrap().spheres());
    }

    #[test]
    fn changing_the_count_keeps_the_shared_spheres_in_place() {
        let mut scene = Scene::new(3, 5).unwrap();
        scene.step(0.7).unwrap();
        let before = scene.spheres()[0];
        scene.set_count(6).unwrap();
        assert_eq!(scene.spheres().len(), 6);
        assert!((scene.spheres()[0].center - before.center).length() < 0.1);
        assert!(scene.set_count(0).is_err());
        assert!(scene.set_count(MAX_SPHERES + 1).is_err());
        assert_eq!(scene.spheres().len(), 6);
    }
}
