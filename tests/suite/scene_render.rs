//! A scene built and saved in the page renders the same offline: `metaballs render --scene` of
//! tests/fixtures/page-scene.json against the page's own picture of it (tests/reference/page-scene.png,
//! which tests/e2e/editing.test.js checks the page still draws), by mean FLIP error.

use crate::common;

use common::*;
use metaballs::offscreen::read_png;
use std::path::Path;

#[test]
fn render_scene_gives_the_pages_picture() {
    let tests = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests");
    let (width, height, expected) = read_png(&tests.join("reference/page-scene.png")).unwrap();
    let out = output_dir().join("render-scene.png");
    let scene = tests.join("fixtures/page-scene.json");
    let size = format!("{width}x{height}");
    let (code, stdout, stderr) =
        cli(&["render", "--scene", scene.to_str().unwrap(), "--size", &size, "--out", out.to_str().unwrap()]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("2 spheres, iso 0.9, 64 cells per axis"), "{stdout}");
    let (w, h, actual) = read_png(&out).unwrap();
    assert_eq!((w, h), (width, height));
    let (mean, _) = flip(width, height, &expected, &actual);
    println!("render --scene against the page's picture: mean FLIP error {mean:.5}");
    assert!(mean < MEAN_FLIP_TOLERANCE, "mean FLIP error {mean} (tolerance {MEAN_FLIP_TOLERANCE})");
    // Not a blank frame that happens to match a blank one: the blob covers part of the picture.
    let lit = actual.chunks(4).filter(|p| p[2] as i32 > p[0] as i32 + 40).count();
    assert!(lit > (width * height / 50) as usize, "{lit} blue pixels");
}
