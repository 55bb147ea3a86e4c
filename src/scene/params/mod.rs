//! Parameters a person can change, and the rules that keep them meaningful.
//!
//! Every check returns a [`ParamError`] whose message names the parameter, the value given and the
//! accepted range; a refused value leaves the previous one in place.

use glam::Vec3;

pub use super::checks::{ParamError, check_f32, check_u32};
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
    /// Display mode, overlays, lights, projection and the construction toggles.
    pub view: ViewOptions,
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
            view: ViewOptions::default(),
        }
    }
}

impl Settings {
    /// Returns the settings if every field is in range (device limits are checked by the renderer).
    pub fn validated(self) -> Result<Self, ParamError> {
        check_sphere_count(self.sphere_count)?;
        check_iso(self.iso)?;
        check_resolution(self.resolution)?;
        check_resolution_for_lod(self.resolution, self.view.lod)?;
        self.material.validated()?;
        check_light_position(self.light_position)?;
        self.camera.validated()?;
        self.view.validated()?;
        Ok(self)
    }

    /// These settings with parameter `name` (a table name or short name) read from `text`: any setting
    /// of the renderer (not the page's animation speed, pause or layout of the figure). The error says
    /// what is accepted.
    pub fn with_parameter(&self, name: &str, text: &str) -> Result<Settings, ParamError> {
        let value = parse_parameter(name, text)?;
        let name = parameter(name).map_or(name, |p| p.name);
        let mut next = *self;
        let number = match value {
            Value::Number(n) => n as f32,
            _ => f32::NAN,
        };
        let whole = number as u32;
        match name {
            "spheres" => next.sphere_count = whole,
            "iso" => next.iso = number,
            "resolution" => next.resolution = whole,
            "seed" => {
                next.seed = match value {
                    Value::Number(n) => n as u64,
                    _ => 0,
                }
            }
            "yaw" => next.camera.yaw_degrees = number,
            "pitch" => next.camera.pitch_degrees = number,
            "distance" => next.camera.distance = number,
            "shininess" => next.material.shininess = number,
            "antialiasing" => next.antialiasing = value == Value::Boolean(true),
            "color" => {
                if let Value::Text(hex) = &value {
                    next.material.base_color = srgb_hex_to_linear(hex);
                }
            }
            "ambient" => next.material.ambient = number,
            "diffuse" => next.material.diffuse = number,
            "specular" => next.material.specular = number,
            "fov" => next.camera.fov_y_degrees = number,
            _ => {
                if !next.view.set(name, &value)? {
                    return Err(ParamError::Invalid {
                        name: "parameter name",
                        value: name.to_string(),
                        expected: "a setting of the renderer".into(),
                    });
                }
            }
        }
        next.validated()
    }
}

/// A `#rrggbb` colour (sRGB, as pickers give it) as linear RGB, the way the shading pass takes it.
pub fn srgb_hex_to_linear(hex: &str) -> Vec3 {
    let channel = |i: usize| {
        let c = hex.get(1 + 2 * i..3 + 2 * i).and_then(|h| u8::from_str_radix(h, 16).ok()).unwrap_or(0);
        let c = c as f32 / 255.0;
        if c <= 0.04045 { c / 12.92 } else { ((c + 0.055) / 1.055).powf(2.4) }
    };
    Vec3::new(channel(0), channel(1), channel(2))
}

/// Checks an iso level.
pub fn check_iso(iso: f32) -> Result<f32, ParamError> {
    check_f32("iso level", iso, ISO_RANGE.0, ISO_RANGE.1)
}

/// Checks a resolution against the crate's bounds (not yet the device's).
pub fn check_resolution(cells_per_axis: u32) -> Result<u32, ParamError> {
    check_u32("resolution (cells per axis)", cells_per_axis, MIN_RESOLUTION, MAX_RESOLUTION)
}

/// Checks that a resolution suits the grid it is for: up to [`MAX_UNIFORM_RESOLUTION`] uniform, and
/// a multiple of the LOD block's cells with `lod`.
pub fn check_resolution_for_lod(cells_per_axis: u32, lod: bool) -> Result<u32, ParamError> {
    let block = LOD_BLOCK_CELLS;
    if !lod && cells_per_axis > MAX_UNIFORM_RESOLUTION {
        return Err(ParamError::Invalid {
            name: "resolution",
            value: cells_per_axis.to_string(),
            expected: format!(
                "at most {MAX_UNIFORM_RESOLUTION} for a uniform grid (lod=on goes up to {MAX_RESOLUTION})"
            ),
        });
    }
    if lod && !cells_per_axis.is_multiple_of(block) {
        return Err(ParamError::Invalid {
            name: "resolution",
            value: cells_per_axis.to_string(),
            expected: format!("a multiple of {block} with lod=on"),
        });
    }
    Ok(cells_per_axis)
}

/// Checks a light position.
pub fn check_light_position(position: Vec3) -> Result<Vec3, ParamError> {
    check_vec3("light position", position, -100.0, 100.0)
}

mod parse;
mod table;
pub mod view;
pub use parse::parse_parameter;
pub use table::{CONTROLS, Kind, PARAMETERS, Parameter, Value, parameter};
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
