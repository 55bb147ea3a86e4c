//! The parameter table: every setting a person can give, declared once, in the panel's order. A row
//! names the setting (and the older spellings still accepted), bounds it, gives its default, its
//! label, its panel group, who holds it and, for the renderer's settings, where it lives in
//! [`Settings`]. Adding a setting is a row here and the code that uses its value.

use super::table::{Action, Field, Group, Kind, Parameter, Value, number, row};
use super::view::{
    Blend, CaseTable, ColorBy, Compare, Display, GridView, Interpolation, Kernel, LIGHT_KINDS, Lights, March,
    MeshOn, Method, Projection, Saddle, Slice, Split, Theme,
};
use super::{MAX_RESOLUTION, MAX_SPHERES, MIN_RESOLUTION, linear_to_srgb_hex, srgb_hex_to_linear};
use super::{ParamError, ViewOptions};
use Group::{Camera, Display as Look, Light, Scene, Surface, Teaching};

/// A view option chosen among words.
macro_rules! word {
    ($field:ident: $ty:ty) => {
        Field::View {
            set: |o, v| o.$field = <$ty>::from_word(v.text()).unwrap_or_default(),
            get: |o| Value::word(o.$field.word()),
        }
    };
}

/// A view option that is on or off.
macro_rules! flag {
    ($field:ident) => {
        Field::View { set: |o, v| o.$field = v.flag(), get: |o| Value::Boolean(o.$field) }
    };
}

/// A number among the view options (`view: spot_angle`) or the settings (`material.shininess`).
macro_rules! real {
    (view: $field:ident) => {
        Field::View { set: |o, v| o.$field = v.number(), get: |o| Value::of_f32(o.$field) }
    };
    ($($path:ident).+) => {
        Field::Settings { set: |s, v| s.$($path).+ = v.number(), get: |s| Value::of_f32(s.$($path).+) }
    };
}

/// A whole number among the settings.
macro_rules! whole {
    ($field:ident: $ty:ty) => {
        Field::Settings { set: |s, v| s.$field = v.whole() as $ty, get: |s| Value::Number(s.$field as f64) }
    };
}

/// Every parameter, in panel order (each group's controls in the order shown).
pub const PARAMETERS: &[Parameter] = &[
    // Surface
    number("spheres", "Spheres", "sphere count", (1.0, MAX_SPHERES as f64), "5")
        .whole()
        .group(Surface)
        .page_only()
        .creation(whole!(sphere_count: u32)),
    number("iso", "Iso level", "iso level", (0.05, 20.0), "1")
        .slider(0.1, 4.0, 0.01)
        .group(Surface)
        .creation(real!(iso)),
    number(
        "resolution",
        "Resolution",
        "resolution (cells per axis)",
        (MIN_RESOLUTION as f64, MAX_RESOLUTION as f64),
        "64",
    )
    .whole()
    .url("res")
    .group(Surface)
    .creation(whole!(resolution: u32)),
    row("lod", "Level of detail", Kind::Boolean, "false").group(Surface).renderer(flag!(lod)),
    number("lod-pixels", "LOD cell size", "LOD cell size (pixels)", (0.25, 32.0), "2")
        .slider(0.5, 8.0, 0.25)
        .url("lod_px")
        .aliases(&["lod_pixels"])
        .group(Surface)
        .renderer(real!(view: lod_pixels)),
    row("lod-freeze", "Freeze LOD", Kind::Boolean, "false")
        .aliases(&["lod_freeze"])
        .group(Surface)
        .renderer(flag!(lod_freeze)),
    row("mesh-on", "Mesh on", Kind::Choice(MeshOn::WORDS), "auto")
        .aliases(&["mesher"])
        .group(Surface)
        .compute()
        .renderer(word!(mesh_on: MeshOn)),
    row("method", "Method", Kind::Choice(Method::WORDS), "marching_cubes")
        .aliases(&["extractor"])
        .group(Surface)
        .renderer(word!(method: Method)),
    row("split", "Tetrahedra", Kind::Choice(Split::WORDS), "six")
        .group(Surface)
        .renderer(word!(split: Split)),
    number("speed", "Speed", "animation speed", (0.0, 3.0), "1").slider(0.0, 3.0, 0.05).group(Surface),
    number("seed", "Layout", "layout seed", (0.0, u32::MAX as f64), "1")
        .whole()
        .slider(0.0, 0.0, 0.0)
        .group(Surface)
        .creation(whole!(seed: u64)),
    row("paused", "Paused", Kind::Boolean, "false").group(Surface),
    row("pause-on", "Pause on", Kind::Choice(&["none", "merge"]), "none")
        .aliases(&["pause_on"])
        .group(Surface)
        .page_only(),
    // Display
    row("display", "Display", Kind::Choice(Display::WORDS), "shaded")
        .group(Look)
        .compute()
        .renderer(word!(display: Display)),
    row("compare", "Exact surface", Kind::Choice(Compare::WORDS), "none")
        .group(Look)
        .compute()
        .renderer(word!(compare: Compare)),
    row("grid", "Grid", Kind::Choice(GridView::WORDS), "none")
        .group(Look)
        .compute()
        .renderer(word!(grid: GridView)),
    row("color-by", "Colour by", Kind::Choice(ColorBy::WORDS), "none")
        .aliases(&["color_by"])
        .group(Look)
        .compute()
        .renderer(word!(color_by: ColorBy)),
    row("ambiguous", "Ambiguous", Kind::Boolean, "false").group(Look).compute().renderer(flag!(ambiguous)),
    row("critical", "Critical points", Kind::Boolean, "false").group(Look).page_only(),
    row("color", "Colour", Kind::Color, "#e77661").group(Look).renderer(Field::Settings {
        set: |s, v| s.material.base_color = srgb_hex_to_linear(v.text()),
        get: |s| Value::Text(linear_to_srgb_hex(s.material.base_color)),
    }),
    row("theme", "Theme", Kind::Choice(Theme::WORDS), "dark")
        .group(Look)
        .page_only()
        .renderer(word!(theme: Theme)),
    row("antialiasing", "Antialiasing", Kind::Boolean, "true").url("aa").group(Look).creation(
        Field::Settings { set: |s, v| s.antialiasing = v.flag(), get: |s| Value::Boolean(s.antialiasing) },
    ),
    // Teaching
    row("slice", "Field slice", Kind::Slice, "off").group(Teaching).compute().renderer(Field::View {
        set: |o, v| o.slice = Slice::parse(v.text()).ok().flatten(),
        get: |o| Value::Text(Slice::text(o.slice)),
    }),
    row("interpolation", "Vertices", Kind::Choice(Interpolation::WORDS), "linear")
        .url("interp")
        .group(Teaching)
        .renderer(word!(interpolation: Interpolation)),
    row("table", "Case table", Kind::Choice(CaseTable::WORDS), "classic")
        .group(Teaching)
        .renderer(word!(case_table: CaseTable)),
    row("blend", "Blend", Kind::Choice(Blend::WORDS), "sum").group(Teaching).renderer(word!(blend: Blend)),
    row("kernel", "Kernel", Kind::Choice(Kernel::WORDS), "inverse_square")
        .group(Teaching)
        .renderer(word!(kernel: Kernel)),
    number("blobbiness", "Blobbiness", "blobbiness", (0.25, 8.0), "2")
        .slider(0.25, 8.0, 0.25)
        .group(Teaching)
        .renderer(real!(view: blobbiness)),
    row("saddle", "Saddles", Kind::Choice(Saddle::WORDS), "table")
        .group(Teaching)
        .compute()
        .renderer(word!(saddle: Saddle)),
    row("levels", "Along the iso level", Kind::Boolean, "false").group(Teaching).page_only(),
    // Light
    row("light", "Lights", Kind::List(LIGHT_KINDS, &[]), "point").group(Light).renderer(Field::View {
        set: |o, v| o.lights = Lights::from_list(v.text()),
        get: |o| Value::Text(o.lights.text()),
    }),
    number("spot-angle", "Spot cone", "spot cone angle (degrees)", (2.0, 80.0), "15")
        .slider(5.0, 60.0, 1.0)
        .aliases(&["spot_angle"])
        .group(Light)
        .renderer(real!(view: spot_angle)),
    number("spot-softness", "Spot edge", "spot softness", (0.0, 1.0), "0.3")
        .slider(0.0, 1.0, 0.05)
        .url("spot_soft")
        .aliases(&["spot_softness"])
        .group(Light)
        .renderer(real!(view: spot_softness)),
    number("ambient", "Ambient", "ambient strength", (0.0, 1.0), "0.15")
        .group(Light)
        .renderer(real!(material.ambient)),
    number("diffuse", "Diffuse", "diffuse strength", (0.0, 2.0), "0.85")
        .group(Light)
        .renderer(real!(material.diffuse)),
    number("specular", "Specular", "specular strength", (0.0, 2.0), "0.6")
        .group(Light)
        .renderer(real!(material.specular)),
    number("shininess", "Shininess", "shininess", (1.0, 1024.0), "64")
        .slider(1.0, 256.0, 1.0)
        .url("shine")
        .group(Light)
        .renderer(real!(material.shininess)),
    // Camera
    row("projection", "Projection", Kind::Choice(Projection::WORDS), "perspective")
        .url("proj")
        .group(Camera)
        .renderer(word!(projection: Projection)),
    number("fov", "Field of view", "field of view (degrees)", (10.0, 120.0), "45")
        .slider(20.0, 100.0, 1.0)
        .group(Camera)
        .renderer(real!(camera.fov_y_degrees)),
    // Scene
    row("edit", "Edit spheres", Kind::Boolean, "false").group(Scene).page_only(),
    // Given by attribute, link or gesture, not by a control of the panel.
    number("yaw", "Yaw", "camera yaw (degrees)", (-360.0, 360.0), "30")
        .slider(-180.0, 180.0, 1.0)
        .renderer(real!(camera.yaw_degrees)),
    number("pitch", "Pitch", "camera pitch (degrees)", (-89.0, 89.0), "20")
        .slider(-89.0, 89.0, 1.0)
        .renderer(real!(camera.pitch_degrees)),
    number("distance", "Distance", "camera distance", (1.5, 20.0), "4.3")
        .slider(1.5, 20.0, 0.1)
        .url("dist")
        .renderer(real!(camera.distance)),
    row("march", "March at cell", Kind::Cell, "off").page_only().renderer(Field::View {
        set: |o, v| o.march = March::parse(v.text()).ok().flatten(),
        get: |o| Value::Text(March::text(o.march)),
    }),
    number("divider", "Divider", "divider position", (0.05, 0.95), "0.5").renderer(real!(view: divider)),
    row("sphere-list", "Spheres", Kind::Spheres, "").aliases(&["balls"]).page_only(),
    row("controls", "Controls", Kind::Controls, "none").page_only(),
    row("hud", "Statistics", Kind::Choice(&["on", "off"]), "off").page_only(),
    row("autoplay", "Autoplay", Kind::Choice(&["visible", "off"]), "visible").page_only(),
    number("max-pixel-ratio", "Pixel ratio", "max-pixel-ratio", (0.25, 4.0), "2")
        .slider(0.25, 4.0, 0.25)
        .url("max_pixel_ratio")
        .page_only(),
    number("min-render-scale", "Lowest render scale", "min-render-scale", (0.25, 1.0), "0.5")
        .slider(0.25, 1.0, 0.05)
        .url("min_render_scale")
        .page_only(),
    number("max-lod-pixels", "Largest LOD cell", "largest LOD cell size (pixels)", (0.25, 64.0), "16")
        .slider(0.5, 32.0, 0.25)
        .url("max_lod_px")
        .page_only(),
    row("alt", "Description", Kind::Text, "").page_only(),
    row("poster", "Poster", Kind::Text, "").page_only(),
    row("sync", "Sync group", Kind::Text, "").page_only(),
];

/// The panel's controls that are not settings, each shown after its group's settings.
pub const ACTIONS: &[Action] = &[
    Action { name: "step", aliases: &[], label: "Step", group: Surface },
    Action { name: "view", aliases: &[], label: "Reset view", group: Surface },
    Action { name: "inspector", aliases: &[], label: "Cell inspector", group: Teaching },
    Action { name: "step-through", aliases: &[], label: "Step through the march", group: Teaching },
    Action { name: "error-plot", aliases: &["error_plot"], label: "Error vs resolution", group: Teaching },
    Action { name: "scene", aliases: &[], label: "Scene file", group: Scene },
    Action { name: "export", aliases: &[], label: "Export", group: Scene },
    Action { name: "share", aliases: &[], label: "Share", group: Scene },
];

/// A parameter by its name, its short name in links or one of its aliases.
pub fn parameter(name: &str) -> Option<&'static Parameter> {
    parameter_named(name).map(|(p, _)| p)
}

/// A parameter and the spelling of it that `name` is (for messages that quote the name given).
pub fn parameter_named(name: &str) -> Option<(&'static Parameter, &'static str)> {
    PARAMETERS.iter().find_map(|p| p.names().find(|n| *n == name).map(|n| (p, n)))
}

/// Every control the `controls` attribute can list, in the panel's order: each group's settings in
/// table order, then its actions.
pub fn control_names() -> Vec<&'static str> {
    let mut names = Vec::new();
    for group in Group::PANEL {
        names.extend(PARAMETERS.iter().filter(|p| p.group == group).map(|p| p.name));
        names.extend(ACTIONS.iter().filter(|a| a.group == group).map(|a| a.name));
    }
    names
}

/// A control's canonical name from any of its names.
pub fn control(name: &str) -> Option<&'static str> {
    let setting = parameter(name).filter(|p| p.group != Group::None).map(|p| p.name);
    setting.or_else(|| ACTIONS.iter().find(|a| a.name == name || a.aliases.contains(&name)).map(|a| a.name))
}

/// Refusal of a name that no row of the table answers to. It names the rows that start with the same
/// letter (a misspelling usually keeps its first), not all of them: the table outgrows a notice.
pub(super) fn unknown(name: &str) -> ParamError {
    let first = name.chars().next().map(|c| c.to_ascii_lowercase());
    let alike: Vec<&str> =
        PARAMETERS.iter().map(|p| p.name).filter(|n| first.is_some_and(|c| n.starts_with(c))).collect();
    let all = format!("one of the table's {} names (docs/embedding.md lists them", PARAMETERS.len());
    let expected = match first {
        Some(c) if !alike.is_empty() => format!("{all}; those starting with {c:?}: {})", alike.join(", ")),
        _ => format!("{all}: spheres, iso, resolution, …)"),
    };
    ParamError::Invalid { name: "parameter name", value: name.to_string(), expected: expected.into() }
}

impl Parameter {
    /// The words it accepts (choices and lists).
    pub fn words(&self) -> Vec<&'static str> {
        match self.kind {
            Kind::Choice(words) | Kind::List(words, _) => words.to_vec(),
            Kind::Controls => control_names(),
            _ => Vec::new(),
        }
    }
}

impl ViewOptions {
    /// Sets the option `name` (any of its names in the parameter table) from a value, checked as its
    /// row says; `Ok(false)` when `name` is not one of these options.
    pub fn set(&mut self, name: &str, value: &Value) -> Result<bool, ParamError> {
        match parameter(name).map(|p| (p, p.field)) {
            Some((p, Some(Field::View { set, .. }))) => {
                set(self, &p.check(value)?);
                Ok(true)
            }
            _ => Ok(false),
        }
    }
}
