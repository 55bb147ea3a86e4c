//! Parameters a person can change, and the rules that keep them meaningful.
//!
//! Every check returns a [`ParamError`] whose message names the parameter, the value given and the
//! accepted range; a refused value leaves the previous one in place.

use glam::Vec3;
use std::fmt;

/// The most spheres a scene holds; raise it here and every buffer follows.
pub const MAX_SPHERES: u32 = 64;
/// Fewest cells along each axis of the grid.
pub const MIN_RESOLUTION: u32 = 8;
/// Most cells along each axis of the grid (devices may hold fewer; see `Renderer::max_resolution`).
pub const MAX_RESOLUTION: u32 = 512;
/// Iso levels accepted: below the lower end the surface fills the box, above the upper end it vanishes.
pub const ISO_RANGE: (f32, f32) = (0.05, 20.0);
/// Camera yaw accepted, degrees.
pub const YAW_RANGE: (f32, f32) = (-360.0, 360.0);
/// Camera pitch accepted, degrees (short of the poles, where the orbit's up vector flips).
pub const PITCH_RANGE: (f32, f32) = (-89.0, 89.0);
/// Camera distance accepted, in box half-widths.
pub const DISTANCE_RANGE: (f32, f32) = (1.5, 20.0);
/// Specular exponents accepted.
pub const SHININESS_RANGE: (f32, f32) = (1.0, 1024.0);

/// A refused parameter value, with a message a person can act on.
#[derive(Debug, Clone, PartialEq)]
pub enum ParamError {
    /// The value is NaN.
    NotANumber { name: &'static str },
    /// The value is infinite.
    Infinite { name: &'static str },
    /// The text is not a value of the expected kind.
    Invalid { name: &'static str, value: String, expected: String },
    /// The value lies outside the accepted range.
    OutOfRange { name: &'static str, value: String, min: String, max: String },
    /// The device cannot hold what the value asks for.
    DeviceLimit { name: &'static str, value: String, detail: String },
}

impl fmt::Display for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::NotANumber { name } => write!(f, "{name} must be a number, got NaN"),
            Self::Infinite { name } => write!(f, "{name} must be finite, got infinity"),
            Self::Invalid { name, value, expected } => write!(f, "{name} must be {expected}, got {value:?}"),
            Self::OutOfRange { name, value, min, max } => {
                write!(f, "{name} must be between {min} and {max}, got {value}")
            }
            Self::DeviceLimit { name, value, detail } => {
                write!(f, "{name} {value} is more than this device can hold: {detail}")
            }
        }
    }
}

impl std::error::Error for ParamError {}

/// Checks that `value` is a finite number within `[min, max]`.
pub fn check_f32(name: &'static str, value: f32, min: f32, max: f32) -> Result<f32, ParamError> {
    if value.is_nan() {
        return Err(ParamError::NotANumber { name });
    }
    if value.is_infinite() {
        return Err(ParamError::Infinite { name });
    }
    check_range(name, value, min, max)
}

/// Checks that an integer `value` lies within `[min, max]`.
pub fn check_u32(name: &'static str, value: u32, min: u32, max: u32) -> Result<u32, ParamError> {
    check_range(name, value, min, max)
}

fn check_range<T: PartialOrd + fmt::Display>(
    name: &'static str,
    value: T,
    min: T,
    max: T,
) -> Result<T, ParamError> {
    if value < min || value > max {
        return Err(ParamError::OutOfRange {
            name,
            value: value.to_string(),
            min: min.to_string(),
            max: max.to_string(),
        });
    }
    Ok(value)
}

fn check_vec3(name: &'static str, v: Vec3, min: f32, max: f32) -> Result<Vec3, ParamError> {
    for c in v.to_array() {
        check_f32(name, c, min, max)?;
    }
    Ok(v)
}

/// Surface material for Blinn-Phong shading.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Linear RGB albedo, each channel in [0, 1].
    pub base_color: Vec3,
    /// Ambient strength, [0, 1].
    pub ambient: f32,
    /// Diffuse (Lambert) strength, [0, 2].
    pub diffuse: f32,
    /// Specular strength, [0, 2].
    pub specular: f32,
    /// Specular exponent, [1, 1024]; higher is glossier.
    pub shininess: f32,
}

impl Default for Material {
    fn default() -> Self {
        Self {
            base_color: Vec3::new(0.80, 0.18, 0.12),
            ambient: 0.15,
            diffuse: 0.85,
            specular: 0.6,
            shininess: 64.0,
        }
    }
}

impl Material {
    /// Returns the material if every field is in range.
    pub fn validated(self) -> Result<Self, ParamError> {
        check_vec3("base colour", self.base_color, 0.0, 1.0)?;
        check_f32("ambient strength", self.ambient, 0.0, 1.0)?;
        check_f32("diffuse strength", self.diffuse, 0.0, 2.0)?;
        check_f32("specular strength", self.specular, 0.0, 2.0)?;
        check_f32("shininess", self.shininess, SHININESS_RANGE.0, SHININESS_RANGE.1)?;
        Ok(self)
    }
}

/// An orbit camera looking at the centre of the box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// Rotation about the vertical axis, degrees, [-360, 360].
    pub yaw_degrees: f32,
    /// Elevation above the horizontal plane, degrees, [-89, 89].
    pub pitch_degrees: f32,
    /// Distance from the box centre, in box half-widths, [1.5, 20].
    pub distance: f32,
    /// Vertical field of view, degrees, [10, 120].
    pub fov_y_degrees: f32,
}

impl Default for Camera {
    fn default() -> Self {
        Self { yaw_degrees: 30.0, pitch_degrees: 20.0, distance: 4.3, fov_y_degrees: 45.0 }
    }
}

impl Camera {
    /// Returns the camera if every field is in range.
    pub fn validated(self) -> Result<Self, ParamError> {
        check_f32("camera yaw (degrees)", self.yaw_degrees, YAW_RANGE.0, YAW_RANGE.1)?;
        check_f32("camera pitch (degrees)", self.pitch_degrees, PITCH_RANGE.0, PITCH_RANGE.1)?;
        check_f32("camera distance", self.distance, DISTANCE_RANGE.0, DISTANCE_RANGE.1)?;
        check_f32("field of view (degrees)", self.fov_y_degrees, 10.0, 120.0)?;
        Ok(self)
    }

    /// The eye position in world space, for a box centred on the origin.
    pub fn eye(&self) -> Vec3 {
        let (yaw, pitch) = (self.yaw_degrees.to_radians(), self.pitch_degrees.to_radians());
        self.distance * Vec3::new(pitch.cos() * yaw.sin(), pitch.sin(), pitch.cos() * yaw.cos())
    }
}

/// Everything that defines a frame apart from the spheres' motion.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Settings {
    /// Spheres in play, [1, MAX_SPHERES].
    pub sphere_count: u32,
    /// The surface is where the field equals this level.
    pub iso: f32,
    /// Cells along each axis of the grid.
    pub resolution: u32,
    /// Seed of the sphere layout.
    pub seed: u64,
    /// Surface material.
    pub material: Material,
    /// Point light position in world space (the box spans [-1, 1] on each axis).
    pub light_position: Vec3,
    /// Viewpoint.
    pub camera: Camera,
    /// 4× multisampling; software adapters draw much faster without it.
    pub antialiasing: bool,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            sphere_count: 5,
            iso: 1.0,
            resolution: 64,
            seed: 1,
            material: Material::default(),
            light_position: Vec3::new(3.0, 4.0, 3.5),
            camera: Camera::default(),
            antialiasing: true,
        }
    }
}

impl Settings {
    /// Returns the settings if every field is in range (device limits are checked by the renderer).
    pub fn validated(self) -> Result<Self, ParamError> {
        check_sphere_count(self.sphere_count)?;
        check_iso(self.iso)?;
        check_resolution(self.resolution)?;
        self.material.validated()?;
        check_light_position(self.light_position)?;
        self.camera.validated()?;
        Ok(self)
    }
}

/// Checks a sphere count.
pub fn check_sphere_count(count: u32) -> Result<u32, ParamError> {
    check_u32("sphere count", count, 1, MAX_SPHERES)
}

/// Checks an iso level.
pub fn check_iso(iso: f32) -> Result<f32, ParamError> {
    check_f32("iso level", iso, ISO_RANGE.0, ISO_RANGE.1)
}

/// Checks a resolution against the crate's bounds (not yet the device's).
pub fn check_resolution(cells_per_axis: u32) -> Result<u32, ParamError> {
    check_u32("resolution (cells per axis)", cells_per_axis, MIN_RESOLUTION, MAX_RESOLUTION)
}

/// Checks a light position.
pub fn check_light_position(position: Vec3) -> Result<Vec3, ParamError> {
    check_vec3("light position", position, -100.0, 100.0)
}

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
    "paused",
    "seed",
    "view",
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
    other("controls", "controls", "Controls", Kind::List(CONTROLS), "none"),
    other("hud", "hud", "Statistics", Kind::Choice(&["on", "off"]), "off"),
    other("autoplay", "autoplay", "Autoplay", Kind::Choice(&["visible", "off"]), "visible"),
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
            "resolution (cells per axis) must be a whole number from 8 to 512, got \"\""
        );
        assert_eq!(message("color", "red"), "color must be a colour written #rrggbb, got \"red\"");
        assert!(message("controls", "iso,zoom").contains("comma list of spheres, iso"));
        assert!(message("autoplay", "always").contains("one of visible, off"));
        assert!(message("nonsense", "1").starts_with("parameter name must be one of spheres"));
    }

    #[test]
    fn defaults_are_valid() {
        assert_eq!(Settings::default().validated(), Ok(Settings::default()));
    }

    #[test]
    fn messages_name_the_parameter_the_value_and_the_range() {
        let e = check_iso(-1.0).unwrap_err().to_string();
        assert_eq!(e, "iso level must be between 0.05 and 20, got -1");
        assert_eq!(check_iso(f32::NAN).unwrap_err().to_string(), "iso level must be a number, got NaN");
        assert_eq!(
            check_iso(f32::INFINITY).unwrap_err().to_string(),
            "iso level must be finite, got infinity"
        );
        assert_eq!(
            check_sphere_count(0).unwrap_err().to_string(),
            "sphere count must be between 1 and 64, got 0"
        );
    }
}
