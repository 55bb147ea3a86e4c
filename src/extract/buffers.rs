//! The buffers the compute passes share for one grid: the active-block and active-cell lists with their
//! indirect dispatches, per-block field values, cases and edge vertices, and the indexed mesh with its
//! indirect draw. Sized by capacities that grow
//! when a frame reports it needed more.

use crate::extract::reference::Grid;
use crate::extract::uniforms::{CounterBlock, Counters};

pub use crate::extract::field::BLOCK_CELLS;
/// Bytes of one vertex: position and normal, three f32 each.
pub const VERTEX_BYTES: u64 = 24;
/// Bytes of one index.
pub const INDEX_BYTES: u64 = 4;
/// Bytes each active block holds in the per-block buffers: 125 field values, 64 cases, 192 edge vertices.
const BLOCK_VALUE_BYTES: u64 = 125 * 4;
const BLOCK_CASE_BYTES: u64 = 64 * 4;
const BLOCK_EDGE_BYTES: u64 = 192 * 4;

/// How much each buffer holds.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Capacity {
    /// Active blocks.
    pub blocks: u32,
    /// Active cells (those the surface crosses).
    pub cells: u32,
    /// Mesh vertices.
    pub vertices: u32,
    /// Mesh indices (three per triangle).
    pub indices: u32,
}

impl Capacity {
    /// A starting point for a grid: room for a surface of several times the box's cross-section.
    pub fn for_grid(grid: Grid) -> Self {
        let n = grid.cells_per_axis;
        let blocks_per_axis = n.div_ceil(BLOCK_CELLS);
        let face_cells = n * n;
        let blocks = blocks_per_axis.pow(3).min((6 * blocks_per_axis * blocks_per_axis).max(512));
        Self {
            blocks,
            cells: (16 * blocks).min(cube(grid.cells_per_axis)),
            vertices: (4 * face_cells).max(4096),
            indices: (24 * face_cells).max(24576),
        }
    }

    /// The largest capacity whose every buffer fits one storage binding of `limit` bytes.
    pub fn largest(grid: Grid, limit: u64) -> Self {
        let fit = |bytes_each: u64| (limit / bytes_each).min(u32::MAX as u64) as u32;
        Self {
            blocks: cube(grid.cells_per_axis.div_ceil(BLOCK_CELLS)).min(fit(BLOCK_EDGE_BYTES)),
            cells: cube(grid.cells_per_axis).min(fit(4)),
            vertices: fit(VERTEX_BYTES),
            indices: fit(INDEX_BYTES) / 3 * 3,
        }
    }

    /// The smaller of each part.
    pub fn min(self, other: Self) -> Self {
        Self {
            blocks: self.blocks.min(other.blocks),
            cells: self.cells.min(other.cells),
            vertices: self.vertices.min(other.vertices),
            indices: self.indices.min(other.indices),
        }
    }

    /// True when every count fits.
    pub fn holds(&self, counters: &Counters) -> bool {
        counters.active_blocks <= self.blocks
            && counters.active_cells <= self.cells
            && counters.vertices <= self.vertices
            && counters.indices <= self.indices
    }

    /// Room for `counters` with a quarter to spare, never less than now.
    pub fn grown_for(&self, counters: &Counters) -> Self {
        let grow = |have: u32, need: u32| if need > have { need.saturating_add(need / 4) } else { have };
        Self {
            blocks: grow(self.blocks, counters.active_blocks),
            cells: grow(self.cells, counters.active_cells),
            vertices: grow(self.vertices, counters.vertices),
            // Whole triangles: rounded up to a multiple of three, and unchanged where it fits.
            indices: grow(self.indices, counters.indices).div_ceil(3) * 3,
        }
    }
}

/// n³, or `u32::MAX` past it (a 2048³ grid has more cells than a `u32` counts).
fn cube(n: u32) -> u32 {
    (n as u64).pow(3).min(u32::MAX as u64) as u32
}

/// The buffers for one grid and capacity.
pub struct MeshBuffers {
    pub grid: Grid,
    pub capacity: Capacity,
    pub counters: wgpu::Buffer,
    pub dispatch: wgpu::Buffer,
    pub cell_dispatch: wgpu::Buffer,
    pub active_blocks: wgpu::Buffer,
    pub active_cells: wgpu::Buffer,
    pub block_slots: wgpu::Buffer,
    pub block_values: wgpu::Buffer,
    pub cell_cases: wgpu::Buffer,
    pub edge_vertices: wgpu::Buffer,
    pub vertices: wgpu::Buffer,
    pub indices: wgpu::Buffer,
    /// With `lod=on`: each triangle's level of detail (for `color-by=level`), or with dual contouring
    /// its corners' QEF ranks (`color-by=rank`, `DualMesher::triangle_marks`); then from
    /// [`MeshBuffers::lod_blocks_offset`] the blocks the surface may cross, four words each (origin,
    /// level | transition faces << 8; for `grid=blocks`, as many as the counters' `active_blocks`). One
    /// buffer, as a stage binds at most 8 storage buffers.
    pub lod_data: wgpu::Buffer,
    pub draw_args: wgpu::Buffer,
}

impl MeshBuffers {
    /// Buffers for `grid` holding `capacity`. On a device without storage buffers (WebGL2) only the
    /// vertex and index buffers matter: the CPU mesher fills them and they are drawn directly.
    pub fn new(device: &wgpu::Device, grid: Grid, capacity: Capacity) -> Self {
        use wgpu::BufferUsages as U;
        let storage = crate::device::has_compute(device);
        let buffer = |label: &str, size: u64, usage: U| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: size.max(16),
                usage: if storage { usage | U::STORAGE } else { (usage - U::INDIRECT) | U::COPY_DST },
                mapped_at_creation: false,
            })
        };
        let blocks = capacity.blocks as u64;
        let total_blocks =
            if storage { (grid.cells_per_axis.div_ceil(BLOCK_CELLS) as u64).pow(3) } else { 0 };
        Self {
            grid,
            capacity,
            counters: buffer(
                "mesh: counters",
                std::mem::size_of::<CounterBlock>() as u64,
                U::COPY_SRC | U::COPY_DST,
            ),
            dispatch: buffer("mesh: per-block dispatch", 12, U::INDIRECT),
            cell_dispatch: buffer("mesh: per-cell dispatch", 12, U::INDIRECT),
            active_blocks: buffer("mesh: active blocks", blocks * 4, U::COPY_SRC),
            active_cells: buffer("mesh: active cells", capacity.cells as u64 * 4, U::empty()),
            block_slots: buffer("mesh: block slots", total_blocks * 4, U::empty()),
            block_values: buffer("mesh: block field values", blocks * BLOCK_VALUE_BYTES, U::COPY_SRC),
            cell_cases: buffer("mesh: cell cases", blocks * BLOCK_CASE_BYTES, U::empty()),
            edge_vertices: buffer("mesh: edge vertices", blocks * BLOCK_EDGE_BYTES, U::empty()),
            vertices: buffer(
                "mesh: vertices",
                capacity.vertices as u64 * VERTEX_BYTES,
                U::VERTEX | U::COPY_SRC | U::COPY_DST,
            ),
            indices: buffer(
                "mesh: indices",
                capacity.indices as u64 * INDEX_BYTES,
                U::INDEX | U::COPY_SRC | U::COPY_DST,
            ),
            lod_data: buffer(
                "mesh: LOD levels and blocks",
                if storage { (capacity.indices as u64 / 3 + 4 * blocks) * 4 } else { 0 },
                U::COPY_DST | U::COPY_SRC,
            ),
            draw_args: buffer("mesh: draw arguments", 20, U::INDIRECT),
        }
    }

    fn all(&self) -> [&wgpu::Buffer; 13] {
        [
            &self.counters,
            &self.dispatch,
            &self.cell_dispatch,
            &self.active_blocks,
            &self.active_cells,
            &self.block_slots,
            &self.block_values,
            &self.cell_cases,
            &self.edge_vertices,
            &self.vertices,
            &self.indices,
            &self.lod_data,
            &self.draw_args,
        ]
    }

    /// True when `vertices` vertices and `indices` indices fit in these buffers.
    pub fn holds(&self, vertices: u32, indices: u32) -> bool {
        vertices <= self.capacity.vertices && indices <= self.capacity.indices
    }

    /// Writes a mesh made on the CPU (6 `f32` per vertex, 3 indices per triangle), as much of it as
    /// the buffers hold, and returns the indices written.
    pub fn upload(&self, queue: &wgpu::Queue, vertices: &[f32], indices: &[u32]) -> u32 {
        let written = (indices.len() as u32).min(self.capacity.indices);
        if !vertices.is_empty() && vertices.len() as u64 <= 6 * self.capacity.vertices as u64 {
            queue.write_buffer(&self.vertices, 0, bytemuck::cast_slice(vertices));
        }
        if written > 0 {
            queue.write_buffer(&self.indices, 0, bytemuck::cast_slice(&indices[..written as usize]));
        }
        written
    }

    /// Where the LOD blocks start in `lod_data`, in words: after one level per triangle.
    pub fn lod_blocks_offset(&self) -> u32 {
        self.capacity.indices / 3
    }

    /// GPU memory these buffers hold, in bytes.
    pub fn bytes(&self) -> u64 {
        self.all().iter().map(|b| b.size()).sum()
    }

    /// Frees the buffers now rather than when the last reference goes.
    pub fn destroy(&self) {
        for buffer in self.all() {
            buffer.destroy();
        }
    }
}
