//! The parameter table for the page: the element and the page build their attributes, link parsing
//! and controls from it, and read values through it.

use super::js_error;
use crate::scene::params::{self, Kind, PARAMETERS, Value};
use wasm_bindgen::prelude::*;

/// The parameter table (name, short name in links, label, kind, accepted range, slider, default), for
/// the page and the element to build their attributes, URL parsing and controls from.
#[wasm_bindgen]
pub fn parameters() -> js_sys::Array {
    let set = |object: &js_sys::Object, key: &str, value: JsValue| {
        let _ = js_sys::Reflect::set(object, &key.into(), &value);
    };
    PARAMETERS
        .iter()
        .map(|p| {
            let object = js_sys::Object::new();
            set(&object, "name", p.name.into());
            set(&object, "url", p.url.into());
            set(&object, "label", p.label.into());
            let (kind, words): (&str, &[&str]) = match p.kind {
                Kind::Integer => ("integer", &[]),
                Kind::Number => ("number", &[]),
                Kind::Boolean => ("boolean", &[]),
                Kind::Color => ("color", &[]),
                Kind::Choice(words) => ("choice", words),
                Kind::List(words) => ("list", words),
                Kind::Slice => ("slice", &[]),
                Kind::Spheres => ("spheres", &[]),
            };
            set(&object, "kind", kind.into());
            set(
                &object,
                "words",
                words.iter().map(|w| JsValue::from_str(w)).collect::<js_sys::Array>().into(),
            );
            set(&object, "min", p.min.into());
            set(&object, "max", p.max.into());
            set(&object, "sliderMin", p.slider.0.into());
            set(&object, "sliderMax", p.slider.1.into());
            set(&object, "step", p.slider.2.into());
            set(&object, "default", p.default.into());
            JsValue::from(object)
        })
        .collect()
}

/// Reads `text` as the value of parameter `name` (or its short name in links): a number, a boolean or
/// a string; throws with a message naming what is accepted.
#[wasm_bindgen]
pub fn parse_parameter(name: &str, text: &str) -> Result<JsValue, JsError> {
    Ok(value_to_js(params::parse_parameter(name, text).map_err(js_error)?))
}

/// A parameter's value as the page holds it: a number, a boolean or a string.
pub(super) fn value_to_js(value: Value) -> JsValue {
    match value {
        Value::Number(v) => v.into(),
        Value::Boolean(b) => b.into(),
        Value::Text(s) => s.into(),
    }
}
