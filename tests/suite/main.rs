//! The native tests, in one binary: one module per subject (each was a test file of its own), built and
//! linked once, its tests spread over every core together. GPU tests draw on one shared device with
//! its pipelines compiled once (`common::with_renderer`); those that test the device itself (memory
//! counts, limits, loss) make their own. `cargo test --test suite MODULE::` runs one module.
#![cfg(not(target_arch = "wasm32"))]

#[path = "../common/mod.rs"]
mod common;

mod animation;
mod architecture;
mod bindings;
mod cell_topology;
mod cpu_mesher;
mod critical;
mod decider;
mod dual;
mod dual_gpu;
mod editing;
mod exact;
mod export;
mod extractors;
mod frame_stats;
mod gpu_matches_oracle;
mod hostile_inputs;
mod image;
mod js_layers;
mod kept_mesh;
mod kernels;
mod lab;
mod lod;
mod lod_select;
mod manifest;
mod march;
mod mc33;
mod mesh_properties;
mod parameters;
mod record;
mod scene_file;
mod scene_render;
mod shared_device;
mod slabs;
mod table;
mod tetrahedra;
mod ties;
mod topology;
mod views;
