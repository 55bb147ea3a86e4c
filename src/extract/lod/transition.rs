//! Transvoxel transition cells (Lengyel, "Transition Cells for Dynamic Multiresolution Marching
//! Cubes", 2010), over the published tables of the `transvoxel-data` crate.
//!
//! A transition cell lies on the face of a coarse block where a block one level finer meets it. Its
//! full-resolution face has nine samples at the fine spacing, numbered `u + 3 v` with `u, v` in half
//! coarse cells (0, 1, 2); its half-resolution face has four samples, 9 to 12, that repeat samples
//! 0, 2, 6 and 8. The cell's patch ends on its full-resolution face exactly as the fine cells beside it
//! do, and on its half-resolution face exactly as the coarse cell behind it does, so the seam between
//! the two levels is closed. Here the cell has no width: both faces lie in the block face, and the
//! patch's triangles stitch the coarse segments to the fine ones in that plane.
//!
//! The tables cut off the corners whose case bit is set on an ambiguous face; the marching-cubes
//! tables (`crate::extract::tables`) cut off the inside corners, so a sample's bit is set when it lies
//! inside (field above iso). The tests below prove the two agree on every face.

use transvoxel_data::transition_cell_data::{
    TRANSITION_CELL_CLASS, TRANSITION_CELL_DATA, TRANSITION_VERTEX_DATA,
};

/// The edge of every vertex of every case, as its two samples a nibble each: the low bytes of
/// `TRANSITION_VERTEX_DATA`, made while the crate compiles. The high bytes (Lengyel's vertex reuse)
/// are not used here, and the whole table would double these bytes in the browser's wasm.
const EDGE_CODES: [[u8; 12]; 512] = {
    let mut codes = [[0u8; 12]; 512];
    let mut case = 0;
    while case < 512 {
        let mut k = 0;
        while k < 12 {
            codes[case][k] = (TRANSITION_VERTEX_DATA[case][k] & 0xff) as u8;
            k += 1;
        }
        case += 1;
    }
    codes
};

/// The full-resolution sample each half-resolution sample (9 to 12) repeats.
pub const HALF_RESOLUTION: [usize; 4] = [0, 2, 6, 8];

/// The bit of each full-resolution sample (0 to 8) in a case index (Lengyel's order: around the
/// face, then the centre).
const CASE_BIT: [u16; 9] = [0x001, 0x002, 0x004, 0x080, 0x100, 0x008, 0x040, 0x020, 0x010];

/// The position of sample `s` (0 to 12) in half coarse cells along the face, `(u, v)`.
pub fn sample_uv(s: usize) -> (u32, u32) {
    let s = if s >= 9 { HALF_RESOLUTION[s - 9] } else { s };
    ((s % 3) as u32, (s / 3) as u32)
}

/// True for the half-resolution samples (9 to 12).
pub fn is_half_resolution(s: usize) -> bool {
    s >= 9
}

/// The case index of a transition cell whose full-resolution sample `s` lies inside when `inside(s)`.
pub fn case_of(inside: impl Fn(usize) -> bool) -> usize {
    (0..9).filter(|&s| inside(s)).fold(0, |m, s| m | CASE_BIT[s] as usize)
}

/// An edge of a transition cell, as its two samples (0 to 12), lower first.
pub type Edge = (u8, u8);

/// The triangles of `case`, each as three edges carrying its vertices, wound counter-clockwise seen
/// from outside when `(u, v, w)` is a right-handed frame, `w` pointing from the full-resolution face
/// into the coarse block (reverse them for a left-handed frame).
pub fn triangles(case: usize) -> impl Iterator<Item = [Edge; 3]> {
    let class = TRANSITION_CELL_CLASS[case];
    let data = &TRANSITION_CELL_DATA[(class & 0x7f) as usize];
    let reversed = class & 0x80 != 0;
    let vertices = &EDGE_CODES[case];
    let edge = move |k: u8| {
        let code = vertices[k as usize];
        let (a, b) = (code >> 4, code & 0x0f);
        (a.min(b), a.max(b))
    };
    (0..data.get_triangle_count() as usize).map(move |t| {
        let [a, b, c] = [0, 1, 2].map(|k| edge(data.vertex_index[3 * t + k]));
        // The tables wind counter-clockwise for an unreversed class in this frame.
        if reversed { [a, c, b] } else { [a, b, c] }
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::extract::tables::{CORNER_OFFSETS, EDGE_CORNERS, TRI_TABLE};
    use std::collections::{BTreeSet, HashMap};

    /// The segments the marching-cubes rule draws on a square face whose corners, in cyclic order,
    /// lie inside when `inside[i]`: each as the two sides (0 to 3, side `i` from corner `i` to corner
    /// `i + 1`) it joins. An ambiguous face cuts off its two inside corners.
    fn face_rule(inside: [bool; 4]) -> BTreeSet<(usize, usize)> {
        let crossed: Vec<usize> = (0..4).filter(|&i| inside[i] != inside[(i + 1) % 4]).collect();
        let mut segments = BTreeSet::new();
        match crossed.len() {
            2 => {
                segments.insert((crossed[0], crossed[1]));
            }
            4 => {
                for c in (0..4).filter(|&c| inside[c]) {
                    let (a, b) = ((c + 3) % 4, c);
                    segments.insert((a.min(b), a.max(b)));
                }
            }
            _ => {}
        }
        segments
    }

    #[test]
    fn marching_cubes_cuts_off_inside_corners() {
        // The bottom face (z = 0) of every case, corners 0, 1, 2, 3 in cyclic order; edges 0..3 are its
        // sides in the same order.
        for (case, row) in TRI_TABLE.iter().enumerate() {
            let inside = [0, 1, 2, 3].map(|c| case >> c & 1 == 1);
            let mut segments = BTreeSet::new();
            for t in row.chunks(3).take_while(|t| t[0] >= 0) {
                for k in 0..3 {
                    let (a, b) = (t[k] as usize, t[(k + 1) % 3] as usize);
                    if a < 4 && b < 4 {
                        segments.insert((a.min(b), a.max(b)));
                    }
                }
            }
            assert_eq!(segments, face_rule(inside), "case {case}");
        }
        assert_eq!(CORNER_OFFSETS[2], [1, 1, 0]);
        assert_eq!(EDGE_CORNERS[2], [3, 2]);
    }

    fn on_edge(e: Edge, s: usize) -> bool {
        e.0 as usize == s || e.1 as usize == s
    }

    #[test]
    fn every_case_uses_exactly_its_crossed_edges() {
        for case in 0..512 {
            let inside = |s: usize| {
                let s = if is_half_resolution(s) { HALF_RESOLUTION[s - 9] } else { s };
                case & CASE_BIT[s] as usize != 0
            };
            let used: BTreeSet<Edge> = triangles(case).flatten().collect();
            for &(a, b) in &used {
                assert_ne!(
                    inside(a as usize),
                    inside(b as usize),
                    "case {case}: edge {a}-{b} is not crossed"
                );
                let (ua, va) = sample_uv(a as usize);
                let (ub, vb) = sample_uv(b as usize);
                let step = ua.abs_diff(ub) + va.abs_diff(vb);
                let half = is_half_resolution(a as usize);
                assert_eq!(half, is_half_resolution(b as usize), "case {case}: edge {a}-{b} joins the faces");
                assert_eq!(step, if half { 2 } else { 1 }, "case {case}: {a}-{b} is not a cell edge");
            }
        }
    }

    /// Every edge a transition patch leaves open lies on one face of the cell, and the open edges on
    /// each square face (the four fine sub-faces, the coarse face) are the marching-cubes rule's.
    #[test]
    fn the_patch_ends_on_the_faces_as_marching_cubes_does() {
        // Squares as their corner samples in cyclic order.
        let squares: [[usize; 4]; 5] =
            [[0, 1, 4, 3], [1, 2, 5, 4], [3, 4, 7, 6], [4, 5, 8, 7], [9, 10, 12, 11]];
        for case in 0..512 {
            let inside = |s: usize| {
                let s = if is_half_resolution(s) { HALF_RESOLUTION[s - 9] } else { s };
                case & CASE_BIT[s] as usize != 0
            };
            let mut uses: HashMap<(Edge, Edge), i32> = HashMap::new();
            for t in triangles(case) {
                for k in 0..3 {
                    let (a, b) = (t[k], t[(k + 1) % 3]);
                    *uses.entry((a.min(b), a.max(b))).or_default() += 1;
                }
            }
            let open: Vec<(Edge, Edge)> = uses.into_iter().filter(|&(_, n)| n == 1).map(|(e, _)| e).collect();
            for square in squares {
                let side = |e: Edge| {
                    (0..4).find(|&i| {
                        let (a, b) = (square[i], square[(i + 1) % 4]);
                        (a.min(b), a.max(b)) == (e.0 as usize, e.1 as usize)
                    })
                };
                let drawn: BTreeSet<(usize, usize)> = open
                    .iter()
                    .filter_map(|&(a, b)| Some((side(a)?, side(b)?)))
                    .map(|(a, b)| (a.min(b), a.max(b)))
                    .collect();
                let expected = face_rule(square.map(inside));
                assert_eq!(drawn, expected, "case {case}, face {square:?}");
            }
            // The rest lie on the side faces (v = 0, u = 2, v = 2, u = 0).
            for &(a, b) in &open {
                let on_side = (0..4).any(|side| {
                    let full = [[0, 1, 2], [2, 5, 8], [6, 7, 8], [0, 3, 6]][side];
                    let half = [[9, 10], [10, 12], [11, 12], [9, 11]][side];
                    let held = |e: Edge| {
                        let set: Vec<usize> = full.iter().chain(&half).copied().collect();
                        set.iter().any(|&s| on_edge(e, s))
                            && set.contains(&(e.0 as usize))
                            && set.contains(&(e.1 as usize))
                    };
                    held(a) && held(b)
                });
                let on_square = squares.iter().any(|sq| {
                    let inn = |e: Edge| sq.contains(&(e.0 as usize)) && sq.contains(&(e.1 as usize));
                    inn(a) && inn(b)
                });
                assert!(on_side || on_square, "case {case}: open edge {a:?}-{b:?} lies on no face");
            }
        }
    }
}
