//! The passes over the active cells, one struct for every method: marching cubes
//! (`shaders/extract/marching_cubes.wgsl`), marching tetrahedra
//! (`shaders/extract/marching_tetrahedra.wgsl`) and the dual methods, surface nets and dual contouring
//! (`shaders/extract/dual.wgsl`), each after the part they share (`shaders/extract/cells.wgsl`).
//! Vertices (on the edges, and with tetrahedra the diagonals, each cell owns; with the dual methods
//! one in each cell), then triangles as indices into them, then the indexed indirect draw's arguments.

use crate::device::{COMMON_WGSL, bind_buffers, bindings, compute_pipeline, shader_module, wgsl};
use crate::extract::buffers::MeshBuffers;
use crate::extract::decider::variant_table;
use crate::extract::gpu::scene_buffers::SceneBuffers;
use metaballs_core::extract::tetra::{
    SLOTS, TETRAHEDRA, TETRAHEDRA_PER_CELL, TETRAHEDRON_TRIANGLE_COUNTS, TETRAHEDRON_TRIANGLES,
};
use wgpu::util::DeviceExt;

const CELLS_WGSL: &str = wgsl!("extract/cells.wgsl");

/// Where the cases start in marching tetrahedra's tables: after three rows of six tetrahedra (`CASES`
/// in the shader).
const CASES: usize = 3 * 6;

/// Marching tetrahedra's tables as the shader reads them: each split's tetrahedra (six words a row,
/// four corners of 3 bits each), then each case's triangle count and triangles (each vertex as its
/// edge's two corners of the tetrahedron, 2 bits each).
fn tetra_table() -> Vec<u32> {
    let mut table = vec![0; CASES + 16];
    for (row, &count) in TETRAHEDRA_PER_CELL.iter().enumerate() {
        for (k, t) in TETRAHEDRA[row][..count].iter().enumerate() {
            table[row * 6 + k] = (0..4).map(|i| (t[i] as u32) << (3 * i)).sum();
        }
    }
    for (case, triangles) in TETRAHEDRON_TRIANGLES.iter().enumerate() {
        let count = TETRAHEDRON_TRIANGLE_COUNTS[case];
        let mut word = count as u32;
        for (j, triangle) in triangles[..count].iter().enumerate() {
            for (i, &[a, b]) in triangle.iter().enumerate() {
                word |= ((a | b << 2) as u32) << (2 + 12 * j + 4 * i);
            }
        }
        table[CASES + case] = word;
    }
    table
}

/// Which passes: they differ in their tables and buffers.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Kind {
    Cubes,
    /// The tables' binding is `TETRA_TABLE`, and the vertices of the seven segments each active cell
    /// owns are kept in a buffer of the pass's own (the mesh's holds three a cell).
    Tetrahedra,
    /// No table; a first dispatch finds the crossings of the three edges each active cell owns into a
    /// buffer of the pass's own (`EDGE_CROSSINGS`), and the quads read the vertices (for their shorter
    /// diagonal) and write each triangle's QEF marks into `LOD_DATA`.
    Dual,
}

/// Owns one method's per-cell pipelines, its tables on the GPU, and bind groups for the current
/// buffers.
#[derive(Clone)]
pub struct MarchingPass {
    label: &'static str,
    /// With the dual methods, the crossings before the vertices.
    crossings: Option<wgpu::ComputePipeline>,
    vertices: wgpu::ComputePipeline,
    triangles: wgpu::ComputePipeline,
    finalize: wgpu::ComputePipeline,
    table: wgpu::Buffer,
    kind: Kind,
    /// In the order the dispatches run: vertices, triangles, draw, and with the dual methods the
    /// crossings first.
    groups: Vec<wgpu::BindGroup>,
}

impl MarchingPass {
    /// Marching cubes, with every case table's triangles.
    pub fn cubes(device: &wgpu::Device) -> Self {
        let source = wgsl!("extract/marching_cubes.wgsl");
        Self::new(
            device,
            "marching cubes",
            source,
            "make_vertices",
            "make_triangles",
            variant_table(),
            Kind::Cubes,
        )
    }

    /// Marching tetrahedra, either split.
    pub fn tetrahedra(device: &wgpu::Device) -> Self {
        let source = wgsl!("extract/marching_tetrahedra.wgsl");
        let (vertices, triangles) = ("make_tetra_vertices", "make_tetra_triangles");
        Self::new(
            device,
            "marching tetrahedra",
            source,
            vertices,
            triangles,
            &tetra_table(),
            Kind::Tetrahedra,
        )
    }

    /// Surface nets and dual contouring (`FLAG_QEF` in the grid's flags chooses).
    pub fn dual(device: &wgpu::Device) -> Self {
        let source = wgsl!("extract/dual.wgsl");
        Self::new(device, "dual methods", source, "make_dual_vertices", "make_dual_quads", &[0], Kind::Dual)
    }

    fn new(
        device: &wgpu::Device,
        label: &'static str,
        source: &str,
        vertices: &str,
        triangles: &str,
        table: &[u32],
        kind: Kind,
    ) -> Self {
        let module = shader_module(device, label, &[COMMON_WGSL, CELLS_WGSL, source]);
        let pipeline = |entry| compute_pipeline(device, label, &module, entry);
        Self {
            label,
            crossings: (kind == Kind::Dual).then(|| pipeline("make_dual_crossings")),
            vertices: pipeline(vertices),
            triangles: pipeline(triangles),
            finalize: pipeline("finalize_draw"),
            table: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytemuck::cast_slice(table),
                usage: wgpu::BufferUsages::STORAGE,
            }),
            kind,
            groups: Vec::new(),
        }
    }

    /// A buffer of the pass's own with `per_block` bytes for each of the mesh's active blocks, or as
    /// many blocks as one binding holds: the cells of blocks past it get no vertices (their triangles
    /// are left out, as when the vertex buffer is full).
    fn own_buffer(&self, device: &wgpu::Device, mesh: &MeshBuffers, per_block: u64) -> wgpu::Buffer {
        let limits = device.limits();
        let most = limits.max_storage_buffer_binding_size.min(limits.max_buffer_size) / per_block;
        device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(self.label),
            size: ((mesh.capacity.blocks as u64).min(most) * per_block).max(16),
            usage: wgpu::BufferUsages::STORAGE,
            mapped_at_creation: false,
        })
    }

    /// Binds the passes to new buffers.
    pub fn bind(&mut self, device: &wgpu::Device, scene: &SceneBuffers, mesh: &MeshBuffers) {
        // Tetrahedra's vertices on seven segments a cell; the dual methods' crossings on three edges a
        // cell, three floats each (2,304 bytes a block: at 128 MiB a binding, 58,254 blocks).
        let own = match self.kind {
            Kind::Cubes => None,
            Kind::Tetrahedra => Some(self.own_buffer(device, mesh, 64 * SLOTS as u64 * 4)),
            Kind::Dual => Some(self.own_buffer(device, mesh, 64 * 3 * 3 * 4)),
        };
        let edge_vertices = match self.kind {
            Kind::Tetrahedra => own.as_ref().unwrap_or(&mesh.edge_vertices),
            _ => &mesh.edge_vertices,
        };
        let group =
            |pipeline, buffers: &[(u32, &wgpu::Buffer)]| bind_buffers(device, self.label, pipeline, buffers);
        let mut vertices = vec![
            (bindings::GRID, &scene.grid),
            (bindings::COUNTERS, &mesh.counters),
            (bindings::ACTIVE_BLOCKS, &mesh.active_blocks),
            (bindings::BLOCK_VALUES, &mesh.block_values),
            (bindings::EDGE_VERTICES, edge_vertices),
            (bindings::VERTICES, &mesh.vertices),
            (bindings::ACTIVE_CELLS, &mesh.active_cells),
        ];
        let mut triangles = vec![
            (bindings::GRID, &scene.grid),
            (bindings::COUNTERS, &mesh.counters),
            (bindings::ACTIVE_BLOCKS, &mesh.active_blocks),
            (bindings::BLOCK_SLOTS, &mesh.block_slots),
            (bindings::EDGE_VERTICES, edge_vertices),
            (bindings::INDICES, &mesh.indices),
            (bindings::ACTIVE_CELLS, &mesh.active_cells),
        ];
        let mut groups = Vec::new();
        match (self.kind, &own, &self.crossings) {
            (Kind::Dual, Some(crossings), Some(first)) => {
                let kept = (bindings::EDGE_CROSSINGS, crossings);
                groups.push(group(
                    first,
                    &[
                        (bindings::GRID, &scene.grid),
                        (bindings::SPHERES, &scene.spheres),
                        (bindings::COUNTERS, &mesh.counters),
                        (bindings::ACTIVE_BLOCKS, &mesh.active_blocks),
                        (bindings::BLOCK_SLOTS, &mesh.block_slots),
                        (bindings::BLOCK_VALUES, &mesh.block_values),
                        (bindings::ACTIVE_CELLS, &mesh.active_cells),
                        kept,
                    ],
                ));
                vertices.extend([(bindings::BLOCK_SLOTS, &mesh.block_slots), kept]);
                triangles.extend([
                    (bindings::BLOCK_VALUES, &mesh.block_values),
                    (bindings::VERTICES, &mesh.vertices),
                    (bindings::LOD_DATA, &mesh.lod_data),
                    kept,
                ]);
            }
            (Kind::Tetrahedra, ..) => {
                vertices.push((bindings::SPHERES, &scene.spheres));
                triangles
                    .extend([(bindings::TETRA_TABLE, &self.table), (bindings::CELL_CASES, &mesh.cell_cases)]);
            }
            _ => {
                vertices.push((bindings::SPHERES, &scene.spheres));
                triangles.extend([
                    (bindings::TRIANGLE_TABLE, &self.table),
                    (bindings::CELL_CASES, &mesh.cell_cases),
                ]);
            }
        }
        groups.push(group(&self.vertices, &vertices));
        groups.push(group(&self.triangles, &triangles));
        groups.push(group(
            &self.finalize,
            &[
                (bindings::GRID, &scene.grid),
                (bindings::COUNTERS, &mesh.counters),
                (bindings::DRAW_ARGS, &mesh.draw_args),
            ],
        ));
        self.groups = groups;
    }

    /// (With the dual methods, the crossings, then) vertices, then triangles, then the draw arguments,
    /// over the active cells.
    pub fn encode(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        mesh: &MeshBuffers,
        timestamp_writes: Option<wgpu::ComputePassTimestampWrites>,
    ) {
        assert!(!self.groups.is_empty(), "MarchingPass::bind before encode");
        let mut pass = encoder
            .begin_compute_pass(&wgpu::ComputePassDescriptor { label: Some(self.label), timestamp_writes });
        let pipelines = self.crossings.iter().chain([&self.vertices, &self.triangles]);
        for (pipeline, group) in pipelines.zip(&self.groups) {
            pass.set_pipeline(pipeline);
            pass.set_bind_group(0, group, &[]);
            pass.dispatch_workgroups_indirect(&mesh.cell_dispatch, 0);
        }
        pass.set_pipeline(&self.finalize);
        pass.set_bind_group(0, self.groups.last(), &[]);
        pass.dispatch_workgroups(1, 1, 1);
    }
}
