//! Frame statistics: each frame copies the GPU's counters into a free staging buffer and maps it; later
//! frames read whichever have arrived (nothing waits for them) and plan larger buffers after an overflow.

use super::Renderer;
use super::limits::largest_capacity;
use crate::device::timing::Timing;
use crate::extract::buffers::{BLOCK_CELLS, Capacity};
use crate::extract::reference::Grid;
use crate::extract::uniforms::{CounterBlock, Counters, LEVEL_SLOTS, LevelCounts, Measures};
use std::sync::Arc;
use std::sync::atomic::{AtomicU8, Ordering};

/// What the GPU reported for a past frame (a frame or two late; nothing waits for it).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FrameStats {
    /// Which frame (counted from 1) these figures are for.
    pub frame: u64,
    /// Triangles written and drawn.
    pub triangles: u32,
    /// Triangles the surface needed; more than `max_triangles` when the index buffer overflowed.
    pub triangles_requested: u32,
    /// Capacity of the index buffer, in triangles.
    pub max_triangles: u32,
    /// Shared vertices the surface needed.
    pub vertices: u32,
    /// Blocks of 4³ cells the surface may cross (the others were skipped).
    pub active_blocks: u32,
    /// Blocks in the grid.
    pub total_blocks: u32,
    /// Cells that emitted triangles.
    pub active_cells: u32,
    /// Cells in the grid.
    pub total_cells: u64,
    /// True when some buffer was too small for this frame, so part of the surface was not drawn (the
    /// buffers grow for the next frames).
    pub overflowed: bool,
    /// GPU memory held by the mesh buffers, in bytes.
    pub mesh_bytes: u64,
    /// With level of detail, triangles per level (finest first).
    pub level_triangles: [u32; LEVEL_SLOTS],
    /// With level of detail selected on the device, blocks per level (finest first).
    pub level_blocks: [u32; LEVEL_SLOTS],
    /// With level of detail selected on the device, the finest level that was held back from splitting
    /// after a frame ran out of room (0: none).
    pub lod_floor: u32,
}

impl FrameStats {
    /// The figures of frame `frame` on `grid`, from the counts the surface needed and the capacity its
    /// buffers had: whatever went past the index buffer was not drawn.
    pub(super) fn from_counts(
        frame: u64,
        grid: Grid,
        capacity: Capacity,
        needed: Counters,
        overflowed: bool,
        mesh_bytes: u64,
        levels: LevelCounts,
    ) -> Self {
        Self {
            frame,
            triangles: needed.indices.min(capacity.indices) / 3,
            triangles_requested: needed.indices / 3,
            max_triangles: capacity.indices / 3,
            vertices: needed.vertices,
            active_blocks: needed.active_blocks,
            total_blocks: grid.cells_per_axis.div_ceil(BLOCK_CELLS).pow(3),
            active_cells: needed.active_cells,
            total_cells: (grid.cells_per_axis as u64).pow(3),
            overflowed: overflowed || levels.overflowed,
            mesh_bytes,
            level_triangles: levels.triangles,
            level_blocks: levels.blocks,
            lod_floor: levels.floor,
        }
    }

    /// True when the surface needed more room than the buffers had, so some of it was not drawn.
    pub fn overflowed(&self) -> bool {
        self.overflowed
    }
}

const SLOT_FREE: u8 = 0;
const SLOT_PENDING: u8 = 1;
const SLOT_READY: u8 = 2;
/// Staging buffers for the statistics: enough that a slow map never makes a frame skip its copy.
const STATS_SLOTS: usize = 3;

struct StatsSlot {
    buffer: wgpu::Buffer,
    state: Arc<AtomicU8>,
    frame: u64,
    capacity: Capacity,
    counted: bool,
    measured: bool,
}

/// Counters of one past frame, with the capacity its buffers had.
pub(super) struct Reading {
    pub frame: u64,
    pub capacity: Capacity,
    pub counters: Counters,
    /// Dual contouring's crossings on the GPU, after the mesh's vertices.
    pub crossings: u32,
    pub levels: LevelCounts,
    /// False when the mesh was uploaded, so the counters say nothing of it.
    pub counted: bool,
    /// The measures pass's sums, when it ran.
    pub measures: Option<Measures>,
}

/// A few mappable buffers the counters are copied into, frame after frame.
pub(super) struct StatsRing {
    slots: Vec<StatsSlot>,
}

impl StatsRing {
    pub fn new(device: &wgpu::Device) -> Self {
        let slots = (0..STATS_SLOTS)
            .map(|_| StatsSlot {
                buffer: device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some("stats: staging"),
                    size: std::mem::size_of::<CounterBlock>() as u64,
                    usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                    mapped_at_creation: false,
                }),
                state: Arc::new(AtomicU8::new(SLOT_FREE)),
                frame: 0,
                capacity: Capacity { blocks: 0, cells: 0, vertices: 0, indices: 0 },
                counted: false,
                measured: false,
            })
            .collect();
        Self { slots }
    }

    /// Records a copy of `counters` into a free staging buffer, if one is free (with every buffer still
    /// in flight, this frame's figures are skipped). Returns the slot to `map` once submitted.
    pub fn record(&self, encoder: &mut wgpu::CommandEncoder, counters: &wgpu::Buffer) -> Option<usize> {
        let slot = self.slots.iter().position(|s| s.state.load(Ordering::Acquire) == SLOT_FREE)?;
        encoder.copy_buffer_to_buffer(counters, 0, &self.slots[slot].buffer, 0, None);
        Some(slot)
    }

    /// Maps the slot `record` returned, after its frame was submitted: `counted` when the compute
    /// passes counted the mesh, `measured` when the measures pass ran.
    pub fn map(&mut self, slot: usize, frame: u64, capacity: Capacity, counted: bool, measured: bool) {
        let slot = &mut self.slots[slot];
        slot.frame = frame;
        slot.capacity = capacity;
        slot.counted = counted;
        slot.measured = measured;
        slot.state.store(SLOT_PENDING, Ordering::Release);
        let state = slot.state.clone();
        slot.buffer.map_async(wgpu::MapMode::Read, .., move |result| {
            state.store(if result.is_ok() { SLOT_READY } else { SLOT_FREE }, Ordering::Release);
        });
    }

    /// True while some copy has not been mapped yet.
    pub fn pending(&self) -> bool {
        self.slots.iter().any(|s| s.state.load(Ordering::Acquire) == SLOT_PENDING)
    }

    /// The readings mapped since the last call; their buffers are free again.
    pub fn take_ready(&mut self) -> Vec<Reading> {
        let mut readings = Vec::new();
        for slot in &mut self.slots {
            if slot.state.load(Ordering::Acquire) != SLOT_READY {
                continue;
            }
            let block: CounterBlock = match slot.buffer.get_mapped_range(..) {
                Ok(bytes) => bytemuck::pod_read_unaligned(&bytes),
                Err(_) => CounterBlock::default(),
            };
            slot.buffer.unmap();
            slot.state.store(SLOT_FREE, Ordering::Release);
            readings.push(Reading {
                frame: slot.frame,
                capacity: slot.capacity,
                counters: block.counters,
                crossings: block.crossings,
                levels: block.levels(),
                counted: slot.counted,
                measures: slot.measured.then_some(block.measures),
            });
        }
        readings
    }
}

/// The frames rendered, the newest statistics and the ring they come back through, and the timestamp
/// queries of timed frames.
pub(super) struct Statistics {
    pub ring: StatsRing,
    /// The newest statistics reported, if any yet.
    pub latest: Option<FrameStats>,
    /// Frames rendered so far: the newest frame's statistics carry this number once read back.
    pub frame: u64,
    /// Timestamp queries, once asked for on a device that has them.
    pub timing: Option<Timing>,
}

impl Statistics {
    pub fn new(device: &wgpu::Device) -> Self {
        Self { ring: StatsRing::new(device), latest: None, frame: 0, timing: None }
    }

    /// Takes `stats` unless newer ones are in.
    pub fn offer(&mut self, stats: FrameStats) {
        if self.latest.is_none_or(|s| s.frame < stats.frame) {
            self.latest = Some(stats);
        }
    }

    /// Asks for timestamp queries, if the device has them; returns whether it does.
    pub fn enable_timing(&mut self, device: &wgpu::Device, queue: &wgpu::Queue) -> bool {
        if self.timing.is_none() {
            self.timing = Timing::new(device, queue);
        }
        self.timing.is_some()
    }

    /// The timestamp queries for a frame that is `timed`.
    pub fn timing_for(&self, timed: bool) -> Option<&Timing> {
        self.timing.as_ref().filter(|_| timed)
    }
}

impl Renderer {
    /// Takes in the statistics that have arrived since the last frame, without drawing (a paused view
    /// calls this so its figures still come in).
    pub fn poll_stats(&mut self) {
        self.collect_stats();
    }

    /// Reads the statistics whose buffers have been mapped since the last call, and plans larger
    /// buffers when a frame overflowed.
    pub(super) fn collect_stats(&mut self) {
        #[cfg(not(target_arch = "wasm32"))]
        let _ = self.device.poll(wgpu::PollType::Poll);
        let grid = self.grid();
        for Reading { frame, capacity, counters, crossings, levels, counted, measures } in
            self.stats.ring.take_ready()
        {
            if let Some(sums) = measures {
                self.teaching.take_measures(frame, &sums);
            }
            if !counted {
                continue;
            }
            let overflowed = !capacity.holds(&counters);
            let bytes = self.stage.buffers.bytes();
            let stats = FrameStats::from_counts(frame, grid, capacity, counters, overflowed, bytes, levels);
            self.stats.offer(stats);
            // Grow once per size: figures from frames drawn with smaller buffers than now are stale. The
            // vertex buffer makes room for dual contouring's crossings after the mesh's vertices too.
            let room = Counters { vertices: counters.vertices.saturating_add(crossings), ..counters };
            self.stage.plan_growth(capacity, &room, largest_capacity(self.context.limits(), grid));
        }
    }

    /// Waits until the statistics of every submitted frame are in (tests and tools).
    pub async fn flush_stats(&mut self) {
        if self.stats.ring.pending() {
            let (sender, receiver) = futures_channel::oneshot::channel::<()>();
            // Queue work done implies earlier map callbacks have run.
            self.queue.on_submitted_work_done(move || {
                let _ = sender.send(());
            });
            #[cfg(not(target_arch = "wasm32"))]
            let _ = self.device.poll(wgpu::PollType::wait_indefinitely());
            let _ = receiver.await;
        }
        self.collect_stats();
    }
}
