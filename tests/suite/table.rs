//! Every row of the parameter table, walked through every way a setting is given outside a page: its
//! names (attribute, link, older spellings), the renderer's settings, a link, a scene file, the
//! element's table and the notebook's traits. A new row is covered here without a new line.

use metaballs::bench::with_view;
use metaballs::manifest;
use metaballs::scene::file::SceneFile;
use metaballs::scene::params::{
    Group, Kind, PARAMETERS, Parameter, Scope, Value, control, control_names, parameter, parse_parameter,
};
use metaballs::{Settings, Sphere};
use serde_json::Value as Json;

/// A value of `p` other than its default, as text.
fn other_value(p: &Parameter) -> String {
    match p.kind {
        Kind::Integer => {
            let v = if p.parse(p.default) == Ok(Value::Number(p.min)) { p.min + 1.0 } else { p.min };
            v.to_string()
        }
        Kind::Number => {
            let v = if p.parse(p.default) == Ok(Value::Number(p.max)) { p.min } else { p.max };
            (v as f32).to_string()
        }
        Kind::Boolean => (p.default != "true").to_string(),
        Kind::Color => "#123456".into(),
        Kind::Choice(words) => words.iter().find(|w| **w != p.default).unwrap().to_string(),
        Kind::List(words, _) => words.last().unwrap().to_string(),
        Kind::Controls => control_names()[1].to_string(),
        Kind::Slice => "z:0.25".into(),
        Kind::Cell => "1,2,3".into(),
        Kind::Spheres => "0,0,0,0.3".into(),
        Kind::Text => "a figure".into(),
        Kind::Levels => "0.5,1.5".into(),
    }
}

/// The settings with `p` at `text`, as a renderer that starts at level of detail where a value
/// needs it (resolutions past the uniform grid's).
fn base_for(p: &Parameter) -> Settings {
    if p.name == "resolution" {
        Settings::default().with_parameter("lod", "on").unwrap()
    } else {
        Settings::default()
    }
}

#[test]
fn every_name_is_the_platforms_and_answers_to_one_row() {
    let mut seen = std::collections::BTreeMap::new();
    for p in PARAMETERS {
        assert!(
            p.name.bytes().all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'-'),
            "{}: attributes are kebab-case",
            p.name
        );
        assert_eq!(p.property(), manifest::property_name(p.name));
        assert!(!p.property().contains('-') && !p.python().contains('-'), "{}", p.name);
        for name in p.names() {
            assert_eq!(parameter(name).map(|q| q.name), Some(p.name), "{name} answers to another row");
            if let Some(other) = seen.insert(name, p.name) {
                assert_eq!(other, p.name, "{name} names two settings");
            }
        }
        assert!(p.parse(p.default).is_ok(), "{}: default {:?}", p.name, p.default);
    }
}

#[test]
fn every_row_is_taken_by_each_of_its_names_in_a_link_and_by_the_renderer() {
    for p in PARAMETERS {
        let text = other_value(p);
        let value = p.parse(&text).unwrap_or_else(|e| panic!("{}: {text:?}: {e}", p.name));
        for name in p.names() {
            assert_eq!(parse_parameter(name, &text), Ok(value.clone()), "{name}={text}");
            let link = with_view(base_for(p), &format!("{name}={text}"));
            match p.field {
                Some(field) => {
                    let settings = link.unwrap_or_else(|e| panic!("{name}={text}: {e}"));
                    assert_eq!(
                        field.get(&settings),
                        value,
                        "{name}={text} read back from the renderer's settings"
                    );
                }
                None => {
                    assert_eq!(p.scope, Scope::Element);
                    assert!(link.is_err(), "{name} is the element's, not the renderer's");
                }
            }
        }
        if let Some(field) = p.field {
            assert_ne!(p.scope, Scope::Element);
            let default = p.parse(p.default).unwrap();
            assert_eq!(
                field.get(&Settings::default()),
                default,
                "{}: the typed default is the row's",
                p.name
            );
        }
    }
}

#[test]
fn every_row_a_scene_holds_is_saved_and_read_back_by_each_of_its_names() {
    let spheres =
        vec![Sphere { center: glam::Vec3::ZERO, radius: 0.3, velocity: glam::Vec3::ZERO, charge: 1.0 }];
    for p in PARAMETERS {
        let text = other_value(p);
        let value = p.parse(&text).unwrap();
        for name in p.names() {
            let given = metaballs::scene::json::Json::object(vec![(
                name.to_string(),
                metaballs::scene::json::Json::text(&text),
            )]);
            let scene = SceneFile::new(spheres.clone(), &given).unwrap_or_else(|e| panic!("{name}: {e}"));
            if !p.in_scene {
                assert_eq!(scene.setting(p.name), None, "{name} belongs to the page, not the scene");
                continue;
            }
            let read = SceneFile::parse(&scene.to_json()).unwrap();
            assert_eq!(read.setting(p.name), Some(&value), "{name}={text}");
            assert_eq!(read.setting(name), Some(&value), "{name}={text} looked up by the name it was given");
        }
    }
}

#[test]
fn a_scene_file_that_gives_a_setting_under_two_of_its_names_is_refused() {
    let text = r#"{ "format": "metaballs-scene", "version": 1, "spheres": [{ "center": [0, 0, 0], "radius": 0.3 }],
        "settings": { "color_by": "area", "color-by": "case" } }"#;
    let message = SceneFile::parse(text).unwrap_err().to_string();
    assert!(message.contains("settings.color-by is given twice"), "{message}");
}

#[test]
fn every_row_reaches_the_elements_table_the_manifest_and_the_notebooks_traits() {
    let attributes = manifest::attributes_js();
    let traits: Json = serde_json::from_str(&manifest::parameters_json()).unwrap();
    let elements: Json = serde_json::from_str(&manifest::custom_elements_json()).unwrap();
    let declared = &elements["modules"][0]["declarations"][0];
    for (p, row) in PARAMETERS.iter().zip(traits.as_array().unwrap()) {
        assert_eq!(row["name"], p.name);
        assert_eq!(row["python"], p.python());
        assert_eq!(row["property"], p.property());
        assert_eq!(row["default"], p.default);
        assert!(attributes.contains(&format!("\"name\":\"{}\",\"property\":\"{}\"", p.name, p.property())));
        let attribute = declared["attributes"].as_array().unwrap().iter().find(|a| a["name"] == p.name);
        assert_eq!(attribute.map(|a| a["fieldName"].clone()), Some(Json::String(p.property())), "{}", p.name);
        if p.group != Group::None {
            assert!(control_names().contains(&p.name), "{} has a group but no control", p.name);
            for alias in p.aliases {
                assert_eq!(control(alias), Some(p.name), "controls={alias}");
            }
        }
    }
}
