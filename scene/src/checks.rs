//! The range checks every parameter and sphere goes through: a refused value comes back as a
//! [`ParamError`] whose message names the parameter, the value given and the accepted range.

use crate::decimal::{Sci, num};
use glam::Vec3;
use std::fmt;

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
            Self::Invalid { name, value, expected } => {
                write!(f, "{name} must be {expected}, got {}", quoted(value))
            }
            Self::OutOfRange { name, value, min, max } => {
                write!(f, "{name} must be between {min} and {max}, got {}", short_number(value))
            }
            Self::DeviceLimit { name, value, detail } => {
                write!(f, "{name} {value} is more than this device can hold: {detail}")
            }
        }
    }
}

impl std::error::Error for ParamError {}

/// Longest part of a given text a message repeats, in characters: a message stays readable in a
/// notice whatever a link or a file holds.
const SHOWN_CHARS: usize = 40;

/// `text` cut short after [`SHOWN_CHARS`] characters (with an ellipsis), for a message.
pub fn cut(text: &str) -> String {
    match text.char_indices().nth(SHOWN_CHARS) {
        Some((end, _)) => format!("{}…", &text[..end]),
        None => text.to_string(),
    }
}

/// `text` in quotes for a message (escaped as Rust's debug format does), cut short after
/// [`SHOWN_CHARS`] characters.
pub fn quoted(text: &str) -> String {
    match text.char_indices().nth(SHOWN_CHARS) {
        Some((end, _)) => format!("{:?}…", &text[..end]),
        None => format!("{text:?}"),
    }
}

/// A number written for a message: as given, or in scientific notation when its digits run long.
fn short_number(text: &str) -> String {
    match crate::number::parse_f64(text) {
        Some(x) if text.len() > 24 => Sci(x).to_string(),
        _ => text.to_string(),
    }
}

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

/// A value as a message writes it: floats through [`crate::decimal`], so that the browser's build
/// holds none of core's float formatting.
pub(crate) trait Written: PartialOrd + Copy {
    fn written(self) -> String;
}

impl Written for f32 {
    fn written(self) -> String {
        num(self).to_string()
    }
}

impl Written for f64 {
    fn written(self) -> String {
        num(self).to_string()
    }
}

impl Written for u32 {
    fn written(self) -> String {
        self.to_string()
    }
}

pub(crate) fn check_range<T: Written>(name: &'static str, value: T, min: T, max: T) -> Result<T, ParamError> {
    if value < min || value > max {
        return Err(ParamError::OutOfRange {
            name,
            value: value.written(),
            min: min.written(),
            max: max.written(),
        });
    }
    Ok(value)
}

pub(crate) fn check_vec3(name: &'static str, v: Vec3, min: f32, max: f32) -> Result<Vec3, ParamError> {
    for c in v.to_array() {
        check_f32(name, c, min, max)?;
    }
    Ok(v)
}
