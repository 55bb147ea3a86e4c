//! One cell's patch against the topology of the cell's trilinear interpolant (in the manner of Etiene et
//! al. 2012): for every one of the 256 sign patterns, random corner values with those signs, the
//! patch's components and Euler characteristic against those of the interpolant's level set inside
//! the cell, found independently by marching a fine resample of it. A sub-cell of the resample holds
//! the interpolant exactly (a trilinear restricted to a box is trilinear), so its faces are resolved
//! exactly by the decider; cells whose critical values (corners, face saddles, body saddles) lie near
//! the iso level are skipped, so that a sub-cell's interior is unlikely to need a tunnel (the margin is
//! a heuristic: the check is that no class without a tunnel ever differs).
//!
//! MC33 (`table=mc33`: the faces as the decider joins them, and a tunnel where the interior test of
//! `extract::interior` finds the interpolant joining two loops inside the cell) must have the
//! interpolant's components and Euler characteristic in every cell.
//!
//! The asymptotic decider resolves faces only. Its patches must have the interpolant's topology in
//! every class without an interior ambiguity, and wherever the interpolant has no saddle inside the
//! cell; the cells of the classes with one (4, 6, 7, 10, 12, 13: a tunnel through the body saddle can
//! join loops the faces leave apart) that differ are counted.

use metaballs::extract::decider::{decided_triangles, face_choices};
use metaballs::extract::interior::interior_code;
use metaballs::extract::tables::{CORNER_OFFSETS, EDGE_CORNERS};
use metaballs::teach::case_classes::case_classes;
use std::collections::{BTreeMap, BTreeSet};

const ISO: f32 = 1.0;
/// Sub-cells per axis of the resample.
const FINE: u32 = 20;
/// Critical values nearer the iso level than this are skipped.
const MARGIN: f32 = 2e-3;
/// Random cells per sign pattern.
const PER_CASE: usize = 24;

/// Components and Euler characteristic of triangles given as vertex triples.
fn shape(triangles: &[[u64; 3]]) -> (usize, i64) {
    let vertices: BTreeSet<u64> = triangles.iter().flatten().copied().collect();
    let index: BTreeMap<u64, usize> = vertices.iter().enumerate().map(|(i, &v)| (v, i)).collect();
    let mut parent: Vec<usize> = (0..vertices.len()).collect();
    fn root(parent: &mut [usize], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    let mut edges = BTreeSet::new();
    for t in triangles {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            edges.insert((a.min(b), a.max(b)));
            let (ra, rb) = (root(&mut parent, index[&a]), root(&mut parent, index[&b]));
            parent[ra] = rb;
        }
    }
    let components = (0..vertices.len()).filter(|&i| root(&mut parent, i) == i).count();
    (components, vertices.len() as i64 - edges.len() as i64 + triangles.len() as i64)
}

/// The trilinear interpolant of corner values `f` at p in the unit cube.
fn trilinear(f: &[f32; 8], p: [f64; 3]) -> f64 {
    (0..8)
        .map(|c| {
            let o = CORNER_OFFSETS[c];
            let w = |i: usize| if o[i] == 1 { p[i] } else { 1.0 - p[i] };
            f[c] as f64 * w(0) * w(1) * w(2)
        })
        .sum()
}

/// The interpolant's values at the resample's points, in f32 as a mesher reads them.
fn resample(f: &[f32; 8]) -> Vec<f32> {
    let n = FINE + 1;
    let mut values = Vec::with_capacity((n * n * n) as usize);
    for z in 0..n {
        for y in 0..n {
            for x in 0..n {
                values.push(trilinear(f, [x, y, z].map(|i| i as f64 / FINE as f64)) as f32);
            }
        }
    }
    values
}

/// The decider's triangles of every sub-cell of the resample, with vertices named by their edge of the
/// fine grid.
fn fine_patch(f: &[f32; 8]) -> Vec<[u64; 3]> {
    let n = FINE + 1;
    let values = resample(f);
    let at = |p: [u32; 3]| (p[0] + n * (p[1] + n * p[2])) as usize;
    let mut triangles = Vec::new();
    for z in 0..FINE {
        for y in 0..FINE {
            for x in 0..FINE {
                let corner = |c: usize| {
                    let o = CORNER_OFFSETS[c];
                    [x + o[0], y + o[1], z + o[2]]
                };
                let v: [f32; 8] = std::array::from_fn(|c| values[at(corner(c))]);
                let case = (0..8).fold(0, |m, c| m | ((v[c] > ISO) as usize) << c);
                let edge = |e: usize| {
                    let [a, b] = EDGE_CORNERS[e];
                    let (pa, pb) = (corner(a), corner(b));
                    let axis = (0..3).find(|&i| pa[i] != pb[i]).unwrap() as u64;
                    at([0, 1, 2].map(|i| pa[i].min(pb[i]))) as u64 * 3 + axis
                };
                for t in decided_triangles(case, face_choices(case, v, ISO), 0) {
                    triangles.push(t.map(edge));
                }
            }
        }
    }
    triangles
}

/// The values of the interpolant at its critical points: the corners, the saddle of each face's
/// bilinear restriction and the body saddles inside the cell; and whether it has a body saddle there.
fn critical_values(f: &[f32; 8]) -> (Vec<f64>, bool) {
    let v = |x: u32, y: u32, z: u32| f[CORNER_OFFSETS.iter().position(|&o| o == [x, y, z]).unwrap()] as f64;
    let mut values: Vec<f64> = f.iter().map(|&x| x as f64).collect();
    // Faces: the bilinear (a, b, c, d) at (0,0), (1,0), (1,1), (0,1) has its saddle value
    // (ac − bd) / (a + c − b − d) at u = (a − d) / (a + c − b − d)... inside the face.
    let face = |q: [f64; 4]| {
        let [a, b, c, d] = q;
        let den = a + c - b - d;
        if den.abs() < 1e-12 {
            return None;
        }
        let (u, w) = ((a - d) / den, (a - b) / den);
        ((0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&w)).then(|| (a * c - b * d) / den)
    };
    for s in 0..2 {
        values.extend(face([v(s, 0, 0), v(s, 1, 0), v(s, 1, 1), v(s, 0, 1)]));
        values.extend(face([v(0, s, 0), v(0, s, 1), v(1, s, 1), v(1, s, 0)]));
        values.extend(face([v(0, 0, s), v(1, 0, s), v(1, 1, s), v(0, 1, s)]));
    }
    let faces_and_corners = values.len();
    values.extend(body_saddles(f).iter().map(|&p| trilinear(f, p)));
    let body = values.len() > faces_and_corners;
    (values, body)
}

/// The interpolant's polynomial coefficients: F = a + bx + cy + dz + e xy + g xz + k yz + h xyz, as
/// [a, b, c, d, e, g, k, h].
fn coefficients(f: &[f32; 8]) -> [f64; 8] {
    let v = |x: u32, y: u32, z: u32| f[CORNER_OFFSETS.iter().position(|&o| o == [x, y, z]).unwrap()] as f64;
    let a = v(0, 0, 0);
    let (b, c, d) = (v(1, 0, 0) - a, v(0, 1, 0) - a, v(0, 0, 1) - a);
    let e = v(1, 1, 0) - v(1, 0, 0) - v(0, 1, 0) + a;
    let g = v(1, 0, 1) - v(1, 0, 0) - v(0, 0, 1) + a;
    let k = v(0, 1, 1) - v(0, 1, 0) - v(0, 0, 1) + a;
    let h = v(1, 1, 1) - v(1, 1, 0) - v(1, 0, 1) - v(0, 1, 1) + v(1, 0, 0) + v(0, 1, 0) + v(0, 0, 1) - a;
    [a, b, c, d, e, g, k, h]
}

/// The interpolant's critical points inside the cell (at most two).
fn body_saddles(f: &[f32; 8]) -> Vec<[f64; 3]> {
    let [_, b, c, d, e, g, k, h] = coefficients(f);
    let mut points = Vec::new();
    if h.abs() > 1e-9 {
        // About the centre (−k/h, −g/h, −e/h) the quadratic terms vanish: F = h XYZ + αX + βY + γZ + δ.
        let [x, y, z] = [-k / h, -g / h, -e / h];
        let (alpha, beta, gamma) =
            (b + e * y + g * z + h * y * z, c + e * x + k * z + h * x * z, d + k * y + g * x + h * x * y);
        let square = -beta * gamma / (alpha * h);
        if alpha.abs() > 1e-12 && square > 0.0 {
            for sign in [-1.0, 1.0] {
                let big_x = sign * square.sqrt();
                let p = [x + big_x, y - gamma / (h * big_x), z - beta / (h * big_x)];
                if p.iter().all(|t| (0.0..=1.0).contains(t)) {
                    points.push(p);
                }
            }
        }
    }
    points
}

struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f32 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 40) as f32 / (1u64 << 24) as f32
    }
}

#[test]
fn the_deciders_patch_has_the_interpolants_topology_where_no_tunnel_can_change_it() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let classes = case_classes();
    // Per class: cells compared, and cells whose topology differs.
    let mut tally = [(0usize, 0usize); 15];
    let mut skipped = 0;
    for (case, &class) in classes.iter().enumerate().take(255).skip(1) {
        let mut done = 0;
        while done < PER_CASE {
            // Inside corners in (1, 2], outside ones in [0, 1).
            let f: [f32; 8] = std::array::from_fn(|c| {
                let r = rng.next();
                if case >> c & 1 == 1 { ISO + (1.0 - r).max(1e-3) } else { ISO * r }
            });
            let (critical, body_saddle) = critical_values(&f);
            if critical.iter().any(|&v| (v - ISO as f64).abs() < MARGIN as f64) {
                skipped += 1;
                continue;
            }
            done += 1;
            let patch: Vec<[u64; 3]> =
                decided_triangles(case, face_choices(case, f, ISO), 0).map(|t| t.map(|e| e as u64)).collect();
            let ours = shape(&patch);
            let interpolant = shape(&fine_patch(&f));
            let class = class as usize;
            tally[class].0 += 1;
            if ours != interpolant {
                tally[class].1 += 1;
                // Only a body saddle can join through the interior what the faces leave apart.
                assert!(
                    body_saddle && [4, 6, 7, 10, 12, 13].contains(&class),
                    "case {case} (class {class}), corners {f:?}: the decider's patch has {ours:?} \
                     (components, χ), the interpolant {interpolant:?}"
                );
            }
        }
    }
    let differing: usize = tally.iter().map(|t| t.1).sum();
    eprintln!(
        "cells per class (compared, differing): {:?}; {skipped} skipped near a critical value",
        tally.iter().enumerate().filter(|(_, t)| t.0 > 0).collect::<Vec<_>>()
    );
    // The interior can matter: the comparison is not blind to tunnels.
    assert!(differing > 0, "no cell needs a tunnel: {tally:?}");
}

/// Every sign pattern with corner values drawn two ways: within one of the level (inside in (1, 2],
/// outside in [0, 1)), and spread from 0.01 to 100 away from it on either side.
#[test]
fn the_mc33_patch_has_the_interpolants_topology_in_every_cell() {
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let (mut compared, mut wrong, mut tunnels) = (0, Vec::new(), 0);
    for (case, spread) in (1..255usize).flat_map(|case| [(case, false), (case, true)]) {
        let mut done = 0;
        while done < PER_CASE {
            let f: [f32; 8] = std::array::from_fn(|c| {
                let r = rng.next();
                let inside = case >> c & 1 == 1;
                match (spread, inside) {
                    (false, true) => ISO + (1.0 - r).max(1e-3),
                    (false, false) => ISO * r,
                    (true, side) => ISO + if side { 1.0 } else { -1.0 } * 10f32.powf(4.0 * r - 2.0),
                }
            });
            if critical_values(&f).0.iter().any(|&v| (v - ISO as f64).abs() < MARGIN as f64) {
                continue;
            }
            done += 1;
            compared += 1;
            let (joined, code) = (face_choices(case, f, ISO), interior_code(f, ISO));
            let patch: Vec<[u64; 3]> =
                decided_triangles(case, joined, code).map(|t| t.map(|e| e as u64)).collect();
            let (ours, interpolant) = (shape(&patch), shape(&fine_patch(&f)));
            // A sheet with h holes has χ = 2 − h: disks give χ = components.
            tunnels += (ours.0 as i64 - ours.1) as usize;
            if ours != interpolant {
                wrong.push((case, f, ours, interpolant));
            }
        }
    }
    eprintln!("{compared} cells, {tunnels} of them with a tunnel");
    assert!(wrong.is_empty(), "{} of {compared} cells: {:?}", wrong.len(), &wrong[..wrong.len().min(6)]);
    assert!(tunnels > 0, "the cells hold tunnels");
}

/// MC33's 33 configurations (`teach::subcases`), each met in every case of its class (every rotation,
/// and with inside and outside swapped) and held there to the interpolant. The published corrections
/// to MC33's tables (Custodio et al. 2013; Vega et al. 2019) concern exactly this: configurations
/// triangulated with the wrong topology in some orientations, and an interior test that missed tunnels
/// in some. Here every sampled cell's choices must be one of the 33, and each of its class's
/// configurations must turn up, away from critical values, with the interpolant's components and χ.
#[test]
fn every_mc33_configuration_occurs_in_every_case_of_its_class_with_the_interpolants_topology() {
    use metaballs::extract::decider::has_tunnel;
    use metaballs::teach::subcases::{SUBCASES, subcase_of};
    const TRIES: usize = 400_000;
    let mut rng = Rng(0x6a09_e667_f3bc_c908);
    let mut checked = 0;
    for case in 1..255usize {
        let class = case_classes()[case];
        let mut missing: Vec<&str> = SUBCASES.iter().filter(|s| s.class == class).map(|s| s.name).collect();
        for k in 0..TRIES {
            if missing.is_empty() {
                break;
            }
            // Three spreads of values: within one of the level, cubed towards it, and 0.01 to 100 away.
            let f: [f32; 8] = std::array::from_fn(|c| {
                let r = rng.next();
                let inside = case >> c & 1 == 1;
                let away = match k % 3 {
                    0 => 1.0 - r,
                    1 => r * r * r * 4.0,
                    _ => 10f32.powf(4.0 * r - 2.0),
                }
                .clamp(1e-3, if inside { 100.0 } else { 0.999 });
                if inside { ISO + away } else { ISO - away }
            });
            let (joined, code) = (face_choices(case, f, ISO), interior_code(f, ISO));
            let tunnel = has_tunnel(case, joined, code);
            let Some(subcase) = subcase_of(case as u8, joined, tunnel) else {
                panic!("case {case}, corners {f:?}: faces {joined:06b}, tunnel {tunnel}: not one of the 33");
            };
            let at = missing.iter().position(|&name| name == subcase.name);
            if at.is_none() || critical_values(&f).0.iter().any(|&v| (v - ISO as f64).abs() < MARGIN as f64) {
                continue;
            }
            let patch: Vec<[u64; 3]> =
                decided_triangles(case, joined, code).map(|t| t.map(|e| e as u64)).collect();
            let (ours, interpolant) = (shape(&patch), shape(&fine_patch(&f)));
            assert_eq!(ours, interpolant, "{} in case {case}, corners {f:?}: (components, χ)", subcase.name);
            missing.remove(at.unwrap());
            checked += 1;
        }
        assert!(missing.is_empty(), "case {case} (class {class}): {missing:?} not met in {TRIES} cells");
    }
    eprintln!("{checked} configurations checked over 254 cases");
}
