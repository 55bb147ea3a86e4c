//! What each saddle does, from where its flow leads: the merge tree of the blobs (from the top down)
//! and the pockets of f < iso (from the bottom up), each with union–find.

use super::interval::{Source, derivatives};
use super::morse::{End, Sets, eigen, flow};
use super::{CriticalPoint, Role, TreeNode};
use glam::DVec3;

/// Follows each saddle's lone direction both ways: up from a join saddle, down from a closing one.
pub(super) fn follow_saddles(sources: &[Source], points: &mut [CriticalPoint], reach: f64) {
    let maxima: Vec<(usize, DVec3)> =
        points.iter().enumerate().filter(|(_, p)| p.index == 3).map(|(k, p)| (k, p.position)).collect();
    let minima: Vec<(usize, DVec3)> =
        points.iter().enumerate().filter(|(_, p)| p.index == 0).map(|(k, p)| (k, p.position)).collect();
    for point in points.iter_mut().filter(|p| p.index == 1 || p.index == 2) {
        let (_, _, h) = derivatives(sources, point.position);
        let (_, vectors) = eigen(h);
        let up = point.index == 2;
        let direction = if up { vectors[2] } else { vectors[0] };
        let nearest = sources.iter().map(|s| s.centre.distance(point.position)).fold(f64::INFINITY, f64::min);
        let step = direction * (1e-4 * nearest);
        let extrema = if up { &maxima } else { &minima };
        point.ends = [-1.0, 1.0].map(|side| flow(sources, point.position + step * side, up, extrema, reach));
    }
}

/// The blobs, from the top down: each adding sphere (and maximum) starts one; a join saddle whose flow
/// reaches two different blobs joins them; one reaching the same blob twice opens a tunnel.
pub(super) fn merge_tree(adding: &[bool], points: &mut [CriticalPoint]) -> Vec<TreeNode> {
    let n = adding.len();
    let mut sets = Sets::new(n + points.len());
    let mut node_of = vec![usize::MAX; n + points.len()];
    let mut tree = Vec::new();
    for i in (0..n).filter(|&i| adding[i]) {
        node_of[i] = tree.len();
        tree.push(TreeNode { value: f64::INFINITY, children: vec![], point: None, spheres: vec![i] });
    }
    let element = |end: End| match end {
        End::Sphere(i) if adding[i] => Some(i),
        End::Point(k) => Some(n + k),
        _ => None,
    };
    for k in 0..points.len() {
        match points[k].index {
            3 => {
                points[k].role = Role::Birth;
                node_of[n + k] = tree.len();
                tree.push(TreeNode {
                    value: points[k].value,
                    children: vec![],
                    point: Some(k),
                    spheres: vec![],
                });
            }
            2 => {
                let [a, b] = points[k].ends.map(element);
                let (Some(a), Some(b)) = (a, b) else { continue };
                let (ra, rb) = (sets.root(a), sets.root(b));
                if ra == rb {
                    points[k].role = Role::Loop;
                    continue;
                }
                points[k].role = Role::Join;
                let (na, nb) = (node_of[ra], node_of[rb]);
                let mut members = tree[na].spheres.clone();
                members.extend(&tree[nb].spheres);
                members.sort_unstable();
                sets.join(ra, rb);
                node_of[sets.root(ra)] = tree.len();
                tree.push(TreeNode {
                    value: points[k].value,
                    children: vec![na, nb],
                    point: Some(k),
                    spheres: members,
                });
            }
            _ => {}
        }
    }
    tree
}

/// The pockets of f < iso, from the bottom up: the outside, each subtracting sphere and each minimum
/// starts one; a closing saddle whose flow reaches two different pockets joins them (below its value
/// they are apart: one is a cavity), one reaching the same pocket twice closes a tunnel.
pub(super) fn sublevel_roles(adding: &[bool], points: &mut [CriticalPoint]) {
    let n = adding.len();
    let outside = n + points.len();
    let mut sets = Sets::new(outside + 1);
    let element = |end: End| match end {
        End::Sphere(i) if !adding[i] => Some(i),
        End::Point(k) => Some(n + k),
        End::Outside => Some(outside),
        _ => None,
    };
    for k in (0..points.len()).rev() {
        match points[k].index {
            0 => points[k].role = Role::Fill,
            1 => {
                let [a, b] = points[k].ends.map(element);
                let (Some(a), Some(b)) = (a, b) else { continue };
                points[k].role = if sets.join(a, b) { Role::Cavity } else { Role::Hole };
            }
            _ => {}
        }
    }
}
