//! The table of parameters a person can set (from a link, an element attribute or a control): names,
//! ranges and defaults live here once, and the page and the element read them from the wasm. How each
//! kind of text is read is in `parse.rs`.

use super::view::{
    Blend, ColorBy, Compare, DIVIDER_RANGE, Display, GridView, Interpolation, LIGHT_KINDS, LOD_PIXELS_RANGE,
    Mesher, Method, Projection, SPOT_ANGLE_RANGE, Theme,
};
use super::{
    DISTANCE_RANGE, ISO_RANGE, MAX_RESOLUTION, MAX_SPHERES, MIN_RESOLUTION, PITCH_RANGE, SHININESS_RANGE,
    YAW_RANGE,
};

/// How a parameter's text is read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// A whole number, written in decimal digits.
    Integer,
    /// A decimal number.
    Number,
    /// `1`, `true`, `on`, `yes` or empty (an HTML boolean attribute), or `0`, `false`, `off`, `no`.
    Boolean,
    /// `#rrggbb`.
    Color,
    /// One of a fixed list of words.
    Choice(&'static [&'static str]),
    /// `all`, `none`, or a comma list of words from a fixed list.
    List(&'static [&'static str]),
    /// `off`, or an axis and a position in the box: `z:0.25`.
    Slice,
    /// Empty (the seeded layout), or spheres written `x,y,z,radius[,vx,vy,vz]` joined by `;` (a negative
    /// radius: a subtracting sphere).
    Spheres,
    /// Any text, kept as written (a description, a URL).
    Text,
}

/// One parameter a person can set: from a link, an element attribute or a control. This table is the
/// one place that names, bounds and defaults them; the page and the element read it from the wasm.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Parameter {
    /// Attribute and property name (`resolution`).
    pub name: &'static str,
    /// Short name in a link's query string (`res`); the long name works there too.
    pub url: &'static str,
    /// Label in the panel.
    pub label: &'static str,
    /// Name in messages ("resolution (cells per axis)").
    pub noun: &'static str,
    pub kind: Kind,
    /// Accepted range (numbers only).
    pub min: f64,
    pub max: f64,
    /// Range and step of the panel's slider (numbers only): a comfortable part of what is accepted.
    pub slider: (f64, f64, f64),
    /// Value when not given, as text.
    pub default: &'static str,
}

/// The controls an element's `controls` attribute can list; `view` is the reset-view button.
pub const CONTROLS: &[&str] = &[
    "spheres",
    "iso",
    "resolution",
    "speed",
    "shininess",
    "color",
    "antialiasing",
    "mesher",
    "extractor",
    "lod",
    "lod_pixels",
    "lod_freeze",
    "paused",
    "pause_on",
    "seed",
    "view",
    "step",
    "display",
    "compare",
    "grid",
    "color_by",
    "slice",
    "ambiguous",
    "interpolation",
    "blend",
    "inspector",
    "error_plot",
    "light",
    "spot_angle",
    "spot_softness",
    "ambient",
    "diffuse",
    "specular",
    "projection",
    "fov",
    "theme",
    "edit",
    "scene",
    "export",
];

#[allow(clippy::too_many_arguments)] // one row of the table
const fn number(
    name: &'static str,
    url: &'static str,
    label: &'static str,
    noun: &'static str,
    integer: bool,
    range: (f64, f64),
    slider: (f64, f64, f64),
    default: &'static str,
) -> Parameter {
    let kind = if integer { Kind::Integer } else { Kind::Number };
    Parameter { name, url, label, noun, kind, min: range.0, max: range.1, slider, default }
}

const fn other(
    name: &'static str,
    url: &'static str,
    label: &'static str,
    kind: Kind,
    default: &'static str,
) -> Parameter {
    Parameter { name, url, label, noun: name, kind, min: 0.0, max: 0.0, slider: (0.0, 0.0, 0.0), default }
}

const fn wide((min, max): (f32, f32)) -> (f64, f64) {
    (min as f64, max as f64)
}

/// Every parameter, in panel order.
pub const PARAMETERS: &[Parameter] = &[
    number(
        "spheres",
        "spheres",
        "Spheres",
        "sphere count",
        true,
        (1.0, MAX_SPHERES as f64),
        (1.0, MAX_SPHERES as f64, 1.0),
        "5",
    ),
    number("iso", "iso", "Iso level", "iso level", false, wide(ISO_RANGE), (0.1, 4.0, 0.01), "1"),
    number(
        "resolution",
        "res",
        "Resolution",
        "resolution (cells per axis)",
        true,
        (MIN_RESOLUTION as f64, MAX_RESOLUTION as f64),
        (MIN_RESOLUTION as f64, MAX_RESOLUTION as f64, 1.0),
        "64",
    ),
    number("seed", "seed", "Layout", "layout seed", true, (0.0, u32::MAX as f64), (0.0, 0.0, 0.0), "1"),
    number("speed", "speed", "Speed", "animation speed", false, (0.0, 3.0), (0.0, 3.0, 0.05), "1"),
    other("paused", "paused", "Paused", Kind::Boolean, "false"),
    number("yaw", "yaw", "Yaw", "camera yaw (degrees)", false, wide(YAW_RANGE), (-180.0, 180.0, 1.0), "30"),
    number(
        "pitch",
        "pitch",
        "Pitch",
        "camera pitch (degrees)",
        false,
        wide(PITCH_RANGE),
        (-89.0, 89.0, 1.0),
        "20",
    ),
    number(
        "distance",
        "dist",
        "Distance",
        "camera distance",
        false,
        wide(DISTANCE_RANGE),
        (1.5, 20.0, 0.1),
        "4.3",
    ),
    number(
        "shininess",
        "shine",
        "Shininess",
        "shininess",
        false,
        wide(SHININESS_RANGE),
        (1.0, 256.0, 1.0),
        "64",
    ),
    other("color", "color", "Colour", Kind::Color, "#e77661"),
    other("antialiasing", "aa", "Antialiasing", Kind::Boolean, "true"),
    other("display", "display", "Display", Kind::Choice(Display::WORDS), "shaded"),
    other("compare", "compare", "Exact surface", Kind::Choice(Compare::WORDS), "none"),
    number(
        "divider",
        "divider",
        "Divider",
        "divider position",
        false,
        wide(DIVIDER_RANGE),
        (0.05, 0.95, 0.01),
        "0.5",
    ),
    other("grid", "grid", "Grid", Kind::Choice(GridView::WORDS), "none"),
    other("color_by", "color_by", "Colour by", Kind::Choice(ColorBy::WORDS), "none"),
    other("slice", "slice", "Field slice", Kind::Slice, "off"),
    other("ambiguous", "ambiguous", "Ambiguous", Kind::Boolean, "false"),
    other("interpolation", "interp", "Vertices", Kind::Choice(Interpolation::WORDS), "linear"),
    other("blend", "blend", "Blend", Kind::Choice(Blend::WORDS), "sum"),
    other("mesher", "mesher", "Meshing", Kind::Choice(Mesher::WORDS), "auto"),
    other("extractor", "extractor", "Extractor", Kind::Choice(Method::WORDS), "marching_cubes"),
    other("lod", "lod", "Level of detail", Kind::Boolean, "false"),
    number(
        "lod_pixels",
        "lod_px",
        "LOD cell size",
        "LOD cell size (pixels)",
        false,
        wide(LOD_PIXELS_RANGE),
        (0.5, 8.0, 0.25),
        "2",
    ),
    other("lod_freeze", "lod_freeze", "Freeze LOD", Kind::Boolean, "false"),
    other("light", "light", "Lights", Kind::List(LIGHT_KINDS), "point"),
    number(
        "spot_angle",
        "spot_angle",
        "Spot cone",
        "spot cone angle (degrees)",
        false,
        wide(SPOT_ANGLE_RANGE),
        (5.0, 60.0, 1.0),
        "15",
    ),
    number(
        "spot_softness",
        "spot_soft",
        "Spot edge",
        "spot softness",
        false,
        (0.0, 1.0),
        (0.0, 1.0, 0.05),
        "0.3",
    ),
    number("ambient", "ambient", "Ambient", "ambient strength", false, (0.0, 1.0), (0.0, 1.0, 0.01), "0.15"),
    number("diffuse", "diffuse", "Diffuse", "diffuse strength", false, (0.0, 2.0), (0.0, 2.0, 0.01), "0.85"),
    number(
        "specular",
        "specular",
        "Specular",
        "specular strength",
        false,
        (0.0, 2.0),
        (0.0, 2.0, 0.01),
        "0.6",
    ),
    other("projection", "proj", "Projection", Kind::Choice(Projection::WORDS), "perspective"),
    number(
        "fov",
        "fov",
        "Field of view",
        "field of view (degrees)",
        false,
        (10.0, 120.0),
        (20.0, 100.0, 1.0),
        "45",
    ),
    other("theme", "theme", "Theme", Kind::Choice(Theme::WORDS), "dark"),
    other("edit", "edit", "Edit spheres", Kind::Boolean, "false"),
    other("balls", "balls", "Spheres", Kind::Spheres, ""),
    other("controls", "controls", "Controls", Kind::List(CONTROLS), "none"),
    other("hud", "hud", "Statistics", Kind::Choice(&["on", "off"]), "off"),
    other("autoplay", "autoplay", "Autoplay", Kind::Choice(&["visible", "off"]), "visible"),
    other("pause_on", "pause_on", "Pause on", Kind::Choice(&["none", "merge"]), "none"),
    number(
        "max-pixel-ratio",
        "max_pixel_ratio",
        "Pixel ratio",
        "max-pixel-ratio",
        false,
        (0.25, 4.0),
        (0.25, 4.0, 0.25),
        "2",
    ),
    number(
        "min-render-scale",
        "min_render_scale",
        "Lowest render scale",
        "min-render-scale",
        false,
        (0.25, 1.0),
        (0.25, 1.0, 0.05),
        "0.5",
    ),
    other("alt", "alt", "Description", Kind::Text, ""),
    other("poster", "poster", "Poster", Kind::Text, ""),
    other("sync", "sync", "Sync group", Kind::Text, ""),
];

/// A parameter by its name or its short name in links.
pub fn parameter(name: &str) -> Option<&'static Parameter> {
    PARAMETERS.iter().find(|p| p.name == name || p.url == name)
}

/// A parameter's value, read from text.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Number(f64),
    Boolean(bool),
    /// A colour as `#rrggbb` (lower case), a choice, or a normalised list (`all`, `none` or names).
    Text(String),
}
