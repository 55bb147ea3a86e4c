//! The mesh's error against the exact surface, and how it falls as the grid gets finer: the data of
//! the "error vs resolution" plot. Meshes come from the CPU mesher and distances from the same Newton
//! projection the GPU's measures pass uses (`reference::surface_distance`).

use crate::extract::cpu::mesher::CpuMesher;
use crate::extract::reference::{Construction, Grid, surface_distance};
use crate::scene::Sphere;
use crate::scene::math;

/// One resolution's figures: distances in box half-widths (world units), so that resolutions compare.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErrorPoint {
    pub cells_per_axis: u32,
    /// Root mean square of the vertices' distances to the exact surface.
    pub rms: f64,
    /// The largest distance.
    pub max: f64,
    pub triangles: u32,
}

/// Meshes the spheres at `cells_per_axis` and measures every vertex's distance to the exact surface.
pub fn error_at(spheres: &[Sphere], iso: f32, construction: Construction, cells_per_axis: u32) -> ErrorPoint {
    let grid = Grid { cells_per_axis };
    let mut mesher = CpuMesher::new();
    mesher.mesh(spheres, iso, grid, construction);
    let mesh = mesher.to_indexed();
    let cell = grid.cell_size() as f64;
    let (mut squares, mut max) = (0.0f64, 0.0f64);
    for &p in &mesh.positions {
        let d = surface_distance(spheres, iso, construction.terms, p, grid) as f64 * cell;
        squares += d * d;
        max = max.max(d);
    }
    let n = mesh.positions.len().max(1) as f64;
    ErrorPoint { cells_per_axis, rms: (squares / n).sqrt(), max, triangles: mesh.triangles.len() as u32 }
}

/// The least-squares slope of log `y` against log `x`: the order of convergence when `y` is an error
/// and `x` the cells per axis (about −2 for linear placement, −1 for midpoints). `None` with fewer than
/// two usable points.
pub fn fitted_slope(points: &[(f64, f64)]) -> Option<f64> {
    let logs: Vec<(f64, f64)> = points
        .iter()
        .filter(|(x, y)| *x > 0.0 && *y > 0.0)
        .map(|(x, y)| (math::ln(*x), math::ln(*y)))
        .collect();
    if logs.len() < 2 {
        return None;
    }
    let n = logs.len() as f64;
    let (mx, my) = (logs.iter().map(|p| p.0).sum::<f64>() / n, logs.iter().map(|p| p.1).sum::<f64>() / n);
    let sxx: f64 = logs.iter().map(|p| (p.0 - mx).powi(2)).sum();
    let sxy: f64 = logs.iter().map(|p| (p.0 - mx) * (p.1 - my)).sum();
    (sxx > 0.0).then(|| sxy / sxx)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_slope_is_read_off_a_power_law() {
        let points: Vec<(f64, f64)> =
            [8.0, 16.0, 32.0, 64.0].iter().map(|&n: &f64| (n, 3.0 * n.powf(-2.0))).collect();
        assert!((fitted_slope(&points).unwrap() + 2.0).abs() < 1e-9);
        assert_eq!(fitted_slope(&points[..1]), None);
        assert_eq!(fitted_slope(&[(8.0, 0.0), (16.0, 0.0)]), None);
    }
}
