//! Motion: Euler steps with elastic bounces keep every sphere in the box at its speed.

use metaballs::Scene;
use metaballs::scene::BOX_HALF_EXTENT;
use metaballs::scene::params::MAX_SPHERES;

#[test]
fn ten_thousand_steps_keep_spheres_inside_and_speeds_unchanged() {
    for (seed, dt) in [(1, 1.0 / 60.0), (2, 1.0 / 144.0), (3, 0.25)] {
        let mut scene = Scene::new(seed, MAX_SPHERES).unwrap();
        let speeds: Vec<f32> = scene.spheres().iter().map(|s| s.velocity.length()).collect();
        let start: Vec<_> = scene.spheres().iter().map(|s| s.center).collect();
        let mut bounced = vec![false; speeds.len()];
        for _ in 0..10_000 {
            let before: Vec<_> = scene.spheres().iter().map(|s| s.velocity).collect();
            scene.step(dt).unwrap();
            for (i, s) in scene.spheres().iter().enumerate() {
                let limit = BOX_HALF_EXTENT - s.radius;
                assert!(s.center.abs().max_element() <= limit + 1e-6, "sphere {i} left the box: {s:?}");
                assert!(
                    (s.velocity.length() - speeds[i]).abs() <= 1e-6 * speeds[i],
                    "sphere {i} changed speed"
                );
                bounced[i] |= s.velocity != before[i];
            }
        }
        assert!(bounced.iter().all(|&b| b), "every sphere should have hit a wall");
        assert!(scene.spheres().iter().zip(&start).all(|(s, p)| s.center != *p));
    }
}

#[test]
fn a_long_step_is_split_and_still_bounces() {
    let mut a = Scene::new(4, 8).unwrap();
    let mut b = a.clone();
    a.step(3.0).unwrap();
    for _ in 0..90 {
        b.step(1.0 / 30.0).unwrap();
    }
    for (x, y) in a.spheres().iter().zip(b.spheres()) {
        assert!(x.center.distance(y.center) < 1e-4);
        assert!(x.center.abs().max_element() <= BOX_HALF_EXTENT - x.radius + 1e-6);
    }
}

#[test]
fn bad_time_steps_are_refused_and_change_nothing() {
    let mut scene = Scene::new(1, 5).unwrap();
    let before = scene.spheres().to_vec();
    for dt in [f32::NAN, f32::INFINITY, -0.1] {
        let e = scene.step(dt).unwrap_err().to_string();
        assert!(e.starts_with("time step (seconds) must"), "{e}");
    }
    assert_eq!(scene.spheres(), &before[..]);
}
