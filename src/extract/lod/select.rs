//! Level selection: each frame, the blocks of an octree over the box that the surface may cross, fine
//! near the camera and coarse far away. One [`Rule`] decides every level, on the CPU ([`select`]) and in
//! the compute passes (`shaders/extract/lod_select.wgsl`, which read the rule's numbers).
//!
//! A block holds [`BLOCK_CELLS`]³ cells of its level; a cell of level `k` is `2^k` finest cells wide.
//! The finest cells are those of a uniform grid of `resolution` cells per axis.
//!
//! **Levels from distance alone.** A block splits while its cells would look larger than the eye's
//! cell size in pixels at the block's point nearest the eye. The view frustum and the field's exact
//! bounds only prune the walk: a block outside the view or one the surface cannot cross is dropped,
//! children and all, and never makes another block finer or coarser.
//!
//! **Why no balance pass is needed.** Write `D_k` for the distance below which a block of level `k`
//! splits: `2^k · ppu / px` finest cells (ppu: pixels one unit covers at distance 1, px: the cell size
//! in pixels), and `W_k = BLOCK_CELLS · 2^k` for its width. Suppose a leaf `A` of level `a` touches a
//! leaf `B` of level `b ≥ a + 2`. `A`'s parent `P` split, so `P` is nearer than `D_{a+1}`; `B` touches
//! `P`, so `B` is nearer than `D_{a+1} + √3 · W_{a+1}` (`P`'s diagonal). `B` did not split, so it is at
//! least `D_b ≥ 2 D_{a+1}` away. Both hold only if `D_{a+1} < √3 · W_{a+1}`, that is
//! `ppu / (BLOCK_CELLS · px) < √3`. So where `px ≤ ppu / (BLOCK_CELLS · √3)` ([`Eye::balanced_pixels`],
//! about 40 pixels for a 640-pixel-high 60° view), touching blocks differ by at most one level, and a
//! larger `lod-pixels` is clamped to it. Four transition faces cannot meet around an edge either: for
//! four blocks around an edge, the squared distances of the two across it from each other sum to the
//! same as the other two's, so the two beside a block cannot both be nearer than `D` while it and the
//! one across the edge are not.
//!
//! **Transition faces from six distance tests.** A leaf's face gets transition cells when the block of
//! its own size across the face splits: that block's ancestors are nearer still, so they split too,
//! and the finer blocks beyond exist.

use crate::scene::BOX_HALF_EXTENT;
use glam::{Mat4, UVec3, Vec3, Vec4};

/// Cells along each axis of a block, at the block's level.
pub const BLOCK_CELLS: u32 = crate::scene::params::LOD_BLOCK_CELLS;
/// The most levels a selection has (the finest is level 0).
pub const MAX_LEVELS: u32 = 10;
/// Blocks that touch differ by at most one level while pixels per unit ÷ (block cells × cell pixels)
/// is at least √3; this is √3 with a margin above `f32` rounding.
pub const BALANCED_RATIO: f32 = 1.733;

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
    /// The largest a cell may look, in pixels, as asked (see [`Eye::cell_pixels`]).
    pub lod_pixels: f32,
    /// Drop the blocks outside the view frustum: true where nothing but the picture reads the mesh,
    /// false where the whole surface is wanted (exports, readbacks).
    pub cull: bool,
}

impl Eye {
    /// Pixels a length `size` covers at distance `distance`.
    pub fn projected(&self, size: f32, distance: f32) -> f32 {
        if self.orthographic { size * self.pixels_per_unit } else { size * self.pixels_per_unit / distance }
    }

    /// The largest cell size in pixels for which levels chosen by distance alone keep touching blocks
    /// within one level (see the module's proof); unbounded for an orthographic view, whose blocks all
    /// share one level.
    pub fn balanced_pixels(&self) -> f32 {
        if self.orthographic {
            f32::INFINITY
        } else {
            self.pixels_per_unit / (BLOCK_CELLS as f32 * BALANCED_RATIO)
        }
    }

    /// The cell size in pixels the selection uses: `lod_pixels`, clamped to [`Eye::balanced_pixels`].
    pub fn cell_pixels(&self) -> f32 {
        self.lod_pixels.min(self.balanced_pixels())
    }

    /// The view frustum's six planes, from the projection (clip depth 0 to 1): a point `p` is inside
    /// where `plane.xyz · p + plane.w ≥ 0` for each.
    pub fn planes(&self) -> [Vec4; 6] {
        let row = |i| self.view_projection.row(i);
        [row(3) + row(0), row(3) - row(0), row(3) + row(1), row(3) - row(1), row(2), row(3) - row(2)]
    }

    /// False when the box from `low` to `high` lies wholly outside one plane of the view frustum: its
    /// corner farthest along the plane's normal is outside.
    pub fn sees(&self, low: Vec3, high: Vec3) -> bool {
        self.planes().iter().all(|plane| {
            let normal = plane.truncate();
            let farthest = Vec3::select(normal.cmpgt(Vec3::ZERO), high, low);
            normal.dot(farthest) + plane.w >= 0.0
        })
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

/// A frame's blocks: the leaves of the octree that the surface may cross (and, culling, that the eye
/// sees). They never overlap.
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

/// The rule that gives every block its level, as numbers the CPU and the compute passes both read.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rule {
    /// Finest cells per axis.
    pub resolution: u32,
    /// The roots' level.
    pub top: u32,
    /// The eye, in finest cells from the box's low corner.
    pub eye: Vec3,
    /// Per level, the squared distance in finest cells below which a block of that level splits;
    /// negative where it never does (level 0, levels at or below the floor, and the slots past the
    /// coarsest, which pad it to three vectors of four for the compute passes).
    pub split_below: [f32; 12],
}

impl Rule {
    /// The rule for `eye` on a grid of `resolution` cells, with no block of level `floor` or finer
    /// split (0: none held back; a larger floor answers a frame that overflowed with larger cells).
    pub fn new(resolution: u32, eye: &Eye, floor: u32) -> Self {
        let finest = 2.0 * BOX_HALF_EXTENT / resolution as f32;
        let top = coarsest_level(resolution);
        let pixels = eye.cell_pixels();
        let split_below = std::array::from_fn(|k| {
            let k = k as u32;
            let cells = (1u32 << k) as f32;
            if k <= floor || k > top {
                -1.0
            } else if eye.orthographic {
                if cells * finest * eye.pixels_per_unit > pixels { f32::MAX } else { -1.0 }
            } else {
                let reach = cells * eye.pixels_per_unit / pixels;
                (reach * reach).min(f32::MAX)
            }
        });
        Self { resolution, top, eye: (eye.position + BOX_HALF_EXTENT) / finest, split_below }
    }

    /// The squared distance, in finest cells, from the eye to the block of `level` at `origin`.
    pub fn distance_squared(&self, origin: UVec3, level: u32) -> f32 {
        let low = origin.as_vec3();
        let high = (origin + UVec3::splat(BLOCK_CELLS << level)).as_vec3();
        let d = self.eye.clamp(low, high) - self.eye;
        d.x * d.x + d.y * d.y + d.z * d.z
    }

    /// True when the block of `level` at `origin` is split into eight.
    pub fn splits(&self, origin: UVec3, level: u32) -> bool {
        self.distance_squared(origin, level) < self.split_below[level as usize]
    }

    /// The transition faces of a leaf: those across which the block of its size splits.
    pub fn transitions(&self, origin: UVec3, level: u32) -> u8 {
        let width = BLOCK_CELLS << level;
        let mut faces = 0;
        for axis in 0..3 {
            for side in 0..2 {
                let mut beyond = origin;
                if side == 0 {
                    if origin[axis] == 0 {
                        continue;
                    }
                    beyond[axis] -= width;
                } else {
                    if origin[axis] + width >= self.resolution {
                        continue;
                    }
                    beyond[axis] += width;
                }
                if self.splits(beyond, level) {
                    faces |= 1 << (2 * axis + side);
                }
            }
        }
        faces
    }

    /// Roots per axis: the blocks of level `top` that tile the box.
    pub fn roots_per_axis(&self) -> u32 {
        self.resolution / (BLOCK_CELLS << self.top)
    }
}

/// Whether the surface may cross the box from `low` to `high` (touching the box's walls or not).
pub type Surface<'a> = dyn Fn(Vec3, Vec3, bool) -> bool + 'a;

/// Selects the blocks for `eye` on a grid of `resolution` finest cells per axis (a multiple of
/// [`BLOCK_CELLS`]), keeping only those `surface` says it may cross. Deterministic: the same inputs
/// give the same blocks in the same order.
pub fn select(resolution: u32, eye: &Eye, surface: &Surface<'_>) -> Selection {
    select_by(&Rule::new(resolution, eye, 0), eye, surface)
}

/// [`select`] by a given rule: level by level from the roots, as the compute passes walk.
pub fn select_by(rule: &Rule, eye: &Eye, surface: &Surface<'_>) -> Selection {
    let resolution = rule.resolution;
    // The settings hold a level-of-detail resolution to a multiple of the blocks' cells.
    debug_assert!(supports(resolution));
    let finest = 2.0 * BOX_HALF_EXTENT / resolution as f32;
    let world = |p: UVec3| Vec3::splat(-BOX_HALF_EXTENT) + p.as_vec3() * finest;
    let roots = rule.roots_per_axis();
    let root_width = BLOCK_CELLS << rule.top;
    let mut queue: Vec<UVec3> = (0..roots.pow(3))
        .map(|i| UVec3::new(i % roots, i / roots % roots, i / (roots * roots)) * root_width)
        .collect();
    let mut blocks = Vec::new();
    for level in (0..=rule.top).rev() {
        let width = BLOCK_CELLS << level;
        let mut next = Vec::new();
        for origin in queue {
            let far = origin + UVec3::splat(width);
            let (low, high) = (world(origin), world(far));
            if eye.cull && !eye.sees(low, high) {
                continue;
            }
            let walls = origin.min_element() == 0 || far.max_element() == resolution;
            if !surface(low, high, walls) {
                continue;
            }
            if rule.splits(origin, level) {
                let half = width / 2;
                next.extend((0..8u32).map(|c| origin + UVec3::new(c & 1, (c >> 1) & 1, c >> 2) * half));
            } else {
                blocks.push(Block { origin, level, transitions: rule.transitions(origin, level) });
            }
        }
        queue = next;
    }
    Selection { resolution, levels: rule.top + 1, blocks }
}
