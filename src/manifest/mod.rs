//! The element's description, written from the parameter table so attributes, their types and their
//! defaults never drift: the table the element's module reads before its wasm arrives
//! (`www/lib/attributes.js`), the Custom Elements Manifest editors read (`www/custom-elements.json`),
//! and the TypeScript declarations (`www/metaballs-view.d.ts`). `metaballs manifest --out www` writes
//! them, and the same for the 2D figure (`plane.rs`); a test checks that the files in the repository
//! are what it writes.

pub use crate::scene::params::table::property_name;
use crate::scene::params::{
    ACTIONS, Kind, PARAMETERS, ParamError, Parameter, Value, control_names, parameter,
};
use crate::scene::sphere::RADIUS_RANGE;
use element::ElementApi;
use metaballs_scene::decimal::num;
use serde_json::{Value as Json, json};

mod api;
mod element;
mod plane;
mod vectors;

pub use api::{CSS_PROPERTIES, EVENTS, METHODS, PARTS, READ_ONLY, STATES};

/// The element's module inside the package.
const MODULE: &str = "www/metaballs-view.js";

fn kind_word(kind: Kind) -> &'static str {
    match kind {
        Kind::Integer => "integer",
        Kind::Number => "number",
        Kind::Boolean => "boolean",
        Kind::Color => "color",
        Kind::Choice(_) => "choice",
        Kind::List(..) | Kind::Controls => "list",
        Kind::Levels => "levels",
        Kind::Slice => "slice",
        Kind::Cell => "cell",
        Kind::Spheres => "spheres",
        Kind::Text => "text",
    }
}

/// The TypeScript type of a parameter's property.
fn ts_type(p: &Parameter) -> String {
    match p.kind {
        Kind::Integer | Kind::Number => "number".into(),
        Kind::Boolean => "boolean".into(),
        Kind::Choice(words) => words.iter().map(|w| format!("'{w}'")).collect::<Vec<_>>().join(" | "),
        Kind::Spheres => "string | MetaballsSphere[]".into(),
        _ => "string".into(),
    }
}

/// A number as the table means it: whole numbers without a fraction, the others at f32 precision
/// (`0.05`, not `0.05000000074505806`).
fn number(x: f64) -> Json {
    if x.fract() == 0.0 && x.abs() < 1e15 {
        json!(x as i64)
    } else {
        json!(metaballs_scene::number::parse_f64(&num(x as f32).to_string()).unwrap_or(x))
    }
}

/// A parameter's default, typed as its property holds it.
fn typed_default(p: &Parameter) -> Json {
    match p.parse(p.default).expect("every default parses") {
        Value::Number(n) => number(n),
        Value::Boolean(b) => json!(b),
        Value::Text(t) => json!(t),
    }
}

/// What a parameter is, in one sentence for editors.
fn description(p: &Parameter) -> String {
    let noun = if p.noun.is_empty() { p.name } else { p.noun };
    let noun = noun[..1].to_ascii_uppercase() + &noun[1..];
    match p.kind {
        Kind::Integer | Kind::Number => format!("{noun}: {} to {}.", number(p.min), number(p.max)),
        Kind::Choice(words) => format!("{noun}: {}.", words.join(", ")),
        Kind::List(..) | Kind::Controls => {
            format!("{noun}: all, none, or a comma list of {}.", p.words().join(", "))
        }
        Kind::Levels => {
            format!("{noun}s: a comma list of numbers from {} to {}.", number(p.min), number(p.max))
        }
        Kind::Boolean => format!("{noun}: a boolean attribute."),
        Kind::Color => format!("{noun}: #rrggbb."),
        Kind::Slice => format!("{noun}: off, or an axis and a position in the box (z:0.25)."),
        Kind::Cell => format!(
            "{noun}: off, or a cell of the grid x,y,z (3,4,5): the step-through of marching cubes there."
        ),
        Kind::Spheres => {
            format!("{noun}: x,y,z,radius[,vx,vy,vz] per sphere joined by ; (a negative radius subtracts).")
        }
        Kind::Text => match p.name {
            "alt" => "The figure's accessible name (without it, one is made from what it shows).".into(),
            "poster" => {
                "An image URL shown before the first frame and in print until a frame is drawn.".into()
            }
            "sync" => "A group name: the figures of a page with the same one share their spheres, \
                       animation time and camera (the first on the page leads)."
                .into(),
            "circles" => "The circles, x,y,r per circle joined by ; (a negative r subtracts); without it, \
                          `spheres` circles from `seed`."
                .into(),
            "march" => "The step-through of the march, open at a square i,j or a step (off: closed).".into(),
            "slice-of" => {
                "The id of a <metaballs-view> with a slice: its slice plane is drawn instead of circles."
                    .into()
            }
            _ => format!("{noun}."),
        },
    }
}

/// The parameter table's rows: the attribute, property and Python names, the short name in links,
/// the older spellings still accepted, label, kind, accepted words, range, slider, default as text
/// and as a value, panel group, who holds it, and whether its control needs compute shaders.
fn rows() -> Vec<Json> {
    PARAMETERS.iter().map(row_json).collect()
}

fn row_json(p: &Parameter) -> Json {
    let mut row = json!({
        "name": p.name, "property": p.property(), "python": p.python(), "url": p.link_name(),
        "aliases": p.aliases, "label": p.label, "kind": kind_word(p.kind), "words": p.words(),
        "min": number(p.min), "max": number(p.max), "sliderMin": number(p.slider.0),
        "sliderMax": number(p.slider.1), "step": number(p.slider.2), "default": p.default,
        "value": typed_default(p), "group": p.group.title(), "scope": p.scope.word(),
        "compute": p.compute, "scene": p.in_scene, "noun": p.noun,
    });
    let aliases = word_aliases(p);
    if aliases.as_object().is_some_and(|a| !a.is_empty()) {
        row["wordAliases"] = aliases;
    }
    row
}

/// The older or shorter spellings a list's words may be given by, each with the word it reads as:
/// for the controls, every other name of a setting with a control and the actions' older names.
fn word_aliases(p: &Parameter) -> Json {
    let pairs: Vec<(&str, &str)> = match p.kind {
        Kind::List(_, older) => older.to_vec(),
        Kind::Controls => PARAMETERS
            .iter()
            .filter(|q| q.group != crate::scene::params::Group::None)
            .flat_map(|q| q.names().filter(move |n| *n != q.name).map(move |n| (n, q.name)))
            .chain(ACTIONS.iter().flat_map(|a| a.aliases.iter().map(move |o| (*o, a.name))))
            .collect(),
        _ => Vec::new(),
    };
    Json::Object(pairs.into_iter().map(|(old, new)| (old.to_string(), json!(new))).collect())
}

/// The panel's controls in order: each setting with a group, and the actions.
fn controls() -> Vec<Json> {
    control_names()
        .into_iter()
        .map(|name| match parameter(name) {
            Some(p) => json!({ "name": name, "label": p.label, "group": p.group.title(), "parameter": true }),
            None => {
                let a = ACTIONS.iter().find(|a| a.name == name).expect("a control is a setting or an action");
                json!({ "name": name, "aliases": a.aliases, "label": a.label, "group": a.group.title(), "parameter": false })
            }
        })
        .collect()
}

/// Ranges the page needs that are not settings: the sphere radii the scene accepts.
fn limits() -> Json {
    json!({ "radius": [number(RADIUS_RANGE.0.into()), number(RADIUS_RANGE.1.into())] })
}

/// What a parameter's errors call it and what they say it accepts (`None` where the accepted text has no
/// one description: free text, slices and sphere lists, checked by the figure itself).
fn expected(p: &Parameter) -> Option<String> {
    match p.kind {
        Kind::Text | Kind::Slice | Kind::Cell | Kind::Spheres => None,
        _ => match p.parse("?") {
            Err(ParamError::Invalid { expected, .. }) => Some(expected.to_string()),
            _ => None,
        },
    }
}

/// `parameters.json`: the table's rows, with each one's description and the words its errors use (the
/// noun and what is accepted), for tools outside a page (the notebook widget's traits).
pub fn parameters_json() -> String {
    described(PARAMETERS.iter())
}

/// Rows of `parameters` with their descriptions and the words their errors use, as JSON text.
fn described<'a>(parameters: impl Iterator<Item = &'a Parameter>) -> String {
    let rows: Vec<Json> = parameters
        .map(|p| {
            let mut row = row_json(p);
            row["description"] = json!(description(p));
            row["expected"] = json!(expected(p));
            row
        })
        .collect();
    serde_json::to_string_pretty(&rows).expect("the table is JSON") + "\n"
}

/// `www/lib/attributes.js`: the parameter table as the element reads it before its wasm arrives.
pub fn attributes_js() -> String {
    // Table rows on lines of their own, two spaces in; the controls four, so the two read apart.
    let lines = |items: Vec<Json>, indent: &str| {
        items.iter().map(|item| format!("{indent}{item},")).collect::<Vec<_>>().join("\n")
    };
    format!(
        "// The parameter table (scene/src/params/rows.rs), written by `metaballs manifest --out www`.\n\
         // Each row: attribute, property and Python names, short name in links, older spellings, label,\n\
         // kind, accepted words, range, slider, default as text and as a value, panel group, who holds\n\
         // it (creation, renderer, element), whether its control needs compute shaders, whether a scene\n\
         // file holds it. Do not edit: change the table and run the command.\n\n\
         export const TABLE = Object.freeze([\n{}\n]);\n\n\
         // The panel's controls in order: the settings with a group, and the actions.\n\
         export const CONTROLS = Object.freeze([\n{}\n]);\n\n\
         // Ranges that are not settings, for gestures and the sphere editor.\n\
         export const LIMITS = Object.freeze({});\n\n\
         // The 2D figure's settings (scene/src/params/plane.rs): the rows it shares, then its own.\n\
         export const PLANE_TABLE = Object.freeze([\n{}\n]);\n\n\
         // The package's version (the crate's), which the share box pins its script tags to.\n\
         export const VERSION = {:?};\n",
        lines(rows(), "  "),
        lines(controls(), "    "),
        limits(),
        lines(plane::plane_parameters().map(row_json).collect(), "  "),
        env!("CARGO_PKG_VERSION"),
    )
}

/// `<metaballs-view>`'s declaration: its rows and its author's API (`api.rs`).
fn view_api() -> ElementApi {
    ElementApi {
        class: "MetaballsView",
        tag: "metaballs-view",
        module: MODULE,
        description: "Merging spheres drawn with marching cubes in WebGPU compute shaders (WebGL2 and a CPU \
                      mesher where WebGPU is missing), with teaching views.",
        parameters: PARAMETERS.iter().collect(),
        fields: READ_ONLY.iter().map(|&(name, ty, text)| (name, ty, false, text)).collect(),
        methods: METHODS,
        events: EVENTS.to_vec(),
        parts: PARTS,
        states: STATES,
        css_properties: CSS_PROPERTIES,
    }
}

/// `www/custom-elements.json`: the Custom Elements Manifest (both elements).
pub fn custom_elements_json() -> String {
    let manifest = json!({
        "schemaVersion": "2.1.0",
        "readme": "README.md",
        "modules": [view_api().module_json(), plane::api().module_json()],
    });
    serde_json::to_string_pretty(&manifest).expect("the manifest is JSON") + "\n"
}

/// What both elements' `shareText()` returns and `record()` takes (the 2D figure's names begin with
/// `Metaballs2d`).
pub(super) const SHARE_TEXT: &str = concat!(
    "/** The figure as it is now, written to paste (`shareText()`). */\n\
     export interface MetaballsShareText {\n  /** The module's script tag and the element with its attributes. */\n  html: string;\n  \
     /** The iframe page's URL. */\n  url: string;\n  /** An iframe of that page at the size the figure was seen at. */\n  iframe: string;\n  \
     /** The notebook widget's call. */\n  python: string;\n  /** MyST's {anywidget} directive. */\n  myst: string;\n  \
     /** The full page's link. */\n  link: string;\n}\n\n",
    "/** What `record()` makes (every field optional). */\n\
     export interface MetaballsRecordOptions {\n  /** Seconds of animation (default 4). */\n  seconds?: number;\n  \
     /** 24, 30 or 60 (default 30). */\n  fps?: 24 | 30 | 60;\n  /** Pixels (default the figure's size, even). */\n  \
     width?: number;\n  height?: number;\n  /** 'webm-vp9', 'webm-vp8', 'mp4-h264' or 'gif' (default the first the browser writes). */\n  \
     format?: string;\n  /** Called after each frame. */\n  onProgress?: (done: number, count: number) => void;\n  \
     /** Aborting it stops the recording: the promise rejects with an AbortError. */\n  signal?: AbortSignal;\n}\n\n",
);

/// The declarations of the words' exports, in both elements' modules (docs/embedding.md, "Languages").
pub(crate) const TRANSLATION: &str = "/** A message: a text with `{field}` placeholders, or plural forms chosen by its `count` field. */\n\
     export type MetaballsMessage =\n  | string\n  \
     | { zero?: string; one?: string; two?: string; few?: string; many?: string; other: string };\n\n\
     /** Adds a language (a tag such as 'nl'), or overrides words of one, for every figure on the page. */\n\
     export declare function registerTranslation(lang: string, messages: Record<string, MetaballsMessage>): void;\n\n\
     /** Every English message by its key: what a translation gives. */\n\
     export declare const englishWords: Readonly<Record<string, MetaballsMessage>>;\n\n";

/// `www/metaballs-view.d.ts`: the element's TypeScript declarations.
pub fn declarations() -> String {
    let out = String::from(
        "// TypeScript declarations of <metaballs-view>, written by `metaballs manifest --out www` from the\n\
         // parameter table. Do not edit: change the table (or src/manifest/mod.rs) and run the command.\n\n\
         export interface MetaballsStats {\n  triangles: number;\n  fps: number;\n  frameTime: number;\n  \
         adapter: string;\n  mesher: string;\n  overflowed: boolean;\n  [name: string]: unknown;\n}\n\n\
         export interface MetaballsSphere {\n  center: [number, number, number];\n  radius: number;\n  \
         velocity: [number, number, number];\n  /** 1 adds the sphere's term, -1 subtracts it. */\n  charge: 1 | -1;\n}\n\n\
         /** The cell inspector's report (see docs/teaching.md). */\n\
         export type MetaballsCellReport = Record<string, unknown>;\n\n\
         /** A critical point of the field (see docs/teaching.md, \"Along the iso level\"). */\n\
         export interface MetaballsCriticalPoint {\n  position: [number, number, number];\n  value: number;\n  \
         index: 0 | 1 | 2 | 3;\n  role: 'join' | 'loop' | 'hole' | 'cavity' | 'fill' | 'birth' | 'unresolved';\n  \
         eigenvalues: [number, number, number];\n  ends: unknown[];\n  inBox: boolean;\n}\n\n\
         /** The surface's shape (`topology()`). */\n\
         export interface MetaballsTopology {\n  components: number;\n  genus: number;\n  closed: boolean;\n  manifold: boolean;\n}\n\n\
         export interface MetaballsLevelCounts {\n  blobs: number;\n  cavities: number;\n  genus: number;\n  surfaces: number;\n}\n\n\
         export interface MetaballsCriticalPoints {\n  points: MetaballsCriticalPoint[];\n  \
         tree: { value: number | null; children: number[]; point: number | null; spheres: number[] }[];\n  \
         bands: (MetaballsLevelCounts & { above: number | null; below: number })[];\n  complete: boolean;\n  \
         undecided: number;\n  wallLevel: number;\n  milliseconds: number;\n  iso: number;\n  counts: MetaballsLevelCounts | null;\n}\n\n",
    ) + SHARE_TEXT
        + TRANSLATION;
    out + &view_api().typescript()
}

/// Every file the command writes, by path under `www/`.
pub fn files() -> Vec<(&'static str, String)> {
    vec![
        ("lib/attributes.js", attributes_js()),
        ("parameters.json", parameters_json()),
        ("plane-parameters.json", described(plane::plane_parameters())),
        ("custom-elements.json", custom_elements_json()),
        ("metaballs-view.d.ts", declarations()),
        ("metaballs-2d.d.ts", plane::declarations()),
        ("parameter-vectors.json", vectors::vectors_json()),
    ]
}
