//! The 15 classic classes of marching-cubes cases: two cases are in one class when a rotation of the
//! cube, possibly with inside and outside swapped, takes one to the other. Numbered as in the classic
//! figure of the 15 cases, from the representatives below.

use crate::extract::tables::CORNER_OFFSETS;
use std::sync::OnceLock;

/// One case of each class, in the classic order: 0 nothing inside; 1 one corner; 2 an edge; 3 two
/// corners across a face; 4 two corners across the cube; 5 three corners of a face; 6 an edge and the
/// far corner; 7 three corners, none adjacent; 8 a face; 9 a corner and its three neighbours; 10 two
/// opposite edges; 11 and 14 a twisted path of three edges (mirror images); 12 three corners of a face
/// and a lone corner; 13 every other corner.
pub const CLASS_REPRESENTATIVES: [u8; 15] = [
    0,
    0b0000_0001,
    0b0000_0011,
    0b0010_0001,
    0b0100_0001,
    0b0000_1110,
    0b0100_0011,
    0b0100_1010,
    0b0000_1111,
    0b1000_1101,
    0b0101_0101,
    0b0111_0001,
    0b0001_1110,
    0b1010_0101,
    0b1101_0001,
];

/// Short descriptions of the classes, in order.
pub const CLASS_NAMES: [&str; 15] = [
    "empty",
    "one corner",
    "an edge",
    "two corners across a face",
    "two corners across the cube",
    "three corners of a face",
    "an edge and the far corner",
    "three separate corners",
    "a face",
    "a corner and its neighbours",
    "two opposite edges",
    "a twisted path",
    "three corners and a lone one",
    "every other corner",
    "a twisted path, mirrored",
];

/// The 24 rotations of the cube as permutations of its corners.
pub(crate) fn rotations() -> Vec<[usize; 8]> {
    let corner = |p: [u32; 3]| CORNER_OFFSETS.iter().position(|&c| c == p).unwrap();
    // Quarter turns about x (y → z) and about z (x → y), on corner coordinates in {0, 1}.
    let about_x = |p: [u32; 3]| [p[0], 1 - p[2], p[1]];
    let about_z = |p: [u32; 3]| [1 - p[1], p[0], p[2]];
    let apply = |f: &dyn Fn([u32; 3]) -> [u32; 3], perm: [usize; 8]| -> [usize; 8] {
        std::array::from_fn(|c| corner(f(CORNER_OFFSETS[perm[c]])))
    };
    let mut found = vec![std::array::from_fn(|c| c)];
    let mut next = 0;
    while next < found.len() {
        for turn in [&about_x as &dyn Fn([u32; 3]) -> [u32; 3], &about_z] {
            let rotated = apply(turn, found[next]);
            if !found.contains(&rotated) {
                found.push(rotated);
            }
        }
        next += 1;
    }
    found
}

/// The case whose inside corners are those of `case` moved by `perm`.
pub(crate) fn rotate(perm: &[usize; 8], case: u8) -> u8 {
    (0..8).filter(|&c| case >> c & 1 == 1).fold(0u8, |r, c| r | 1 << perm[c])
}

fn canonical(case: u8, rotations: &[[usize; 8]]) -> u8 {
    rotations.iter().flat_map(|perm| [rotate(perm, case), !rotate(perm, case)]).min().unwrap()
}

/// The class (0 to 14) of each of the 256 cases (computed once).
pub fn case_classes() -> &'static [u8; 256] {
    static CLASSES: OnceLock<[u8; 256]> = OnceLock::new();
    CLASSES.get_or_init(|| {
        let rotations = rotations();
        let keys: Vec<u8> = CLASS_REPRESENTATIVES.iter().map(|&r| canonical(r, &rotations)).collect();
        std::array::from_fn(|case| {
            let key = canonical(case as u8, &rotations);
            keys.iter().position(|&k| k == key).expect("every case is in one of the 15 classes") as u8
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::extract::tables::CASE_TRIANGLES;

    #[test]
    fn there_are_24_rotations_and_15_classes() {
        assert_eq!(rotations().len(), 24);
        let classes = case_classes();
        for class in 0..15u8 {
            assert!(classes.contains(&class), "class {class} has no case");
            assert_eq!(classes[CLASS_REPRESENTATIVES[class as usize] as usize], class);
        }
        // A class's cases with fewer than four corners inside are rotations of its representative, and
        // emit as many triangles. (Complements need not: the classic table joins some of them differently.)
        for case in (0..256usize).filter(|c| c.count_ones() < 4) {
            let representative = CLASS_REPRESENTATIVES[classes[case] as usize] as usize;
            assert_eq!(CASE_TRIANGLES[case], CASE_TRIANGLES[representative], "case {case}");
        }
        assert_eq!(classes[0], 0);
        assert_eq!(classes[255], 0);
        assert_eq!(classes[1], 1);
        assert_eq!(classes[254], 1);
    }
}
