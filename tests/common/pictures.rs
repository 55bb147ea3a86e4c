//! Comparing frames with committed reference images, perceptually (FLIP), and the pixel measures the
//! image tests share.

use metaballs::offscreen::{read_png, write_png};
use std::path::{Path, PathBuf};

/// Largest mean FLIP error accepted against a reference (0 = identical, 1 = opposite). Rendering
/// differences between driver versions stay well below it; a wrong colour, a moved sphere or a broken
/// surface goes well above it.
pub const MEAN_FLIP_TOLERANCE: f32 = 0.02;
/// Fewest pixels per degree FLIP assumes: a 0.7 m wide 4K monitor seen from 0.7 m.
const PIXELS_PER_DEGREE: f32 = 67.0;

/// `tests/output/`, where actual and difference images go.
pub fn output_dir() -> PathBuf {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/output");
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// Rec. 709 luminance of an RGBA pixel, 0 to 255.
pub fn luminance(p: &[u8]) -> f32 {
    0.2126 * p[0] as f32 + 0.7152 * p[1] as f32 + 0.0722 * p[2] as f32
}

/// Mean luminance of an RGBA image.
pub fn mean_luminance(rgba: &[u8]) -> f32 {
    rgba.chunks(4).map(luminance).sum::<f32>() / (rgba.len() / 4) as f32
}

/// The mean FLIP error of `actual` against `expected` (RGBA images of one size), with its error map.
pub fn flip(width: u32, height: u32, expected: &[u8], actual: &[u8]) -> (f32, nv_flip::FlipImageFloat) {
    let rgb = |rgba: &[u8]| rgba.chunks(4).flat_map(|p| &p[..3]).copied().collect::<Vec<u8>>();
    let error_map = nv_flip::flip(
        nv_flip::FlipImageRgb8::with_data(width, height, &rgb(expected)),
        nv_flip::FlipImageRgb8::with_data(width, height, &rgb(actual)),
        PIXELS_PER_DEGREE,
    );
    (nv_flip::FlipPool::from_image(&error_map).mean(), error_map)
}

/// The mean FLIP error of `pixels` against `tests/reference/{name}.png`; above the tolerance, writes
/// the actual image and the error map to `tests/output/` and fails. `METABALLS_UPDATE_REFERENCE=1`
/// writes the reference instead.
pub fn assert_matches_reference(name: &str, width: u32, height: u32, pixels: &[u8]) -> f32 {
    let reference = Path::new(env!("CARGO_MANIFEST_DIR")).join(format!("tests/reference/{name}.png"));
    if std::env::var_os("METABALLS_UPDATE_REFERENCE").is_some() {
        std::fs::create_dir_all(reference.parent().unwrap()).unwrap();
        write_png(&reference, width, height, pixels).unwrap();
    }
    let (rw, rh, expected) = read_png(&reference).unwrap_or_else(|e| {
        panic!("cannot read {}: {e} (METABALLS_UPDATE_REFERENCE=1 writes it)", reference.display())
    });
    assert_eq!((rw, rh), (width, height), "{name}: reference size");
    let (mean, error_map) = flip(width, height, &expected, pixels);
    println!("{name}: mean FLIP error against the reference {mean:.5} (tolerance {MEAN_FLIP_TOLERANCE})");
    if mean > MEAN_FLIP_TOLERANCE {
        let dir = output_dir();
        let actual = dir.join(format!("{name}.actual.png"));
        let diff = dir.join(format!("{name}.flip.png"));
        write_png(&actual, width, height, pixels).unwrap();
        let diff_rgb = error_map.apply_color_lut(&nv_flip::magma_lut()).to_vec();
        let diff_rgba: Vec<u8> = diff_rgb.chunks(3).flat_map(|p| [p[0], p[1], p[2], 255]).collect();
        write_png(&diff, width, height, &diff_rgba).unwrap();
        panic!(
            "{name}: mean FLIP error {mean:.4} exceeds {MEAN_FLIP_TOLERANCE}; actual: {}, difference: {}",
            actual.display(),
            diff.display()
        );
    }
    mean
}
