//! Reading parameter values for the page. The table itself reaches the page as a plain module
//! (`www/lib/attributes.js`, written by `metaballs manifest`), so the element knows its attributes
//! before the wasm arrives; values are read here, with the table's checks and messages.

use super::js_error;
use crate::scene::params::{self, Value};
use wasm_bindgen::prelude::*;

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
