//! What a row of the parameter table says about a setting. The rows themselves, and finding a row by
//! any of its names, are in `rows.rs`: each setting is declared there once, and everything else (the
//! typed defaults, validation, dispatch by name, the panel's groups, the manifest, the element's table,
//! the Python traits) is read from it. How each kind of text is read is in `parse.rs`.

use super::Settings;
use super::view::ViewOptions;
use crate::decimal::num;

/// How a parameter's text is read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// A whole number, written in decimal digits.
    Integer,
    /// A decimal number.
    Number,
    /// `1`, `true`, `on`, `yes` or empty (an HTML boolean attribute), or `0`, `false`, `off`, `no`.
    Boolean,
    /// `#rrggbb`.
    Color,
    /// One of a fixed list of words.
    Choice(&'static [&'static str]),
    /// `all`, `none`, or a comma list of words from a fixed list; the pairs are older spellings of
    /// words, read as the word (`levels` → `iso-levels`).
    List(&'static [&'static str], &'static [(&'static str, &'static str)]),
    /// Empty (none), or a comma list of numbers each in the row's range (`0.5, 1.5`), held as the
    /// list of their shortest decimals.
    Levels,
    /// `all`, `none`, or a comma list of the panel's controls ([`control_names`]), by any of their names.
    Controls,
    /// `off`, or an axis and a position in the box: `z:0.25`.
    Slice,
    /// `off`, or a cell of the grid `x,y,z` (whole numbers).
    Cell,
    /// Empty (the seeded layout), or spheres written `x,y,z,radius[,vx,vy,vz]` joined by `;` (a negative
    /// radius: a subtracting sphere).
    Spheres,
    /// Any text, kept as written (a description, a URL).
    Text,
}

/// The panel's folding groups, in the panel's order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Group {
    /// Not a control of the panel (set by attribute, link or gesture).
    None,
    Surface,
    Display,
    Teaching,
    Light,
    Camera,
    Scene,
}

impl Group {
    /// The groups that hold controls, in the panel's order.
    pub const PANEL: [Group; 6] =
        [Group::Surface, Group::Display, Group::Teaching, Group::Light, Group::Camera, Group::Scene];

    /// The group's heading in the panel (empty for `None`).
    pub fn title(self) -> &'static str {
        match self {
            Group::None => "",
            Group::Surface => "Surface",
            Group::Display => "Display",
            Group::Teaching => "Teaching",
            Group::Light => "Light",
            Group::Camera => "Camera",
            Group::Scene => "Scene",
        }
    }
}

/// Who holds a parameter's value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scope {
    /// A setting of the renderer that it takes when it is made.
    Creation,
    /// A setting of the renderer, changed on a running one.
    Renderer,
    /// The element alone (its animation, its layout on the page, its description).
    Element,
}

impl Scope {
    /// Its word in the element's table.
    pub fn word(self) -> &'static str {
        match self {
            Scope::Creation => "creation",
            Scope::Renderer => "renderer",
            Scope::Element => "element",
        }
    }
}

/// Where a renderer setting lives in [`Settings`]: how a checked value is put there and read back.
#[derive(Clone, Copy)]
pub enum Field {
    /// A field of the settings themselves (the grid, the material, the camera).
    Settings { set: fn(&mut Settings, &Value), get: fn(&Settings) -> Value },
    /// One of the [`ViewOptions`] (display, overlays, lights, construction).
    View { set: fn(&mut ViewOptions, &Value), get: fn(&ViewOptions) -> Value },
}

impl std::fmt::Debug for Field {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(match self {
            Field::Settings { .. } => "Field::Settings",
            Field::View { .. } => "Field::View",
        })
    }
}

impl Field {
    /// Puts `value` (already checked) into `settings`.
    pub fn set(&self, settings: &mut Settings, value: &Value) {
        match self {
            Field::Settings { set, .. } => set(settings, value),
            Field::View { set, .. } => set(&mut settings.view, value),
        }
    }

    /// The value `settings` hold.
    pub fn get(&self, settings: &Settings) -> Value {
        match self {
            Field::Settings { get, .. } => get(settings),
            Field::View { get, .. } => get(&settings.view),
        }
    }
}

/// One parameter a person can set: from a link, an element attribute, a control, a scene file or a
/// notebook. This row is the one place that names, bounds and defaults it.
#[derive(Clone, Copy, Debug)]
pub struct Parameter {
    /// The attribute (kebab-case, as HTML names attributes): `color-by`. Its property is the same in
    /// camel case (`colorBy`, [`Parameter::property`]), its Python trait in snake case.
    pub name: &'static str,
    /// Other spellings accepted wherever the name is (links, attributes, scene files): the names
    /// pages and saved links already use.
    pub aliases: &'static [&'static str],
    /// Short name in a link's query string (`res`) where it is not an older spelling; empty: links
    /// use the first older spelling, else the name ([`Parameter::link_name`]). Every name works there.
    pub url: &'static str,
    /// Label in the panel.
    pub label: &'static str,
    /// Name in messages ("resolution (cells per axis)"); empty: the name the value was given by.
    pub noun: &'static str,
    pub kind: Kind,
    /// Accepted range (numbers only).
    pub min: f64,
    pub max: f64,
    /// Range and step of the panel's slider (numbers only): a comfortable part of what is accepted.
    pub slider: (f64, f64, f64),
    /// Value when not given, as text.
    pub default: &'static str,
    /// The panel's group its control sits in.
    pub group: Group,
    pub scope: Scope,
    /// Its control needs compute shaders (a view drawn from the compute passes' buffers, or the
    /// choice of where to mesh): shown disabled where the browser has only WebGL2.
    pub compute: bool,
    /// A scene document saves and restores it (not the page's layout of the figure).
    pub in_scene: bool,
    /// Where the renderer keeps it (renderer settings only).
    pub field: Option<Field>,
}

impl PartialEq for Parameter {
    fn eq(&self, other: &Self) -> bool {
        self.name == other.name
    }
}

/// A row that holds text in the element alone; the builder methods below add the rest.
pub(super) const fn row(
    name: &'static str,
    label: &'static str,
    kind: Kind,
    default: &'static str,
) -> Parameter {
    Parameter {
        name,
        aliases: &[],
        url: "",
        label,
        noun: "",
        kind,
        min: 0.0,
        max: 0.0,
        slider: (0.0, 0.0, 0.0),
        default,
        group: Group::None,
        scope: Scope::Element,
        compute: false,
        in_scene: true,
        field: None,
    }
}

/// A number's row: its noun in messages and its accepted range (the slider spans it unless told).
pub(super) const fn number(
    name: &'static str,
    label: &'static str,
    noun: &'static str,
    (min, max): (f64, f64),
    default: &'static str,
) -> Parameter {
    Parameter { noun, min, max, slider: (min, max, 0.01), ..row(name, label, Kind::Number, default) }
}

impl Parameter {
    pub(super) const fn whole(self) -> Self {
        Parameter { kind: Kind::Integer, slider: (self.slider.0, self.slider.1, 1.0), ..self }
    }
    pub(super) const fn kind(self, kind: Kind) -> Self {
        Parameter { kind, ..self }
    }
    pub(super) const fn url(self, url: &'static str) -> Self {
        Parameter { url, ..self }
    }
    pub(super) const fn aliases(self, aliases: &'static [&'static str]) -> Self {
        Parameter { aliases, ..self }
    }
    pub(super) const fn slider(self, min: f64, max: f64, step: f64) -> Self {
        Parameter { slider: (min, max, step), ..self }
    }
    pub(super) const fn group(self, group: Group) -> Self {
        Parameter { group, ..self }
    }
    pub(super) const fn compute(self) -> Self {
        Parameter { compute: true, ..self }
    }
    pub(super) const fn page_only(self) -> Self {
        Parameter { in_scene: false, ..self }
    }
    pub(super) const fn renderer(self, field: Field) -> Self {
        Parameter { scope: Scope::Renderer, field: Some(field), ..self }
    }
    pub(super) const fn creation(self, field: Field) -> Self {
        Parameter { scope: Scope::Creation, field: Some(field), ..self }
    }

    /// The property's name: dashes become camel case (`max-pixel-ratio` → `maxPixelRatio`).
    pub fn property(&self) -> String {
        property_name(self.name)
    }

    /// The Python trait's name: dashes become underscores (`color-by` → `color_by`).
    pub fn python(&self) -> String {
        self.name.replace('-', "_")
    }

    /// Every name it answers to: its name, its short name in links and its aliases.
    pub fn names(&self) -> impl Iterator<Item = &'static str> + use<> {
        [self.name, self.url].into_iter().filter(|n| !n.is_empty()).chain(self.aliases.iter().copied())
    }

    /// The name links write: the short name, else the first older spelling (so links read as they
    /// always have), else the name.
    pub fn link_name(&self) -> &'static str {
        match (self.url, self.aliases.first()) {
            ("", Some(old)) => old,
            ("", None) => self.name,
            (url, _) => url,
        }
    }
}

/// A property's name from an attribute's: dashes become camel case (`max-pixel-ratio` → `maxPixelRatio`).
pub fn property_name(name: &str) -> String {
    let mut out = String::new();
    let mut upper = false;
    for c in name.chars() {
        if c == '-' {
            upper = true;
        } else if upper {
            out.push(c.to_ascii_uppercase());
            upper = false;
        } else {
            out.push(c);
        }
    }
    out
}

/// A control of the panel that is not a setting: a button or a view of its own.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Action {
    pub name: &'static str,
    pub aliases: &'static [&'static str],
    pub label: &'static str,
    pub group: Group,
}

/// A parameter's value, read from text.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Number(f64),
    Boolean(bool),
    /// A colour as `#rrggbb` (lower case), a choice, or a normalised list (`all`, `none` or names).
    Text(String),
}

impl Value {
    /// An f32 as the table holds numbers: its shortest decimal, so that it reads back as itself.
    pub fn of_f32(x: f32) -> Value {
        let read = || crate::number::parse_f64(&num(x).to_string());
        Value::Number(crate::decimal::shortest_as_f64(x).or_else(read).unwrap_or(f64::from(x)))
    }

    /// A word or other text.
    pub fn word(word: &str) -> Value {
        Value::Text(word.to_string())
    }

    /// The number (NaN for other kinds).
    pub fn number(&self) -> f32 {
        match self {
            Value::Number(n) => *n as f32,
            _ => f32::NAN,
        }
    }

    /// The whole number (0 for other kinds).
    pub fn whole(&self) -> u64 {
        match self {
            Value::Number(n) => *n as u64,
            _ => 0,
        }
    }

    /// True for `Boolean(true)`.
    pub fn flag(&self) -> bool {
        matches!(self, Value::Boolean(true))
    }

    /// The text (empty for other kinds).
    pub fn text(&self) -> &str {
        match self {
            Value::Text(t) => t,
            _ => "",
        }
    }

    /// The value as a link or an attribute writes it.
    pub fn to_text(&self) -> String {
        match self {
            Value::Number(n) => num(*n).to_string(),
            Value::Boolean(b) => b.to_string(),
            Value::Text(t) => t.clone(),
        }
    }
}
