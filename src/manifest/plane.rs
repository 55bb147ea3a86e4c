//! The 2D figure's part of the manifests: its module's declaration in the Custom Elements Manifest,
//! from its rows (`scene::params::plane`).

use super::{description, ts_type};
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
];

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
    let members: Vec<Json> = METHODS
        .iter()
        .map(|(name, signature, text)| {
            json!({ "kind": "method", "name": name, "description": text, "signature": signature })
        })
        .collect();
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
            "events": [{
                "name": "metaballs-change",
                "type": { "text": "CustomEvent<{ attribute: string; value: string | null }>" },
                "description": "A setting changed in the figure (its panel, an edit by hand).",
            }],
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
