//! The element's description never drifts from the parameter table: the files in `www/` are what
//! `metaballs manifest` writes, the manifest lists every attribute with its default, and the themes
//! reach the drawn picture.

use crate::common;

use common::*;
use metaballs::manifest;
use metaballs::scene::params::PARAMETERS;
use serde_json::Value;

fn repository_file(path: &str) -> String {
    let full = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("www").join(path);
    std::fs::read_to_string(&full).unwrap_or_else(|e| panic!("{}: {e}", full.display()))
}

#[test]
fn the_committed_files_are_what_the_command_writes() {
    for (path, text) in manifest::files() {
        assert!(
            repository_file(path) == text,
            "www/{path} is out of date with the parameter table: run `cargo run -- manifest --out www`"
        );
    }
}

#[test]
fn the_manifest_lists_every_attribute_with_its_type_and_default() {
    let json: Value = serde_json::from_str(&manifest::custom_elements_json()).unwrap();
    let class = &json["modules"][0]["declarations"][0];
    assert_eq!(class["tagName"], "metaballs-view");
    assert_eq!(json["modules"][0]["path"], "www/metaballs-view.js");
    let attributes = class["attributes"].as_array().unwrap();
    assert_eq!(attributes.len(), PARAMETERS.len());
    for (p, a) in PARAMETERS.iter().zip(attributes) {
        assert_eq!(a["name"], p.name);
        // The default as the attribute would be written.
        assert_eq!(a["default"], serde_json::to_string(p.default).unwrap(), "{}", p.name);
        assert!(!a["type"]["text"].as_str().unwrap().is_empty());
        let field = class["members"]
            .as_array()
            .unwrap()
            .iter()
            .find(|m| m["attribute"] == p.name)
            .unwrap_or_else(|| panic!("no property for {}", p.name));
        assert_eq!(field["name"], manifest::property_name(p.name));
    }
    for part in ["canvas", "panel", "hud", "notice", "poster"] {
        assert!(class["cssParts"].as_array().unwrap().iter().any(|x| x["name"] == part), "{part}");
    }
    for property in ["--metaballs-background-top", "--metaballs-background-bottom", "--metaballs-accent"] {
        assert!(class["cssProperties"].as_array().unwrap().iter().any(|x| x["name"] == property));
    }
    let typings = manifest::declarations();
    assert!(typings.contains("'metaballs-view': MetaballsView;"));
    assert!(typings.contains("  maxPixelRatio: number;"));
    assert!(typings.contains("  theme: 'dark' | 'light' | 'auto';"));
}

#[test]
fn the_light_theme_draws_a_light_background() {
    // The top-left corner is background at the default camera.
    let corner = |view: &str| {
        let dir = scratch_dir("metaballs-theme");
        let out = dir.join("theme.png");
        let (code, _, stderr) = cli(&[
            "render",
            "--out",
            out.to_str().unwrap(),
            "--size",
            "64x48",
            "--resolution",
            "16",
            "--view",
            view,
        ]);
        assert_eq!(code, 0, "{stderr}");
        let (_, _, pixels) = metaballs::offscreen::read_png(&out).unwrap();
        std::fs::remove_dir_all(&dir).unwrap();
        pixels[..3].iter().map(|&c| c as u32).sum::<u32>() / 3
    };
    let dark = corner("theme=dark");
    let light = corner("theme=light");
    assert!(dark < 100, "the dark theme's background is {dark}");
    assert!(light > 200, "the light theme's background is {light}");
}
