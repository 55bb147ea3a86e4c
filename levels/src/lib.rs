//! The field's critical points and the surface's area and volume along the iso level, built as its own
//! small WebAssembly module (`pkg-levels/`), loaded by the page's topology worker only when a figure
//! asks for them, so the drawing build does not carry the search.

use glam::Vec3;
use metaballs_core::critical::{self, json};
use metaballs_core::extract::cpu::mesher::CpuMesher;
use metaballs_core::extract::reference::{Construction, Grid};
use metaballs_core::scene::Sphere;

#[cfg(target_arch = "wasm32")]
use wasm_bindgen::prelude::wasm_bindgen;

/// Spheres from `[x, y, z, signed radius]` per sphere, as the page packs them.
fn spheres(packed: &[f32]) -> Vec<Sphere> {
    packed
        .chunks_exact(4)
        .map(|s| Sphere::from_signed(Vec3::new(s[0], s[1], s[2]), s[3], Vec3::ZERO))
        .collect()
}

/// The critical points of the packed spheres' field, their merge tree and the surface's counts
/// between critical levels, as JSON (`metaballs_core::critical::json`); `milliseconds` is the time the
/// caller measures, filled in by it.
#[cfg_attr(target_arch = "wasm32", wasm_bindgen)]
pub fn critical_points(packed: &[f32]) -> String {
    json::to_json(&critical::find(&spheres(packed)), 0.0)
}

/// The surface's area and enclosed volume at each of `levels`, meshed on an `n`³ grid with MC33:
/// `[area, volume]` per level.
#[cfg_attr(target_arch = "wasm32", wasm_bindgen)]
pub fn measures(packed: &[f32], levels: &[f32], n: u32) -> Vec<f32> {
    let spheres = spheres(packed);
    let mut mesher = CpuMesher::new();
    let construction = Construction {
        case_table: metaballs_core::scene::params::view::CaseTable::Mc33,
        ..Construction::default()
    };
    let mut out = Vec::with_capacity(2 * levels.len());
    for &iso in levels {
        mesher.mesh(&spheres, iso, Grid { cells_per_axis: n.clamp(8, 128) }, construction);
        let mesh = mesher.to_indexed();
        let area: f64 = mesh
            .triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| mesh.positions[i as usize].as_dvec3());
                0.5 * (b - a).cross(c - a).length()
            })
            .sum();
        out.extend([area as f32, mesh.enclosed_volume() as f32]);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One sphere of radius r at iso 1 is the sphere itself: area 4πr², volume 4/3 πr³.
    #[test]
    fn a_lone_sphere_measures_as_a_sphere() {
        let m = measures(&[0.0, 0.0, 0.0, 0.5], &[1.0, 4.0], 96);
        let pi = std::f32::consts::PI;
        for (k, r) in [0.5f32, 0.25].into_iter().enumerate() {
            assert!((m[2 * k] / (4.0 * pi * r * r) - 1.0).abs() < 0.01, "{m:?}");
            assert!((m[2 * k + 1] / (4.0 / 3.0 * pi * r * r * r) - 1.0).abs() < 0.01, "{m:?}");
        }
        let text = critical_points(&[-0.3, 0.0, 0.0, 0.2, 0.3, 0.0, 0.0, 0.2]);
        assert!(text.contains("\"role\":\"join\""), "{text}");
    }
}
