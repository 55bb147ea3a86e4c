//! The mesh stage: the buffers every extractor fills, the extractors themselves, which made the latest
//! mesh and how it was counted, and how the buffers are sized.

use crate::extract::Extractor;
use crate::extract::buffers::{Capacity, MeshBuffers};
use crate::extract::reference::Grid;
use crate::extract::uniforms::Counters;
use crate::scene::params::ParamError;

/// How the buffers are sized.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Sizing {
    /// Start from `Capacity::for_grid` and grow when a frame reports it needed more.
    Automatic,
    /// A fixed triangle budget (tests and tools); overflow is reported, nothing grows.
    FixedTriangles(u32),
    /// A fixed number of blocks (tests and tools): level of detail answers a frame that needs more
    /// with larger cells; everything else grows as with `Automatic`.
    FixedBlocks(u32),
}

/// How the latest frame's mesh was counted.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub(super) struct Counted {
    /// On the device: its statistics come back later.
    pub on_device: bool,
    /// The mesh is known to be closed: whole, by marching cubes, counted on the CPU.
    pub closed: bool,
    /// Indices the frame drew, when counted on the CPU.
    pub drawn: Option<u32>,
}

/// The mesh buffers and the extractors that fill them.
pub(super) struct MeshStage {
    pub buffers: MeshBuffers,
    /// Every extractor the device runs, in order of preference (`extract::EXTRACTORS`).
    pub extractors: Vec<Box<dyn Extractor>>,
    /// Which of them made the latest frame's mesh.
    pub active: usize,
    /// Which of them `pin` fixed, if any.
    pub pinned: Option<usize>,
    pub counted: Counted,
    pub sizing: Sizing,
    /// Capacity a past frame asked for, applied before the next one.
    pub pending_capacity: Option<Capacity>,
}

impl MeshStage {
    /// Buffers of `capacity` for `grid`, and a fresh instance of each of `extractors`.
    pub fn new(
        device: &wgpu::Device,
        extractors: &[Box<dyn Extractor>],
        grid: Grid,
        capacity: Capacity,
    ) -> Self {
        Self {
            buffers: MeshBuffers::new(device, grid, capacity),
            extractors: extractors.iter().map(|e| e.fresh()).collect(),
            active: 0,
            pinned: None,
            counted: Counted::default(),
            sizing: Sizing::Automatic,
            pending_capacity: None,
        }
    }

    /// Frees the buffers and makes them anew with `capacity` for `grid`; the extractors bind again.
    pub fn reallocate(&mut self, device: &wgpu::Device, grid: Grid, capacity: Capacity) {
        self.buffers.destroy();
        self.buffers = MeshBuffers::new(device, grid, capacity);
        self.pending_capacity = None;
        for extractor in &mut self.extractors {
            extractor.buffers_changed();
        }
    }

    /// The next frame meshes anew whatever its extractor kept of the last one.
    pub fn forget_meshes(&mut self) {
        for extractor in &mut self.extractors {
            extractor.forget_mesh();
        }
    }

    /// The extractor that made the latest frame's mesh.
    pub fn active(&self) -> &dyn Extractor {
        self.extractors[self.active].as_ref()
    }

    /// The names of the extractors, in order of preference.
    pub fn names(&self) -> Vec<&'static str> {
        self.extractors.iter().map(|e| e.name()).collect()
    }

    /// Fixes the extractor called `name` (`None` lets the settings choose again).
    pub fn pin(&mut self, name: Option<&str>) -> Result<(), ParamError> {
        self.pinned = match name {
            None => None,
            Some(name) => Some(self.extractors.iter().position(|e| e.name() == name).ok_or_else(|| {
                ParamError::Invalid {
                    name: "extractor",
                    value: name.to_string(),
                    expected: format!("one of {}", self.names().join(", ")).into(),
                }
            })?),
        };
        Ok(())
    }

    /// The room a frame asked for, clamped to a fixed triangle budget as the device clamps it.
    pub fn budgeted(&self, mut room: Counters) -> Counters {
        if let Sizing::FixedTriangles(n) = self.sizing {
            room.indices = room.indices.min(3 * n);
        }
        room
    }

    /// After a frame drawn with buffers of `capacity` that needed `counters`, plans larger buffers (at
    /// most `largest`) when it overflowed and the buffers still are that size and grow by themselves.
    pub fn plan_growth(&mut self, capacity: Capacity, counters: &Counters, largest: Capacity) {
        let current = self.pending_capacity.unwrap_or(self.buffers.capacity);
        let grows = matches!(self.sizing, Sizing::Automatic | Sizing::FixedBlocks(_));
        if !capacity.holds(counters) && grows && capacity == self.buffers.capacity {
            let mut grown = current.grown_for(counters).min(largest);
            if let Sizing::FixedBlocks(blocks) = self.sizing {
                grown.blocks = blocks;
            }
            if grown != current {
                self.pending_capacity = Some(grown);
            }
        }
    }

    /// Frees the buffers at once.
    pub fn destroy(&self) {
        self.buffers.destroy();
    }
}
