//! How a parameter's text is read: each kind of the table's parameters parsed and checked, with a
//! message saying what is accepted when the text is refused.

use super::rows::{control, control_names, parameter_named, unknown};
use super::table::{Kind, Parameter, Value};
use super::view::{March, Slice};
use super::{Expected, ParamError, check_f32, check_range};

use crate::decimal::num;
use crate::number::{parse_f32, parse_f64};

impl Parameter {
    /// Reads `text` as this parameter's value and checks it; the error says what is accepted.
    pub fn parse(&self, text: &str) -> Result<Value, ParamError> {
        self.parse_as(self.name, text)
    }

    /// Checks a value given as a value (not as text), as `parse` checks text; returns it as the table
    /// holds it.
    pub fn check(&self, value: &Value) -> Result<Value, ParamError> {
        match (self.kind, value) {
            (Kind::Number, Value::Number(n)) => self.accepts(value).map(|()| Value::of_f32(*n as f32)),
            (Kind::Integer, Value::Number(_)) => self.accepts(value).map(|()| value.clone()),
            _ => self.parse(&value.to_text()),
        }
    }

    /// Whether `value` is one of this parameter's values, as [`Parameter::check`] says, without
    /// making the value again (settings check every row each time one changes).
    pub fn accepts(&self, value: &Value) -> Result<(), ParamError> {
        match (self.kind, value) {
            (Kind::Number, Value::Number(n)) => {
                check_f32(self.noun, *n as f32, self.min as f32, self.max as f32).map(drop)
            }
            (Kind::Integer, Value::Number(n)) => check_range(self.noun, *n, self.min, self.max).map(drop),
            _ => self.parse(&value.to_text()).map(drop),
        }
    }

    /// `parse`, with messages that call the parameter by `given` (one of its names) where its row
    /// has no noun of its own.
    pub fn parse_as(&self, given: &'static str, text: &str) -> Result<Value, ParamError> {
        let trimmed = text.trim();
        let noun = if self.noun.is_empty() { given } else { self.noun };
        let invalid =
            |expected: Expected| ParamError::Invalid { name: noun, value: text.to_string(), expected };
        match self.kind {
            // What is accepted is written out only when a value is refused: settings are checked
            // many times on a figure's start, and formatting numbers costs more than checking them.
            Kind::Integer => {
                let range =
                    || Expected::Whole { min: num(self.min).to_string(), max: num(self.max).to_string() };
                if trimmed.is_empty() || !trimmed.bytes().all(|b| b.is_ascii_digit()) {
                    return Err(invalid(range()));
                }
                let value = parse_f64(trimmed).ok_or_else(|| invalid(range()))?;
                check_range(noun, value, self.min, self.max).map(Value::Number)
            }
            // Read as the f32 the renderer keeps, and held as that f32's shortest decimal: the value
            // checked is the value used, and it reads back as itself.
            Kind::Number => self.read_f32(noun, trimmed, text).map(Value::of_f32),
            Kind::Levels => {
                let mut levels = String::new();
                for item in trimmed.split(',').map(str::trim).filter(|s| !s.is_empty()) {
                    if !levels.is_empty() {
                        levels.push(',');
                    }
                    levels.push_str(&num(self.read_f32(noun, item, item)?).to_string());
                }
                Ok(Value::Text(levels))
            }
            Kind::Boolean => match trimmed.to_ascii_lowercase().as_str() {
                "" | "1" | "true" | "on" | "yes" => Ok(Value::Boolean(true)),
                "0" | "false" | "off" | "no" => Ok(Value::Boolean(false)),
                _ => Err(invalid(Expected::Flag)),
            },
            Kind::Color => {
                let hex = trimmed.strip_prefix('#').unwrap_or(trimmed);
                if hex.len() == 6 && hex.bytes().all(|b| b.is_ascii_hexdigit()) {
                    Ok(Value::Text(format!("#{}", hex.to_ascii_lowercase())))
                } else {
                    Err(invalid(Expected::Colour))
                }
            }
            Kind::Choice(words) => {
                let word = trimmed.to_ascii_lowercase();
                if words.contains(&word.as_str()) {
                    Ok(Value::Text(word))
                } else {
                    Err(invalid(Expected::OneOf(words.join(", "))))
                }
            }
            Kind::List(words, older) => {
                let word = |item: &str| {
                    let item = older.iter().find(|(old, _)| *old == item).map_or(item, |(_, new)| *new);
                    words.iter().find(|w| **w == item).copied()
                };
                read_list(trimmed, word).ok_or_else(|| invalid(Expected::ListOf(words.join(", "))))
            }
            Kind::Controls => read_list(trimmed, control)
                .ok_or_else(|| invalid(Expected::ListOf(control_names().join(", ")))),
            Kind::Slice => Slice::parse(trimmed).map(|slice| Value::Text(Slice::text(slice))),
            Kind::Cell => March::parse(trimmed).map(|cell| Value::Text(March::text(cell))),
            Kind::Text => Ok(Value::Text(text.to_string())),
            Kind::Spheres if trimmed.is_empty() => Ok(Value::Text(String::new())),
            Kind::Spheres => crate::sphere::parse_spheres_text(trimmed)
                .map(|spheres| Value::Text(crate::sphere::spheres_text(&spheres)))
                .map_err(|e| ParamError::Invalid {
                    name: noun,
                    value: text.to_string(),
                    expected: Expected::Spheres(e.to_string()),
                }),
        }
    }
}

impl Parameter {
    /// `trimmed` read as an f32 in this parameter's range; the error calls it `noun` and quotes `text`.
    fn read_f32(&self, noun: &'static str, trimmed: &str, text: &str) -> Result<f32, ParamError> {
        let (min, max) = (self.min as f32, self.max as f32);
        let value = parse_f32(trimmed).ok_or_else(|| ParamError::Invalid {
            name: noun,
            value: text.to_string(),
            expected: Expected::Number { min: num(min).to_string(), max: num(max).to_string() },
        })?;
        check_f32(noun, value, min, max)
    }
}

/// `all`, `none`, or a comma list of words each read by `word` (normalised); `None` where one is none.
fn read_list(trimmed: &str, word: impl Fn(&str) -> Option<&'static str>) -> Option<Value> {
    let list = trimmed.to_ascii_lowercase();
    if list == "all" || list == "none" {
        return Some(Value::Text(list));
    }
    let items: Option<Vec<&str>> =
        list.split(',').map(str::trim).filter(|s| !s.is_empty()).map(word).collect();
    items.filter(|items| !items.is_empty()).map(|items| Value::Text(items.join(",")))
}

/// Reads `text` as the value of the parameter called `name` (any of its names).
pub fn parse_parameter(name: &str, text: &str) -> Result<Value, ParamError> {
    let (p, given) = parameter_named(name).ok_or_else(|| unknown(name))?;
    p.parse_as(given, text)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::params::Settings;
    use crate::params::{PARAMETERS, parameter};

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
        let settings = crate::params::Settings::default();
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
        assert!(message("nonsense", "1").starts_with("parameter name must be one of the table's"));
        assert!(message("critcal", "1").contains("those starting with 'c': "), "{}", message("critcal", "1"));
        assert!(message("critcal", "1").contains("critical"));
        assert_eq!(parse_parameter("edit", "on"), Ok(Value::Boolean(true)));
        assert_eq!(parse_parameter("balls", "0, 0,0,0.40"), Ok(Value::Text("0,0,0,0.4".into())));
        assert_eq!(parse_parameter("balls", ""), Ok(Value::Text(String::new())));
        assert!(
            message("balls", "0,0,0,2")
                .contains("balls sphere 1.radius: sphere radius must be between 0.01 and 1")
        );
    }
}
