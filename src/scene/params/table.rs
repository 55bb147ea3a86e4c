//! The table of parameters a person can set (from a link, an element attribute or a control), and how
//! their text is read. The page and the element read it from the wasm, so names, ranges and defaults
//! live here once.

use super::view::{
    Blend, ColorBy, Compare, DIVIDER_RANGE, Display, GridView, Interpolation, LIGHT_KINDS, LOD_PIXELS_RANGE,
    Mesher, Method, Projection, SPOT_ANGLE_RANGE, Slice, Theme,
};
use super::{
    DISTANCE_RANGE, ISO_RANGE, MAX_RESOLUTION, MAX_SPHERES, MIN_RESOLUTION, PITCH_RANGE, ParamError,
    SHININESS_RANGE, YAW_RANGE, check_f32, check_range,
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

impl Parameter {
    /// Reads `text` as this parameter's value and checks it; the error says what is accepted.
    pub fn parse(&self, text: &str) -> Result<Value, ParamError> {
        let trimmed = text.trim();
        let invalid =
            |expected: String| ParamError::Invalid { name: self.noun, value: text.to_string(), expected };
        match self.kind {
            Kind::Integer => {
                let range = format!("a whole number from {} to {}", self.min, self.max);
                if trimmed.is_empty() || !trimmed.bytes().all(|b| b.is_ascii_digit()) {
                    return Err(invalid(range));
                }
                let value: f64 = trimmed.parse().map_err(|_| invalid(range))?;
                check_range(self.noun, value, self.min, self.max).map(Value::Number)
            }
            Kind::Number => {
                let (min, max) = (self.min as f32, self.max as f32);
                let expected = format!("a number from {min} to {max}");
                let value: f64 = trimmed.parse().map_err(|_| invalid(expected.clone()))?;
                check_f32(self.noun, value as f32, min, max)?;
                Ok(Value::Number(value))
            }
            Kind::Boolean => match trimmed.to_ascii_lowercase().as_str() {
                "" | "1" | "true" | "on" | "yes" => Ok(Value::Boolean(true)),
                "0" | "false" | "off" | "no" => Ok(Value::Boolean(false)),
                _ => Err(invalid("true or false (also 1/0, on/off)".into())),
            },
            Kind::Color => {
                let hex = trimmed.strip_prefix('#').unwrap_or(trimmed);
                if hex.len() == 6 && hex.bytes().all(|b| b.is_ascii_hexdigit()) {
                    Ok(Value::Text(format!("#{}", hex.to_ascii_lowercase())))
                } else {
                    Err(invalid("a colour written #rrggbb".into()))
                }
            }
            Kind::Choice(words) => {
                let word = trimmed.to_ascii_lowercase();
                if words.contains(&word.as_str()) {
                    Ok(Value::Text(word))
                } else {
                    Err(invalid(format!("one of {}", words.join(", "))))
                }
            }
            Kind::List(words) => {
                let list = trimmed.to_ascii_lowercase();
                if list == "all" || list == "none" {
                    return Ok(Value::Text(list));
                }
                let items: Vec<&str> = list.split(',').map(str::trim).filter(|s| !s.is_empty()).collect();
                if items.is_empty() || !items.iter().all(|item| words.contains(item)) {
                    return Err(invalid(format!("all, none, or a comma list of {}", words.join(", "))));
                }
                Ok(Value::Text(items.join(",")))
            }
            Kind::Slice => Slice::parse(trimmed).map(|slice| Value::Text(Slice::text(slice))),
            Kind::Text => Ok(Value::Text(text.to_string())),
            Kind::Spheres if trimmed.is_empty() => Ok(Value::Text(String::new())),
            Kind::Spheres => crate::scene::sphere::parse_spheres_text(trimmed)
                .map(|spheres| Value::Text(crate::scene::sphere::spheres_text(&spheres)))
                .map_err(|e| ParamError::Invalid {
                    name: self.noun,
                    value: text.to_string(),
                    expected: format!("x,y,z,radius[,vx,vy,vz] per sphere joined by ; ({e})"),
                }),
        }
    }
}

/// Reads `text` as the value of the parameter called `name` (or its short name in links).
pub fn parse_parameter(name: &str, text: &str) -> Result<Value, ParamError> {
    parameter(name)
        .ok_or_else(|| ParamError::Invalid {
            name: "parameter name",
            value: name.to_string(),
            expected: format!("one of {}", PARAMETERS.iter().map(|p| p.name).collect::<Vec<_>>().join(", ")),
        })?
        .parse(text)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::params::Settings;

    #[test]
    fn every_default_in_the_table_parses() {
        for p in PARAMETERS {
            assert!(p.parse(p.default).is_ok(), "{}: default {:?}", p.name, p.default);
        }
    }

    #[test]
    fn the_table_agrees_with_the_settings_defaults() {
        let s = Settings::default();
        let number = |name| match parse_parameter(name, parameter(name).unwrap().default) {
            Ok(Value::Number(v)) => v,
            other => panic!("{name}: {other:?}"),
        };
        assert_eq!(number("spheres") as u32, s.sphere_count);
        assert_eq!(number("iso") as f32, s.iso);
        assert_eq!(number("resolution") as u32, s.resolution);
        assert_eq!(number("seed") as u64, s.seed);
        assert_eq!(number("yaw") as f32, s.camera.yaw_degrees);
        assert_eq!(number("pitch") as f32, s.camera.pitch_degrees);
        assert_eq!(number("distance") as f32, s.camera.distance);
        assert_eq!(number("shininess") as f32, s.material.shininess);
    }

    #[test]
    fn parameter_text_is_read_and_refused_with_what_is_accepted() {
        assert_eq!(parse_parameter("iso", " 0.8 "), Ok(Value::Number(0.8)));
        assert_eq!(parse_parameter("res", "96"), Ok(Value::Number(96.0)));
        assert_eq!(parse_parameter("paused", ""), Ok(Value::Boolean(true)));
        assert_eq!(parse_parameter("aa", "0"), Ok(Value::Boolean(false)));
        assert_eq!(parse_parameter("color", "E77661"), Ok(Value::Text("#e77661".into())));
        assert_eq!(parse_parameter("controls", "iso, resolution"), Ok(Value::Text("iso,resolution".into())));
        assert_eq!(parse_parameter("hud", "ON"), Ok(Value::Text("on".into())));
        let message = |name, text| parse_parameter(name, text).unwrap_err().to_string();
        assert_eq!(message("iso", "abc"), "iso level must be a number from 0.05 to 20, got \"abc\"");
        assert_eq!(message("iso", "NaN"), "iso level must be a number, got NaN");
        assert_eq!(message("iso", "-1"), "iso level must be between 0.05 and 20, got -1");
        assert_eq!(message("spheres", "500"), "sphere count must be between 1 and 64, got 500");
        assert_eq!(
            message("spheres", "2.5"),
            "sphere count must be a whole number from 1 to 64, got \"2.5\""
        );
        assert_eq!(
            message("resolution", ""),
            "resolution (cells per axis) must be a whole number from 8 to 2048, got \"\""
        );
        let settings = crate::scene::params::Settings::default();
        let refused = settings.with_parameter("resolution", "1024").unwrap_err().to_string();
        assert!(refused.contains("at most 512 for a uniform grid (lod=on goes up to 2048)"), "{refused}");
        let lod = settings.with_parameter("lod", "on").unwrap();
        assert_eq!(lod.with_parameter("resolution", "2048").unwrap().resolution, 2048);
        let refused = lod.with_parameter("resolution", "100").unwrap_err().to_string();
        assert!(refused.contains("a multiple of 8 with lod=on"), "{refused}");
        assert!(lod.with_parameter("lod_px", "0.1").is_err());
        assert_eq!(lod.with_parameter("lod_px", "3.5").unwrap().view.lod_pixels, 3.5);
        assert_eq!(message("color", "red"), "color must be a colour written #rrggbb, got \"red\"");
        assert!(message("controls", "iso,zoom").contains("comma list of spheres, iso"));
        assert!(message("autoplay", "always").contains("one of visible, off"));
        assert!(message("nonsense", "1").starts_with("parameter name must be one of spheres"));
        assert_eq!(parse_parameter("edit", "on"), Ok(Value::Boolean(true)));
        assert_eq!(parse_parameter("balls", "0, 0,0,0.40"), Ok(Value::Text("0,0,0,0.4".into())));
        assert_eq!(parse_parameter("balls", ""), Ok(Value::Text(String::new())));
        assert!(
            message("balls", "0,0,0,2")
                .contains("balls sphere 1.radius: sphere radius must be between 0.01 and 1")
        );
    }
}
