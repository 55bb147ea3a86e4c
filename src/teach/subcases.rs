//! The 33 configurations of Chernyaev's MC33: each class of cases split by how its ambiguous faces are
//! joined and whether a tunnel joins two of its loops through the inside (`extract::interior`). These
//! are the ways the trilinear interpolant of a cell's corner values can meet the iso level, up to
//! rotations of the cube and swapping inside and outside: they are named here, and found by sampling
//! corner values in the tests (`tests/suite/cell_topology.rs` meets each one in every case where it
//! occurs, and holds its triangles to the interpolant).
//!
//! Numbered as Chernyaev numbers them: the class, then the configuration, then (where the interior
//! decides) 1 for no tunnel and 2 for a tunnel. 12.2 and 12.3 are mirror images of each other, as the
//! classes 11 and 14 are.

use crate::extract::decider::{ambiguous_faces, decided_triangles, has_tunnel};
use crate::extract::interior::INTERIOR_CODES;
use crate::extract::tables::FACE_CORNERS;
use crate::teach::case_classes::{CLASS_REPRESENTATIVES, case_classes, rotate, rotations};
use std::sync::OnceLock;

/// One configuration: a class, the faces of its representative (`CLASS_REPRESENTATIVES`) whose inside
/// corners are joined (bit per face, `FACE_CORNERS`), and whether a tunnel joins two loops inside.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Subcase {
    pub name: &'static str,
    pub class: u8,
    pub joined: u8,
    pub tunnel: bool,
}

const fn subcase(name: &'static str, class: u8, joined: u8, tunnel: bool) -> Subcase {
    Subcase { name, class, joined, tunnel }
}

/// The 33, in class order.
pub const SUBCASES: [Subcase; 33] = [
    subcase("0", 0, 0, false),
    subcase("1", 1, 0, false),
    subcase("2", 2, 0, false),
    subcase("3.1", 3, 0, false),
    subcase("3.2", 3, 0b000100, false),
    subcase("4.1.1", 4, 0, false),
    subcase("4.1.2", 4, 0, true),
    subcase("5", 5, 0, false),
    subcase("6.1.1", 6, 0, false),
    subcase("6.1.2", 6, 0, true),
    subcase("6.2", 6, 0b000010, false),
    subcase("7.1", 7, 0, false),
    subcase("7.2", 7, 0b000010, false),
    subcase("7.3", 7, 0b001010, false),
    subcase("7.4.1", 7, 0b011010, false),
    subcase("7.4.2", 7, 0b011010, true),
    subcase("8", 8, 0, false),
    subcase("9", 9, 0, false),
    subcase("10.1.1", 10, 0, false),
    subcase("10.1.2", 10, 0, true),
    subcase("10.2", 10, 0b010000, false),
    subcase("11", 11, 0, false),
    subcase("12.1.1", 12, 0, false),
    subcase("12.1.2", 12, 0, true),
    subcase("12.2", 12, 0b000001, false),
    subcase("12.3", 12, 0b000100, false),
    subcase("13.1", 13, 0, false),
    subcase("13.2", 13, 0b000001, false),
    subcase("13.3", 13, 0b000101, false),
    subcase("13.4", 13, 0b010101, false),
    subcase("13.5.1", 13, 0b010110, false),
    subcase("13.5.2", 13, 0b010110, true),
    subcase("14", 14, 0, false),
];

/// The faces (bit per face) that the corner permutation `perm` takes the faces `faces` to.
fn rotate_faces(perm: &[usize; 8], faces: u8) -> u8 {
    let corners = |face: usize, perm: &dyn Fn(usize) -> usize| -> u8 {
        FACE_CORNERS[face].iter().fold(0, |m, &c| m | 1 << perm(c))
    };
    (0..6).filter(|&f| faces >> f & 1 == 1).fold(0, |out, f| {
        let moved = corners(f, &|c| perm[c]);
        out | 1 << (0..6).position(|g| corners(g, &|c| c) == moved).expect("a rotation takes faces to faces")
    })
}

/// The configuration of a cell of case `case` whose ambiguous faces `joined` join their inside corners
/// (bit per face), with a tunnel inside or not: the rotation (with inside and outside swapped where
/// the class needs it) that takes the case to its class's representative takes the choices to one
/// listed in `SUBCASES`. `None` for choices no trilinear interpolant makes.
pub fn subcase_of(case: u8, joined: u8, tunnel: bool) -> Option<&'static Subcase> {
    static ROTATIONS: OnceLock<Vec<[usize; 8]>> = OnceLock::new();
    let class = case_classes()[case as usize];
    let representative = CLASS_REPRESENTATIVES[class as usize];
    let joined = joined & ambiguous_faces(case as usize);
    let mut moves = ROTATIONS.get_or_init(rotations).iter().flat_map(|perm| {
        let moved = rotate(perm, case);
        let faces = rotate_faces(perm, joined);
        // With inside and outside swapped, a face joins the inside corners it cut apart.
        [
            (moved == representative).then_some(faces),
            (!moved == representative).then(|| ambiguous_faces(representative as usize) & !faces),
        ]
    });
    moves.find_map(|faces| {
        let faces = faces?;
        SUBCASES.iter().find(|s| s.class == class && s.joined == faces && s.tunnel == tunnel)
    })
}

/// `subcase` drawn: the triangles (edge triples, wound as `decided_triangles` winds them) of its class's
/// representative with its choices, and how many ambiguous faces it joins of how many there are.
pub fn subcase_triangles(subcase: &Subcase) -> (Vec<[usize; 3]>, u32, u32) {
    let case = CLASS_REPRESENTATIVES[subcase.class as usize] as usize;
    let code = (1..INTERIOR_CODES as u32)
        .find(|&code| subcase.tunnel && has_tunnel(case, subcase.joined, code))
        .unwrap_or(0);
    let triangles = decided_triangles(case, subcase.joined, code).collect();
    (triangles, subcase.joined.count_ones(), ambiguous_faces(case).count_ones())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::extract::decider::tunnel_possible;

    #[test]
    fn each_class_splits_as_mc33_splits_it() {
        let counts: Vec<usize> = (0..15).map(|k| SUBCASES.iter().filter(|s| s.class == k).count()).collect();
        assert_eq!(counts, [1, 1, 1, 2, 2, 1, 3, 5, 1, 1, 3, 1, 4, 6, 1]);
        for s in &SUBCASES {
            let representative = CLASS_REPRESENTATIVES[s.class as usize];
            assert_eq!(
                s.joined & !ambiguous_faces(representative as usize),
                0,
                "{}: ambiguous faces only",
                s.name
            );
            assert_eq!(subcase_of(representative, s.joined, s.tunnel), Some(s), "{}", s.name);
            let (triangles, _, _) = subcase_triangles(s);
            let plain = decided_triangles(representative as usize, s.joined, 0).count();
            // A tunnel's band has four triangles more than the two loops' fills.
            assert_eq!(triangles.len(), plain + if s.tunnel { 4 } else { 0 }, "{}", s.name);
            assert!(!s.tunnel || tunnel_possible(representative as usize));
        }
    }

    /// Every case's choices with no face joined, and with every face joined, name a configuration:
    /// what the classic table draws, and its complement.
    #[test]
    fn the_classic_tables_choices_are_configurations() {
        for case in 0..=255u8 {
            let all = ambiguous_faces(case as usize);
            for joined in [0, all] {
                let found = subcase_of(case, joined, false);
                assert!(
                    found.is_some_and(|s| s.class == case_classes()[case as usize]),
                    "case {case}, {joined:06b}"
                );
            }
        }
        // A face joined against the other faces' choices in a way no interpolant makes: two opposite
        // faces of class 13.
        assert_eq!(subcase_of(CLASS_REPRESENTATIVES[13], 0b000011, false), None);
    }
}
