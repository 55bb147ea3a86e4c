//! Level of detail in compute shaders: the selection passes ([`walk`](super::walk)) choose the blocks
//! by the rule every path follows, and the meshing passes (`shaders/extract/lod.wgsl`) sample and mesh
//! them where they are, with indirect dispatches and draw and no readback. The CPU's part of a frame
//! is one small uniform and a fixed number of dispatches, however many blocks there are.

use super::select::{Eye, Rule};
use super::transition;
use super::walk::{Walk, WalkPipelines};
use super::{LodSummary, eye_of};
use crate::device::{
    COMMON_WGSL, bind_buffers, bindings, compute_pipeline, has_compute, shader_module, wgsl,
};
use crate::extract::buffers::MeshBuffers;
use crate::extract::extractor::{Capabilities, Extractor, Job, MeshCount, Output};
use crate::extract::gpu::scene_buffers::SceneBuffers;
use crate::extract::tables::{flat_triangle_table, packed_case_table};
use crate::extract::uniforms::Counters;
use crate::scene::params::view::Method;
use std::sync::{Arc, OnceLock};
use wgpu::util::DeviceExt;

/// Partitions of the vertex hash table (`PARTITIONS` in the shader).
const PARTITIONS: u64 = 1024;

/// The transition table as the shader reads it: per case the triangle count, then each triangle's
/// edges, a byte each (the two samples as nibbles).
pub fn packed_transition_table() -> Vec<u32> {
    let mut table = Vec::with_capacity(512 * 13);
    for case in 0..512 {
        let triangles: Vec<u32> = transition::triangles(case)
            .map(|t| {
                t.iter().enumerate().fold(0, |m, (j, &(a, b))| m | ((a as u32) | (b as u32) << 4) << (8 * j))
            })
            .collect();
        table.push(triangles.len() as u32);
        table.extend(&triangles);
        table.resize(table.len() + 12 - triangles.len(), 0);
    }
    table
}

/// The pipelines and tables, compiled once per device.
struct Pipelines {
    walk: WalkPipelines,
    find_cells: wgpu::ComputePipeline,
    plan_cells: wgpu::ComputePipeline,
    triangles: wgpu::ComputePipeline,
    finalize: wgpu::ComputePipeline,
    /// The case, triangle and transition tables in one buffer (`tables` in the shader).
    tables: wgpu::Buffer,
}

impl Pipelines {
    fn new(device: &wgpu::Device) -> Self {
        let meshing = wgsl!("extract/lod.wgsl");
        let selection = wgsl!("extract/lod_select.wgsl");
        let module = shader_module(device, "lod: shader", &[COMMON_WGSL, meshing, selection]);
        let pipeline = |name: &str| compute_pipeline(device, &format!("lod: {name} pipeline"), &module, name);
        let mut tables: Vec<u32> = packed_case_table().to_vec();
        tables.extend(flat_triangle_table().iter().map(|&e| e as u32));
        tables.extend(packed_transition_table());
        Self {
            walk: WalkPipelines {
                begin: pipeline("begin_walk"),
                select: pipeline("select_blocks"),
                plan: pipeline("plan_level"),
            },
            find_cells: pipeline("find_cells"),
            plan_cells: pipeline("plan_cells"),
            triangles: pipeline("make_triangles"),
            finalize: pipeline("finalize_draw"),
            tables: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("lod: tables"),
                contents: bytemuck::cast_slice(&tables),
                usage: wgpu::BufferUsages::STORAGE,
            }),
        }
    }
}

/// This renderer's buffers and bind groups, for one capacity of the mesh buffers.
struct Bound {
    walk: Walk,
    /// Per slot of the vertex hash table, its edge key and vertex.
    hash: wgpu::Buffer,
    dispatch: wgpu::Buffer,
    groups: [wgpu::BindGroup; 4],
}

impl Bound {
    fn new(device: &wgpu::Device, p: &Pipelines, scene: &SceneBuffers, mesh: &MeshBuffers) -> Self {
        use wgpu::BufferUsages as U;
        let buffer = |label: &str, size: u64, usage: U| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size: size.max(16),
                usage: usage | U::STORAGE,
                mapped_at_creation: false,
            })
        };
        let capacity = mesh.capacity;
        // Room for four slots per vertex, in partitions of a power of two.
        let partition_slots = (4 * capacity.vertices as u64).div_ceil(PARTITIONS).next_power_of_two().max(4);
        let table_slots = partition_slots * PARTITIONS;
        let uniform = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("lod: uniforms"),
            contents: bytemuck::cast_slice(&[0u32, partition_slots as u32, mesh.lod_blocks_offset(), 0]),
            usage: U::UNIFORM | U::COPY_DST,
        });
        let cells = buffer("lod: listed cells", capacity.cells as u64 * 8, U::empty());
        let hash = buffer("lod: vertex hash table", table_slots * 8, U::COPY_DST);
        let dispatch = buffer("lod: dispatch", 24, U::INDIRECT);
        let group = |label: &str, pipeline: &wgpu::ComputePipeline, entries: &[(u32, &wgpu::Buffer)]| {
            bind_buffers(device, label, pipeline, entries)
        };
        let groups = [
            group(
                "lod: find cells",
                &p.find_cells,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::SPHERES, &scene.spheres),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::LOD_TABLES, &p.tables),
                    (bindings::VERTICES, &mesh.vertices),
                    (bindings::LOD, &uniform),
                    (bindings::CELLS, &cells),
                    (bindings::HASH, &hash),
                    (bindings::LOD_DATA, &mesh.lod_data),
                ],
            ),
            group(
                "lod: plan cells",
                &p.plan_cells,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::LOD_DISPATCH, &dispatch),
                ],
            ),
            group(
                "lod: triangles",
                &p.triangles,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::LOD_TABLES, &p.tables),
                    (bindings::INDICES, &mesh.indices),
                    (bindings::LOD, &uniform),
                    (bindings::CELLS, &cells),
                    (bindings::HASH, &hash),
                    (bindings::LOD_DATA, &mesh.lod_data),
                ],
            ),
            group(
                "lod: finalize",
                &p.finalize,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::DRAW_ARGS, &mesh.draw_args),
                ],
            ),
        ];
        let walk = Walk::new(device, &p.walk, scene, mesh, &dispatch);
        Self { walk, hash, dispatch, groups }
    }
}

/// Level of detail in compute shaders: compiled on the first frame that needs it.
pub struct LodGpuExtractor {
    compiled: Arc<OnceLock<Pipelines>>,
    bound: Option<Bound>,
    /// The frame's rule and eye, from `prepare`.
    rule: Option<(Rule, Eye)>,
    /// The eye while the selection is frozen.
    frozen: Option<Eye>,
}

impl LodGpuExtractor {
    /// The passes, on a device with compute shaders.
    pub fn compile(device: &wgpu::Device) -> Option<Box<dyn Extractor>> {
        if !has_compute(device) {
            return None;
        }
        // On wasm32 wgpu's objects are not Send: a page runs them on one thread.
        #[allow(clippy::arc_with_non_send_sync)]
        let compiled = Arc::new(OnceLock::new());
        Some(Box::new(Self { compiled, bound: None, rule: None, frozen: None }))
    }
}

impl Extractor for LodGpuExtractor {
    fn name(&self) -> &'static str {
        "lod-gpu"
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            needs_compute: true,
            cell_lists: false,
            cpu_copy: false,
            lod: true,
            method: Method::MarchingCubes,
        }
    }

    fn fresh(&self) -> Box<dyn Extractor> {
        Box::new(Self { compiled: self.compiled.clone(), bound: None, rule: None, frozen: None })
    }

    fn buffers_changed(&mut self) {
        self.bound = None;
    }

    fn pipeline_sets(&self) -> usize {
        usize::from(self.compiled.get().is_some())
    }

    /// Makes the frame's rule: a few numbers, whatever the blocks; the device walks the octree.
    fn prepare(&mut self, job: &Job) -> Option<Counters> {
        self.rule =
            eye_of(&mut self.frozen, job).map(|eye| (Rule::new(job.grid.cells_per_axis, &eye, 0), eye));
        None
    }

    fn write(&mut self, output: Output) -> MeshCount {
        let Output { device, queue, scene, encoder, buffers, timing, .. } = output;
        let Some((rule, eye)) = self.rule else { return MeshCount::OnDevice };
        let p = self.compiled.get_or_init(|| Pipelines::new(device));
        let bound = self.bound.get_or_insert_with(|| Bound::new(device, p, scene, buffers));
        bound.walk.prepare(queue, &rule, &eye);
        encoder.clear_buffer(&buffers.counters, 0, None);
        encoder.clear_buffer(&bound.hash, 0, None);
        let [find_cells, plan_cells, triangles, finalize] = &bound.groups;
        let describe = |label: &'static str, stage: u32| wgpu::ComputePassDescriptor {
            label: Some(label),
            timestamp_writes: timing.map(|t| t.compute_writes(stage)),
        };
        {
            let mut pass = encoder.begin_compute_pass(&describe("lod: selection", 0));
            bound.walk.encode(&mut pass, &p.walk, &rule);
        }
        {
            let mut pass = encoder.begin_compute_pass(&describe("lod: cells", 2));
            pass.set_pipeline(&p.find_cells);
            pass.set_bind_group(0, find_cells, &[]);
            pass.dispatch_workgroups_indirect(&bound.dispatch, 0);
            pass.set_pipeline(&p.plan_cells);
            pass.set_bind_group(0, plan_cells, &[]);
            pass.dispatch_workgroups(1, 1, 1);
        }
        {
            let mut pass = encoder.begin_compute_pass(&describe("lod: triangles", 3));
            pass.set_pipeline(&p.triangles);
            pass.set_bind_group(0, triangles, &[]);
            pass.dispatch_workgroups_indirect(&bound.dispatch, 12);
            pass.set_pipeline(&p.finalize);
            pass.set_bind_group(0, finalize, &[]);
            pass.dispatch_workgroups(1, 1, 1);
        }
        MeshCount::OnDevice
    }

    /// The blocks and triangles per level are counted on the device: the statistics read them back.
    fn lod_summary(&self) -> Option<LodSummary> {
        let (rule, _) = self.rule?;
        Some(LodSummary {
            resolution: rule.resolution,
            blocks: Vec::new(),
            triangles: None,
            cells_processed: None,
        })
    }
}
