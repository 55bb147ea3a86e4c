//! GPU time per stage from timestamp queries, for benchmarks (where the adapter has them).

use crate::device::read_buffer;

/// The stages timed, in frame order.
/// The first is level of detail's selection of blocks (nothing for a uniform grid).
pub const STAGES: [&str; 5] = ["selection", "blocks", "field", "marching cubes", "shading"];

/// GPU milliseconds spent in each stage of one frame.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StageTimes {
    /// In `STAGES` order.
    pub stages_ms: [f64; 5],
}

impl StageTimes {
    /// From the first stage's start to the last one's end.
    pub fn total_ms(&self) -> f64 {
        self.stages_ms.iter().sum()
    }
}

/// A query set with a begin and an end timestamp per stage.
pub struct Timing {
    queries: wgpu::QuerySet,
    resolved: wgpu::Buffer,
    period_ns: f64,
}

impl Timing {
    /// `None` when the device lacks timestamp queries.
    pub fn new(device: &wgpu::Device, queue: &wgpu::Queue) -> Option<Self> {
        if !device.features().contains(wgpu::Features::TIMESTAMP_QUERY) {
            return None;
        }
        let count = 2 * STAGES.len() as u32;
        Some(Self {
            queries: device.create_query_set(&wgpu::QuerySetDescriptor {
                label: Some("timing: timestamps"),
                ty: wgpu::QueryType::Timestamp,
                count,
            }),
            resolved: device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("timing: resolved timestamps"),
                size: count as u64 * 8,
                usage: wgpu::BufferUsages::QUERY_RESOLVE | wgpu::BufferUsages::COPY_SRC,
                mapped_at_creation: false,
            }),
            period_ns: queue.get_timestamp_period() as f64,
        })
    }

    /// Timestamps around compute stage `stage`.
    pub fn compute_writes(&self, stage: u32) -> wgpu::ComputePassTimestampWrites<'_> {
        wgpu::ComputePassTimestampWrites {
            query_set: &self.queries,
            beginning_of_pass_write_index: Some(2 * stage),
            end_of_pass_write_index: Some(2 * stage + 1),
        }
    }

    /// Timestamps around render stage `stage`.
    pub fn render_writes(&self, stage: u32) -> wgpu::RenderPassTimestampWrites<'_> {
        wgpu::RenderPassTimestampWrites {
            query_set: &self.queries,
            beginning_of_pass_write_index: Some(2 * stage),
            end_of_pass_write_index: Some(2 * stage + 1),
        }
    }

    /// Copies the timestamps where `read` finds them.
    pub fn resolve(&self, encoder: &mut wgpu::CommandEncoder) {
        encoder.resolve_query_set(&self.queries, 0..2 * STAGES.len() as u32, &self.resolved, 0);
    }

    /// The stage times of the frame resolved last. Waits for the GPU.
    pub async fn read(&self, device: &wgpu::Device, queue: &wgpu::Queue) -> StageTimes {
        let bytes = read_buffer(device, queue, &self.resolved, 0, self.resolved.size()).await;
        let ticks: &[u64] = bytemuck::cast_slice(&bytes);
        let mut times = StageTimes::default();
        for (stage, ms) in times.stages_ms.iter_mut().enumerate() {
            *ms = ticks[2 * stage + 1].saturating_sub(ticks[2 * stage]) as f64 * self.period_ns / 1e6;
        }
        times
    }
}
