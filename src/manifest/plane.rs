//! The 2D figure's part of the manifests: its module's declaration in the Custom Elements Manifest and
//! its TypeScript declarations (`www/metaballs-2d.d.ts`), from its rows (`scene::params::plane`) and its
//! author's API declared here once (`tests/e2e/api.test.js` holds the element to it).

use super::api;
use super::element::{ElementApi, Entry};
pub(super) use crate::scene::params::plane::plane_parameters;

/// The 2D figure's module.
const MODULE: &str = "www/metaballs-2d.js";

/// Its methods: name, signature, what it does.
const METHODS: &[Entry] = &[
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
    (
        "shareText",
        "(): Metaballs2dShareText",
        "The figure as it is now, written to paste: its HTML, the iframe page's URL and an iframe, the Python widget's call, a MyST directive and the full page's link.",
    ),
    (
        "makePoster",
        "(scale?: number): Promise<Blob>",
        "A PNG of the picture at the figure's size times `scale`.",
    ),
    (
        "record",
        "(options?: Metaballs2dRecordOptions): Promise<Blob>",
        "A clip of the circles moving, its frames 1/fps of animation apart: WebM, MP4 or GIF.",
    ),
    ("openShare", "(): void", "Opens the share box."),
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
fn events() -> Vec<Entry> {
    let shared =
        api::EVENTS.iter().filter(|(name, ..)| ["metaballs-change", "metaballs-error"].contains(name));
    shared
        .copied()
        .chain([("metaballs-2d-drag", "{ circles: Metaballs2dCircle[] }", "A circle is being dragged.")])
        .collect()
}

/// `<metaballs-2d>`'s declaration: its rows and its author's API.
pub(super) fn api() -> ElementApi {
    ElementApi {
        class: "Metaballs2d",
        tag: "metaballs-2d",
        module: MODULE,
        description: "Marching squares over circles in the plane: samples, cases, saddles, contours and bands, \
                      a step-through of the march; drawn on a 2D canvas.",
        parameters: plane_parameters().collect(),
        fields: FIELDS.to_vec(),
        methods: METHODS,
        events: events(),
        parts: &[
            ("canvas", "The picture."),
            ("notice", "The notice for a bad value."),
            ("panel", "The folding panel of controls."),
            ("stepper", "The step-through's panel."),
        ],
        states: &[
            ("stacked", "Narrower than 520 CSS px: the step-through is below the picture, not beside it."),
            ("compact", "Narrower than 440 CSS px: the panel is at most 55 % of the picture's height."),
        ],
        css_properties: &[],
    }
}

/// `www/metaballs-2d.d.ts`: the 2D element's TypeScript declarations.
pub(super) fn declarations() -> String {
    String::from(
        "// TypeScript declarations of <metaballs-2d>, written by `metaballs manifest --out www` from the\n\
         // 2D figure's rows and src/manifest/plane.rs. Do not edit: change those and run the command.\n\n\
         export interface Metaballs2dCircle {\n  x: number;\n  y: number;\n  r: number;\n  \
         /** 1 adds the circle's term, -1 subtracts it. */\n  charge?: 1 | -1;\n}\n\n",
    ) + super::SHARE_TEXT
        .replace("MetaballsShareText", "Metaballs2dShareText")
        .replace("MetaballsRecordOptions", "Metaballs2dRecordOptions")
        .as_str()
        + super::TRANSLATION
        + &api().typescript()
}
