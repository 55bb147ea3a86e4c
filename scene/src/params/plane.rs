//! The 2D figure's settings (`<metaballs-2d>`, marching squares over circles): the rows of the
//! parameter table it shares with the 3D figure, named here and declared once in [`PARAMETERS`], and
//! the rows that are its own, declared here in the same form. The element, its panel, its page's
//! links, the notebook widget and the manifests all read them from `metaballs manifest`'s output.

use super::PARAMETERS;
use super::table::{Group, Kind, Parameter, number, row};

/// What the 2D figure can show: the grid, each sample's value, inside and outside corners, each
/// square's case, the crossings, the contour, the saddle squares, the bands between levels, the circles.
pub const SHOWN: &[&str] =
    &["grid", "values", "corners", "cases", "crossings", "contour", "saddles", "bands", "circles"];

/// The 2D figure's panel controls, in order (`controls`).
pub const PLANE_CONTROLS: &[&str] = &[
    "iso",
    "resolution",
    "interpolation",
    "saddle",
    "kernel",
    "blobbiness",
    "iso-levels",
    "show",
    "paused",
    "speed",
    "spheres",
    "seed",
    "theme",
    "step-through",
    "circles",
    "scene",
    "share",
];

/// The rows of the parameter table the 2D figure takes as the 3D figure does.
pub const PLANE_SHARED: &[&str] = &[
    "iso",
    "interpolation",
    "saddle",
    "kernel",
    "blobbiness",
    "spheres",
    "seed",
    "speed",
    "paused",
    "theme",
    "alt",
];

/// The 2D figure's own settings.
pub const PLANE_PARAMETERS: &[Parameter] = &[
    number("resolution", "Resolution", "resolution (squares per axis)", (8.0, 1024.0), "16")
        .whole()
        .slider(8.0, 256.0, 1.0)
        .group(Group::Surface),
    row("circles", "Circles", Kind::Text, ""),
    // Further iso levels, drawn as lines and bands: `levels` before the name said which levels (the 3D
    // figure's `levels` is its "Along the iso level" box).
    number("iso-levels", "Levels", "iso level", (0.05, 20.0), "")
        .kind(Kind::Levels)
        .url("iso-levels")
        .aliases(&["levels"])
        .group(Group::Display),
    row("show", "Show", Kind::List(SHOWN, &[]), "grid,values,corners,cases,crossings,contour,saddles,bands")
        .group(Group::Display),
    row("march", "Step-through", Kind::Text, "").page_only(),
    row("slice-of", "Slice of", Kind::Text, "").page_only(),
    row("controls", "Controls", Kind::List(PLANE_CONTROLS, &[("levels", "iso-levels")]), "none").page_only(),
];

/// Every setting of the 2D figure: the shared rows, then its own.
pub fn plane_parameters() -> impl Iterator<Item = &'static Parameter> {
    let shared = PLANE_SHARED.iter().map(|name| {
        PARAMETERS.iter().find(|p| p.name == *name).expect("a shared setting is a row of the table")
    });
    shared.chain(PLANE_PARAMETERS.iter())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_setting_of_the_2d_figure_is_declared_once_and_its_defaults_parse() {
        let names: Vec<&str> = plane_parameters().map(|p| p.name).collect();
        for (i, name) in names.iter().enumerate() {
            assert!(!names[i + 1..].contains(name), "{name} is declared twice");
        }
        for p in plane_parameters() {
            p.parse(p.default).unwrap_or_else(|e| panic!("{}: {e}", p.name));
        }
        assert!(p_words("show").contains(&"circles"));
        assert_eq!(plane_parameters().count(), PLANE_SHARED.len() + PLANE_PARAMETERS.len());
    }

    #[test]
    fn further_levels_are_numbers_in_the_iso_range_and_controls_take_the_older_word() {
        let levels = plane_parameters().find(|p| p.name == "iso-levels").unwrap();
        assert_eq!(levels.aliases, &["levels"]);
        assert_eq!(levels.parse(" 0.5, ,1.50 "), Ok(crate::params::Value::Text("0.5,1.5".into())));
        assert_eq!(levels.parse(""), Ok(crate::params::Value::Text(String::new())));
        let refused = levels.parse("0.5,30").unwrap_err().to_string();
        assert_eq!(refused, "iso level must be between 0.05 and 20, got 30");
        assert!(levels.parse("0x10").is_err());
        let controls = plane_parameters().find(|p| p.name == "controls").unwrap();
        assert_eq!(controls.parse("iso, LEVELS"), Ok(crate::params::Value::Text("iso,iso-levels".into())));
        assert!(
            controls.parse("iso,zoom").unwrap_err().to_string().contains("comma list of iso, resolution")
        );
    }

    fn p_words(name: &str) -> Vec<&'static str> {
        plane_parameters().find(|p| p.name == name).unwrap().words()
    }
}
