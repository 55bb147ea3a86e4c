//! One element's declaration, written the same way for both elements: its module in the Custom Elements
//! Manifest and its class and events in TypeScript, from its rows of the parameter table and its
//! author's API (`api.rs` for `<metaballs-view>`, `plane.rs` for `<metaballs-2d>`).

use super::{description, ts_type, typed_default};
use crate::scene::params::{Kind, Parameter};
use serde_json::{Value as Json, json};

/// A name, its TypeScript type or signature, and what it is.
pub(super) type Entry = (&'static str, &'static str, &'static str);

/// What an element declares.
pub(super) struct ElementApi {
    pub class: &'static str,
    pub tag: &'static str,
    pub module: &'static str,
    pub description: &'static str,
    /// Its settings, each an attribute and a property.
    pub parameters: Vec<&'static Parameter>,
    /// Its properties beyond its settings: name, type, whether a page may set it, what it is.
    pub fields: Vec<(&'static str, &'static str, bool, &'static str)>,
    /// Its methods: name, signature after the name, what it does.
    pub methods: &'static [Entry],
    /// Its events: name, the type of `detail`, when.
    pub events: Vec<Entry>,
    /// `::part()` names and what they are.
    pub parts: &'static [(&'static str, &'static str)],
    /// Custom states a page may style (`:state(name)`): name, meaning.
    pub states: &'static [(&'static str, &'static str)],
    /// CSS custom properties: name, default, meaning.
    pub css_properties: &'static [Entry],
}

impl ElementApi {
    /// Its module in the Custom Elements Manifest.
    pub fn module_json(&self) -> Json {
        let declaration = json!({ "name": self.class, "module": self.module });
        let attributes: Vec<Json> = self
            .parameters
            .iter()
            .map(|p| {
                json!({
                    "name": p.name, "fieldName": p.property(), "type": { "text": ts_type(p) },
                    "default": json!(p.default).to_string(), "description": description(p),
                })
            })
            .collect();
        let settings = self.parameters.iter().map(|p| {
            json!({
                "kind": "field", "name": p.property(), "type": { "text": ts_type(p) },
                "default": typed_default(p).to_string(), "attribute": p.name, "description": description(p),
            })
        });
        let fields = self.fields.iter().map(|(name, ty, writable, text)| {
            let mut field =
                json!({ "kind": "field", "name": name, "type": { "text": ty }, "description": text });
            if !writable {
                field["readonly"] = json!(true);
            }
            field
        });
        let methods = self.methods.iter().map(|(name, signature, text)| {
            json!({ "kind": "method", "name": name, "description": text, "signature": signature })
        });
        json!({
            "kind": "javascript-module",
            "path": self.module,
            "declarations": [{
                "kind": "class",
                "name": self.class,
                "tagName": self.tag,
                "customElement": true,
                "description": self.description,
                "superclass": { "name": "HTMLElement" },
                "attributes": attributes,
                "members": settings.chain(fields).chain(methods).collect::<Vec<_>>(),
                "events": self.events.iter().map(|(name, detail, text)| json!({
                    "name": name, "type": { "text": format!("CustomEvent<{detail}>") }, "description": text,
                })).collect::<Vec<_>>(),
                "cssParts": self.parts.iter().map(|(name, text)| json!({ "name": name, "description": text }))
                    .collect::<Vec<_>>(),
                "cssStates": self.states.iter().map(|(name, text)| json!({ "name": name, "description": text }))
                    .collect::<Vec<_>>(),
                "cssProperties": self.css_properties.iter().map(|(name, default, text)| json!({
                    "name": name, "default": default, "description": text,
                })).collect::<Vec<_>>(),
            }],
            "exports": [
                { "kind": "js", "name": self.class, "declaration": declaration },
                { "kind": "custom-element-definition", "name": self.tag, "declaration": declaration },
            ],
        })
    }

    /// Its class, its events' map and its place among the page's elements, in TypeScript.
    pub fn typescript(&self) -> String {
        let mut out = format!("export declare class {} extends HTMLElement {{\n", self.class);
        for p in &self.parameters {
            let doc = format!(
                "  /** {} Attribute `{}`; default {}. */\n",
                description(p),
                p.name,
                typed_default(p)
            );
            if p.kind == Kind::Spheres {
                // Read as the spheres in play; set from the attribute's text or from such a list.
                let name = p.property();
                out += &format!(
                    "{doc}  get {name}(): MetaballsSphere[];\n{doc}  set {name}(value: {});\n",
                    ts_type(p)
                );
            } else {
                out += &format!("{doc}  {}: {};\n", p.property(), ts_type(p));
            }
        }
        for (name, ty, writable, text) in &self.fields {
            let readonly = if *writable { "" } else { "readonly " };
            out += &format!("  /** {text} */\n  {readonly}{name}: {ty};\n");
        }
        for (name, signature, text) in self.methods {
            out += &format!("  /** {text} */\n  {name}{signature};\n");
        }
        out += &format!("}}\n\nexport interface {}EventMap {{\n", self.class);
        for (name, detail, text) in &self.events {
            out += &format!("  /** {text} */\n  '{name}': CustomEvent<{detail}>;\n");
        }
        out + &format!(
            "}}\n\ndeclare global {{\n  interface HTMLElementTagNameMap {{\n    '{}': {};\n  }}\n  \
             interface HTMLElementEventMap extends {}EventMap {{}}\n}}\n",
            self.tag, self.class, self.class
        )
    }
}
