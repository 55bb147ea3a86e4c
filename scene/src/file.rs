//! Scenes as files: the spheres (centre, radius, velocity) and every setting of the picture, as a small
//! versioned JSON document, and a compact text form of the spheres alone for links.
//!
//! A document is read whole and checked whole before anything uses it: whatever is wrong (not JSON, cut
//! short, too large, another version, a missing field, a value out of range) comes back as one message
//! naming the field and the value, and the caller's scene stays as it was.
//!
//! ```json
//! { "format": "metaballs-scene", "version": 1,
//!   "spheres": [ { "center": [-0.3, 0, 0], "radius": 0.35, "velocity": [0, 0, 0] } ],
//!   "settings": { "iso": 1, "resolution": 64, "color": "#e77661", "yaw": 30 } }
//! ```

use super::checks::cut;
use super::decimal::{Fixed, num};
use super::json::{Json, Kind};
use super::number::{parse_f32, parse_f64};
use super::params::{Settings, Value, parameter};
use super::sphere::{SceneError, Sphere, at, check_count, check_sphere};
use glam::Vec3;

/// The `format` field of every scene document.
pub const FORMAT: &str = "metaballs-scene";
/// The document version this build writes and reads.
pub const VERSION: u64 = 1;
/// Largest document read, in bytes: 64 spheres take about 10 KB.
pub const MAX_BYTES: usize = 1 << 20;
/// A checked scene: the spheres, and settings by parameter name (only names a scene holds, each
/// value checked by the parameter table).
#[derive(Clone, Debug, PartialEq)]
pub struct SceneFile {
    pub spheres: Vec<Sphere>,
    pub settings: Vec<(&'static str, Value)>,
}

/// Refuses a file longer than a scene document can be (before reading it, where the size is known).
pub fn check_size(bytes: u64) -> Result<(), SceneError> {
    if bytes > MAX_BYTES as u64 {
        return Err(SceneError(format!(
            "the file is {} MB; a scene file is at most {} MB",
            Fixed(bytes as f64 / (1 << 20) as f64, 1),
            MAX_BYTES >> 20
        )));
    }
    Ok(())
}

/// The parameters a scene document holds, in table order.
pub fn scene_parameters() -> impl Iterator<Item = &'static super::params::Parameter> {
    super::params::PARAMETERS.iter().filter(|p| p.in_scene)
}

/// Describes a JSON value for messages: short values whole, long ones by kind.
fn describe(value: &Json) -> String {
    let text = value.compact();
    if text.len() <= 40 {
        return text;
    }
    match value.kind() {
        Kind::Array(a) => format!("an array of {} items", a.len()),
        Kind::Object(o) => format!("an object with {} fields", o.len()),
        _ => format!("{}…", text.chars().take(37).collect::<String>()),
    }
}

fn number(value: &Json, field: &str) -> Result<f32, SceneError> {
    match value.kind() {
        // Through the shortest decimal text, so that an f32 written by `to_json` reads back exactly.
        Kind::Number(_, n) => {
            parse_f32(&n).ok_or_else(|| SceneError(format!("{field} must be a number, got {n}")))
        }
        _ => Err(SceneError(format!("{field} must be a number, got {}", describe(value)))),
    }
}

fn vector(value: &Json, field: &str) -> Result<Vec3, SceneError> {
    match value.items() {
        Some(items) if items.len() == 3 => {
            let c = |k: usize| number(&items[k], &format!("{field}[{k}]"));
            Ok(Vec3::new(c(0)?, c(1)?, c(2)?))
        }
        _ => Err(SceneError(format!("{field} must be three numbers [x, y, z], got {}", describe(value)))),
    }
}

/// The member `name` of an object's `fields`, if there.
fn member<'a>(fields: &'a [(String, Json)], name: &str) -> Option<&'a Json> {
    fields.iter().find(|(k, _)| k == name).map(|(_, v)| v)
}

fn sphere(value: &Json, field: &str) -> Result<Sphere, SceneError> {
    let object = value.fields().ok_or_else(|| {
        SceneError(format!("{field} must be an object with center and radius, got {}", describe(value)))
    })?;
    let get =
        |name: &str| member(&object, name).ok_or_else(|| SceneError(format!("{field}.{name} is missing")));
    let velocity = match member(&object, "velocity") {
        Some(v) => vector(v, &format!("{field}.velocity"))?,
        None => Vec3::ZERO,
    };
    let charge = match member(&object, "charge") {
        Some(c) => number(c, &format!("{field}.charge"))?,
        None => 1.0,
    };
    let s = Sphere {
        center: vector(get("center")?, &format!("{field}.center"))?,
        radius: number(get("radius")?, &format!("{field}.radius"))?,
        velocity,
        charge,
    };
    check_sphere(field, s)
}

fn setting(name: &str, value: &Json) -> Result<(&'static str, Value), SceneError> {
    let field = format!("settings.{}", cut(name));
    let spec = parameter(name)
        .filter(|p| p.in_scene)
        .ok_or_else(|| SceneError(format!("{field}: not a setting a scene holds")))?;
    let text = match value.kind() {
        // Whole numbers written with a fraction (`64.0`) read as whole numbers.
        Kind::Number(x, _) if x.fract() == 0.0 && x.abs() < 1e15 => (x as i64).to_string(),
        Kind::Number(_, n) => n,
        Kind::Bool(b) => b.to_string(),
        Kind::Text(s) => s,
        _ => {
            return Err(SceneError(format!(
                "{field} must be a number, true/false or text, got {}",
                describe(value)
            )));
        }
    };
    spec.parse(&text).map(|v| (spec.name, v)).map_err(|e| at(&field, e))
}

/// Refuses a setting given twice (under two of its names, `color_by` and `color-by`).
fn once_each(settings: Vec<(&'static str, Value)>) -> Result<Vec<(&'static str, Value)>, SceneError> {
    for (i, (name, _)) in settings.iter().enumerate() {
        if settings[..i].iter().any(|(earlier, _)| earlier == name) {
            return Err(SceneError(format!("settings.{name} is given twice (under two of its names)")));
        }
    }
    Ok(settings)
}

impl SceneFile {
    /// Reads and checks a scene document.
    pub fn parse(text: &str) -> Result<SceneFile, SceneError> {
        check_size(text.len() as u64)?;
        let document = Json::parse(text).map_err(|e| {
            let what = if e.ends_early { "the file ends early (is it cut short?)" } else { "not valid JSON" };
            SceneError(format!("{what}: {}", e.message))
        })?;
        let object = document
            .fields()
            .ok_or_else(|| SceneError(format!("a scene is a JSON object, got {}", describe(&document))))?;
        match member(&object, "format").map(|f| (f, f.kind())) {
            Some((_, Kind::Text(f))) if f == FORMAT => {}
            Some((other, _)) => {
                return Err(SceneError(format!("format must be \"{FORMAT}\", got {}", describe(other))));
            }
            None => return Err(SceneError(format!("format is missing: this is not a {FORMAT} document"))),
        }
        match member(&object, "version").map(|v| (v, v.kind())) {
            Some((_, Kind::Number(v, _))) if v == VERSION as f64 => {}
            Some((other, _)) => {
                return Err(SceneError(format!(
                    "version {} is not one this build reads (it reads version {VERSION})",
                    describe(other)
                )));
            }
            None => return Err(SceneError("version is missing".into())),
        }
        let listed = member(&object, "spheres").ok_or_else(|| SceneError("spheres is missing".into()))?;
        let list = listed
            .items()
            .ok_or_else(|| SceneError(format!("spheres must be an array, got {}", describe(listed))))?;
        check_count("spheres", list.len())?;
        let spheres = list
            .iter()
            .enumerate()
            .map(|(i, s)| sphere(s, &format!("spheres[{i}]")))
            .collect::<Result<_, _>>()?;
        let settings = match member(&object, "settings") {
            None => Vec::new(),
            Some(given) => match given.fields() {
                Some(fields) => once_each(
                    fields.iter().map(|(name, value)| setting(name, value)).collect::<Result<_, _>>()?,
                )?,
                None => {
                    return Err(SceneError(format!("settings must be an object, got {}", describe(given))));
                }
            },
        };
        Ok(SceneFile { spheres, settings })
    }

    /// Checks spheres and settings given by name (a page's state, a JSON object) and makes them a
    /// scene.
    pub fn new(spheres: Vec<Sphere>, settings: &Json) -> Result<SceneFile, SceneError> {
        let settings = settings.fields().ok_or_else(|| {
            SceneError(format!("the settings must be a JSON object, got {}", describe(settings)))
        })?;
        check_count("spheres", spheres.len())?;
        for (i, s) in spheres.iter().enumerate() {
            check_sphere(&format!("spheres[{i}]"), *s)?;
        }
        let settings = settings
            .iter()
            .filter(|(name, _)| parameter(name).is_none_or(|p| p.in_scene))
            .map(|(name, value)| setting(name, value))
            .collect::<Result<_, _>>()?;
        Ok(SceneFile { spheres, settings: once_each(settings)? })
    }

    /// The document, indented, with numbers written as short as they read back exactly.
    pub fn to_json(&self) -> String {
        let vector = |v: Vec3| Json::array(v.to_array().map(short).into());
        let spheres = self
            .spheres
            .iter()
            .map(|s| {
                let mut sphere = vec![
                    ("center".to_string(), vector(s.center)),
                    ("radius".to_string(), short(s.radius)),
                    ("velocity".to_string(), vector(s.velocity)),
                ];
                if s.is_subtractive() {
                    sphere.push(("charge".to_string(), Json::whole(-1)));
                }
                Json::object(sphere)
            })
            .collect();
        let settings = self
            .settings
            .iter()
            .map(|(name, value)| {
                let v = match value {
                    Value::Number(n) if n.fract() == 0.0 && n.abs() < 1e15 => Json::whole(*n as i64),
                    Value::Number(n) => Json::number(*n),
                    Value::Boolean(b) => Json::boolean(*b),
                    Value::Text(t) => Json::text(t),
                };
                (name.to_string(), v)
            })
            .collect();
        Json::object(vec![
            ("format".to_string(), Json::text(FORMAT)),
            ("version".to_string(), Json::whole(VERSION as i64)),
            ("spheres".to_string(), Json::array(spheres)),
            ("settings".to_string(), Json::object(settings)),
        ])
        .pretty()
    }

    /// A setting's value, if the scene holds it.
    pub fn setting(&self, name: &str) -> Option<&Value> {
        let name = parameter(name).map_or(name, |p| p.name);
        self.settings.iter().find(|(n, _)| *n == name).map(|(_, v)| v)
    }

    /// `base` with every setting of this scene the renderer takes (the animation's speed and pause
    /// belong to the page, and are left out), and the sphere count of this scene.
    pub fn applied_to(&self, base: Settings) -> Result<Settings, SceneError> {
        let mut settings = Settings { sphere_count: self.spheres.len() as u32, ..base };
        // Level of detail first: it decides which resolutions are allowed.
        let lod_first = self.settings.iter().filter(|(n, _)| *n == "lod");
        for (name, value) in lod_first.chain(self.settings.iter().filter(|(n, _)| *n != "lod")) {
            // The animation's speed and pause belong to the page.
            if parameter(name).is_some_and(|p| p.field.is_none()) {
                continue;
            }
            settings = settings
                .with_parameter(name, &value.to_text())
                .map_err(|e| at(&format!("settings.{name}"), e))?;
        }
        Ok(settings)
    }
}

/// An f32 as the JSON number with the shortest decimal text that reads back as the same f32.
fn short(x: f32) -> Json {
    parse_f64(&num(x).to_string()).map_or(Json::number(f64::NAN), Json::number)
}
