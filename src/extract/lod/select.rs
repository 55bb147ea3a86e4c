//! Level selection: each frame, an octree of blocks over the box, fine near the camera and coarse far
//! away, 2:1 balanced. The one function [`select`] serves every LOD extractor.
//!
//! A block holds [`BLOCK_CELLS`]³ cells of its level; a cell of level `k` is `2^k` finest cells wide.
//! The finest cells are those of a uniform grid of `resolution` cells per axis. A block is split while
//! its cells would cover more than `lod_pixels` pixels at the block's nearest point to the camera, and
//! blocks outside the view frustum stay as coarse as the balance allows, as do blocks the surface
//! cannot cross (by the field's exact bounds). Balance: blocks the surface may cross that share a face,
//! an edge or a corner differ by at most one level, so every seam is between two neighbouring levels,
//! where a transition cell closes it. A block the surface cannot cross needs no balance: its closed box,
//! faces and edges included, holds no crossing, so nothing meets it to be stitched.

use crate::scene::BOX_HALF_EXTENT;
use glam::{Mat4, UVec3, Vec3, Vec4};

/// Cells along each axis of a block, at the block's level.
pub const BLOCK_CELLS: u32 = crate::scene::params::LOD_BLOCK_CELLS;
/// The most levels a selection has (the finest is level 0).
pub const MAX_LEVELS: u32 = 10;

/// The camera, as level selection needs it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Eye {
    /// Where it is, in world units.
    pub position: Vec3,
    /// Projection times view, for the frustum.
    pub view_projection: Mat4,
    /// Pixels one world unit covers at distance 1 (perspective), or at any distance (orthographic).
    pub pixels_per_unit: f32,
    pub orthographic: bool,
    /// The largest a cell may look, in pixels.
    pub lod_pixels: f32,
}

impl Eye {
    /// Pixels a length `size` covers at distance `distance`.
    pub fn projected(&self, size: f32, distance: f32) -> f32 {
        if self.orthographic { size * self.pixels_per_unit } else { size * self.pixels_per_unit / distance }
    }

    /// False when the box from `low` to `high` lies wholly outside one plane of the view frustum.
    pub fn sees(&self, low: Vec3, high: Vec3) -> bool {
        let corners = (0..8).map(|i| {
            let p = Vec3::new(
                if i & 1 == 0 { low.x } else { high.x },
                if i & 2 == 0 { low.y } else { high.y },
                if i & 4 == 0 { low.z } else { high.z },
            );
            self.view_projection * Vec4::from((p, 1.0))
        });
        let corners: Vec<Vec4> = corners.collect();
        let outside = |test: &dyn Fn(Vec4) -> bool| corners.iter().all(|&c| test(c));
        !(outside(&|c| c.x < -c.w)
            || outside(&|c| c.x > c.w)
            || outside(&|c| c.y < -c.w)
            || outside(&|c| c.y > c.w)
            || outside(&|c| c.z < 0.0)
            || outside(&|c| c.z > c.w))
    }
}

/// One selected block.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Block {
    /// Its lowest corner, in finest cells.
    pub origin: UVec3,
    /// 0 for the finest.
    pub level: u32,
    /// Bit `2 a + s` is set when the block one level finer lies beyond face `s` (0 low, 1 high) of
    /// axis `a`: that face gets transition cells.
    pub transitions: u8,
}

impl Block {
    /// Width of one of its cells, in finest cells.
    pub fn step(&self) -> u32 {
        1 << self.level
    }

    /// Its width, in finest cells.
    pub fn width(&self) -> u32 {
        BLOCK_CELLS << self.level
    }
}

/// A frame's blocks: they tile the box without gaps or overlaps.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Selection {
    /// Finest cells per axis.
    pub resolution: u32,
    /// Levels the octree may use (the coarsest is `levels - 1`).
    pub levels: u32,
    pub blocks: Vec<Block>,
}

impl Selection {
    /// Blocks at each level, finest first.
    pub fn blocks_per_level(&self) -> Vec<u32> {
        let mut counts = vec![0; self.levels as usize];
        for b in &self.blocks {
            counts[b.level as usize] += 1;
        }
        counts
    }
}

/// The coarsest level a grid of `resolution` cells allows: its root blocks tile the box exactly.
pub fn coarsest_level(resolution: u32) -> u32 {
    (0..MAX_LEVELS).rev().find(|&k| resolution.is_multiple_of(BLOCK_CELLS << k)).unwrap_or(0)
}

/// True when a grid of `resolution` cells can be split into blocks at all.
pub fn supports(resolution: u32) -> bool {
    resolution.is_multiple_of(BLOCK_CELLS)
}

#[derive(Clone, Copy)]
struct Node {
    origin: UVec3,
    level: u32,
    /// Index of the first of eight children, or 0 for a leaf.
    children: u32,
}

struct Tree {
    nodes: Vec<Node>,
    /// Per node: the surface may cross its closed box.
    holds: Vec<bool>,
    roots_per_axis: u32,
    root_width: u32,
    resolution: u32,
}

impl Tree {
    fn leaf_at(&self, p: UVec3) -> usize {
        let r = p / self.root_width;
        let mut i = (r.x + self.roots_per_axis * (r.y + self.roots_per_axis * r.z)) as usize;
        while self.nodes[i].children != 0 {
            let n = self.nodes[i];
            let half = (BLOCK_CELLS << n.level) / 2;
            let o = (p - n.origin) / half;
            i = n.children as usize + (o.x + 2 * o.y + 4 * o.z) as usize;
        }
        i
    }

    fn push(&mut self, node: Node, surface: &Surface<'_>) {
        let far = node.origin + UVec3::splat(BLOCK_CELLS << node.level);
        let walls = node.origin.min_element() == 0 || far.max_element() == self.resolution;
        self.holds.push(surface(self.world(node.origin), self.world(far), walls));
        self.nodes.push(node);
    }

    fn world(&self, p: UVec3) -> Vec3 {
        Vec3::splat(-BOX_HALF_EXTENT) + p.as_vec3() * (2.0 * BOX_HALF_EXTENT / self.resolution as f32)
    }

    fn split(&mut self, i: usize, surface: &Surface<'_>) -> std::ops::Range<usize> {
        let n = self.nodes[i];
        let first = self.nodes.len();
        let half = (BLOCK_CELLS << n.level) / 2;
        for c in 0..8u32 {
            let offset = UVec3::new(c & 1, (c >> 1) & 1, (c >> 2) & 1) * half;
            self.push(Node { origin: n.origin + offset, level: n.level - 1, children: 0 }, surface);
        }
        self.nodes[i].children = first as u32;
        first..first + 8
    }

    /// The point just beyond node `n` in direction `d` (each component −1, 0 or 1), if in the box.
    fn beyond(&self, n: Node, d: [i32; 3]) -> Option<UVec3> {
        let width = BLOCK_CELLS << n.level;
        let mut p = [0u32; 3];
        for a in 0..3 {
            p[a] = match d[a] {
                -1 => n.origin[a].checked_sub(1)?,
                1 => Some(n.origin[a] + width).filter(|&x| x < self.resolution)?,
                _ => n.origin[a],
            };
        }
        Some(UVec3::from_array(p))
    }
}

impl Tree {
    /// True when, around one of the block's edges, the two blocks beside it are finer and the one
    /// across the edge is not: four transition faces would then meet on that edge, where a closed
    /// surface has room for two. Splitting the block leaves one coarse block around the edge.
    fn alternates_around_an_edge(&self, n: Node) -> bool {
        if n.level == 0 {
            return false;
        }
        // Only blocks the surface may cross count: an edge of one that it cannot holds no crossing.
        let level = |d: [i32; 3]| {
            let j = self.leaf_at(self.beyond(n, d)?);
            Some(if self.holds[j] { self.nodes[j].level } else { u32::MAX })
        };
        (0..3).any(|axis| {
            let (b, c) = ((axis + 1) % 3, (axis + 2) % 3);
            [(-1, -1), (-1, 1), (1, -1), (1, 1)].into_iter().any(|(sb, sc)| {
                let mut across_b = [0; 3];
                across_b[b] = sb;
                let mut across_c = [0; 3];
                across_c[c] = sc;
                let mut diagonal = across_b;
                diagonal[c] = sc;
                let finer = |l: Option<u32>| l.is_some_and(|l| l < n.level);
                finer(level(across_b))
                    && finer(level(across_c))
                    && level(diagonal).is_some_and(|l| l >= n.level)
            })
        })
    }
}

/// The 26 directions to a block's neighbours.
fn directions() -> impl Iterator<Item = [i32; 3]> {
    (0..27).map(|i| [i % 3 - 1, i / 3 % 3 - 1, i / 9 - 1]).filter(|d| *d != [0, 0, 0])
}

/// Whether the surface may cross the box from `low` to `high` (touching the box's walls or not).
pub type Surface<'a> = dyn Fn(Vec3, Vec3, bool) -> bool + 'a;

/// Selects the blocks for `eye` on a grid of `resolution` finest cells per axis (a multiple of
/// [`BLOCK_CELLS`]), refining only where `surface` says it may cross. Deterministic: the same inputs
/// give the same blocks in the same order.
pub fn select(resolution: u32, eye: &Eye, surface: &Surface<'_>) -> Selection {
    assert!(supports(resolution), "resolution {resolution} is not a multiple of {BLOCK_CELLS}");
    let top = coarsest_level(resolution);
    let root_width = BLOCK_CELLS << top;
    let roots_per_axis = resolution / root_width;
    let finest = 2.0 * BOX_HALF_EXTENT / resolution as f32;
    let world = |p: UVec3| Vec3::splat(-BOX_HALF_EXTENT) + p.as_vec3() * finest;
    let mut tree = Tree { nodes: Vec::new(), holds: Vec::new(), roots_per_axis, root_width, resolution };
    for z in 0..roots_per_axis {
        for y in 0..roots_per_axis {
            for x in 0..roots_per_axis {
                let origin = UVec3::new(x, y, z) * root_width;
                tree.push(Node { origin, level: top, children: 0 }, surface);
            }
        }
    }
    // Refine by the camera, breadth first.
    let mut i = 0;
    while i < tree.nodes.len() {
        let n = tree.nodes[i];
        if n.level > 0 {
            let (low, high) = (world(n.origin), world(n.origin + UVec3::splat(BLOCK_CELLS << n.level)));
            let distance = (eye.position.clamp(low, high) - eye.position).length().max(1e-6);
            let cell = finest * (1u32 << n.level) as f32;
            if tree.holds[i] && eye.sees(low, high) && eye.projected(cell, distance) > eye.lod_pixels {
                tree.split(i, surface);
            }
        }
        i += 1;
    }
    // Balance: split any block more than one level coarser than a neighbour, until none is.
    let leaf_with_surface = |tree: &Tree, i: usize| tree.nodes[i].children == 0 && tree.holds[i];
    let mut pending: Vec<usize> = (0..tree.nodes.len()).filter(|&i| leaf_with_surface(&tree, i)).collect();
    while let Some(i) = pending.pop() {
        if !leaf_with_surface(&tree, i) {
            continue;
        }
        let n = tree.nodes[i];
        for d in directions() {
            let Some(p) = tree.beyond(n, d) else { continue };
            let j = tree.leaf_at(p);
            if tree.holds[j] && tree.nodes[j].level > n.level + 1 {
                pending.extend(tree.split(j, surface));
                pending.push(i);
                break;
            }
        }
        if tree.nodes[i].children == 0 && tree.alternates_around_an_edge(n) {
            pending.extend(tree.split(i, surface));
        }
    }
    let mut blocks = Vec::new();
    for n in tree.nodes.iter().filter(|n| n.children == 0) {
        let mut transitions = 0u8;
        for a in 0..3 {
            for s in 0..2 {
                let mut d = [0; 3];
                d[a] = if s == 0 { -1 } else { 1 };
                if let Some(p) = tree.beyond(*n, d)
                    && tree.nodes[tree.leaf_at(p)].level < n.level
                {
                    transitions |= 1 << (2 * a + s);
                }
            }
        }
        blocks.push(Block { origin: n.origin, level: n.level, transitions });
    }
    Selection { resolution, levels: top + 1, blocks }
}
