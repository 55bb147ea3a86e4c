//! The teaching views from the page: every view option by name, the cell inspector (pick, select,
//! report) and the case gallery's data.

use super::{View, js_error};
use crate::extract::kernel::Terms;
use crate::extract::reference::Construction;
use crate::extract::tables::{CORNER_OFFSETS, EDGE_CORNERS};
use crate::scene::params::view::Interpolation;
use crate::teach::case_classes::{CLASS_NAMES, CLASS_REPRESENTATIVES, case_classes};
use crate::teach::error::error_at;
use crate::teach::inspect::CellReport;
use crate::teach::subcases::{SUBCASES, subcase_triangles};
use glam::UVec3;
use wasm_bindgen::prelude::*;

fn set(object: &js_sys::Object, key: &str, value: JsValue) {
    let _ = js_sys::Reflect::set(object, &key.into(), &value);
}

fn numbers<T: Into<JsValue> + Copy>(values: &[T]) -> JsValue {
    values.iter().map(|&v| v.into()).collect::<js_sys::Array>().into()
}

/// Triangles as edge numbers, wound as drawn.
fn edge_triangles(triangles: impl Iterator<Item = [usize; 3]>) -> JsValue {
    triangles.map(|t| numbers(&[t[0] as u32, t[2] as u32, t[1] as u32])).collect::<js_sys::Array>().into()
}

fn report_object(report: &CellReport) -> JsValue {
    let object = js_sys::Object::new();
    set(&object, "cell", numbers(&report.cell.to_array()));
    set(&object, "corners", numbers(&report.corners));
    set(&object, "case", report.case.into());
    set(&object, "bits", format!("{:08b}", report.case).into());
    set(&object, "class", report.class.into());
    set(&object, "className", CLASS_NAMES[report.class as usize].into());
    let (triangles, faces) = (js_sys::Array::new(), js_sys::Array::new());
    for t in &report.triangles {
        triangles.push(&numbers(t));
    }
    for f in &report.faces {
        let face = js_sys::Object::new();
        set(&face, "face", f.face.into());
        set(&face, "saddle", f.saddle.map_or(JsValue::NULL, JsValue::from));
        set(&face, "deciderJoins", f.decider_joins.into());
        set(&face, "joined", f.joined.into());
        faces.push(&face);
    }
    set(&object, "triangles", triangles.into());
    set(&object, "faces", faces.into());
    let interior: Vec<u8> = (0..8).filter(|c| report.interior >> c & 1 == 1).collect();
    set(&object, "interior", numbers(&interior));
    set(&object, "tunnel", report.tunnel.into());
    set(&object, "subcase", report.subcase.into());
    set(&object, "drawnSubcase", report.drawn_subcase.into());
    let edges: js_sys::Array = report
        .edges
        .iter()
        .map(|e| {
            let edge = js_sys::Object::new();
            set(&edge, "edge", e.edge.into());
            set(&edge, "t", e.t.into());
            set(&edge, "vertex", numbers(&e.vertex.to_array()));
            JsValue::from(edge)
        })
        .collect();
    set(&object, "edges", edges.into());
    object.into()
}

/// The 15 classes of cases for the gallery: number, name, representative case, its inside corners, how
/// many of the 256 cases fall in it and which, and its configurations under
/// MC33 (`teach::subcases`): name, triangles, how many of the ambiguous faces they join, and whether a
/// tunnel joins two loops inside.
#[wasm_bindgen]
pub fn case_gallery() -> js_sys::Array {
    let classes = case_classes();
    CLASS_REPRESENTATIVES
        .iter()
        .enumerate()
        .map(|(k, &case)| {
            let object = js_sys::Object::new();
            set(&object, "class", (k as u32).into());
            set(&object, "name", CLASS_NAMES[k].into());
            set(&object, "case", case.into());
            let inside: Vec<u32> = (0..8).filter(|c| case >> c & 1 == 1).collect();
            set(&object, "inside", numbers(&inside));
            let members: Vec<u32> = (0..256).filter(|&c| classes[c as usize] as usize == k).collect();
            set(&object, "cases", (members.len() as u32).into());
            set(&object, "members", numbers(&members));
            let subcases: js_sys::Array = SUBCASES
                .iter()
                .filter(|s| s.class as usize == k)
                .map(|s| {
                    let (triangles, joined, ambiguous) = subcase_triangles(s);
                    let subcase = js_sys::Object::new();
                    set(&subcase, "name", s.name.into());
                    set(&subcase, "triangles", edge_triangles(triangles.into_iter()));
                    set(&subcase, "joined", joined.into());
                    set(&subcase, "ambiguous", ambiguous.into());
                    set(&subcase, "tunnel", s.tunnel.into());
                    JsValue::from(subcase)
                })
                .collect();
            set(&object, "subcases", subcases.into());
            JsValue::from(object)
        })
        .collect()
}

/// A cell's corners (offsets from its lowest corner) and edges (pairs of corners), numbered as the
/// case table numbers them.
#[wasm_bindgen]
pub fn cube_geometry() -> js_sys::Object {
    let object = js_sys::Object::new();
    let corners: js_sys::Array = CORNER_OFFSETS.iter().map(|c| numbers(c)).collect();
    let edges: js_sys::Array = EDGE_CORNERS.iter().map(|e| numbers(&e.map(|c| c as u32))).collect();
    set(&object, "corners", corners.into());
    set(&object, "edges", edges.into());
    object
}

#[wasm_bindgen]
impl View {
    /// Sets any renderer setting by its name in the parameter table (or an older spelling), from
    /// text; throws with what is accepted and keeps the previous value.
    pub fn set_parameter(&mut self, name: &str, text: &str) -> Result<(), JsError> {
        self.renderer.set_parameter(name, text).map_err(js_error)
    }

    /// Sets several renderer settings at once (`names[i]` from `texts[i]`), checked together, as the
    /// resolution and level of detail must be: all or nothing.
    pub fn set_parameters(&mut self, names: Vec<String>, texts: Vec<String>) -> Result<(), JsError> {
        if names.len() != texts.len() {
            return Err(JsError::new("set_parameters takes as many texts as names"));
        }
        let pairs: Vec<(&str, &str)> =
            names.iter().map(String::as_str).zip(texts.iter().map(String::as_str)).collect();
        self.renderer.set_parameters(&pairs).map_err(js_error)
    }

    /// Sets the background's gradient from the page's colours (`#rrggbb` top and bottom, as the
    /// element's CSS custom properties give them); empty text for either goes back to the theme's.
    pub fn set_background(&mut self, top: &str, bottom: &str) -> Result<(), JsError> {
        let color = |text: &str| -> Result<Option<[f32; 3]>, JsError> {
            if text.trim().is_empty() {
                return Ok(None);
            }
            match crate::scene::params::parse_parameter("color", text).map_err(js_error)? {
                crate::scene::params::Value::Text(hex) => {
                    Ok(Some(crate::scene::params::srgb_hex_to_linear(&hex).to_array()))
                }
                _ => Ok(None),
            }
        };
        let mut settings = *self.renderer.settings();
        settings.view.background = match (color(top)?, color(bottom)?) {
            (Some(top), Some(bottom)) => Some([top, bottom]),
            (Some(top), None) => Some([top, settings.view.theme.background()[1]]),
            (None, Some(bottom)) => Some([settings.view.theme.background()[0], bottom]),
            (None, None) => None,
        };
        self.renderer.set_settings(settings).map_err(js_error)
    }

    /// Selects the cell under canvas pixel (`x`, `y`) (device pixels from the top left), or nothing
    /// over the background; returns the cell's report, or null.
    pub fn pick_cell(&mut self, x: f32, y: f32) -> JsValue {
        let cell = self.renderer.pick(x, y);
        self.renderer.select_cell(cell);
        self.inspect()
    }

    /// Selects cell (`x`, `y`, `z`); returns its report, or null when it is outside the grid.
    pub fn select_cell(&mut self, x: u32, y: u32, z: u32) -> JsValue {
        self.renderer.select_cell(Some(UVec3::new(x, y, z)));
        self.inspect()
    }

    /// The first cell after (`x`, `y`, `z`) in the march's order (x fastest, then y, then z) that the
    /// surface crosses now, as [x, y, z]; none when no later cell is crossed.
    pub fn next_crossed_cell(&self, x: u32, y: u32, z: u32) -> Option<Vec<u32>> {
        let cell = self.renderer.next_crossed(Some(UVec3::new(x, y, z)))?;
        Some(cell.to_array().to_vec())
    }

    /// Deselects the cell.
    pub fn clear_selection(&mut self) {
        self.renderer.select_cell(None);
    }

    /// What marching cubes decides in the selected cell now (it changes as the spheres move), or null.
    pub fn inspect(&self) -> JsValue {
        match self.renderer.selected_cell() {
            Some(cell) => report_object(&self.renderer.inspect(cell)),
            None => JsValue::NULL,
        }
    }
}

#[wasm_bindgen]
impl View {
    /// One point of the "error vs resolution" plot for the current spheres, iso level and blend: the
    /// mesh at `cells_per_axis` on the CPU, with `midpoint` or linear placement. Returns `[RMS error,
    /// largest error (box half-widths), triangles]`. The page calls it between frames, one resolution
    /// at a time.
    pub fn error_at(&self, cells_per_axis: u32, midpoint: bool) -> Result<Vec<f64>, JsError> {
        crate::scene::params::check_resolution(cells_per_axis).map_err(js_error)?;
        let settings = self.renderer.settings();
        let interpolation = if midpoint { Interpolation::Midpoint } else { Interpolation::Linear };
        let construction = Construction {
            interpolation,
            terms: Terms::of(&settings.view),
            case_table: settings.view.case_table,
            ..Construction::default()
        };
        let p = error_at(self.renderer.scene().spheres(), settings.iso, construction, cells_per_axis);
        Ok(vec![p.rms, p.max, p.triangles as f64])
    }
}

/// The least-squares slope of log `ys` against log `xs` (the order the error plot reads off), or
/// nothing with fewer than two usable points.
#[wasm_bindgen]
pub fn fitted_slope(xs: Vec<f64>, ys: Vec<f64>) -> Option<f64> {
    let points: Vec<(f64, f64)> = xs.into_iter().zip(ys).collect();
    crate::teach::error::fitted_slope(&points)
}
