//! The range checks every parameter and sphere goes through: a refused value comes back as a
//! [`ParamError`] whose message names the parameter, the value given and the accepted range.

use crate::decimal::{Sci, num};
use glam::Vec3;
use std::fmt;

/// A refused parameter value, with a message a person can act on.
#[derive(Clone, PartialEq)]
pub enum ParamError {
    /// The value is NaN.
    NotANumber { name: &'static str },
    /// The value is infinite.
    Infinite { name: &'static str },
    /// The text is not a value of the expected kind.
    Invalid { name: &'static str, value: String, expected: Expected },
    /// The value lies outside the accepted range.
    OutOfRange { name: &'static str, value: String, min: String, max: String },
    /// The device cannot hold what the value asks for.
    DeviceLimit { name: &'static str, value: String, detail: String },
}

/// In English, except in the browser's build: there a refusal is written as its code and fields
/// ([`ParamError::coded`]), which the page words in its reader's language and in English for its
/// console (www/lib/i18n/words.js), so that the WebAssembly holds no sentences of its own.
impl fmt::Display for ParamError {
    #[cfg(target_arch = "wasm32")]
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.coded())
    }

    #[cfg(not(target_arch = "wasm32"))]
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

/// What a refused text should have been, for [`ParamError::Invalid`]: a code and its fields, which a
/// page words in its reader's language ([`ParamError::coded`]) and `Display` in English.
#[derive(Clone, PartialEq)]
pub enum Expected {
    /// A whole number in a range (both ends written).
    Whole { min: String, max: String },
    /// A number in a range (both ends written).
    Number { min: String, max: String },
    /// true or false.
    Flag,
    /// A colour written #rrggbb.
    Colour,
    /// One of the words (joined by ", ").
    OneOf(String),
    /// all, none or a comma list of the words (joined by ", ").
    ListOf(String),
    /// A slice: off, or an axis and a position.
    Slice,
    /// A cell of the grid, or off.
    Cell,
    /// A sphere list; the detail says what is wrong with it.
    Spheres(String),
    /// A multiple of the LOD block's cells (its cells a side).
    LodMultiple(u32),
    /// At most `max` cells a side for a uniform grid (`lod_max` with level of detail).
    UniformAtMost { max: u32, lod_max: u32 },
    /// Anything else, said in English (the command line's and the library's own checks).
    Text(String),
}

// Both written as `Display` writes them (quoted): what a failed test or an `unwrap` shows.
impl fmt::Debug for Expected {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        #[cfg(not(target_arch = "wasm32"))]
        return write!(f, "{:?}", self.to_string());
        #[cfg(target_arch = "wasm32")]
        f.write_str("Expected")
    }
}

impl fmt::Debug for ParamError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{:?}", self.to_string())
    }
}

#[cfg(not(target_arch = "wasm32"))]
impl fmt::Display for Expected {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Self::Whole { min, max } => write!(f, "a whole number from {min} to {max}"),
            Self::Number { min, max } => write!(f, "a number from {min} to {max}"),
            Self::Flag => f.write_str("true or false (also 1/0, on/off)"),
            Self::Colour => f.write_str("a colour written #rrggbb"),
            Self::OneOf(words) => write!(f, "one of {words}"),
            Self::ListOf(words) => write!(f, "all, none, or a comma list of {words}"),
            Self::Slice => f.write_str("off, or an axis and a position such as z:0.25 (x, y or z; -1 to 1)"),
            Self::Cell => {
                f.write_str("off, or a cell of the grid as x,y,z (whole numbers from 0, such as 3,4,5)")
            }
            Self::Spheres(detail) => write!(f, "x,y,z,radius[,vx,vy,vz] per sphere joined by ; ({detail})"),
            Self::LodMultiple(block) => write!(f, "a multiple of {block} with lod=on"),
            Self::UniformAtMost { max, lod_max } => {
                write!(f, "at most {max} for a uniform grid (lod=on goes up to {lod_max})")
            }
            Self::Text(text) => f.write_str(text),
        }
    }
}

impl From<String> for Expected {
    fn from(text: String) -> Self {
        Self::Text(text)
    }
}

impl From<&str> for Expected {
    fn from(text: &str) -> Self {
        Self::Text(text.to_string())
    }
}

impl ParamError {
    /// The refusal as a code and its fields joined by U+001F, for a page to word in its reader's
    /// language (www/lib/i18n/words.js): `code, noun, value, a, b`, where an invalid text's `a` is what
    /// was expected as a code and `b`, `c` its fields.
    pub fn coded(&self) -> String {
        let mut out = String::new();
        let mut put = |parts: &[&str]| {
            for part in parts {
                out.push_str(part);
                out.push('\u{1f}');
            }
        };
        match self {
            Self::NotANumber { name } => put(&["not-a-number", name]),
            Self::Infinite { name } => put(&["infinite", name]),
            Self::OutOfRange { name, value, min, max } => {
                put(&["out-of-range", name, &short_number(value), min, max])
            }
            Self::DeviceLimit { name, value, detail } => put(&["device-limit", name, value, detail, ""]),
            Self::Invalid { name, value, expected } => {
                put(&["invalid", name, &quoted(value)]);
                match expected {
                    Expected::Whole { min, max } => put(&["whole", min, max]),
                    Expected::Number { min, max } => put(&["number", min, max]),
                    Expected::Flag => put(&["flag", "", ""]),
                    Expected::Colour => put(&["colour", "", ""]),
                    Expected::OneOf(words) => put(&["one-of", words, ""]),
                    Expected::ListOf(words) => put(&["list-of", words, ""]),
                    Expected::Slice => put(&["slice", "", ""]),
                    Expected::Cell => put(&["cell", "", ""]),
                    // A refusal inside the detail keeps its fields apart with U+001E.
                    Expected::Spheres(detail) => {
                        let detail: String =
                            detail.chars().map(|c| if c == '\u{1f}' { '\u{1e}' } else { c }).collect();
                        put(&["spheres", &detail, ""])
                    }
                    Expected::LodMultiple(cells) => put(&["lod-multiple", &cells.to_string(), ""]),
                    Expected::UniformAtMost { max, lod_max } => {
                        put(&["uniform-at-most", &max.to_string(), &lod_max.to_string()])
                    }
                    Expected::Text(text) => put(&["text", text, ""]),
                };
            }
        };
        out.pop();
        out
    }
}

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
