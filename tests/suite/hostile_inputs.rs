//! Generated hostile inputs for every parser a student's file or link reaches: the scene document, the
//! link (`name=value&…`), the compact `balls` form and each setting's text. Arbitrary JSON, mutated valid
//! documents, random bytes, huge and tiny numbers and deep nesting: each input is accepted and reads
//! back to itself, or refused with a short message naming what is wrong; never a panic.
//!
//! The number of cases per property follows `PROPTEST_CASES` (256 by default, as the test command runs
//! them); `PROPTEST_CASES=20000 cargo test --release --test suite hostile_inputs::` is the longer run.

use glam::Vec3;
use metaballs::Settings;
use metaballs::Sphere;
use metaballs::bench::with_view;
use metaballs::scene::file::SceneFile;
use metaballs::scene::params::{Kind, PARAMETERS, Value, parse_parameter};
use metaballs::scene::sphere::{parse_spheres_text, spheres_text};
use proptest::prelude::*;
use serde_json::json;

/// Longest message a refusal may give, whatever the input: the figure shows it in a notice.
const MAX_MESSAGE: usize = 700;

fn short_message(message: &str) -> Result<(), TestCaseError> {
    prop_assert!(!message.trim().is_empty(), "an empty message");
    prop_assert!(message.len() <= MAX_MESSAGE, "a message of {} bytes: {message:.200}", message.len());
    Ok(())
}

/// Numbers as text, from the ordinary to the hostile: huge, tiny, subnormal, signed zeros, long digit
/// strings, exponents past any float, and the words Rust's float parser takes.
fn number_text() -> impl Strategy<Value = String> {
    prop_oneof![
        any::<f64>().prop_map(|x| x.to_string()),
        any::<f32>().prop_map(|x| format!("{x:e}")),
        any::<i64>().prop_map(|x| x.to_string()),
        (-2.0f64..2.0).prop_map(|x| format!("{x:.3}")),
        "[-+]?[0-9]{0,40}(\\.[0-9]{0,40})?([eE][-+]?[0-9]{1,4})?",
        "[0-9]{300,400}",
        prop::sample::select(vec![
            "NaN", "inf", "-inf", "infinity", "-0", "1e-45", "3.4e38", "1e39", "0x10", ""
        ])
        .prop_map(String::from),
    ]
}

/// Any text a link or an attribute could carry.
fn any_text() -> impl Strategy<Value = String> {
    prop_oneof![
        number_text(),
        ".{0,40}",
        "[a-z_,;:# ]{0,30}",
        prop::collection::vec(any::<u8>(), 0..60).prop_map(|b| String::from_utf8_lossy(&b).into_owned()),
        ".{2000,4000}",
    ]
}

/// A value's text as a link writes it.
fn value_text(value: &Value) -> String {
    match value {
        Value::Number(n) => n.to_string(),
        Value::Boolean(b) => b.to_string(),
        Value::Text(t) => t.clone(),
    }
}

/// Any JSON value, nested up to a few levels, with hostile numbers and strings among the leaves.
fn any_json() -> impl Strategy<Value = serde_json::Value> {
    let leaf = prop_oneof![
        Just(serde_json::Value::Null),
        any::<bool>().prop_map(serde_json::Value::from),
        any::<f64>().prop_map(|x| serde_json::Number::from_f64(x).map_or(json!(null), Into::into)),
        any::<i64>().prop_map(serde_json::Value::from),
        any::<u64>().prop_map(serde_json::Value::from),
        (-1.0f64..1.0).prop_map(serde_json::Value::from),
        any_text().prop_map(serde_json::Value::from),
    ];
    leaf.prop_recursive(4, 48, 6, |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..6).prop_map(serde_json::Value::from),
            prop::collection::btree_map("[a-z_]{0,10}", inner, 0..6)
                .prop_map(|m| serde_json::Value::Object(m.into_iter().collect())),
        ]
    })
}

/// A valid sphere: its centre keeps it inside the box.
fn valid_sphere() -> impl Strategy<Value = Sphere> {
    (0.01f32..=1.0, any::<bool>())
        .prop_flat_map(|(radius, subtracts)| {
            let limit = 1.0 - radius;
            let c = -limit..=limit;
            let v = -2.0f32..=2.0;
            (Just(radius), Just(subtracts), (c.clone(), c.clone(), c), (v.clone(), v.clone(), v))
        })
        .prop_map(|(radius, subtracts, (x, y, z), (vx, vy, vz))| Sphere {
            center: Vec3::new(x, y, z),
            radius,
            velocity: Vec3::new(vx, vy, vz),
            charge: if subtracts { -1.0 } else { 1.0 },
        })
}

/// A valid scene document's JSON: spheres, and settings that each parse.
fn valid_document() -> impl Strategy<Value = serde_json::Value> {
    let names: Vec<&'static str> = metaballs::scene::file::scene_parameters().map(|p| p.name).collect();
    (prop::collection::vec(valid_sphere(), 1..8), prop::sample::subsequence(names, 0..12)).prop_map(
        |(spheres, names)| {
            let settings = names
                .into_iter()
                .filter(|&n| n != "resolution" && n != "lod")
                .map(|name| {
                    let p = PARAMETERS.iter().find(|p| p.name == name).unwrap();
                    (name, p.parse(p.default).unwrap())
                })
                .collect();
            let text = SceneFile { spheres, settings }.to_json();
            serde_json::from_str(&text).unwrap()
        },
    )
}

/// One change to a document: a value anywhere replaced, a field removed, or a number made hostile.
#[derive(Clone, Debug)]
enum Mutation {
    Replace(Vec<usize>, serde_json::Value),
    Remove(Vec<usize>),
    Number(Vec<usize>, f64),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let path = prop::collection::vec(0usize..16, 1..5);
    let hostile = prop_oneof![
        any::<f64>(),
        Just(f64::MAX),
        Just(f64::MIN_POSITIVE),
        Just(5e-324),
        Just(-0.0),
        Just(1e39),
        Just(-1e-39),
        Just(1e15 + 0.5),
        Just(2f64.powi(64) + 1.0),
    ];
    prop_oneof![
        (path.clone(), any_json()).prop_map(|(p, v)| Mutation::Replace(p, v)),
        path.clone().prop_map(Mutation::Remove),
        (path, hostile).prop_map(|(p, x)| Mutation::Number(p, x)),
    ]
}

/// The value at `path` (each step picks among an object's fields or an array's items, modulo their count).
fn walk<'a>(value: &'a mut serde_json::Value, path: &[usize]) -> Option<(&'a mut serde_json::Value, usize)> {
    let (&last, rest) = path.split_last()?;
    let mut at = value;
    for &step in rest {
        at = match at {
            serde_json::Value::Object(m) if !m.is_empty() => {
                let n = m.len();
                m.values_mut().nth(step % n)?
            }
            serde_json::Value::Array(a) if !a.is_empty() => {
                let n = a.len();
                &mut a[step % n]
            }
            _ => return None,
        };
    }
    Some((at, last))
}

fn mutate(mut document: serde_json::Value, change: &Mutation) -> serde_json::Value {
    let path = match change {
        Mutation::Replace(p, _) | Mutation::Remove(p) | Mutation::Number(p, _) => p,
    };
    let Some((parent, step)) = walk(&mut document, path) else { return document };
    let replacement = match change {
        Mutation::Replace(_, v) => Some(v.clone()),
        Mutation::Number(_, x) => Some(serde_json::Number::from_f64(*x).map_or(json!(null), Into::into)),
        Mutation::Remove(_) => None,
    };
    match parent {
        serde_json::Value::Object(m) if !m.is_empty() => {
            let key = m.keys().nth(step % m.len()).unwrap().clone();
            match replacement {
                Some(v) => m[&key] = v,
                None => {
                    m.remove(&key);
                }
            }
        }
        serde_json::Value::Array(a) if !a.is_empty() => {
            let i = step % a.len();
            match replacement {
                Some(v) => a[i] = v,
                None => {
                    a.remove(i);
                }
            }
        }
        _ => {}
    }
    document
}

/// A scene document is taken whole or refused whole: a taken one reads back to itself and applies to
/// the settings or is refused there with a message.
fn check_document(text: &str) -> Result<(), TestCaseError> {
    match SceneFile::parse(text) {
        Ok(scene) => {
            let again = SceneFile::parse(&scene.to_json());
            prop_assert_eq!(again.as_ref(), Ok(&scene), "a taken document reads back to itself");
            if let Err(e) = scene.applied_to(Settings::default()) {
                short_message(&e.to_string())?;
            }
        }
        Err(e) => short_message(&e.to_string())?,
    }
    Ok(())
}

proptest! {
    #[test]
    fn every_setting_reads_any_text_or_refuses_it_briefly(index in 0..PARAMETERS.len(), text in any_text()) {
        let p = &PARAMETERS[index];
        match parse_parameter(p.name, &text) {
            Ok(value) => {
                // The value as a link writes it reads back to the same value.
                prop_assert_eq!(parse_parameter(p.name, &value_text(&value)), Ok(value.clone()));
                if let Value::Number(n) = value {
                    // Checked as the f32 the renderer keeps.
                    prop_assert!(n.is_finite() && n as f32 >= p.min as f32 && n as f32 <= p.max as f32, "{} = {n}", p.name);
                    if p.kind == Kind::Integer {
                        prop_assert_eq!(n.fract(), 0.0);
                    }
                }
            }
            Err(e) => short_message(&e.to_string())?,
        }
        let base = Settings::default();
        match base.with_parameter(p.name, &text) {
            Ok(next) => prop_assert!(next.validated().is_ok(), "{} {:?} gives settings that fail their checks", p.name, text),
            Err(e) => short_message(&e.to_string())?,
        }
    }

    #[test]
    fn links_are_taken_whole_or_refused(
        pairs in prop::collection::vec(
            (prop_oneof![prop::sample::select(PARAMETERS.iter().map(|p| p.link_name()).collect::<Vec<_>>()).prop_map(String::from), "[a-z_=&]{0,8}"],
             prop_oneof![number_text(), any_text()]),
            0..8),
        raw in any_text(),
    ) {
        let link: String = pairs.iter().map(|(n, v)| format!("{n}={v}")).collect::<Vec<_>>().join("&");
        for spec in [link.as_str(), raw.as_str()] {
            match with_view(Settings::default(), spec) {
                Ok(settings) => {
                    prop_assert!(settings.validated().is_ok());
                    // Each pair sets a value outright: the same link again changes nothing.
                    prop_assert_eq!(with_view(settings, spec), Ok(settings));
                }
                Err(e) => short_message(&e.to_string())?,
            }
        }
    }

    #[test]
    fn sphere_lists_in_links_read_back_or_are_refused(text in prop_oneof![
        any_text(),
        prop::collection::vec(prop::collection::vec(number_text(), 0..9).prop_map(|n| n.join(",")), 0..70)
            .prop_map(|groups| groups.join(";")),
    ]) {
        match parse_spheres_text(&text) {
            Ok(spheres) => {
                prop_assert!(!spheres.is_empty() && spheres.len() <= 64);
                let written = spheres_text(&spheres);
                let back = parse_spheres_text(&written);
                prop_assert!(back.is_ok(), "{written:?} was written for {text:?} and refused: {back:?}");
                prop_assert_eq!(spheres_text(&back.unwrap()), written);
            }
            Err(e) => short_message(&e.to_string())?,
        }
    }

    #[test]
    fn valid_spheres_written_for_a_link_read_back_to_its_precision(spheres in prop::collection::vec(valid_sphere(), 1..65)) {
        let written = spheres_text(&spheres);
        let back = parse_spheres_text(&written);
        prop_assert!(back.is_ok(), "{written:?}: {back:?}");
        for (a, b) in spheres.iter().zip(back.unwrap()) {
            // Rounded to 3 decimals; a centre at a wall may be pulled in by a step more.
            prop_assert!((a.center - b.center).abs().max_element() <= 0.0026 && (a.radius - b.radius).abs() <= 0.0006);
            prop_assert_eq!(a.charge, b.charge);
        }
    }

    #[test]
    fn random_bytes_are_refused_as_a_scene(bytes in prop::collection::vec(any::<u8>(), 0..400)) {
        check_document(&String::from_utf8_lossy(&bytes))?;
    }

    #[test]
    fn arbitrary_json_is_a_scene_or_refused(document in any_json()) {
        check_document(&document.to_string())?;
    }

    #[test]
    fn valid_documents_read_back_to_themselves(document in valid_document()) {
        let text = serde_json::to_string_pretty(&document).unwrap();
        let scene = SceneFile::parse(&text);
        prop_assert!(scene.is_ok(), "{scene:?}");
        prop_assert_eq!(scene.unwrap().to_json(), text);
    }

    #[test]
    fn mutated_documents_are_taken_whole_or_refused(
        document in valid_document(),
        changes in prop::collection::vec(mutation(), 1..4),
        cut in any::<prop::sample::Index>(),
        cut_it in prop::bool::weighted(0.2),
    ) {
        let mutated = changes.iter().fold(document, mutate);
        let mut text = serde_json::to_string_pretty(&mutated).unwrap();
        if cut_it {
            let end = cut.index(text.len() + 1);
            text = String::from_utf8_lossy(&text.as_bytes()[..end]).into_owned();
        }
        check_document(&text)?;
    }

    #[test]
    fn deep_nesting_is_refused_without_overflowing_the_stack(depth in 1usize..20_000, object in any::<bool>(), at_settings in any::<bool>()) {
        let (open, close) = if object { ("{\"a\":", "}") } else { ("[", "]") };
        let inner = format!("{}0{}", open.repeat(depth), close.repeat(depth));
        let text = if at_settings {
            format!("{{\"format\":\"metaballs-scene\",\"version\":1,\"spheres\":[{{\"center\":[0,0,0],\"radius\":0.3}}],\"settings\":{{\"iso\":{inner}}}}}")
        } else {
            inner
        };
        check_document(&text)?;
    }
}

#[test]
fn oversized_documents_are_refused_before_they_are_read() {
    let big = format!("{{\"format\":\"metaballs-scene\",\"pad\":\"{}\"}}", "x".repeat(2 << 20));
    let message = SceneFile::parse(&big).unwrap_err().to_string();
    assert!(message.contains("a scene file is at most 1 MB"), "{message}");
}
