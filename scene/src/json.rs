//! JSON as scene files read and write it, through the platform's own: the browser's `JSON` in the
//! page's build (so that the wasm carries no JSON reader or writer of its own, about 13 KB gzipped),
//! `serde_json` elsewhere. A document is read whole into a `Json`, looked at through `kind`, and
//! written from values made with `Json::number` and the rest.
//!
//! What differs between the two is only what the platform says about text that is not JSON, and how
//! a number is spelled when written (`1.0` or `1`): every value reads back the same in both.

/// A JSON value as the scene file looks at it.
pub enum Kind {
    Null,
    Bool(bool),
    /// The number, and its text as the platform writes it.
    Number(f64, String),
    Text(String),
    Array(Vec<Json>),
    Object(Vec<(String, Json)>),
}

/// Why text is not a JSON document.
pub struct NotJson {
    /// What the platform's reader says.
    pub message: String,
    /// The text ended before the document did (a file cut short).
    pub ends_early: bool,
}

#[cfg(not(target_arch = "wasm32"))]
mod platform {
    use super::{Kind, NotJson};
    use serde_json::Value;

    /// A JSON value.
    #[derive(Clone)]
    pub struct Json(Value);

    impl Json {
        /// Reads a whole document.
        pub fn parse(text: &str) -> Result<Json, NotJson> {
            serde_json::from_str(text)
                .map(Json)
                .map_err(|e| NotJson { message: e.to_string(), ends_early: e.is_eof() })
        }

        pub fn kind(&self) -> Kind {
            match &self.0 {
                Value::Null => Kind::Null,
                Value::Bool(b) => Kind::Bool(*b),
                Value::Number(n) => Kind::Number(n.as_f64().unwrap_or(f64::NAN), n.to_string()),
                Value::String(s) => Kind::Text(s.clone()),
                Value::Array(items) => Kind::Array(items.iter().cloned().map(Json).collect()),
                Value::Object(map) => {
                    Kind::Object(map.iter().map(|(k, v)| (k.clone(), Json(v.clone()))).collect())
                }
            }
        }

        /// The value on one line, as JSON.
        pub fn compact(&self) -> String {
            self.0.to_string()
        }

        /// The document, indented by two spaces.
        pub fn pretty(&self) -> String {
            serde_json::to_string_pretty(&self.0).expect("a JSON value always serialises")
        }

        /// A number; null where it is not finite.
        pub fn number(x: f64) -> Json {
            Json(serde_json::Number::from_f64(x).map_or(Value::Null, Value::Number))
        }

        /// A whole number.
        pub fn whole(n: i64) -> Json {
            Json(n.into())
        }

        pub fn boolean(b: bool) -> Json {
            Json(b.into())
        }

        pub fn text(s: &str) -> Json {
            Json(s.into())
        }

        pub fn array(items: Vec<Json>) -> Json {
            Json(Value::Array(items.into_iter().map(|j| j.0).collect()))
        }

        /// An object with `fields` in their order.
        pub fn object(fields: Vec<(String, Json)>) -> Json {
            Json(Value::Object(fields.into_iter().map(|(k, v)| (k, v.0)).collect()))
        }
    }
}

#[cfg(target_arch = "wasm32")]
mod platform {
    use super::{Kind, NotJson};
    use js_sys::{Array, JSON, Object, Reflect};
    use wasm_bindgen::{JsCast, JsValue};

    /// A JSON value.
    #[derive(Clone)]
    pub struct Json(JsValue);

    /// Where `needle` first occurs in `text`, by a plain scan: the messages looked through are short,
    /// and the standard library's substring search (`str::contains`, `str::split` by a `&str`) is
    /// about 2 KB of the wasm that nothing else needs.
    fn find(text: &str, needle: &str) -> Option<usize> {
        text.as_bytes().windows(needle.len()).position(|w| w == needle.as_bytes())
    }

    /// The text of `value` written by `JSON.stringify` (indented by `indent` spaces where given).
    fn stringify(value: &JsValue, indent: Option<u32>) -> String {
        let written = match indent {
            Some(n) => JSON::stringify_with_replacer_and_space(value, &JsValue::NULL, &n.into()),
            None => JSON::stringify(value),
        };
        written.ok().and_then(|s| s.as_string()).unwrap_or_default()
    }

    impl Json {
        /// Reads a whole document.
        pub fn parse(text: &str) -> Result<Json, NotJson> {
            JSON::parse(text).map(Json).map_err(|error| {
                let message = Reflect::get(&error, &"message".into())
                    .ok()
                    .and_then(|m| m.as_string())
                    .unwrap_or_else(|| "not JSON".into());
                // What each engine says of text that ends early: "Unexpected end of JSON input" or an
                // error at the position just past the text (Chromium), "unexpected end of data"
                // (Firefox), "Unexpected EOF" (Safari).
                let length = text.encode_utf16().count();
                const AT: &str = "at position ";
                let at = find(&message, AT)
                    .and_then(|i| message[i + AT.len()..].split(|c: char| !c.is_ascii_digit()).next())
                    .and_then(|digits| digits.parse::<usize>().ok());
                let lower = message.to_ascii_lowercase();
                let ends_early = ["end of json input", "end of data", "unexpected eof"]
                    .iter()
                    .any(|w| find(&lower, w).is_some())
                    || at.is_some_and(|p| p >= length);
                NotJson { message, ends_early }
            })
        }

        pub fn kind(&self) -> Kind {
            let v = &self.0;
            if let Some(b) = v.as_bool() {
                Kind::Bool(b)
            } else if let Some(x) = v.as_f64() {
                Kind::Number(x, stringify(v, None))
            } else if let Some(s) = v.as_string() {
                Kind::Text(s)
            } else if Array::is_array(v) {
                Kind::Array(v.unchecked_ref::<Array>().iter().map(Json).collect())
            } else if v.is_object() {
                let keys = Object::keys(v.unchecked_ref::<Object>());
                Kind::Object(
                    keys.iter()
                        .filter_map(|k| Some((k.as_string()?, Json(Reflect::get(v, &k).ok()?))))
                        .collect(),
                )
            } else {
                Kind::Null
            }
        }

        /// The value on one line, as JSON.
        pub fn compact(&self) -> String {
            stringify(&self.0, None)
        }

        /// The document, indented by two spaces.
        pub fn pretty(&self) -> String {
            stringify(&self.0, Some(2))
        }

        /// A number; null where it is not finite.
        pub fn number(x: f64) -> Json {
            Json(if x.is_finite() { x.into() } else { JsValue::NULL })
        }

        /// A whole number.
        pub fn whole(n: i64) -> Json {
            Json((n as f64).into())
        }

        pub fn boolean(b: bool) -> Json {
            Json(b.into())
        }

        pub fn text(s: &str) -> Json {
            Json(s.into())
        }

        pub fn array(items: Vec<Json>) -> Json {
            Json(items.into_iter().map(|j| j.0).collect::<Array>().into())
        }

        /// An object with `fields` in their order.
        pub fn object(fields: Vec<(String, Json)>) -> Json {
            let object = Object::new();
            for (k, v) in fields {
                let _ = Reflect::set(&object, &k.into(), &v.0);
            }
            Json(object.into())
        }
    }
}

pub use platform::Json;

impl Json {
    /// The fields of an object, or `None` for any other value.
    pub fn fields(&self) -> Option<Vec<(String, Json)>> {
        match self.kind() {
            Kind::Object(fields) => Some(fields),
            _ => None,
        }
    }

    /// The items of an array, or `None` for any other value.
    pub fn items(&self) -> Option<Vec<Json>> {
        match self.kind() {
            Kind::Array(items) => Some(items),
            _ => None,
        }
    }
}
