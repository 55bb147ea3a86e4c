//! The test vectors of the table's reader (`www/parameter-vectors.json`): for every row of both
//! figures' tables whose kind the page reads without the WebAssembly, texts a page, a link or a
//! notebook may send (the default, the range's ends, each word, and hostile ones: hexadecimal,
//! `Infinity`, `no`, digits of other scripts, long and escaped text), each with what `Parameter::parse`
//! makes of it: the value, or the message of its refusal. The JavaScript reader (`www/lib/core/read.js`)
//! and the notebook's (`_parameters.py`) are held to them by their tests.

use crate::scene::params::plane::PLANE_PARAMETERS;
use crate::scene::params::{Kind, PARAMETERS, Parameter, Value};
use serde_json::{Value as Json, json};

/// Texts every row is given.
const HOSTILE: &[&str] = &[
    "",
    " ",
    "0",
    "1",
    "-1",
    "+2",
    "16",
    "2.5",
    ".5",
    "5.",
    "1e3",
    "1E-3",
    "0x10",
    "0b1",
    "1_000",
    "1,5",
    "Infinity",
    "-inf",
    "NaN",
    "no",
    "Yes",
    " ON ",
    "banana",
    "\t8\n",
    "8 8",
    "١٢",
    "\u{200b}8",
    "12345678901234567890123456789",
    "1e39",
    "1e400",
    "1e-50",
    // Powers of two, where an f32's shortest decimal is not the nearest one of its length.
    "1.2621774483536188887e-29",
    "154742504910672534362390528",
    "1237940039285380274899124224",
    "-0",
    "say \"hi\" \\ é 中 🙂",
    "combining e\u{301} and \u{1b}[0m",
    "a text longer than forty characters, cut short in the message",
    "all",
    "none",
    "#E77661",
    "fff",
];

/// The kinds the page's reader reads itself (the others go to the WebAssembly's parser).
fn read_in_javascript(kind: Kind) -> bool {
    !matches!(kind, Kind::Slice | Kind::Cell | Kind::Spheres)
}

/// Texts that reach a row's own edges: its default, range and words, written as pages write them.
fn own_texts(p: &Parameter) -> Vec<String> {
    let mut texts = vec![p.default.to_string()];
    if matches!(p.kind, Kind::Number | Kind::Integer | Kind::Levels) {
        for x in [p.min, p.max] {
            texts.push(format!("{x}"));
            texts.push(format!("{}", x + 0.5));
            texts.push(format!("{}", x - 1e-9));
        }
        texts.push(format!(" {} , {}", p.min, p.max));
    }
    let words = p.words();
    for word in &words {
        texts.push(word.to_ascii_uppercase());
    }
    if words.len() > 1 {
        texts.push(format!("{}, ,{}", words[0], words[words.len() - 1]));
        texts.push(format!("{},{}", words[0], "nope"));
    }
    match p.kind {
        Kind::List(_, older) => texts.extend(older.iter().map(|(old, _)| old.to_string())),
        Kind::Controls => {
            texts.extend(["res", "color_by", "inspector,error_plot", "Iso, RES"].map(String::from))
        }
        _ => {}
    }
    texts
}

fn outcome(p: &Parameter, given: &'static str, text: &str) -> Json {
    match p.parse_as(given, text) {
        Ok(Value::Number(x)) => json!({ "value": x }),
        Ok(Value::Boolean(b)) => json!({ "value": b }),
        Ok(Value::Text(t)) => json!({ "value": t }),
        Err(error) => json!({ "message": error.to_string() }),
    }
}

/// A whole number too long for a double.
fn ones() -> String {
    "1".repeat(400)
}

/// The vectors of one table (`view` or `plane`).
fn table_vectors<'a>(table: &str, rows: impl Iterator<Item = &'a Parameter>) -> Vec<Json> {
    let mut out = Vec::new();
    for p in rows.filter(|p| read_in_javascript(p.kind)) {
        let mut texts: Vec<String> = HOSTILE.iter().map(|t| t.to_string()).collect();
        texts.push(ones());
        texts.extend(own_texts(p));
        let mut seen = std::collections::HashSet::new();
        for text in texts.into_iter().filter(|t| seen.insert(t.clone())) {
            let mut vector = json!({ "table": table, "name": p.name, "text": text });
            for (key, value) in outcome(p, p.name, &text).as_object().unwrap() {
                vector[key] = value.clone();
            }
            out.push(vector);
        }
        // Every other spelling names the parameter in its messages where the row has no noun.
        for given in p.names().filter(|n| *n != p.name && p.kind != Kind::Text) {
            let mut vector = json!({ "table": table, "name": p.name, "given": given, "text": "banana" });
            vector["message"] = outcome(p, given, "banana")["message"].clone();
            out.push(vector);
        }
    }
    out
}

/// `parameter-vectors.json`: one vector a line.
pub fn vectors_json() -> String {
    let mut vectors = table_vectors("view", PARAMETERS.iter());
    // The 2D figure's own rows (the others are the 3D figure's).
    vectors.extend(table_vectors("plane", PLANE_PARAMETERS.iter()));
    let lines: Vec<String> = vectors.iter().map(|v| format!("  {v}")).collect();
    format!("[\n{}\n]\n", lines.join(",\n"))
}
