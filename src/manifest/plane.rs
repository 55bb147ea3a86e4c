//! The 2D figure's part of the manifests: its module's declaration in the Custom Elements Manifest and
//! its TypeScript declarations (`www/metaballs-2d.d.ts`), from its rows (`scene::params::plane`) and its
//! author's API declared here once (`tests/e2e/api.test.js` holds the element to it).

use super::{api, description, ts_type, typed_default};
pub(super) use crate::scene::params::plane::plane_parameters;
use serde_json::{Value as Json, json};

/// The 2D figure's module.
const MODULE: &str = "www/metaballs-2d.js";

/// Its methods: name, signature, what it does.
const METHODS: &[(&str, &str, &str)] = &[
    ("contours", "(): object", "The contour at the iso level as data: rings, saddles, crossings and cases."),
    ("toSVG", "(size?: number): string", "The picture as an SVG document (vector)."),
    (
        "samples",
        "(): { cells: number; values: number[] }",
        "The samples drawn, row by row from the lower left.",
    ),
    ("play", "(): void", "Sets the circles moving."),
    ("pause", "(): void", "Holds the circles still."),
    ("stepTo", "(k: number): void", "Opens the step-through at step k, or moves it there."),
    ("stepForward", "(): void", "One square forward."),
    ("stepBack", "(): void", "One square back."),
    ("nextCrossed", "(): void", "The next square the contour crosses."),
    ("saveScene", "(): string", "The circles and every setting of the picture as a scene document (JSON)."),
    (
        "loadScene",
        "(text: string): void",
        "Loads a scene document; throws with what is wrong, changing nothing.",
    ),
    ("downloadScene", "(): void", "Downloads the scene document."),
    ("showNotice", "(text: string, ms?: number): void", "Shows a short message inside the figure."),
];

/// Its properties beyond its settings: name, TypeScript type, whether a page may set it, what it is.
const FIELDS: &[(&str, &str, bool, &str)] = &[
    ("circleList", "Metaballs2dCircle[]", true, "The circles as placed; set to such a list to place them."),
    (
        "stepIndex",
        "number | null",
        false,
        "The step-through's step (square j · resolution + i), or null when it is off.",
    ),
    (
        "following",
        "HTMLElement | null",
        false,
        "The <metaballs-view> whose slice plane it follows (slice-of), or null.",
    ),
    ("frameMs", "number", false, "The last frame's time to sample, march and paint, in ms."),
];

/// Its events: the 3D figure's change and error events, and the drag of a circle.
fn events() -> Vec<(&'static str, &'static str, &'static str)> {
    let shared =
        api::EVENTS.iter().filter(|(name, ..)| ["metaballs-change", "metaballs-error"].contains(name));
    shared
        .copied()
        .chain([("metaballs-2d-drag", "{ circles: Metaballs2dCircle[] }", "A circle is being dragged.")])
        .collect()
}

/// `www/metaballs-2d.d.ts`: the 2D element's TypeScript declarations.
pub(super) fn declarations() -> String {
    let mut out = String::from(
        "// TypeScript declarations of <metaballs-2d>, written by `metaballs manifest --out www` from the\n\
         // 2D figure's rows and src/manifest/plane.rs. Do not edit: change those and run the command.\n\n\
         export interface Metaballs2dCircle {\n  x: number;\n  y: number;\n  r: number;\n  \
         /** 1 adds the circle's term, -1 subtracts it. */\n  charge?: 1 | -1;\n}\n\n\
         export declare class Metaballs2d extends HTMLElement {\n",
    );
    for p in plane_parameters() {
        out += &format!(
            "  /** {} Attribute `{}`; default {}. */\n  {}: {};\n",
            description(p),
            p.name,
            typed_default(p),
            p.property(),
            ts_type(p)
        );
    }
    for (name, ty, writable, text) in FIELDS {
        let readonly = if *writable { "" } else { "readonly " };
        out += &format!("  /** {text} */\n  {readonly}{name}: {ty};\n");
    }
    for (name, signature, text) in METHODS {
        out += &format!("  /** {text} */\n  {name}{signature};\n");
    }
    out += "}\n\nexport interface Metaballs2dEventMap {\n";
    for (name, detail, text) in events() {
        out += &format!("  /** {text} */\n  '{name}': CustomEvent<{detail}>;\n");
    }
    out += "}\n\ndeclare global {\n  interface HTMLElementTagNameMap {\n    'metaballs-2d': Metaballs2d;\n  }\n}\n";
    out
}

/// The module declaring `<metaballs-2d>`.
pub(super) fn module() -> Json {
    let declaration = json!({ "name": "Metaballs2d", "module": MODULE });
    let attributes: Vec<Json> = plane_parameters()
        .map(|p| {
            json!({
                "name": p.name, "type": { "text": ts_type(p) }, "default": json!(p.default).to_string(),
                "description": description(p),
            })
        })
        .collect();
    let mut members: Vec<Json> = plane_parameters()
        .map(|p| {
            json!({
                "kind": "field", "name": p.property(), "type": { "text": ts_type(p) },
                "default": typed_default(p).to_string(), "attribute": p.name, "description": description(p),
            })
        })
        .collect();
    members.extend(FIELDS.iter().map(|(name, ty, writable, text)| {
        json!({ "kind": "field", "name": name, "type": { "text": ty }, "readonly": !writable, "description": text })
    }));
    members.extend(METHODS.iter().map(|(name, signature, text)| {
        json!({ "kind": "method", "name": name, "description": text, "signature": signature })
    }));
    json!({
        "kind": "javascript-module",
        "path": MODULE,
        "declarations": [{
            "kind": "class",
            "name": "Metaballs2d",
            "tagName": "metaballs-2d",
            "customElement": true,
            "description": "Marching squares over circles in the plane: samples, cases, saddles, contours and \
                            bands, a step-through of the march; drawn on a 2D canvas.",
            "superclass": { "name": "HTMLElement" },
            "attributes": attributes,
            "members": members,
            "events": events().iter().map(|(name, detail, text)| json!({
                "name": name, "type": { "text": format!("CustomEvent<{detail}>") }, "description": text,
            })).collect::<Vec<_>>(),
            "cssParts": [
                { "name": "canvas", "description": "The picture." },
                { "name": "notice", "description": "The notice for a bad value." },
                { "name": "panel", "description": "The folding panel of controls." },
                { "name": "stepper", "description": "The step-through's panel." },
            ],
        }],
        "exports": [
            { "kind": "js", "name": "Metaballs2d", "declaration": declaration },
            { "kind": "custom-element-definition", "name": "metaballs-2d", "declaration": declaration },
        ],
    })
}
