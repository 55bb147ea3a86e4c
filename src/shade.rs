//! The shading pass (`shaders/shade.wgsl`): background, the box's edges, then the surface with
//! Blinn-Phong, depth-tested and (with antialiasing) multisampled and resolved into the caller's view.

use crate::mesh_buffers::{MeshBuffers, VERTEX_BYTES};
use crate::uniforms::ShadingUniform;

/// Samples per pixel with antialiasing on; 4 is supported for every renderable format WebGPU guarantees.
pub const MULTISAMPLES: u32 = 4;
const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// Owns the shading pipelines, their uniform buffer, and multisampled colour and depth targets sized to
/// the output.
pub struct ShadePass {
    background: wgpu::RenderPipeline,
    box_edges: wgpu::RenderPipeline,
    surface: wgpu::RenderPipeline,
    uniform: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    format: wgpu::TextureFormat,
    sample_count: u32,
    /// The multisampled colour target, resolved into the output (none without antialiasing).
    color: Option<wgpu::TextureView>,
    depth: wgpu::TextureView,
}

impl ShadePass {
    /// Draws `width` × `height` frames of `format`, 4× multisampled when `antialiasing`.
    pub fn new(
        device: &wgpu::Device,
        format: wgpu::TextureFormat,
        width: u32,
        height: u32,
        antialiasing: bool,
    ) -> Self {
        let sample_count = if antialiasing { MULTISAMPLES } else { 1 };
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("shade: shader"),
            source: wgpu::ShaderSource::Wgsl(include_str!("../shaders/shade.wgsl").into()),
        });
        let uniform = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("shade: uniforms"),
            size: std::mem::size_of::<ShadingUniform>() as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("shade: bind group layout"),
            entries: &[wgpu::BindGroupLayoutEntry {
                binding: 0,
                visibility: wgpu::ShaderStages::VERTEX_FRAGMENT,
                ty: wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: wgpu::BufferSize::new(std::mem::size_of::<ShadingUniform>() as u64),
                },
                count: None,
            }],
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("shade: bind group"),
            layout: &layout,
            entries: &[wgpu::BindGroupEntry { binding: 0, resource: uniform.as_entire_binding() }],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("shade: pipeline layout"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let vertex_layout = wgpu::VertexBufferLayout {
            array_stride: VERTEX_BYTES,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3],
        };
        let pipeline = |label,
                        vertex_entry,
                        fragment_entry,
                        buffers: &[Option<wgpu::VertexBufferLayout>],
                        topology,
                        depth_write| {
            device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
                label: Some(label),
                layout: Some(&pipeline_layout),
                vertex: wgpu::VertexState {
                    module: &module,
                    entry_point: Some(vertex_entry),
                    compilation_options: Default::default(),
                    buffers,
                },
                fragment: Some(wgpu::FragmentState {
                    module: &module,
                    entry_point: Some(fragment_entry),
                    compilation_options: Default::default(),
                    targets: &[Some(format.into())],
                }),
                primitive: wgpu::PrimitiveState {
                    topology,
                    front_face: wgpu::FrontFace::Ccw,
                    // Both sides are drawn: where a wall cuts the surface open, its inside shows.
                    cull_mode: None,
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
                multisample: wgpu::MultisampleState { count: sample_count, ..Default::default() },
                multiview_mask: None,
                cache: None,
            })
        };
        use wgpu::PrimitiveTopology::{LineList, TriangleList};
        let background = pipeline(
            "shade: background pipeline",
            "background_vertex",
            "background_fragment",
            &[],
            TriangleList,
            false,
        );
        let box_edges = pipeline("shade: box pipeline", "box_vertex", "box_fragment", &[], LineList, true);
        let surface = pipeline(
            "shade: surface pipeline",
            "surface_vertex",
            "surface_fragment",
            &[Some(vertex_layout)],
            TriangleList,
            true,
        );
        let (color, depth) = targets(device, format, width, height, sample_count);
        Self { background, box_edges, surface, uniform, bind_group, format, sample_count, color, depth }
    }

    /// Reallocates the multisampled targets for a new output size.
    pub fn resize(&mut self, device: &wgpu::Device, width: u32, height: u32) {
        (self.color, self.depth) = targets(device, self.format, width, height, self.sample_count);
    }

    /// The uniform buffer the renderer writes each frame.
    pub fn uniform(&self) -> &wgpu::Buffer {
        &self.uniform
    }

    /// Draws the background, the box and the mesh (as far as its indirect draw arguments say) into `view`.
    pub fn encode(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        view: &wgpu::TextureView,
        mesh: &MeshBuffers,
        timestamp_writes: Option<wgpu::RenderPassTimestampWrites>,
    ) {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("shade: pass"),
            color_attachments: &[Some(wgpu::RenderPassColorAttachment {
                view: self.color.as_ref().unwrap_or(view),
                depth_slice: None,
                resolve_target: self.color.as_ref().map(|_| view),
                ops: wgpu::Operations {
                    load: wgpu::LoadOp::Clear(wgpu::Color::BLACK),
                    store: if self.color.is_some() { wgpu::StoreOp::Discard } else { wgpu::StoreOp::Store },
                },
            })],
            depth_stencil_attachment: Some(wgpu::RenderPassDepthStencilAttachment {
                view: &self.depth,
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
        pass.set_pipeline(&self.background);
        pass.draw(0..3, 0..1);
        pass.set_pipeline(&self.box_edges);
        pass.draw(0..24, 0..1);
        pass.set_pipeline(&self.surface);
        pass.set_vertex_buffer(0, mesh.vertices.slice(..));
        pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
        pass.draw_indexed_indirect(&mesh.draw_args, 0);
    }
}

fn targets(
    device: &wgpu::Device,
    format: wgpu::TextureFormat,
    width: u32,
    height: u32,
    sample_count: u32,
) -> (Option<wgpu::TextureView>, wgpu::TextureView) {
    let texture = |label, format| {
        device
            .create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d { width, height, depth_or_array_layers: 1 },
                mip_level_count: 1,
                sample_count,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
                view_formats: &[],
            })
            .create_view(&wgpu::TextureViewDescriptor::default())
    };
    let color = (sample_count > 1).then(|| texture("shade: multisampled colour", format));
    (color, texture("shade: depth", DEPTH_FORMAT))
}
