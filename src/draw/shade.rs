//! The shading pass (`shaders/draw/shade.wgsl`): background, the box's edges, then the surface with
//! Blinn-Phong, depth-tested and (with antialiasing) multisampled and resolved into the caller's view.

use crate::device::bindings;
use crate::draw::uniforms::{SHADE_WGSL, ShadingUniform};
use crate::draw::views::{ViewFrame, ViewPipelines, ViewState};
use crate::extract::buffers::VERTEX_BYTES;
use std::sync::{Arc, OnceLock};

/// Samples per pixel with antialiasing on; 4 is supported for every renderable format WebGPU guarantees.
pub const MULTISAMPLES: u32 = 4;
const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// The shading pipelines for one output format and sample count, with their bind group layout.
/// Cloning shares them: every renderer on a device drawing the same format uses one set.
#[derive(Clone)]
pub struct ShadePipelines {
    background: wgpu::RenderPipeline,
    box_edges: wgpu::RenderPipeline,
    /// The surface's pipeline for each set of lights (`LIGHT_SLOTS` in the shader), drawing both sides
    /// or front faces only (`+ 8`), built on first use.
    surface: Arc<[OnceLock<wgpu::RenderPipeline>; 16]>,
    /// What a surface pipeline is built from.
    surface_source: SurfaceSource,
    layout: wgpu::BindGroupLayout,
    format: wgpu::TextureFormat,
    sample_count: u32,
    /// The teaching views' pipelines, built the first time a renderer shows one.
    views: Arc<OnceLock<ViewPipelines>>,
}

impl ShadePipelines {
    /// Compiles the shading shader and its pipelines for `format` with `sample_count` samples.
    pub fn new(device: &wgpu::Device, format: wgpu::TextureFormat, sample_count: u32) -> Self {
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("shade: shader"),
            source: wgpu::ShaderSource::Wgsl(SHADE_WGSL.into()),
        });
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("shade: bind group layout"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: bindings::SHADING,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: wgpu::BufferSize::new(std::mem::size_of::<ShadingUniform>() as u64),
                },
                count: None,
            }],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("shade: pipeline layout"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let source = SurfaceSource { device: device.clone(), module, pipeline_layout, format, sample_count };
        use wgpu::PrimitiveTopology::{LineList, TriangleList};
        let background = source.pipeline(
            "shade: background pipeline",
            ("background_vertex", "background_fragment"),
            &[],
            (TriangleList, None),
            false,
            &[],
        );
        let box_edges = source.pipeline(
            "shade: box pipeline",
            ("box_vertex", "box_fragment"),
            &[],
            (LineList, None),
            true,
            &[],
        );
        // On wasm32 wgpu's objects are not Send: a page runs them on one thread.
        #[allow(clippy::arc_with_non_send_sync)]
        let views = Arc::new(OnceLock::new());
        #[allow(clippy::arc_with_non_send_sync)]
        let surface = Arc::new(Default::default());
        Self { background, box_edges, surface, surface_source: source, layout, format, sample_count, views }
    }

    /// The surface's pipeline lit by the light slots in `slots` (bit 0 point, 1 directional, 2 spot):
    /// the lights that are off cost a software rasteriser nothing. `front_only` culls back faces.
    fn surface(&self, slots: u32, front_only: bool) -> &wgpu::RenderPipeline {
        let slots = slots & 7;
        self.surface[slots as usize + 8 * front_only as usize].get_or_init(|| {
            let vertex_layout = wgpu::VertexBufferLayout {
                array_stride: VERTEX_BYTES,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3],
            };
            self.surface_source.pipeline(
                "shade: surface pipeline",
                ("surface_vertex", "surface_fragment"),
                &[Some(vertex_layout)],
                (wgpu::PrimitiveTopology::TriangleList, front_only.then_some(wgpu::Face::Back)),
                true,
                &[("LIGHT_SLOTS", slots as f64)],
            )
        })
    }

    /// The teaching views' pipelines for this format and sample count, built on first use.
    pub fn views(&self, device: &wgpu::Device) -> &ViewPipelines {
        self.views.get_or_init(|| ViewPipelines::new(device, self.format, self.sample_count, DEPTH_FORMAT))
    }
}

/// The shading shader with what its pipelines share.
#[derive(Clone)]
struct SurfaceSource {
    device: wgpu::Device,
    module: wgpu::ShaderModule,
    pipeline_layout: wgpu::PipelineLayout,
    format: wgpu::TextureFormat,
    sample_count: u32,
}

impl SurfaceSource {
    /// A pipeline of the shading shader drawing `topology` with `entries` (vertex, fragment), culling
    /// the faces given, writing depth or drawing behind everything, with `constants` for the shader's
    /// overrides. Each encodes sRGB itself exactly when the format does not (`ENCODE_SRGB`), as the
    /// renderer's `encode_srgb` uniform says for the views.
    fn pipeline(
        &self,
        label: &str,
        (vertex_entry, fragment_entry): (&str, &str),
        buffers: &[Option<wgpu::VertexBufferLayout>],
        (topology, cull_mode): (wgpu::PrimitiveTopology, Option<wgpu::Face>),
        depth_write: bool,
        constants: &[(&str, f64)],
    ) -> wgpu::RenderPipeline {
        let encode = [("ENCODE_SRGB", if self.format.is_srgb() { 0.0 } else { 1.0 })];
        let constants: Vec<(&str, f64)> = constants.iter().chain(&encode).copied().collect();
        let options = wgpu::PipelineCompilationOptions { constants: &constants, ..Default::default() };
        self.device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(label),
            layout: Some(&self.pipeline_layout),
            vertex: wgpu::VertexState {
                module: &self.module,
                entry_point: Some(vertex_entry),
                compilation_options: options.clone(),
                buffers,
            },
            fragment: Some(wgpu::FragmentState {
                module: &self.module,
                entry_point: Some(fragment_entry),
                compilation_options: options,
                targets: &[Some(self.format.into())],
            }),
            primitive: wgpu::PrimitiveState {
                topology,
                front_face: wgpu::FrontFace::Ccw,
                cull_mode,
                ..Default::default()
            },
            depth_stencil: Some(wgpu::DepthStencilState {
                format: DEPTH_FORMAT,
                depth_write_enabled: Some(depth_write),
                depth_compare: Some(if depth_write {
                    wgpu::CompareFunction::Less
                } else {
                    wgpu::CompareFunction::Always
                }),
                stencil: Default::default(),
                bias: Default::default(),
            }),
            multisample: wgpu::MultisampleState { count: self.sample_count, ..Default::default() },
            multiview_mask: None,
            cache: None,
        })
    }
}

/// How many indices a frame draws.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DrawCount {
    /// As the compute passes wrote in the draw arguments buffer.
    Indirect,
    /// A count known on the CPU (the CPU mesher's; the only kind WebGL2 draws).
    Direct(u32),
}

/// The mesh a frame draws, wherever it was made.
pub struct MeshDraw<'a> {
    pub vertices: &'a wgpu::Buffer,
    pub indices: &'a wgpu::Buffer,
    /// The indexed indirect draw's arguments (read with `DrawCount::Indirect`).
    pub draw_args: &'a wgpu::Buffer,
    pub count: DrawCount,
    /// The light slots that are on (`LIGHT_SLOTS` in the shader).
    pub light_slots: u32,
    /// The mesh is closed and the eye outside it, so its back faces are hidden and need not be drawn.
    pub front_only: bool,
}

/// Draws a renderer's frames: shared pipelines, plus its own uniform buffer and colour and depth
/// targets sized to the output.
pub struct ShadePass {
    pipelines: ShadePipelines,
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    targets: Targets,
}

impl ShadePass {
    /// Draws `width` × `height` frames with `pipelines` (which fix the format and sample count).
    pub fn new(device: &wgpu::Device, pipelines: ShadePipelines, width: u32, height: u32) -> Self {
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("shade: uniforms"),
            size: std::mem::size_of::<ShadingUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("shade: bind group"),
            layout: &pipelines.layout,
            entries: &[wgpu::BindGroupEntry {
                binding: bindings::SHADING,
                resource: uniform.as_entire_binding(),
            }],
        });
        let targets = Targets::new(device, &pipelines, width, height);
        Self { pipelines, uniform, bind_group, targets }
    }

    /// Reallocates the multisampled targets for a new output size.
    pub fn resize(&mut self, device: &wgpu::Device, width: u32, height: u32) {
        self.targets.destroy();
        self.targets = Targets::new(device, &self.pipelines, width, height);
    }

    /// GPU memory held by this pass's own targets and uniforms, in bytes.
    pub fn bytes(&self) -> u64 {
        self.uniform.size() + self.targets.bytes()
    }

    /// Frees the targets and uniforms now rather than when the last reference goes.
    pub fn destroy(&self) {
        self.targets.destroy();
        self.uniform.destroy();
    }

    /// The pipelines this pass draws with.
    pub fn pipelines(&self) -> &ShadePipelines {
        &self.pipelines
    }

    /// The uniform buffer the renderer writes each frame.
    pub fn uniform(&self) -> &wgpu::Buffer {
        &self.uniform
    }

    /// Draws the background, the box and the mesh into `view`.
    pub fn encode(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        view: &wgpu::TextureView,
        mesh: MeshDraw,
        views: Option<ViewFrame>,
        timestamp_writes: Option<wgpu::RenderPassTimestampWrites>,
    ) {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("shade: pass"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: self.targets.color_view.as_ref().unwrap_or(view),
                depth_slice: None,
                resolve_target: self.targets.color_view.as_ref().map(|_| view),
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                    store: if self.targets.color.is_some() {
                        wgpu::StoreOp::Discard
                    } else {
                        wgpu::StoreOp::Store
                    },
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &self.targets.depth_view,
                depth_ops: Some(wgpu::Operations {
                    load: wgpu::LoadOp::Clear(1.0),
                    store: wgpu::StoreOp::Discard,
                }),
                stencil_ops: None,
            }),
            timestamp_writes,
            ..Default::default()
        });
        pass.set_bind_group(0, &self.bind_group, &[]);
        pass.set_pipeline(&self.pipelines.background);
        pass.draw(0..3, 0..1);
        pass.set_pipeline(&self.pipelines.box_edges);
        pass.draw(0..24, 0..1);
        if let Some(v) = &views {
            v.state.draw_before_surface(&mut pass, v.pipelines, v.options);
        }
        if views.as_ref().is_none_or(|v| ViewState::draws_plain_surface(v.options)) {
            if let Some(v) = &views {
                let size = (self.targets.depth.width(), self.targets.depth.height());
                crate::draw::views::exact::clip_mesh(&mut pass, v.options, size);
            }
            pass.set_bind_group(0, &self.bind_group, &[]);
            pass.set_pipeline(self.pipelines.surface(mesh.light_slots, mesh.front_only));
            pass.set_vertex_buffer(0, mesh.vertices.slice(..));
            pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
            match mesh.count {
                DrawCount::Indirect => pass.draw_indexed_indirect(mesh.draw_args, 0),
                DrawCount::Direct(0) => {}
                DrawCount::Direct(n) => pass.draw_indexed(0..n, 0, 0..1),
            }
        }
        if let Some(v) = &views {
            let size = (self.targets.depth.width(), self.targets.depth.height());
            v.state.draw_after_surface(&mut pass, v, size);
        }
    }
}

/// The multisampled colour target (none without antialiasing) and the depth target.
struct Targets {
    color: Option<wgpu::Texture>,
    depth: wgpu::Texture,
    color_view: Option<wgpu::TextureView>,
    depth_view: wgpu::TextureView,
}

impl Targets {
    fn new(device: &wgpu::Device, pipelines: &ShadePipelines, width: u32, height: u32) -> Self {
        let texture = |label, format| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count: pipelines.sample_count,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                view_formats: &[],
            })
        };
        let view = |t: &wgpu::Texture| t.create_view(&wgpu::TextureViewDescriptor::default());
        let color =
            (pipelines.sample_count > 1).then(|| texture("shade: multisampled colour", pipelines.format));
        let depth = texture("shade: depth", DEPTH_FORMAT);
        Self { color_view: color.as_ref().map(view), depth_view: view(&depth), color, depth }
    }

    fn bytes(&self) -> u64 {
        let bytes = |t: &wgpu::Texture| {
            let block = t.format().block_copy_size(None).unwrap_or(4) as u64;
            t.width() as u64 * t.height() as u64 * t.sample_count() as u64 * block
        };
        self.color.as_ref().map_or(0, bytes) + bytes(&self.depth)
    }

    fn destroy(&self) {
        if let Some(color) = &self.color {
            color.destroy();
        }
        self.depth.destroy();
    }
}
