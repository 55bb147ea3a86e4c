//! The 256-case marching-cubes tables, shared by the GPU (uploaded as storage buffers) and the CPU
//! oracle, so that a table error cannot hide from the tests. They are generated here from the cube's
//! definition, never typed: for a case, each face contributes the segments that separate its inside
//! corners from its outside ones (a segment from each crossing where a walk round the face leaves the
//! inside to the crossing where it comes back in); the segments of the six faces close into loops on
//! the cell's boundary (`loops`), and each loop is filled with triangles (`fill`). A face whose inside
//! corners sit on a diagonal (an ambiguous face) may join them or cut them off one by one: the classic
//! table cuts them off, and the asymptotic decider (`decider`) chooses per face from the samples.
//!
//! Corner `i` of a cell sits at `CORNER_OFFSETS[i]` (in cells) from the cell's minimum corner. Bit `i`
//! of a case index is set when corner `i` lies inside the surface (field above iso). Edge `e` joins the
//! corners `EDGE_CORNERS[e]`. Seen from outside, the table's triangles wind clockwise; meshes reverse
//! them so that front faces wind counter-clockwise, the usual convention.

use std::sync::LazyLock;

/// Offsets of the eight corners of a cell from its minimum corner, in cells.
pub const CORNER_OFFSETS: [[u32; 3]; 8] =
    [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]];

/// The two corners each of the twelve cell edges joins.
///
/// Each pair is ordered from the corner nearer the grid origin, so that the two cells sharing an edge
/// interpolate it in the same direction and compute bit-identical vertices.
pub const EDGE_CORNERS: [[usize; 2]; 12] =
    [[0, 1], [1, 2], [3, 2], [0, 3], [4, 5], [5, 6], [7, 6], [4, 7], [0, 4], [1, 5], [2, 6], [3, 7]];

/// For each case, a 12-bit mask of the edges the surface crosses: an edge is crossed exactly when its two
/// corners lie on opposite sides. Computed, so it cannot disagree with `EDGE_CORNERS`.
pub const EDGE_TABLE: [u16; 256] = edge_table();

const fn edge_table() -> [u16; 256] {
    let mut table = [0u16; 256];
    let mut case = 0;
    while case < 256 {
        let mut edge = 0;
        while edge < 12 {
            let [a, b] = EDGE_CORNERS[edge];
            if ((case >> a) & 1) != ((case >> b) & 1) {
                table[case] |= 1 << edge;
            }
            edge += 1;
        }
        case += 1;
    }
    table
}

/// The most triangles a single cell emits under the classic table (`decider::MAX_DECIDED_TRIANGLES`
/// under the others).
pub const MAX_TRIANGLES_PER_CELL: usize = 5;

/// The case table as the shader reads it: crossed-edge mask in bits 0..11, triangle count from bit 16.
pub fn packed_case_table() -> [u32; 256] {
    std::array::from_fn(|case| EDGE_TABLE[case] as u32 | (CASE_TRIANGLES[case] as u32) << 16)
}

/// The triangle table flattened to 16 `i32` per case.
pub fn flat_triangle_table() -> Vec<i32> {
    TRI_TABLE.iter().flatten().map(|&e| e as i32).collect()
}

/// For each case, the triangles as triples of edge numbers, ended by -1: its loops (`loops(case, 0)`)
/// filled, each ambiguous face's inside corners cut off one by one (the classic table's choice).
pub static TRI_TABLE: LazyLock<[[i8; 16]; 256]> = LazyLock::new(|| {
    let mut table = [[-1; 16]; 256];
    let mut triangles = Vec::new();
    for (case, row) in table.iter_mut().enumerate() {
        triangles.clear();
        for ring in loops(case, 0).rings() {
            fill(ring, &mut triangles);
        }
        for (k, &t) in triangles.iter().enumerate() {
            row[3 * k..3 * k + 3].copy_from_slice(&[t & 15, (t >> 4) & 15, (t >> 8) & 15].map(|e| e as i8));
        }
    }
    table
});

/// Number of triangles each case emits (0 to 5).
pub static CASE_TRIANGLES: LazyLock<[u8; 256]> =
    LazyLock::new(|| TRI_TABLE.map(|row| (row.iter().take_while(|&&e| e >= 0).count() / 3) as u8));

/// The six faces of a cell, face `2 * axis + side` the one at `side` (0 or 1) along `axis`: its corners
/// in the face's own order (u, v) = (0, 0), (1, 0), (1, 1), (0, 1), with (u, v, axis) right-handed. Two
/// cells sharing a face list its corners at the same grid points in the same order.
pub const FACE_CORNERS: [[usize; 4]; 6] = face_corners();

const fn face_corners() -> [[usize; 4]; 6] {
    let mut faces = [[0; 4]; 6];
    let mut face = 0;
    while face < 6 {
        let (axis, side) = (face / 2, (face % 2) as u32);
        let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
        let steps = [[0, 0], [1, 0], [1, 1], [0, 1]];
        let mut k = 0;
        while k < 4 {
            let mut corner = 0;
            while corner < 8 {
                let o = CORNER_OFFSETS[corner];
                if o[axis] == side && o[u] == steps[k][0] && o[v] == steps[k][1] {
                    faces[face][k] = corner;
                }
                corner += 1;
            }
            k += 1;
        }
        face += 1;
    }
    faces
}

/// The edge joining corners `a` and `b` of a cell (12 where none does).
pub fn edge_between(a: usize, b: usize) -> usize {
    let mut e = 0;
    while e < 12 && EDGE_CORNERS[e] != [a, b] && EDGE_CORNERS[e] != [b, a] {
        e += 1;
    }
    e
}

/// The loops of crossed edges on a cell's boundary, one after another in `order`, loop k ending at
/// `ends[k + 1]`.
pub struct Loops {
    order: [usize; 12],
    ends: [usize; 5],
    count: usize,
}

impl Loops {
    /// Each loop's crossed edges in order, wound as `fill` winds them (at most four loops).
    pub fn rings(&self) -> impl Iterator<Item = &[usize]> {
        (0..self.count).map(|k| &self.order[self.ends[k]..self.ends[k + 1]])
    }
}

/// The loops of `case` on the cell's boundary, with bit `face` of `joined` set where that ambiguous
/// face joins its inside corners.
#[inline(never)]
pub fn loops(case: usize, joined: u8) -> Loops {
    let inside = |c: usize| (case >> c) & 1 == 1;
    // next[e]: the crossing after the one on edge e, going round its loop (12: none).
    let mut next = [12; 13];
    for (face, corners) in FACE_CORNERS.iter().enumerate() {
        // Walked counter-clockwise seen from outside the cell.
        let walk = |k: usize| corners[if face % 2 == 0 { 3 - k % 4 } else { k % 4 }];
        let join = joined & (1 << face) != 0;
        for k in 0..4 {
            // Leaving the inside at step k, the walk comes back in at step k + 1 past the outside
            // corner (that corner cut off, the inside ones joined) or, on an ambiguous face whose
            // inside corners are not joined, at step k + 3, before the inside corner it left.
            if inside(walk(k)) && !inside(walk(k + 1)) {
                let back = (k + 1..k + 4)
                    .filter(|&j| !inside(walk(j)) && inside(walk(j + 1)))
                    .nth((!join && inside(walk(k + 2))) as usize)
                    .unwrap_or(k + 1);
                next[edge_between(walk(k), walk(k + 1))] = edge_between(walk(back), walk(back + 1));
            }
        }
    }
    let mut loops = Loops { order: [0; 12], ends: [0; 5], count: 0 };
    let (mut seen, mut n) = ([false; 13], 0);
    for start in 0..12 {
        if next[start] == 12 || seen[start] {
            continue;
        }
        let mut e = start;
        while !seen[e] {
            seen[e] = true;
            loops.order[n] = e;
            n += 1;
            e = next[e];
        }
        loops.count += 1;
        loops.ends[loops.count] = n;
    }
    loops
}

/// True when edges `a` and `b` lie on one face of the cell.
fn on_one_face(a: usize, b: usize) -> bool {
    FACE_CORNERS.iter().any(|f| [a, b].iter().all(|&e| EDGE_CORNERS[e].iter().all(|c| f.contains(c))))
}

/// Fills the loop `ring` with triangles, with as few inner sides as it can that join two crossings on
/// one face (such a side lies in the face; some loops of nine or more crossings need one).
#[inline(never)]
pub fn fill(ring: &[usize], out: &mut Vec<u32>) {
    let n = ring.len();
    let cost = |i: usize, j: usize| (j > i + 1 && j + 1 - i < n && on_one_face(ring[i], ring[j])) as u32;
    // best[i][j]: the fewest such sides filling ring[i..=j] closed by the side i–j, and the apex k of the
    // triangle (i, k, j) on that side.
    let mut best = [[(0u32, 0usize); 12]; 12];
    for span in 2..n {
        for i in 0..n - span {
            let j = i + span;
            best[i][j] = (u32::MAX, 0);
            for k in i + 1..j {
                best[i][j] = best[i][j].min((best[i][k].0 + best[k][j].0 + cost(i, k) + cost(k, j), k));
            }
        }
    }
    let (mut stack, mut top) = ([(0, 0); 12], 1);
    stack[0] = (0, n - 1);
    while top > 0 {
        top -= 1;
        let (i, j) = stack[top];
        if j >= i + 2 {
            let k = best[i][j].1;
            out.push((ring[i] | ring[k] << 4 | ring[j] << 8) as u32);
            stack[top] = (i, k);
            stack[top + 1] = (k, j);
            top += 2;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::{BTreeSet, HashMap};

    fn triangles(case: usize) -> Vec<[usize; 3]> {
        TRI_TABLE[case]
            .chunks(3)
            .take_while(|t| t[0] >= 0)
            .map(|t| [t[0] as usize, t[1] as usize, t[2] as usize])
            .collect()
    }

    fn inside(case: usize, corner: usize) -> bool {
        (case >> corner) & 1 == 1
    }

    fn corner_position(corner: usize) -> [f32; 3] {
        CORNER_OFFSETS[corner].map(|v| v as f32)
    }

    fn edge_midpoint(edge: usize) -> [f32; 3] {
        let [a, b] = EDGE_CORNERS[edge];
        let (pa, pb) = (corner_position(a), corner_position(b));
        [0, 1, 2].map(|i| 0.5 * (pa[i] + pb[i]))
    }

    /// The face (axis, side) both edges lie on, if any.
    fn shared_face(e0: usize, e1: usize) -> Option<(usize, u32)> {
        (0..3).flat_map(|axis| [(axis, 0), (axis, 1)]).find(|&(axis, side)| {
            [e0, e1].iter().all(|&e| EDGE_CORNERS[e].iter().all(|&c| CORNER_OFFSETS[c][axis] == side))
        })
    }

    #[test]
    fn edges_run_from_the_lower_corner() {
        for [a, b] in EDGE_CORNERS {
            let (pa, pb) = (CORNER_OFFSETS[a], CORNER_OFFSETS[b]);
            let axis_steps: Vec<_> = (0..3).filter(|&i| pa[i] != pb[i]).collect();
            assert_eq!(axis_steps.len(), 1);
            assert!(pa[axis_steps[0]] < pb[axis_steps[0]]);
        }
    }

    #[test]
    fn every_case_uses_exactly_its_crossed_edges() {
        for case in 0..256 {
            let used: u16 = triangles(case).iter().flatten().fold(0, |m, &e| m | 1 << e);
            assert_eq!(used, EDGE_TABLE[case], "case {case}");
            assert!(triangles(case).len() <= MAX_TRIANGLES_PER_CELL);
            assert_eq!(triangles(case).len(), CASE_TRIANGLES[case] as usize);
        }
    }

    #[test]
    fn each_case_is_a_consistently_oriented_patch_bounded_by_the_faces() {
        for case in 0..256 {
            let mut directed: HashMap<(usize, usize), i32> = HashMap::new();
            for t in triangles(case) {
                for k in 0..3 {
                    *directed.entry((t[k], t[(k + 1) % 3])).or_default() += 1;
                }
            }
            for (&(a, b), &n) in &directed {
                assert_eq!(n, 1, "case {case}: segment {a}->{b} used {n} times");
                let reverse = directed.contains_key(&(b, a));
                // A segment across the cell's interior is shared by two triangles with opposite
                // windings; a segment on a face is the patch's boundary and appears once.
                assert_eq!(reverse, shared_face(a, b).is_none(), "case {case}: segment {a}->{b}");
            }
        }
    }

    #[test]
    fn triangles_wind_clockwise_seen_from_outside() {
        for case in 1..255 {
            for t in triangles(case) {
                let [p0, p1, p2] = t.map(edge_midpoint);
                let u = [0, 1, 2].map(|i| p1[i] - p0[i]);
                let v = [0, 1, 2].map(|i| p2[i] - p0[i]);
                let n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
                // Along each crossed edge, outward is from the inside corner to the outside corner.
                let outward: f32 = t
                    .iter()
                    .map(|&e| {
                        let [a, b] = EDGE_CORNERS[e];
                        let (from, to) = if inside(case, a) { (a, b) } else { (b, a) };
                        let (pf, pt) = (corner_position(from), corner_position(to));
                        (0..3).map(|i| n[i] * (pt[i] - pf[i])).sum::<f32>()
                    })
                    .sum();
                assert!(outward < 0.0, "case {case}: triangle {t:?} winds the other way");
            }
        }
    }

    /// Neighbouring cells share a face; the surface is crack-free only if both draw the same segments
    /// on it, which holds when a face's segments depend on that face's four corners alone.
    #[test]
    fn segments_on_a_face_depend_only_on_its_corners() {
        // Key: (axis, corner bits of the face in low-face corner order); value: the segments, each as a
        // sorted pair of low-face edges.
        type Segments = BTreeSet<(usize, usize)>;
        let mut seen: HashMap<(usize, u8), (usize, Segments)> = HashMap::new();
        for case in 0..256 {
            for axis in 0..3 {
                for side in 0..2u32 {
                    let to_low_corner = |c: usize| {
                        let mut o = CORNER_OFFSETS[c];
                        o[axis] = 0;
                        CORNER_OFFSETS.iter().position(|&x| x == o).unwrap()
                    };
                    let to_low_edge = |e: usize| {
                        let [a, b] = EDGE_CORNERS[e].map(to_low_corner);
                        EDGE_CORNERS.iter().position(|&[x, y]| (x, y) == (a, b) || (x, y) == (b, a)).unwrap()
                    };
                    let face_corners: Vec<usize> = (0..8).filter(|&c| CORNER_OFFSETS[c][axis] == 0).collect();
                    let bits = face_corners.iter().enumerate().fold(0u8, |m, (i, &low)| {
                        let actual = (0..8)
                            .find(|&c| to_low_corner(c) == low && CORNER_OFFSETS[c][axis] == side)
                            .unwrap();
                        m | (inside(case, actual) as u8) << i
                    });
                    let mut segments = BTreeSet::new();
                    for t in triangles(case) {
                        for k in 0..3 {
                            let (a, b) = (t[k], t[(k + 1) % 3]);
                            if shared_face(a, b) == Some((axis, side)) {
                                let (a, b) = (to_low_edge(a), to_low_edge(b));
                                segments.insert((a.min(b), a.max(b)));
                            }
                        }
                    }
                    match seen.get(&(axis, bits)) {
                        Some((other, s)) => assert_eq!(
                            s, &segments,
                            "axis {axis} face bits {bits:04b}: case {case} and case {other} disagree"
                        ),
                        None => {
                            seen.insert((axis, bits), (case, segments));
                        }
                    }
                }
            }
        }
    }
}
