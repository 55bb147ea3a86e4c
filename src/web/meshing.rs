//! Meshing off the page's thread: a view gives the job of its next frame's CPU mesh as numbers, the
//! page's mesher worker (a second instance of this module) meshes it with `mesh_job`, and the view
//! takes the mesh back and draws it, so that the page's thread only uploads and draws.

use super::{View, js_error};
use crate::extract::GivenMesh;
use crate::extract::cpu::elsewhere::Meshers;
use std::cell::RefCell;
use wasm_bindgen::prelude::*;

thread_local! {
    /// This instance's meshers, whose buffers are kept from job to job (boxed: a pointer to set up
    /// rather than every field).
    static MESHERS: RefCell<Box<Meshers>> = RefCell::default();
}

/// Meshes a job `View::cpu_job` packed: `[vertices (Float32Array), indices
/// (Uint32Array), active blocks, active cells, decided cells]`, the first four for `View::give_mesh`;
/// the last (Uint32Array, x, y, z and kind of each in turn), with marching cubes, the cells whose
/// triangles the asymptotic decider or MC33 changes (`CpuMesher::decided_cells`).
#[wasm_bindgen]
pub fn mesh_job(packed: &[f32]) -> Result<js_sys::Array, JsError> {
    MESHERS.with(|meshers| {
        let mut meshers = meshers.borrow_mut();
        let mesh = meshers.mesh(packed).map_err(js_error)?;
        let [blocks, cells] = mesh.counts;
        let out = js_sys::Array::of4(
            &js_sys::Float32Array::from(mesh.vertices.as_slice()),
            &js_sys::Uint32Array::from(mesh.indices.as_slice()),
            &blocks.into(),
            &cells.into(),
        );
        out.push(&js_sys::Uint32Array::from(meshers.decided_cells().as_flattened()));
        Ok(out)
    })
}

/// Meshes the layers of cells `from` to `to` of a job `View::cpu_job` packed (marching cubes only):
/// `[vertices (Float32Array), indices (Uint32Array), active blocks, active cells, the grid edge of
/// each vertex (Uint32Array)]`, joined with the other slabs' by the page (`www/lib/engine/slabs.js`).
#[wasm_bindgen]
pub fn mesh_slab(packed: &[f32], from: u32, to: u32) -> Result<js_sys::Array, JsError> {
    MESHERS.with(|meshers| {
        let mut meshers = meshers.borrow_mut();
        let slab = meshers.mesh_slab(packed, from, to).map_err(js_error)?;
        let [blocks, cells] = slab.counts;
        let out = js_sys::Array::of4(
            &js_sys::Float32Array::from(slab.vertices),
            &js_sys::Uint32Array::from(slab.indices),
            &blocks.into(),
            &cells.into(),
        );
        out.push(&js_sys::Uint32Array::from(slab.keys));
        Ok(out)
    })
}

/// The shape of a mesh of `vertex_count` vertices and `triangles` (three indices each, as
/// `View::mesh_triangles` gives them): `[components, genus, closed (0/1), manifold (0/1)]`.
#[wasm_bindgen]
pub fn mesh_shape(vertex_count: u32, triangles: &[u32]) -> Result<Vec<f64>, JsError> {
    let triangles: Vec<[u32; 3]> = triangles.chunks_exact(3).map(|t| [t[0], t[1], t[2]]).collect();
    if let Some(&beyond) = triangles.as_flattened().iter().find(|&&i| i >= vertex_count) {
        return Err(JsError::new(&format!("a triangle uses vertex {beyond} of {vertex_count}")));
    }
    let s = crate::extract::mesh::shape_of(vertex_count as usize, &triangles);
    Ok(vec![s.components as f64, s.genus as f64, s.closed as u8 as f64, s.manifold as u8 as f64])
}

#[wasm_bindgen]
impl View {
    /// Advances the animation by `dt` seconds without drawing (the frame is drawn once its mesh is in).
    pub fn advance(&mut self, dt: f32) -> Result<(), JsError> {
        self.renderer.update(dt).map_err(js_error)
    }

    /// The next frame's mesh job as numbers, when a mesher on the CPU makes it (else none); with
    /// `any`, the frame's scene as a job for marching cubes on the CPU whichever mesher draws it (for
    /// the cells the decider changes, from `mesh_job`).
    pub fn cpu_job(&self, any: bool) -> Option<Vec<f32>> {
        if any { Some(self.renderer.scene_job()) } else { self.renderer.cpu_job() }
    }

    /// The mesh `mesh_job` made of `job`: the next frame draws it while its job is still the frame's.
    pub fn give_mesh(
        &mut self,
        job: Vec<f32>,
        vertices: Vec<f32>,
        indices: Vec<u32>,
        blocks: u32,
        cells: u32,
    ) {
        self.renderer.give_mesh(GivenMesh { job, vertices, indices, counts: [blocks, cells] });
    }
}
