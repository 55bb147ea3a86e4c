//! Extraction in compute shaders, all on the device: the block pass bounds the field over blocks of 4³
//! cells and lists those the surface may cross, the field pass evaluates them and lists the crossed
//! cells, and the per-cell passes (marching cubes or tetrahedra, surface nets or dual contouring) write
//! shared vertices and indices. Counters feed indirect
//! dispatches and the indexed indirect draw; nothing is read back.

pub mod blocks;
pub mod field;
pub mod marching;
pub mod scene_buffers;

use super::extractor::{Capabilities, Crossings, Extractor, Job, MeshCount, Output};
use super::uniforms::Counters;
use crate::device::has_compute;
use crate::scene::params::view::Method;
use blocks::BlockPass;
use field::FieldPass;
use marching::MarchingPass;
use std::sync::{Arc, OnceLock};

/// The three compute passes.
#[derive(Clone)]
struct Passes {
    blocks: BlockPass,
    field: FieldPass,
    marching: MarchingPass,
}

/// The compute passes, compiled once per device on the first frame that uses them (so a page whose
/// frames are meshed on the CPU, as on a software adapter, never waits for them); clones share the
/// compiled pipelines and bind their own buffers.
#[derive(Clone)]
pub struct GpuExtractor {
    /// Marching cubes or tetrahedra, surface nets or dual contouring.
    method: Method,
    compiled: Arc<OnceLock<Passes>>,
    /// This renderer's passes, bound to its current buffers; `None` until a frame uses them after the
    /// buffers were made.
    bound: Option<Passes>,
}

impl GpuExtractor {
    /// Marching cubes' passes, on a device with compute shaders (compiled when a frame first needs
    /// them).
    pub fn compile(device: &wgpu::Device) -> Option<Box<dyn Extractor>> {
        Self::of(device, Method::MarchingCubes)
    }

    /// Marching tetrahedra's passes (`method=marching_tetrahedra`), likewise.
    pub fn compile_tetrahedra(device: &wgpu::Device) -> Option<Box<dyn Extractor>> {
        Self::of(device, Method::MarchingTetrahedra)
    }

    /// Surface nets' passes (`method=surface_nets`), likewise.
    pub fn compile_surface_nets(device: &wgpu::Device) -> Option<Box<dyn Extractor>> {
        Self::of(device, Method::SurfaceNets)
    }

    /// Dual contouring's passes (`method=dual_contouring`), likewise.
    pub fn compile_dual_contouring(device: &wgpu::Device) -> Option<Box<dyn Extractor>> {
        Self::of(device, Method::DualContouring)
    }

    fn of(device: &wgpu::Device, method: Method) -> Option<Box<dyn Extractor>> {
        if !has_compute(device) {
            return None;
        }
        // On wasm32 wgpu's objects are not Send: a page runs them on one thread.
        #[allow(clippy::arc_with_non_send_sync)]
        let compiled = Arc::new(OnceLock::new());
        Some(Box::new(Self { method, compiled, bound: None }))
    }
}

impl Extractor for GpuExtractor {
    fn name(&self) -> &'static str {
        match self.method {
            Method::MarchingCubes => "gpu",
            Method::MarchingTetrahedra => "gpu-tetrahedra",
            Method::SurfaceNets => "gpu-surface-nets",
            Method::DualContouring => "gpu-dual-contouring",
        }
    }

    fn capabilities(&self) -> Capabilities {
        Capabilities {
            needs_compute: true,
            // The teaching views' cell lists are marching cubes' cases.
            cell_lists: self.method == Method::MarchingCubes,
            cpu_copy: false,
            lod: false,
            method: self.method,
        }
    }

    fn fresh(&self) -> Box<dyn Extractor> {
        Box::new(self.clone())
    }

    fn buffers_changed(&mut self) {
        self.bound = None;
    }

    fn pipeline_sets(&self) -> usize {
        usize::from(self.compiled.get().is_some())
    }

    fn crossings(&self) -> Option<Crossings> {
        (self.method == Method::DualContouring).then_some(Crossings::Counted)
    }

    /// The passes read the scene from the uniforms the renderer uploaded: nothing to do before them.
    fn prepare(&mut self, _job: &Job) -> Option<Counters> {
        None
    }

    fn write(&mut self, output: Output) -> MeshCount {
        let Output { device, scene, encoder, buffers, timing, .. } = output;
        let passes = self.bound.get_or_insert_with(|| {
            let mut passes = self
                .compiled
                .get_or_init(|| Passes {
                    blocks: BlockPass::new(device),
                    field: FieldPass::new(device),
                    marching: match self.method {
                        Method::MarchingCubes => MarchingPass::cubes(device),
                        Method::MarchingTetrahedra => MarchingPass::tetrahedra(device),
                        Method::SurfaceNets | Method::DualContouring => MarchingPass::dual(device),
                    },
                })
                .clone();
            passes.blocks.bind(device, scene, buffers);
            passes.field.bind(device, scene, buffers);
            passes.marching.bind(device, scene, buffers);
            passes
        });
        passes.blocks.encode(encoder, buffers, timing.map(|t| t.compute_writes(1)));
        passes.field.encode(encoder, buffers, timing.map(|t| t.compute_writes(2)));
        passes.marching.encode(encoder, buffers, timing.map(|t| t.compute_writes(3)));
        MeshCount::OnDevice
    }
}
