//! The cell's interior resolved, as Chernyaev's MC33 resolves it: a tunnel through the cell joins two
//! loops that the faces leave apart where the trilinear interpolant joins them inside the cell.
//!
//! The trilinear interpolant F has no squared terms, so it has no maximum or minimum inside the cell:
//! every inside or outside region reaches a corner, and the interior can only join regions at a body
//! saddle. The horizontal slice through a body saddle is a bilinear whose own saddle it is, so the
//! slice's values on the four vertical edges tell which edges the saddle joins. Where those edges are
//! A (corners 0–4), B (1–5), C (2–6) and D (3–7), each linear in the height t, a tunnel joining A and C
//! needs A·C − B·D > 0 at some height between two where it is not; that product is a quadratic in t,
//! so its vertex t* (inside the cell) is the slice to look at. This is the interior test of Lewiner et
//! al. (2003) and Vega et al. (2019), applied to every cell rather than chosen per case. It needs no
//! square root, and a cell whose interpolant has no xyz term (so no body saddle) needs no special
//! handling.
//!
//! What the test finds is a code: 0 for no join, else 1 + 2·pair + side, where pair 0 joins the
//! corners among 0, 2, 4, 6 and pair 1 those among 1, 3, 5, 7, on the inside (side 0) or the outside
//! (side 1). The join changes the triangles only where it makes one sheet of two loops: those two
//! loops are then joined by a band of triangles (`band`) instead of being filled one by one.

/// Codes a cell's interior can have (`interior_code`).
pub const INTERIOR_CODES: usize = 5;

/// The interior's join for a cell with corner values `values` (corner order) at level `iso`: 0 for
/// none, else 1 + 2·pair + side (see the module's text). Computed in the same order, in `f32`, in
/// `shaders/extract/field.wgsl`.
pub fn interior_code(values: [f32; 8], iso: f32) -> u32 {
    let u = values.map(|v| v - iso);
    let (da, db, dc, dd) = (u[4] - u[0], u[5] - u[1], u[6] - u[2], u[7] - u[3]);
    // A(t)·C(t) − B(t)·D(t) = qa t² + qb t + qc.
    let qa = da * dc - db * dd;
    let qb = (u[0] * dc + u[2] * da) - (u[1] * dd + u[3] * db);
    // The vertex t* = −qb / (2 qa) inside (0, 1), decided without the division (which a GPU may
    // round differently): −qb and 2 qa of one sign, and |qb| < |2 qa|.
    let w = 2.0 * qa;
    if !((-qb > 0.0) == (w > 0.0) && qb != 0.0 && qb.abs() < w.abs()) {
        return 0;
    }
    let t = -qb / w;
    let (a, b, c, d) = (u[0] + da * t, u[1] + db * t, u[2] + dc * t, u[3] + dd * t);
    let (ac, bd) = (a * c, b * d);
    if ac > bd && ac > 0.0 {
        1 + (a <= 0.0) as u32
    } else if bd > ac && bd > 0.0 {
        3 + (b <= 0.0) as u32
    } else {
        0
    }
}

/// The corners (bit per corner) that interior code `code` joins in a cell of case `case`.
pub fn joined_corners(case: usize, code: u32) -> u8 {
    if code == 0 {
        return 0;
    }
    let pair = [0x55u8, 0xaa][((code - 1) / 2) as usize];
    let inside = case as u8;
    pair & if (code - 1).is_multiple_of(2) { inside } else { !inside }
}

/// Groups of corners (a root per corner, union-find on eight) joined along the cube's edges between
/// corners of one sign and across each ambiguous face's decided diagonal: its inside corners where
/// `joined` has the face's bit, else its outside ones; then all the corners in `interior`.
fn groups(case: usize, joined: u8, interior: u8) -> ([usize; 8], [usize; 8]) {
    use super::tables::{EDGE_CORNERS, FACE_CORNERS};
    let inside = |c: usize| (case >> c) & 1 == 1;
    let mut parent = [0, 1, 2, 3, 4, 5, 6, 7];
    fn root(parent: &[usize; 8], mut c: usize) -> usize {
        while parent[c] != c {
            c = parent[c];
        }
        c
    }
    let join = |parent: &mut [usize; 8], a: usize, b: usize| {
        let (ra, rb) = (root(parent, a), root(parent, b));
        parent[ra] = rb;
    };
    for [a, b] in EDGE_CORNERS {
        if inside(a) == inside(b) {
            join(&mut parent, a, b);
        }
    }
    for (face, c) in FACE_CORNERS.iter().enumerate() {
        if inside(c[0]) == inside(c[2]) && inside(c[1]) == inside(c[3]) && inside(c[0]) != inside(c[1]) {
            // The diagonal of the sign that is joined across the face.
            let join_inside = joined & (1 << face) != 0;
            let [a, b] = if inside(c[0]) == join_inside { [c[0], c[2]] } else { [c[1], c[3]] };
            join(&mut parent, a, b);
        }
    }
    let patches = std::array::from_fn(|c| root(&parent, c));
    let mut first = None;
    for c in (0..8).filter(|&c| interior & (1 << c) != 0) {
        match first {
            None => first = Some(c),
            Some(f) => join(&mut parent, f, c),
        }
    }
    (patches, std::array::from_fn(|c| root(&parent, c)))
}

/// Of the loops `rings` (crossed edges in order) of a cell of case `case` with face choices `joined`,
/// the two that the interior's join `interior` (corners) makes one sheet, if any: the two loops whose
/// inside and outside patches become the same two regions.
pub fn tunnel(case: usize, joined: u8, interior: u8, rings: &[&[usize]]) -> Option<(usize, usize)> {
    use super::tables::EDGE_CORNERS;
    if interior == 0 {
        return None;
    }
    let (patches, regions) = groups(case, joined, interior);
    // Each loop's (inside, outside) corner across its first edge.
    let sides = |ring: &[usize]| {
        let [a, b] = EDGE_CORNERS[ring[0]];
        if (case >> a) & 1 == 1 { (a, b) } else { (b, a) }
    };
    for i in 0..rings.len() {
        for j in i + 1..rings.len() {
            let ((ai, ao), (bi, bo)) = (sides(rings[i]), sides(rings[j]));
            let same_sheet = regions[ai] == regions[bi] && regions[ao] == regions[bo];
            let same_loop_pair = patches[ai] == patches[bi] && patches[ao] == patches[bo];
            if same_sheet && !same_loop_pair {
                return Some((i, j));
            }
        }
    }
    None
}

/// Joins the loops `a` and `b` (crossed edges, each in the order its fill would wind it) with a band
/// of triangles, one word each like `decider::triangulate`'s: walking `a` forward and `b` backward
/// from some rung, the walk with the fewest triangles lying in a face of the cell (a neighbour may draw
/// on that face too), then the shortest rungs between edge midpoints.
pub fn band(a: &[usize], b: &[usize], out: &mut Vec<u32>) {
    use super::tables::{CORNER_OFFSETS, EDGE_CORNERS, FACE_CORNERS};
    let mid = |e: usize| {
        let [p, q] = EDGE_CORNERS[e].map(|c| CORNER_OFFSETS[c]);
        [0, 1, 2].map(|i| p[i] + q[i])
    };
    let apart = |x: usize, y: usize| {
        let (p, q) = (mid(x), mid(y));
        (0..3).map(|i| p[i].abs_diff(q[i]).pow(2)).sum::<u32>()
    };
    let flat = |t: [usize; 3]| {
        FACE_CORNERS.iter().any(|f| t.iter().all(|&e| EDGE_CORNERS[e].iter().all(|c| f.contains(c))))
    };
    let (n, m) = (a.len(), b.len());
    // Walks from rung (0, 0) to rung (n, m), which is the same rung (a[0] and b[start]): no other rung
    // may come twice, so a walk starts along `a`, reaches a's end only once it has left b's start, and
    // b's end only past where it first stepped along b (`turned`, n + 1 before it has). best[i][j][t]:
    // the least cost of reaching rung (i, j) having turned at t, the step that got there, and the turn
    // before it.
    const NONE: u32 = u32::MAX;
    let mut chosen: Option<(u32, usize, Vec<bool>)> = None;
    for start in 0..m {
        let at_b = |j: usize| b[(start + m - j % m) % m];
        let triangle = |i: usize, j: usize, along_a: bool| {
            if along_a { [a[i], a[(i + 1) % n], at_b(j)] } else { [at_b(j + 1), at_b(j), a[i % n]] }
        };
        let cost = |t: [usize; 3], rung: (usize, usize)| flat(t) as u32 * 1000 + apart(rung.0, rung.1);
        let mut best = vec![[[(NONE, false, 0); 11]; 10]; 10];
        let first = apart(a[0], at_b(0)) + cost(triangle(0, 0, true), (a[1 % n], at_b(0)));
        best[1][0][n + 1] = (first, true, n + 1);
        for i in 1..=n {
            for j in 0..=m {
                for turned in 1..=n + 1 {
                    let (here, _, _) = best[i][j][turned];
                    if here == NONE {
                        continue;
                    }
                    let mut step = |i2: usize, j2: usize, t2: usize, along_a: bool| {
                        let c = here + cost(triangle(i, j, along_a), (a[i2 % n], at_b(j2)));
                        if c < best[i2][j2][t2].0 {
                            best[i2][j2][t2] = (c, along_a, turned);
                        }
                    };
                    if i < n && (i + 1 < n || j > 0) {
                        step(i + 1, j, turned, true);
                    }
                    let t2 = turned.min(i);
                    if j < m && (j + 1 < m || i > t2) {
                        step(i, j + 1, t2, false);
                    }
                }
            }
        }
        // The cheapest way to the end, and its steps back to the start.
        let Some(end) = (1..=n + 1).filter(|&t| best[n][m][t].0 != NONE).min_by_key(|&t| best[n][m][t].0)
        else {
            continue;
        };
        let total = best[n][m][end].0;
        if chosen.as_ref().is_some_and(|c| c.0 <= total) {
            continue;
        }
        let (mut i, mut j, mut turned, mut steps) = (n, m, end, Vec::new());
        while (i, j) != (0, 0) {
            let (_, along_a, before) = best[i][j][turned];
            steps.push(along_a);
            if along_a {
                i -= 1
            } else {
                j -= 1
            }
            turned = before;
        }
        steps.reverse();
        chosen = Some((total, start, steps));
    }
    let Some((_, start, steps)) = chosen else { return };
    let at_b = |j: usize| b[(start + m - j % m) % m];
    let (mut i, mut j) = (0, 0);
    for along_a in steps {
        let t = if along_a { [a[i], a[(i + 1) % n], at_b(j)] } else { [at_b(j + 1), at_b(j), a[i % n]] };
        if along_a {
            i += 1
        } else {
            j += 1
        }
        out.push((t[0] | t[1] << 4 | t[2] << 8) as u32);
    }
}
