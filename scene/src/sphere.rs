//! One sphere of the field, the checks every sphere passes (wherever it comes from: a layout, a hand
//! edit, a scene file, a link), and the compact text form of a sphere list that links carry.

use super::checks::{ParamError, check_f32, check_u32, quoted};
use super::decimal::{Fixed, num};
use super::number::parse_f32;
use glam::Vec3;
use std::fmt;

/// Half the width of the cubic box the spheres move in; the box spans `[-BOX_HALF_EXTENT, BOX_HALF_EXTENT]`
/// on every axis.
pub const BOX_HALF_EXTENT: f32 = 1.0;

/// The most spheres a scene holds; raise it here and every buffer follows.
pub const MAX_SPHERES: u32 = 64;
/// Smallest and largest sphere radius accepted (the centre must keep the sphere inside the box).
pub const RADIUS_RANGE: (f32, f32) = (0.01, BOX_HALF_EXTENT);
/// Largest speed along each axis accepted, box half-widths per second.
pub const MAX_VELOCITY: f32 = 100.0;

/// One sphere of the field: it adds `charge · radius² / |p − center|²` at every point `p`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    pub center: Vec3,
    pub radius: f32,
    /// Box half-widths per second.
    pub velocity: Vec3,
    /// 1 adds the sphere's term; −1 subtracts it, denting or cutting the blobs it reaches.
    pub charge: f32,
}

impl Sphere {
    /// Centre and signed radius (`charge · radius`) packed as the GPU reads them.
    pub fn to_gpu(&self) -> [f32; 4] {
        [self.center.x, self.center.y, self.center.z, self.signed_radius()]
    }

    /// The radius with the charge's sign: the form links, the page and the GPU carry.
    pub fn signed_radius(&self) -> f32 {
        if self.is_subtractive() { -self.radius } else { self.radius }
    }

    /// The numerator of the sphere's term, `charge · radius²`. Inline: the CPU meshers (built in
    /// another crate, for speed) read it for every sphere at every vertex.
    #[inline]
    pub fn weight(&self) -> f32 {
        let r2 = self.radius * self.radius;
        if self.is_subtractive() { -r2 } else { r2 }
    }

    /// True for a sphere that subtracts its term.
    #[inline]
    pub fn is_subtractive(&self) -> bool {
        self.charge < 0.0
    }

    /// A still sphere from its centre and signed radius (negative: subtractive).
    pub fn from_signed(center: Vec3, signed_radius: f32, velocity: Vec3) -> Sphere {
        let charge = if signed_radius < 0.0 { -1.0 } else { 1.0 };
        Sphere { center, radius: signed_radius.abs(), velocity, charge }
    }
}

/// A refused scene document or sphere list: which field, and what is wrong with its value.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneError(pub String);

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for SceneError {}

pub(crate) fn at(field: &str, error: ParamError) -> SceneError {
    SceneError(format!("{field}: {error}"))
}

/// Checks one sphere: radius in range, centre keeping it inside the box, finite bounded velocity.
pub fn check_sphere(field: &str, sphere: Sphere) -> Result<Sphere, SceneError> {
    if sphere.charge != 1.0 && sphere.charge != -1.0 {
        return Err(SceneError(format!(
            "{field}.charge: a sphere's charge is 1 (adds) or -1 (subtracts), got {}",
            num(sphere.charge)
        )));
    }
    let (min, max) = RADIUS_RANGE;
    check_f32("sphere radius", sphere.radius, min, max).map_err(|e| at(&format!("{field}.radius"), e))?;
    let limit = BOX_HALF_EXTENT - sphere.radius;
    for (axis, c) in sphere.center.to_array().into_iter().enumerate() {
        check_f32("centre coordinate (inside the box for this radius)", c, -limit, limit)
            .map_err(|e| at(&format!("{field}.center[{axis}]"), e))?;
    }
    for (axis, v) in sphere.velocity.to_array().into_iter().enumerate() {
        check_f32("velocity", v, -MAX_VELOCITY, MAX_VELOCITY)
            .map_err(|e| at(&format!("{field}.velocity[{axis}]"), e))?;
    }
    Ok(sphere)
}

/// Checks a sphere count.
pub fn check_sphere_count(count: u32) -> Result<u32, ParamError> {
    check_u32("sphere count", count, 1, MAX_SPHERES)
}

pub(crate) fn check_count(field: &str, count: usize) -> Result<(), SceneError> {
    if count == 0 || count > MAX_SPHERES as usize {
        return Err(SceneError(format!("{field}: a scene holds 1 to {MAX_SPHERES} spheres, got {count}")));
    }
    Ok(())
}

/// The compact form of spheres in links: `x,y,z,r` (a still sphere) or `x,y,z,r,vx,vy,vz`, joined by
/// `;`, positions to 3 decimals and speeds to 2. A subtractive sphere is written with a negative radius.
/// A centre coordinate is pulled in by a step of its last decimal where rounding would put the sphere
/// past a wall, so that what is written always reads back as a valid sphere.
pub fn spheres_text(spheres: &[Sphere]) -> String {
    let n = |x: f32, places: usize| {
        let t = Fixed(f64::from(x), places).to_string();
        let t = t.trim_end_matches('0').trim_end_matches('.');
        if t == "-0" || t.is_empty() { "0".to_string() } else { t.to_string() }
    };
    // Written straight into one string (a join of owned strings is a second copy of the joining
    // code in the wasm, beside the one for lists of words).
    let mut text = String::new();
    for (i, s) in spheres.iter().enumerate() {
        if i > 0 {
            text.push(';');
        }
        let radius = parse_f32(&n(s.radius, 3)).unwrap_or(s.radius);
        let limit = BOX_HALF_EXTENT - radius;
        let mut parts: Vec<String> = s
            .center
            .to_array()
            .iter()
            .map(|&c| {
                let mut t = n(c, 3);
                for step in 1..=3 {
                    if !parse_f32(&t).is_some_and(|v| v.abs() > limit) {
                        break;
                    }
                    t = n(c - c.signum() * 0.001 * step as f32, 3);
                }
                t
            })
            .collect();
        parts.push(n(radius * s.charge, 3));
        let v: Vec<String> = s.velocity.to_array().iter().map(|&c| n(c, 2)).collect();
        if v.iter().any(|c| c != "0") {
            parts.extend(v);
        }
        for (k, part) in parts.iter().enumerate() {
            if k > 0 {
                text.push(',');
            }
            text.push_str(part);
        }
    }
    text
}

/// Reads the compact form written by [`spheres_text`] (a negative radius: a subtractive sphere); every
/// sphere is checked as in a document.
pub fn parse_spheres_text(text: &str) -> Result<Vec<Sphere>, SceneError> {
    let groups: Vec<&str> = text.split(';').map(str::trim).filter(|g| !g.is_empty()).collect();
    check_count("balls", groups.len())?;
    groups
        .iter()
        .enumerate()
        .map(|(i, group)| {
            let field = format!("balls sphere {}", i + 1);
            let numbers = group
                .split(',')
                .map(|t| {
                    parse_f32(t.trim())
                        .ok_or_else(|| SceneError(format!("{field}: {} is not a number", quoted(t.trim()))))
                })
                .collect::<Result<Vec<f32>, _>>()?;
            let s = match numbers[..] {
                [x, y, z, r] => Sphere::from_signed(Vec3::new(x, y, z), r, Vec3::ZERO),
                [x, y, z, r, vx, vy, vz] => Sphere::from_signed(Vec3::new(x, y, z), r, Vec3::new(vx, vy, vz)),
                _ => {
                    return Err(SceneError(format!(
                        "{field}: expected x,y,z,radius or x,y,z,radius,vx,vy,vz, got {} numbers",
                        numbers.len()
                    )));
                }
            };
            check_sphere(&field, s)
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_compact_form_reads_back_to_its_precision() {
        let spheres = vec![
            Sphere { center: Vec3::new(-0.3, 0.1234, 0.0), radius: 0.35, velocity: Vec3::ZERO, charge: 1.0 },
            Sphere {
                center: Vec3::new(0.4, -0.2, 0.25),
                radius: 0.3,
                velocity: Vec3::new(0.5, -0.25, 0.0),
                charge: 1.0,
            },
        ];
        let text = spheres_text(&spheres);
        assert_eq!(text, "-0.3,0.123,0,0.35;0.4,-0.2,0.25,0.3,0.5,-0.25,0");
        let back = parse_spheres_text(&text).unwrap();
        assert_eq!(back.len(), 2);
        assert!((back[0].center - spheres[0].center).abs().max_element() < 1e-3);
        assert_eq!(back[1].velocity, spheres[1].velocity);
        let e = parse_spheres_text("0,0,0,0.3;0.9,0,0,0.3").unwrap_err().to_string();
        assert!(e.contains("balls sphere 2.center[0]") && e.contains("got 0.9"), "{e}");
        assert!(parse_spheres_text("0,0,0").unwrap_err().to_string().contains("got 3 numbers"));
        assert!(parse_spheres_text("0,0,x,1").unwrap_err().to_string().contains("\"x\" is not a number"));
        assert!(parse_spheres_text("").is_err());
        let dented = parse_spheres_text("0,0,0,0.5;0.2,0,0,-0.2").unwrap();
        assert_eq!((dented[0].charge, dented[1].charge, dented[1].radius), (1.0, -1.0, 0.2));
        assert_eq!(spheres_text(&dented), "0,0,0,0.5;0.2,0,0,-0.2");
        let e = parse_spheres_text("0,0,0,-2").unwrap_err().to_string();
        assert!(e.contains("balls sphere 1.radius: sphere radius must be between 0.01 and 1"), "{e}");
    }
}
