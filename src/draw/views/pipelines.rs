//! The teaching views' pipelines: one explicit bind group layout over the compute passes' buffers for
//! every drawing entry of `shaders/draw/views/`, and the overlay pass's compute pipelines
//! (`shaders/draw/overlays.wgsl`) with the tables they read.

use crate::device::{COMMON_WGSL, bindings, shader_module, wgsl};
use crate::draw::slice::packed_square_segments;
use crate::draw::uniforms::SHADE_WGSL;
use crate::teach::case_classes::case_classes;
use wgpu::util::DeviceExt;

/// The teaching views' WGSL, one file per view after what they share: one module holds them all.
const VIEW_SOURCES: [&str; 11] = [
    wgsl!("draw/views/common.wgsl"),
    wgsl!("draw/views/triangles.wgsl"),
    wgsl!("draw/views/points.wgsl"),
    wgsl!("draw/views/lattice.wgsl"),
    wgsl!("draw/views/cells.wgsl"),
    wgsl!("draw/views/blocks.wgsl"),
    wgsl!("draw/views/ambiguous.wgsl"),
    wgsl!("draw/views/slice.wgsl"),
    wgsl!("draw/views/selected.wgsl"),
    wgsl!("draw/views/gizmo.wgsl"),
    wgsl!("draw/views/exact.wgsl"),
];

/// The pipelines of the views for one output format and sample count, with the compute pipelines of
/// the overlay pass and the tables they read.
pub struct ViewPipelines {
    pub(super) layout: wgpu::BindGroupLayout,
    pub(super) triangles: wgpu::RenderPipeline,
    pub(super) points: wgpu::RenderPipeline,
    pub(super) normals: wgpu::RenderPipeline,
    pub(super) crossings: wgpu::RenderPipeline,
    pub(super) lattice: wgpu::RenderPipeline,
    pub(super) cells: wgpu::RenderPipeline,
    pub(super) blocks: wgpu::RenderPipeline,
    pub(super) lod_blocks: wgpu::RenderPipeline,
    pub(super) ambiguous: wgpu::RenderPipeline,
    pub(super) contour: wgpu::RenderPipeline,
    pub(super) slice: wgpu::RenderPipeline,
    pub(super) selected_edges: wgpu::RenderPipeline,
    pub(super) selected_corners: wgpu::RenderPipeline,
    pub(super) gizmo: wgpu::RenderPipeline,
    pub(super) exact: wgpu::RenderPipeline,
    pub(super) exact_outline: wgpu::RenderPipeline,
    /// Casts the exact view's rays for listed pixels (`exact_probe`).
    pub(crate) exact_probe: wgpu::ComputePipeline,
    pub(super) sample_slice: wgpu::ComputePipeline,
    pub(super) contour_slice: wgpu::ComputePipeline,
    pub(super) plan: wgpu::ComputePipeline,
    pub(super) case_classes: wgpu::Buffer,
    pub(super) square_segments: wgpu::Buffer,
}

impl ViewPipelines {
    pub fn new(
        device: &wgpu::Device,
        format: wgpu::TextureFormat,
        sample_count: u32,
        depth: wgpu::TextureFormat,
    ) -> Self {
        // After the grid and spheres, the shading uniforms and lighting.
        let module = |label, source: &str| shader_module(device, label, &[COMMON_WGSL, SHADE_WGSL, source]);
        let views = module("views: shader", &VIEW_SOURCES.join("\n"));
        let overlays = module("overlays: shader", wgsl!("draw/overlays.wgsl"));

        use wgpu::ShaderStages as S;
        let entry =
            |binding, visibility, ty| wgpu::BindGroupLayoutEntry { binding, visibility, ty, count: None };
        let uniform = wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        };
        let storage = wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Storage { read_only: true },
            has_dynamic_offset: false,
            min_binding_size: None,
        };
        let both = S::VERTEX_FRAGMENT;
        let mut entries = vec![
            entry(bindings::GRID, both, uniform),
            entry(bindings::SPHERES, both, uniform),
            entry(bindings::SHADING, both, uniform),
            entry(bindings::CASE_CLASSES, both, uniform),
            entry(bindings::SLICE_VALUES, S::FRAGMENT, storage),
        ];
        // What only the vertex stages read.
        let vertex_reads = [
            bindings::ACTIVE_BLOCKS,
            bindings::BLOCK_SLOTS,
            bindings::CELL_CASES,
            bindings::VERTICES,
            bindings::INDICES,
            bindings::ACTIVE_CELLS,
            bindings::LOD_DATA,
            bindings::SEGMENTS,
        ];
        entries.extend(vertex_reads.map(|b| entry(b, S::VERTEX, storage)));
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("views: bind group layout"),
            entries: &entries,
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("views: pipeline layout"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let blend = wgpu::BlendState::ALPHA_BLENDING;
        let pipeline = |label, vertex, fragment, topology, depth_write: bool, compare| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(&pipeline_layout),
                vertex: wgpu::VertexState {
                    module: &views,
                    entry_point: Some(vertex),
                    compilation_options: Default::default(),
                    buffers: &[],
                },
                fragment: Some(wgpu::FragmentState {
                    module: &views,
                    entry_point: Some(fragment),
                    compilation_options: Default::default(),
                    targets: &[Some(wgpu::ColorTargetState {
                        format,
                        blend: Some(blend),
                        write_mask: wgpu::ColorWrites::ALL,
                    })],
                }),
                primitive: wgpu::PrimitiveState { topology, cull_mode: None, ..Default::default() },
                depth_stencil: Some(wgpu::DepthStencilState {
                    format: depth,
                    depth_write_enabled: Some(depth_write),
                    depth_compare: Some(compare),
                    stencil: Default::default(),
                    bias: Default::default(),
                }),
                multisample: wgpu::MultisampleState { count: sample_count, ..Default::default() },
                multiview_mask: None,
                cache: None,
            })
        };
        use wgpu::CompareFunction::{Always, LessEqual};
        use wgpu::PrimitiveTopology::{LineList, TriangleList};
        let line = |label, vertex| pipeline(label, vertex, "mark_fragment", LineList, false, LessEqual);
        let on_top =
            |label, vertex, topology| pipeline(label, vertex, "mark_fragment", topology, false, Always);
        let compute_in = |module, label, entry| {
            device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some(label),
                layout: None,
                module,
                entry_point: Some(entry),
                compilation_options: Default::default(),
                cache: None,
            })
        };
        let compute = |label, entry| compute_in(&overlays, label, entry);
        let classes: Vec<u32> = case_classes().iter().map(|&c| c as u32).collect();
        Self {
            triangles: pipeline(
                "views: triangle pipeline",
                "triangle_vertex",
                "triangle_fragment",
                TriangleList,
                true,
                wgpu::CompareFunction::Less,
            ),
            points: pipeline(
                "views: point pipeline",
                "point_vertex",
                "mark_fragment",
                TriangleList,
                true,
                LessEqual,
            ),
            normals: line("views: normal pipeline", "normal_vertex"),
            crossings: line("views: crossing pipeline", "crossing_vertex"),
            lattice: line("views: lattice pipeline", "lattice_vertex"),
            cells: line("views: cell pipeline", "cell_vertex"),
            blocks: line("views: block pipeline", "block_vertex"),
            lod_blocks: line("views: LOD block pipeline", "lod_block_vertex"),
            // On top: an ambiguous face lies where the surface pinches, mostly inside it.
            ambiguous: on_top("views: ambiguous face pipeline", "ambiguous_vertex", LineList),
            contour: line("views: contour pipeline", "contour_vertex"),
            slice: pipeline(
                "views: slice pipeline",
                "slice_vertex",
                "slice_fragment",
                TriangleList,
                true,
                LessEqual,
            ),
            selected_edges: on_top("views: selected edge pipeline", "selected_edge_vertex", LineList),
            selected_corners: on_top(
                "views: selected corner pipeline",
                "selected_corner_vertex",
                TriangleList,
            ),
            gizmo: on_top("views: gizmo pipeline", "gizmo_vertex", LineList),
            exact: pipeline(
                "views: exact surface pipeline",
                "exact_vertex",
                "exact_fragment",
                TriangleList,
                true,
                wgpu::CompareFunction::Less,
            ),
            exact_outline: pipeline(
                "views: exact outline pipeline",
                "exact_vertex",
                "exact_outline_fragment",
                TriangleList,
                false,
                Always,
            ),
            exact_probe: compute_in(&views, "views: exact probe pipeline", "exact_probe"),
            sample_slice: compute("overlays: slice sample pipeline", "sample_slice"),
            contour_slice: compute("overlays: slice contour pipeline", "contour_slice"),
            plan: compute("overlays: plan pipeline", "plan_overlays"),
            case_classes: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("views: case classes"),
                contents: bytemuck::cast_slice(&classes),
                usage: wgpu::BufferUsages::UNIFORM,
            }),
            square_segments: device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some("overlays: marching squares table"),
                contents: bytemuck::cast_slice(&packed_square_segments()),
                usage: wgpu::BufferUsages::UNIFORM,
            }),
            layout,
        }
    }
}
