//! A search's result as JSON, the form the page's `criticalPoints()`, the notebook widget and
//! `metaballs critical` all give: the critical points, the merge tree, and the surface's counts in each
//! band between consecutive critical levels.

use super::morse::End;
use super::{Critical, CriticalPoint};
use std::fmt::Write;

/// A finite number as JSON, `null` otherwise (+∞ for a sphere's node).
fn num(v: f64) -> String {
    if v.is_finite() { format!("{v}") } else { "null".into() }
}

fn end(e: End) -> String {
    match e {
        End::Sphere(i) => format!("{{\"sphere\":{i}}}"),
        End::Point(k) => format!("{{\"point\":{k}}}"),
        End::Outside => "\"outside\"".into(),
        End::Lost => "null".into(),
    }
}

fn point(p: &CriticalPoint) -> String {
    let saddle = p.index == 1 || p.index == 2;
    format!(
        "{{\"position\":[{},{},{}],\"value\":{},\"index\":{},\"role\":\"{}\",\"eigenvalues\":[{},{},{}],\"ends\":{},\"inBox\":{}}}",
        num(p.position.x),
        num(p.position.y),
        num(p.position.z),
        num(p.value),
        p.index,
        p.role.word(),
        num(p.eigenvalues[0]),
        num(p.eigenvalues[1]),
        num(p.eigenvalues[2]),
        if saddle { format!("[{},{}]", end(p.ends[0]), end(p.ends[1])) } else { "[]".into() },
        p.in_box
    )
}

/// The result, with `milliseconds` the search took.
pub fn to_json(found: &Critical, milliseconds: f64) -> String {
    let points: Vec<String> = found.points.iter().map(point).collect();
    let tree: Vec<String> = found
        .tree
        .iter()
        .map(|n| {
            format!(
                "{{\"value\":{},\"children\":{:?},\"point\":{},\"spheres\":{:?}}}",
                num(n.value),
                n.children,
                n.point.map_or("null".into(), |k| k.to_string()),
                n.spheres
            )
        })
        .collect();
    // The counts in each band between consecutive levels above zero, from the highest down.
    let levels = if found.counts_unknown().is_some() { vec![] } else { found.levels() };
    let mut bands = String::new();
    let mut above = f64::INFINITY;
    let last = if found.counts_unknown().is_some() { &[][..] } else { &[0.0][..] };
    for (k, &below) in levels.iter().chain(last.iter()).enumerate() {
        let iso = if above.is_finite() { 0.5 * (above + below) } else { below * 2.0 + 1.0 };
        let c = found.counts(iso);
        let _ = write!(
            bands,
            "{}{{\"above\":{},\"below\":{},\"blobs\":{},\"cavities\":{},\"genus\":{},\"surfaces\":{}}}",
            if k > 0 { "," } else { "" },
            num(above),
            num(below),
            c.blobs,
            c.cavities,
            c.genus,
            c.surfaces
        );
        above = below;
    }
    format!(
        "{{\"points\":[{}],\"tree\":[{}],\"bands\":[{bands}],\"complete\":{},\"countsUnknown\":{},\"undecided\":{},\"unresolved\":{},\"pieces\":{},\"reach\":{},\"wallLevel\":{},\"milliseconds\":{}}}",
        points.join(","),
        tree.join(","),
        found.complete,
        found.counts_unknown().map_or("null".into(), |why| format!("\"{why}\"")),
        found.undecided,
        found.unresolved,
        found.pieces,
        num(found.reach),
        num(found.wall_level),
        num(milliseconds)
    )
}
