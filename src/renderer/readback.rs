//! Reading the mesh and the field back from the GPU: for tests and tools, never the frame loop.

use super::Renderer;
use super::limits::storage_limit;
use super::stage::Sizing;
use crate::device::{read_buffer, try_map_and_read};
use crate::extract::buffers::{BLOCK_CELLS, Capacity, INDEX_BYTES, VERTEX_BYTES};
use crate::extract::mesh::IndexedMesh;
use crate::extract::uniforms::Counters;
use glam::{UVec3, Vec3};

impl Renderer {
    /// Extracts and reads the counters back, with a level-of-detail selection that ran out of room
    /// asking for more blocks than the buffers hold (it does by itself: see `plan_level`).
    async fn run_extraction(&mut self) -> Counters {
        self.extract();
        let bytes = read_buffer(&self.device, &self.queue, &self.stage.buffers.counters, 0, 16).await;
        bytemuck::pod_read_unaligned(&bytes)
    }

    /// Extracts the surface for the current state and reads the indexed mesh back, growing the buffers
    /// first if the surface needs it (unless the budget is fixed). Waits for the GPU: for tests and
    /// tools, not the frame loop.
    /// An extractor that keeps its mesh on the CPU gives it as it was uploaded.
    pub async fn extract_mesh(&mut self) -> IndexedMesh {
        if self.next_capabilities().cpu_copy {
            return self.mesh_readback().finish_clamped().await.0;
        }
        let mut counters = self.run_extraction().await;
        while self.stage.sizing == Sizing::Automatic && !self.stage.buffers.capacity.holds(&counters) {
            let largest = Capacity::largest(self.grid(), storage_limit(self.context.limits()));
            let grown = self.stage.buffers.capacity.grown_for(&counters).min(largest);
            if grown == self.stage.buffers.capacity {
                break;
            }
            self.reallocate(grown);
            counters = self.run_extraction().await;
        }
        self.mesh_readback().finish_clamped().await.0
    }

    /// With level of detail, the blocks the latest frame selected, as the views draw them (origin in
    /// finest cells, then level | transition faces << 8), read back from the device; empty without.
    /// Waits for the GPU: for tests and tools.
    pub async fn lod_blocks(&self) -> Vec<[u32; 4]> {
        let buffers = &self.stage.buffers;
        if !self.settings.view.lod || !buffers.counters.usage().contains(wgpu::BufferUsages::STORAGE) {
            return Vec::new();
        }
        let counters = read_buffer(&self.device, &self.queue, &buffers.counters, 0, 16).await;
        let counters: Counters = bytemuck::pod_read_unaligned(&counters);
        let count = counters.active_blocks.min(buffers.capacity.blocks) as u64;
        if count == 0 {
            return Vec::new();
        }
        let at = 4 * buffers.lod_blocks_offset() as u64;
        let bytes = read_buffer(&self.device, &self.queue, &buffers.lod_data, at, 16 * count).await;
        bytemuck::cast_slice(&bytes).to_vec()
    }

    /// The field values the GPU computed for the current state: every grid point of every active block,
    /// with its grid coordinates (a point on a face between blocks appears once per block).
    pub async fn extract_field(&mut self) -> Vec<(UVec3, f32)> {
        let counters = self.run_extraction().await;
        let active = counters.active_blocks.min(self.stage.buffers.capacity.blocks) as u64;
        let blocks =
            read_buffer(&self.device, &self.queue, &self.stage.buffers.active_blocks, 0, active * 4).await;
        let values =
            read_buffer(&self.device, &self.queue, &self.stage.buffers.block_values, 0, active * 500).await;
        let blocks: &[u32] = bytemuck::cast_slice(&blocks);
        let values: &[f32] = bytemuck::cast_slice(&values);
        let n = self.settings.resolution;
        let per_axis = n.div_ceil(BLOCK_CELLS);
        let mut points = Vec::new();
        for (slot, &block) in blocks.iter().enumerate() {
            let coords =
                UVec3::new(block % per_axis, (block / per_axis) % per_axis, block / (per_axis * per_axis));
            for i in 0..125u32 {
                let id = coords * BLOCK_CELLS + UVec3::new(i % 5, (i / 5) % 5, i / 25);
                if id.max_element() <= n {
                    points.push((id, values[slot * 125 + i as usize]));
                }
            }
        }
        points
    }
}

/// What the overlay pass planned for the last frame drawn with teaching views.
#[derive(Clone, Debug, PartialEq)]
pub struct OverlayReadback {
    /// (vertices, instances) of the triangle, point, normal, cell, block, ambiguous-face and contour
    /// draws, in that order.
    pub draws: [(u32, u32); 7],
    /// The slice's contour segments.
    pub segments: Vec<[Vec3; 2]>,
}

impl Renderer {
    /// Reads back what the overlay pass planned in the last frame (`None` when no teaching view was
    /// drawn). Waits for the GPU: for tests and tools.
    pub async fn read_overlays(&self) -> Option<OverlayReadback> {
        let views = self.teaching.views.as_ref()?;
        let (segments, overlays) = views.contour_buffers();
        let bytes = read_buffer(&self.device, &self.queue, overlays, 0, overlays.size()).await;
        let words: Vec<u32> = bytemuck::pod_collect_to_vec(&bytes);
        let draws: [(u32, u32); 7] = std::array::from_fn(|k| (words[4 + 4 * k], words[5 + 4 * k]));
        let count = draws[6].1 as u64;
        let bytes = read_buffer(&self.device, &self.queue, segments, 0, count * 32).await;
        let points: Vec<[f32; 4]> = bytemuck::pod_collect_to_vec(&bytes);
        let segments = points
            .chunks(2)
            .map(|pair| [Vec3::from_slice(&pair[0][..3]), Vec3::from_slice(&pair[1][..3])])
            .collect();
        Some(OverlayReadback { draws, segments })
    }
}

/// The mesh of one frame on its way back from the GPU. It owns what it reads, so a page can wait for it
/// while the renderer goes on drawing: the copies were queued right after that frame's extraction.
pub enum MeshReadback {
    /// A mesh kept on the CPU: nothing to wait for.
    Ready(IndexedMesh),
    /// Copies of the counters and the vertex and index buffers, queued behind the extraction, and the
    /// capacity the buffers had.
    Queued {
        device: wgpu::Device,
        counters: wgpu::Buffer,
        vertices: wgpu::Buffer,
        indices: wgpu::Buffer,
        capacity: Capacity,
    },
}

impl MeshReadback {
    /// The mesh, or why it is incomplete (the frame's triangles outgrew the buffers).
    pub async fn finish(self) -> Result<IndexedMesh, String> {
        let (mesh, requested) = self.finish_clamped().await;
        if requested == usize::MAX {
            return Err(
                "the surface needs more room than the mesh buffers held in this frame; try again in \
                        a moment, or lower the resolution"
                    .into(),
            );
        }
        if requested > mesh.triangles.len() {
            return Err(format!(
                "the surface needs {requested} triangles, more than the mesh buffers held in this frame; \
                 try again in a moment, or lower the resolution"
            ));
        }
        Ok(mesh)
    }

    /// The mesh as far as the buffers held it, and the triangle count the frame asked for (`usize::MAX`
    /// where a level-of-detail selection ran out of room, so that nothing was meshed, or the blocks,
    /// cells or vertices did, so that triangles are missing or lost corners).
    pub async fn finish_clamped(self) -> (IndexedMesh, usize) {
        let (device, counters, vertices, indices, capacity) = match self {
            MeshReadback::Ready(mesh) => {
                let count = mesh.triangles.len();
                return (mesh, count);
            }
            MeshReadback::Queued { device, counters, vertices, indices, capacity } => {
                (device, counters, vertices, indices, capacity)
            }
        };
        // A device lost while the copies were on their way gives no bytes: an empty mesh, not a panic
        // (the figure starts again on a new device).
        let empty = || (IndexedMesh { positions: Vec::new(), normals: Vec::new(), triangles: Vec::new() }, 0);
        let Some(block) = try_map_and_read(&device, &counters).await else {
            return empty();
        };
        let counters: Counters = bytemuck::pod_read_unaligned(&block[..std::mem::size_of::<Counters>()]);
        let out_of_room = block.get(16..20).is_some_and(|w| w != [0; 4]);
        let vertex_count = (counters.vertices as u64).min(vertices.size() / VERTEX_BYTES);
        // Blocks, cells or vertices past the buffers leave triangles out or without corners.
        let out_of_room = out_of_room || !capacity.holds(&Counters { indices: 0, ..counters });
        let index_count = (counters.indices as u64).min(indices.size() / INDEX_BYTES / 3 * 3);
        let (Some(vertex_bytes), Some(index_bytes)) =
            (try_map_and_read(&device, &vertices).await, try_map_and_read(&device, &indices).await)
        else {
            return empty();
        };
        let floats: &[[f32; 6]] =
            bytemuck::cast_slice(&vertex_bytes[..(vertex_count * VERTEX_BYTES) as usize]);
        let indices: &[u32] = bytemuck::cast_slice(&index_bytes[..(index_count * INDEX_BYTES) as usize]);
        let mesh = IndexedMesh {
            positions: floats.iter().map(|v| Vec3::new(v[0], v[1], v[2])).collect(),
            normals: floats.iter().map(|v| Vec3::new(v[3], v[4], v[5])).collect(),
            triangles: indices.chunks(3).map(|t| [t[0], t[1], t[2]]).collect(),
        };
        (mesh, if out_of_room { usize::MAX } else { counters.indices as usize / 3 })
    }
}

impl Renderer {
    /// Extracts the surface for the current state and queues its readback: one on-demand copy (for
    /// exports), never part of a frame. An extractor that keeps its mesh on the CPU has it at hand.
    pub fn mesh_readback(&mut self) -> MeshReadback {
        self.extract();
        self.drawn_mesh_readback()
    }

    /// Queues the readback of the mesh the last frame drew, without extracting again: for what is
    /// measured of the picture on show (its live topology), where the scene may already have moved on
    /// while its next mesh is made elsewhere.
    pub fn drawn_mesh_readback(&self) -> MeshReadback {
        if let Some(mesh) = self.active_extractor().cpu_mesh() {
            return MeshReadback::Ready(mesh);
        }
        let staging = |label: &str, size: u64| {
            self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: size.max(16),
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            })
        };
        // The counters, and whether a level-of-detail selection ran out of room (`lod_overflowed`).
        let counters = staging("mesh readback: counters", 24);
        let mesh = &self.stage.buffers;
        let vertices = staging("mesh readback: vertices", mesh.vertices.size());
        let indices = staging("mesh readback: indices", mesh.indices.size());
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: Some("mesh readback: copy") });
        encoder.copy_buffer_to_buffer(&mesh.counters, 0, &counters, 0, 24);
        encoder.copy_buffer_to_buffer(&mesh.vertices, 0, &vertices, 0, mesh.vertices.size());
        encoder.copy_buffer_to_buffer(&mesh.indices, 0, &indices, 0, mesh.indices.size());
        self.queue.submit([encoder.finish()]);
        let capacity = mesh.capacity;
        MeshReadback::Queued { device: self.device.clone(), counters, vertices, indices, capacity }
    }
}
