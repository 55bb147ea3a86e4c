//! Parameters a person can change, and the rules that keep them meaningful.
//!
//! Every check returns a [`ParamError`] whose message names the parameter, the value given and the
//! accepted range; a refused value leaves the previous one in place.

use crate::math;
use glam::Vec3;
use std::sync::OnceLock;

pub use super::checks::{Expected, ParamError, check_f32, check_u32};
pub(crate) use super::checks::{check_range, check_vec3};
pub use super::sphere::{MAX_SPHERES, check_sphere_count};

/// Fewest cells along each axis of the grid.
pub const MIN_RESOLUTION: u32 = 8;
/// Most cells along each axis of the grid (devices may hold fewer; see `Renderer::max_resolution`).
pub const MAX_RESOLUTION: u32 = 2048;
/// Cells along each axis of a level-of-detail block, at the block's level.
pub const LOD_BLOCK_CELLS: u32 = 8;
/// The finest uniform grid: past it, only level of detail (`lod=on`) holds the grid.
pub const MAX_UNIFORM_RESOLUTION: u32 = 512;
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
        Settings::default().material
    }
}

impl Material {
    /// Returns the material if every field is in range.
    pub fn validated(self) -> Result<Self, ParamError> {
        Settings { material: self, ..Settings::default() }.validated().map(|_| self)
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
        Settings::default().camera
    }
}

impl Camera {
    /// Returns the camera if every field is in range.
    pub fn validated(self) -> Result<Self, ParamError> {
        Settings { camera: self, ..Settings::default() }.validated().map(|_| self)
    }

    /// The eye position in world space, for a box centred on the origin.
    pub fn eye(&self) -> Vec3 {
        let (yaw, pitch) = (self.yaw_degrees.to_radians(), self.pitch_degrees.to_radians());
        let (sin, cos) = (math::sin, math::cos);
        self.distance * Vec3::new(cos(pitch) * sin(yaw), sin(pitch), cos(pitch) * cos(yaw))
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
    /// Display mode, overlays, lights, projection and the construction toggles.
    pub view: ViewOptions,
}

impl Default for Settings {
    /// The table's defaults (`rows.rs`), with the light where the shading expects it.
    fn default() -> Self {
        static DEFAULTS: OnceLock<Settings> = OnceLock::new();
        *DEFAULTS.get_or_init(|| {
            let mut settings = Settings {
                sphere_count: 0,
                iso: 0.0,
                resolution: 0,
                seed: 0,
                material: Material {
                    base_color: Vec3::ZERO,
                    ambient: 0.0,
                    diffuse: 0.0,
                    specular: 0.0,
                    shininess: 0.0,
                },
                light_position: Vec3::new(3.0, 4.0, 3.5),
                camera: Camera { yaw_degrees: 0.0, pitch_degrees: 0.0, distance: 0.0, fov_y_degrees: 0.0 },
                antialiasing: false,
                view: ViewOptions::unset(),
            };
            for p in PARAMETERS {
                if let Some(field) = p.field {
                    field.set(&mut settings, &p.parse(p.default).expect("every default in the table parses"));
                }
            }
            settings
        })
    }
}

impl Settings {
    /// Returns the settings if every field is in range (device limits are checked by the renderer):
    /// each renderer setting by its row of the table, then the rules that join two of them.
    pub fn validated(self) -> Result<Self, ParamError> {
        check_vec3("base colour", self.material.base_color, 0.0, 1.0)?;
        check_light_position(self.light_position)?;
        for p in PARAMETERS {
            if let Some(field) = p.field {
                p.accepts(&field.get(&self))?;
            }
        }
        check_resolution_for_lod(self.resolution, self.view.lod)?;
        Ok(self)
    }

    /// These settings with parameter `name` (any of its names) read from `text`: any setting of the
    /// renderer (not the page's animation speed, pause or layout of the figure). The error says what
    /// is accepted.
    pub fn with_parameter(&self, name: &str, text: &str) -> Result<Settings, ParamError> {
        self.with_parameters(&[(name, text)])
    }

    /// These settings with several parameters read from text, checked together (the resolution and
    /// level of detail allow each other's values): all or nothing.
    pub fn with_parameters(&self, pairs: &[(&str, &str)]) -> Result<Settings, ParamError> {
        let mut next = *self;
        for (name, text) in pairs {
            let (p, given) = parameter_named(name).ok_or_else(|| rows::unknown(name))?;
            // The value first: a refused value is named as such whoever holds the setting.
            let value = p.parse_as(given, text)?;
            let field = p.field.ok_or_else(|| ParamError::Invalid {
                name: "parameter name",
                value: name.to_string(),
                expected: "a setting of the renderer".into(),
            })?;
            field.set(&mut next, &value);
        }
        next.validated()
    }

    /// The value of renderer setting `name` (any of its names), as the table reads it.
    pub fn parameter(&self, name: &str) -> Option<Value> {
        parameter(name).and_then(|p| p.field).map(|field| field.get(self))
    }
}

/// A `#rrggbb` colour (sRGB, as pickers give it) as linear RGB, the way the shading pass takes it.
pub fn srgb_hex_to_linear(hex: &str) -> Vec3 {
    let channel = |i: usize| {
        let c = hex.get(1 + 2 * i..3 + 2 * i).and_then(|h| u8::from_str_radix(h, 16).ok()).unwrap_or(0);
        let c = c as f32 / 255.0;
        if c <= 0.04045 { c / 12.92 } else { math::powf((c + 0.055) / 1.055, 2.4) }
    };
    Vec3::new(channel(0), channel(1), channel(2))
}

/// A linear RGB colour as the `#rrggbb` (sRGB) text that reads back as it.
pub fn linear_to_srgb_hex(color: Vec3) -> String {
    let channel = |c: f32| {
        let c = c.clamp(0.0, 1.0);
        let s = if c <= 0.0031308 { c * 12.92 } else { 1.055 * math::powf(c, 1.0 / 2.4) - 0.055 };
        (s * 255.0).round() as u8
    };
    format!("#{:02x}{:02x}{:02x}", channel(color.x), channel(color.y), channel(color.z))
}

/// Checks an iso level.
pub fn check_iso(iso: f32) -> Result<f32, ParamError> {
    row("iso").check(&Value::Number(iso.into())).map(|_| iso)
}

/// Checks a resolution against the crate's bounds (not yet the device's).
pub fn check_resolution(cells_per_axis: u32) -> Result<u32, ParamError> {
    row("resolution").check(&Value::Number(cells_per_axis.into())).map(|_| cells_per_axis)
}

/// The table's row called `name`.
fn row(name: &str) -> &'static Parameter {
    parameter(name).expect("a row of the table")
}

/// Checks that a resolution suits the grid it is for: up to [`MAX_UNIFORM_RESOLUTION`] uniform, and
/// a multiple of the LOD block's cells with `lod`.
pub fn check_resolution_for_lod(cells_per_axis: u32, lod: bool) -> Result<u32, ParamError> {
    let block = LOD_BLOCK_CELLS;
    if !lod && cells_per_axis > MAX_UNIFORM_RESOLUTION {
        return Err(ParamError::Invalid {
            name: "resolution",
            value: cells_per_axis.to_string(),
            expected: Expected::UniformAtMost { max: MAX_UNIFORM_RESOLUTION, lod_max: MAX_RESOLUTION },
        });
    }
    if lod && !cells_per_axis.is_multiple_of(block) {
        return Err(ParamError::Invalid {
            name: "resolution",
            value: cells_per_axis.to_string(),
            expected: Expected::LodMultiple(block),
        });
    }
    Ok(cells_per_axis)
}

/// Checks a light position.
pub fn check_light_position(position: Vec3) -> Result<Vec3, ParamError> {
    check_vec3("light position", position, -100.0, 100.0)
}

mod choice;
mod parse;
pub mod plane;
mod rows;
pub mod table;
pub mod view;
pub use parse::parse_parameter;
pub use rows::{ACTIONS, PARAMETERS, control, control_names, parameter, parameter_named};
pub use table::{Action, Field, Group, Kind, Parameter, Scope, Value};
pub use view::ViewOptions;

#[cfg(test)]
mod tests {
    use super::*;

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
