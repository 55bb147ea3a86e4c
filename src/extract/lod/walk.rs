//! Level selection in compute passes (`shaders/extract/lod_select.wgsl`): the octree is walked one
//! level per dispatch, coarsest first, by the [`Rule`] the CPU's [`select`](super::select::select)
//! follows, and the leaves land where the meshing passes read them. The CPU writes one small uniform
//! a frame and encodes a fixed number of dispatches (two per level); nothing proportional to the blocks
//! crosses between the CPU and the device.

use super::select::{Eye, MAX_LEVELS, Rule};
use crate::device::{bind_buffers, bindings};
use crate::extract::buffers::MeshBuffers;
use crate::extract::gpu::scene_buffers::SceneBuffers;
use bytemuck::{Pod, Zeroable};

/// Workgroups in a row of a dispatch (`DISPATCH_ROW` in `shaders/common.wgsl`).
const DISPATCH_ROW: u32 = 32768;
/// Candidates the two queues hold per block the leaves have room for.
const QUEUED_PER_BLOCK: u64 = 8;
/// The most candidates a queue holds, whatever the leaves' room.
const MOST_QUEUED: u64 = 1 << 22;

/// The walk's uniforms (`Walk` in the shader).
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable, PartialEq)]
pub struct WalkUniform {
    /// The view frustum's planes ([`Eye::planes`]).
    pub planes: [glam::Vec4; 6],
    /// The eye in finest cells from the box's low corner; w: 1 to drop the blocks outside the view.
    pub eye: [f32; 4],
    /// [`Rule::split_below`] (four levels to a vector in the shader).
    pub split_below: [f32; 12],
    pub top: u32,
    pub roots_per_axis: u32,
    pub queue_capacity: u32,
    /// Where the kept blocks start in `lod_data`, in words.
    pub blocks_offset: u32,
}
const _: () = assert!(std::mem::size_of::<WalkUniform>() == 176);

impl WalkUniform {
    pub fn new(rule: &Rule, eye: &Eye, queue_capacity: u32, blocks_offset: u32) -> Self {
        Self {
            planes: eye.planes(),
            eye: [rule.eye.x, rule.eye.y, rule.eye.z, if eye.cull { 1.0 } else { 0.0 }],
            split_below: rule.split_below,
            top: rule.top,
            roots_per_axis: rule.roots_per_axis(),
            queue_capacity,
            blocks_offset,
        }
    }
}

/// The walk's state between its dispatches and frames (`WalkState` in the shader).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable, PartialEq, Eq)]
pub struct WalkState {
    pub level: u32,
    /// Levels at or below it are held back from splitting, after a frame ran out of room.
    pub floor: u32,
    pub overflowed: u32,
    pub queued: [u32; 2],
    pub leaves: u32,
    /// Some block of the last frame would have split but for the floor.
    pub held: u32,
    pub _pad: u32,
}

/// The walk's pipelines, compiled once per device from the level-of-detail module
/// (`shaders/extract/lod_select.wgsl` with `shaders/extract/lod.wgsl`).
pub struct WalkPipelines {
    pub begin: wgpu::ComputePipeline,
    pub select: wgpu::ComputePipeline,
    pub plan: wgpu::ComputePipeline,
}

/// One renderer's walk: its buffers and bind groups, for one capacity of the mesh buffers.
pub struct Walk {
    uniform: wgpu::Buffer,
    /// The state, kept from frame to frame (the floor), readable for tests.
    pub state: wgpu::Buffer,
    dispatch: wgpu::Buffer,
    queue_capacity: u32,
    blocks_offset: u32,
    groups: [wgpu::BindGroup; 3],
}

impl Walk {
    /// The walk writing its leaves into the mesh buffers' `lod_data` and counters, and the meshing
    /// passes' dispatch into `meshing` (`lod_dispatch`), with queues sized for the blocks they hold.
    pub fn new(
        device: &wgpu::Device,
        p: &WalkPipelines,
        scene: &SceneBuffers,
        mesh: &MeshBuffers,
        meshing: &wgpu::Buffer,
    ) -> Self {
        use wgpu::BufferUsages as U;
        let limit = device.limits().max_storage_buffer_binding_size / 8;
        let queue_capacity =
            (QUEUED_PER_BLOCK * mesh.capacity.blocks as u64).clamp(4096, MOST_QUEUED.min(limit)) as u32;
        let buffer = |label: &str, size: u64, usage: U| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size,
                usage,
                mapped_at_creation: false,
            })
        };
        let uniform =
            buffer("lod: rule", std::mem::size_of::<WalkUniform>() as u64, U::UNIFORM | U::COPY_DST);
        let queues = buffer("lod: queues", 8 * queue_capacity as u64, U::STORAGE);
        // Zeroed, as every new buffer is: no level held back, nothing overflowed.
        let state = buffer("lod: walk", std::mem::size_of::<WalkState>() as u64, U::STORAGE | U::COPY_SRC);
        let dispatch = buffer("lod: walk dispatch", 12 * MAX_LEVELS as u64, U::STORAGE | U::INDIRECT);
        let groups = [
            bind_buffers(
                device,
                "lod: begin",
                &p.begin,
                &[(bindings::GRID, &scene.grid), (bindings::WALK, &uniform), (bindings::STATE, &state)],
            ),
            bind_buffers(
                device,
                "lod: select",
                &p.select,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::SPHERES, &scene.spheres),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::WALK, &uniform),
                    (bindings::QUEUES, &queues),
                    (bindings::STATE, &state),
                    (bindings::LOD_DATA, &mesh.lod_data),
                ],
            ),
            bind_buffers(
                device,
                "lod: plan",
                &p.plan,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::WALK, &uniform),
                    (bindings::STATE, &state),
                    (bindings::WALK_DISPATCH, &dispatch),
                    (bindings::LOD_DISPATCH, meshing),
                ],
            ),
        ];
        Self { uniform, state, dispatch, queue_capacity, blocks_offset: mesh.lod_blocks_offset(), groups }
    }

    /// Candidates each of the two queues holds.
    pub fn queue_capacity(&self) -> u32 {
        self.queue_capacity
    }

    /// Writes the frame's rule: the one upload of the walk, a few hundred bytes.
    pub fn prepare(&self, queue: &wgpu::Queue, rule: &Rule, eye: &Eye) {
        let uniform = WalkUniform::new(rule, eye, self.queue_capacity, self.blocks_offset);
        queue.write_buffer(&self.uniform, 0, bytemuck::bytes_of(&uniform));
    }

    /// Encodes the walk for `rule` (written by `prepare`) into `pass`: after it the leaves are in
    /// `lod_data`, counted by the counters' `active_blocks`, and the meshing passes' dispatch is written.
    pub fn encode(&self, pass: &mut wgpu::ComputePass<'_>, p: &WalkPipelines, rule: &Rule) {
        let [begin, select, plan] = &self.groups;
        pass.set_pipeline(&p.begin);
        pass.set_bind_group(0, begin, &[]);
        pass.dispatch_workgroups(1, 1, 1);
        for level in (0..=rule.top).rev() {
            pass.set_pipeline(&p.select);
            pass.set_bind_group(0, select, &[]);
            if level == rule.top {
                let groups = rule.roots_per_axis().pow(3).div_ceil(64);
                pass.dispatch_workgroups(groups.min(DISPATCH_ROW), groups.div_ceil(DISPATCH_ROW), 1);
            } else {
                pass.dispatch_workgroups_indirect(&self.dispatch, 12 * level as u64);
            }
            pass.set_pipeline(&p.plan);
            pass.set_bind_group(0, plan, &[]);
            pass.dispatch_workgroups(1, 1, 1);
        }
    }
}
