//! The teaching views (`shaders/draw/views/`, `shaders/draw/overlays.wgsl`): display modes, the lattice,
//! crossed cells and kept blocks, ambiguous faces, the field slice with its contour, the selected cell
//! and an axis gizmo. Everything is drawn from the buffers the compute passes fill, with indirect draws
//! whose counts a one-invocation pass writes on the GPU: no readback.

use crate::device::{bind_buffers, bind_buffers_to, bindings};
use crate::draw::uniforms::ShadingUniform;
use crate::extract::Crossings;
use crate::extract::buffers::MeshBuffers;
use crate::extract::gpu::scene_buffers::SceneBuffers;
use crate::extract::reference::Grid;
use crate::scene::params::view::{
    ColorBy, Compare, Display, GridView, Method, Projection, Slice, ViewOptions,
};

/// The indirect draws the overlay pass plans, in order (`plan_overlays`).
#[derive(Clone, Copy)]
enum Draw {
    Triangles = 0,
    Points = 1,
    Normals = 2,
    Cells = 3,
    Blocks = 4,
    Ambiguous = 5,
    Contour = 6,
    LodBlocks = 7,
    /// Dual contouring's crossings as the device counted them.
    Crossings = 8,
}

/// Bytes before the draws in the overlay buffer (the segment counter, padded).
const DRAWS_OFFSET: u64 = 16;
const OVERLAY_BYTES: u64 = DRAWS_OFFSET + 9 * 16;
/// Side of the axis gizmo's square, in pixels.
const GIZMO_PIXELS: f32 = 72.0;

/// The lattice draw for `cells_per_axis` cells: (vertices per instance, instances). Instance i draws
/// the n + 1 grid lines along axis i / (n + 1) whose third coordinate is i % (n + 1): one instanced
/// draw, both counts linear in n, 3 (n + 1)² lines in all.
pub fn lattice_draw(cells_per_axis: u32) -> (u32, u32) {
    let points = cells_per_axis + 1;
    (2 * points, 3 * points)
}

pub mod exact;
mod pipelines;
pub use pipelines::ViewPipelines;

/// True when `options` draw anything beyond the plain shaded surface.
pub fn needed(options: &ViewOptions, selected: bool) -> bool {
    selected
        || options.display != Display::Shaded
        || options.grid != GridView::None
        || options.color_by != ColorBy::None
        || options.slice.is_some()
        || options.ambiguous
        || options.compare != Compare::None
        // Orthographic views carry the axis gizmo: without perspective, depth cues are few.
        || options.projection == Projection::Orthographic
}

/// True when the frame's mesh comes without the cell lists the teaching views read: level of detail
/// and every method but marching cubes.
pub fn mesh_only(options: &ViewOptions) -> bool {
    options.lod || !options.method.has_cases()
}

/// The views `options` ask for that the frame's mesh can show: with level of detail there is no
/// uniform grid, so its lattice, cells, ambiguous faces and slice are left out (`grid=blocks` shows
/// the LOD blocks); the other methods keep the grid but have no cases, so the crossed cells, kept
/// blocks, ambiguous faces and case colours are left out.
pub fn shown(options: &ViewOptions) -> ViewOptions {
    let options = &exact::mesh_side(options);
    // Only dual contouring's vertices have a QEF rank, and only level of detail has levels.
    let ranked = options.method == Method::DualContouring && !options.lod;
    let options = &match options.color_by {
        ColorBy::Rank if !ranked => ViewOptions { color_by: ColorBy::None, ..*options },
        ColorBy::Level if !options.lod => ViewOptions { color_by: ColorBy::None, ..*options },
        _ => *options,
    };
    if !options.lod {
        if options.method.has_cases() {
            return *options;
        }
        let grid = if options.grid == GridView::Lattice { GridView::Lattice } else { GridView::None };
        let color_by = if options.color_by == ColorBy::Case { ColorBy::None } else { options.color_by };
        return ViewOptions { grid, color_by, ambiguous: false, ..*options };
    }
    let grid = if options.grid == GridView::Blocks { GridView::Blocks } else { GridView::None };
    ViewOptions { grid, ambiguous: false, slice: None, ..*options }
}

/// What the shading pass draws of the teaching views this frame.
pub struct ViewFrame<'a> {
    pub state: &'a ViewState,
    pub pipelines: &'a ViewPipelines,
    pub options: &'a ViewOptions,
    pub selected: bool,
    /// The vertex records holding the crossings of the grid's edges, where the mesher wrote them.
    pub crossings: Option<Crossings>,
}

/// One renderer's view resources for one grid: the slice's samples and contour, the overlay counts
/// and draws, and the bind groups over its mesh buffers.
pub struct ViewState {
    grid: Grid,
    slice_values: wgpu::Buffer,
    segments: wgpu::Buffer,
    overlays: wgpu::Buffer,
    draw_group: wgpu::BindGroup,
    sample_group: wgpu::BindGroup,
    contour_group: wgpu::BindGroup,
    plan_group: wgpu::BindGroup,
}

impl ViewState {
    pub fn new(
        device: &wgpu::Device,
        pipelines: &ViewPipelines,
        scene: &SceneBuffers,
        mesh: &MeshBuffers,
        shading: &wgpu::Buffer,
    ) -> Self {
        let grid = mesh.grid;
        let n = grid.cells_per_axis as u64;
        let buffer = |label, size: u64, usage| {
            device.create_buffer(&wgpu::BufferDescriptor {
                label: Some(label),
                size,
                usage: wgpu::BufferUsages::STORAGE | usage,
                mapped_at_creation: false,
            })
        };
        use wgpu::BufferUsages as U;
        let slice_values = buffer("overlays: slice samples", (n + 1) * (n + 1) * 4, U::empty());
        let segments = buffer("overlays: slice contour", 2 * n * n * 32, U::COPY_SRC);
        let overlays =
            buffer("overlays: counts and draws", OVERLAY_BYTES, U::INDIRECT | U::COPY_DST | U::COPY_SRC);
        let p = pipelines;
        Self {
            draw_group: bind_buffers_to(
                device,
                "views: bind group",
                &p.layout,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::SPHERES, &scene.spheres),
                    (bindings::ACTIVE_BLOCKS, &mesh.active_blocks),
                    (bindings::BLOCK_SLOTS, &mesh.block_slots),
                    (bindings::CELL_CASES, &mesh.cell_cases),
                    (bindings::VERTICES, &mesh.vertices),
                    (bindings::INDICES, &mesh.indices),
                    (bindings::ACTIVE_CELLS, &mesh.active_cells),
                    (bindings::SHADING, shading),
                    (bindings::LOD_DATA, &mesh.lod_data),
                    (bindings::SLICE_VALUES, &slice_values),
                    (bindings::SEGMENTS, &segments),
                    (bindings::CASE_CLASSES, &p.case_classes),
                ],
            ),
            sample_group: bind_buffers(
                device,
                "overlays: slice sample bind group",
                &p.sample_slice,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::SPHERES, &scene.spheres),
                    (bindings::SHADING, shading),
                    (bindings::SLICE_VALUES, &slice_values),
                ],
            ),
            contour_group: bind_buffers(
                device,
                "overlays: slice contour bind group",
                &p.contour_slice,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::SHADING, shading),
                    (bindings::SLICE_VALUES, &slice_values),
                    (bindings::SEGMENTS, &segments),
                    (bindings::OVERLAYS, &overlays),
                    (bindings::SQUARE_SEGMENTS, &p.square_segments),
                ],
            ),
            plan_group: bind_buffers(
                device,
                "overlays: plan bind group",
                &p.plan,
                &[
                    (bindings::GRID, &scene.grid),
                    (bindings::COUNTERS, &mesh.counters),
                    (bindings::OVERLAYS, &overlays),
                ],
            ),
            grid,
            slice_values,
            segments,
            overlays,
        }
    }

    /// The grid these resources were made for.
    pub fn grid(&self) -> Grid {
        self.grid
    }

    /// The contour's segments and their count (tests read them back).
    pub fn contour_buffers(&self) -> (&wgpu::Buffer, &wgpu::Buffer) {
        (&self.segments, &self.overlays)
    }

    /// GPU memory held, in bytes.
    pub fn bytes(&self) -> u64 {
        self.slice_values.size() + self.segments.size() + self.overlays.size()
    }

    pub fn destroy(&self) {
        self.slice_values.destroy();
        self.segments.destroy();
        self.overlays.destroy();
    }

    /// Records the overlay pass: the slice (when shown) and the draws' counts.
    pub fn encode(
        &self,
        encoder: &mut wgpu::CommandEncoder,
        pipelines: &ViewPipelines,
        options: &ViewOptions,
    ) {
        encoder.clear_buffer(&self.overlays, 0, Some(DRAWS_OFFSET));
        let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
            label: Some("overlays: pass"),
            timestamp_writes: None,
        });
        if options.slice.is_some() {
            let n = self.grid.cells_per_axis;
            pass.set_pipeline(&pipelines.sample_slice);
            pass.set_bind_group(0, &self.sample_group, &[]);
            let groups = (n + 1).div_ceil(8);
            pass.dispatch_workgroups(groups, groups, 1);
            pass.set_pipeline(&pipelines.contour_slice);
            pass.set_bind_group(0, &self.contour_group, &[]);
            pass.dispatch_workgroups(n.div_ceil(8), n.div_ceil(8), 1);
        }
        pass.set_pipeline(&pipelines.plan);
        pass.set_bind_group(0, &self.plan_group, &[]);
        pass.dispatch_workgroups(1, 1, 1);
    }

    fn indirect(&self, pass: &mut wgpu::RenderPass, pipeline: &wgpu::RenderPipeline, draw: Draw) {
        pass.set_pipeline(pipeline);
        pass.draw_indirect(&self.overlays, DRAWS_OFFSET + 16 * draw as u64);
    }

    /// True when the shading pass should draw the indexed, smooth surface itself.
    pub fn draws_plain_surface(options: &ViewOptions) -> bool {
        matches!(options.display, Display::Shaded | Display::Normals) && options.color_by == ColorBy::None
    }

    /// Draws what goes before the surface (the slice plane).
    pub fn draw_before_surface(
        &self,
        pass: &mut wgpu::RenderPass,
        pipelines: &ViewPipelines,
        options: &ViewOptions,
    ) {
        pass.set_bind_group(0, &self.draw_group, &[]);
        if options.slice.is_some() {
            pass.set_pipeline(&pipelines.slice);
            pass.draw(0..6, 0..1);
        }
    }

    /// Draws the surface in its display mode (unless the shading pass draws it) and the overlays.
    pub fn draw_after_surface(&self, pass: &mut wgpu::RenderPass, frame: &ViewFrame, size: (u32, u32)) {
        let (p, options, selected) = (frame.pipelines, frame.options, frame.selected);
        pass.set_bind_group(0, &self.draw_group, &[]);
        exact::clip_mesh(pass, options, size);
        if options.display == Display::Points {
            self.indirect(pass, &p.points, Draw::Points);
        } else if options.display == Display::Exact {
            pass.set_pipeline(&p.exact);
            pass.draw(0..3, 0..1);
        } else if !Self::draws_plain_surface(options) {
            self.indirect(pass, &p.triangles, Draw::Triangles);
        }
        if options.display == Display::Normals {
            self.indirect(pass, &p.normals, Draw::Normals);
            // Dual contouring's Hermite data: each crossing with the field's normal, two vertices each.
            match &frame.crossings {
                Some(Crossings::Listed(listed)) => {
                    pass.set_pipeline(&p.crossings);
                    pass.draw(2 * listed.start..2 * listed.end, 0..1);
                }
                Some(Crossings::Counted) => self.indirect(pass, &p.crossings, Draw::Crossings),
                None => {}
            }
        }
        exact::draw_beside_mesh(pass, p, options, size);
        match options.grid {
            GridView::None => {}
            GridView::Lattice => {
                let (vertices, instances) = lattice_draw(self.grid.cells_per_axis);
                pass.set_pipeline(&p.lattice);
                pass.draw(0..vertices, 0..instances);
            }
            GridView::Cells => self.indirect(pass, &p.cells, Draw::Cells),
            GridView::Blocks if options.lod => self.indirect(pass, &p.lod_blocks, Draw::LodBlocks),
            GridView::Blocks => self.indirect(pass, &p.blocks, Draw::Blocks),
        }
        if options.ambiguous {
            self.indirect(pass, &p.ambiguous, Draw::Ambiguous);
        }
        if options.slice.is_some() {
            self.indirect(pass, &p.contour, Draw::Contour);
        }
        if selected {
            pass.set_pipeline(&p.selected_edges);
            pass.draw(0..24, 0..1);
            pass.set_pipeline(&p.selected_corners);
            pass.draw(0..6, 0..8);
        }
        let side = GIZMO_PIXELS.min(size.0 as f32 / 4.0).min(size.1 as f32 / 4.0);
        if side >= 16.0 {
            // Bottom right: the panel sits top left, the statistics top right.
            pass.set_viewport(size.0 as f32 - side - 4.0, size.1 as f32 - side - 4.0, side, side, 0.0, 1.0);
            pass.set_pipeline(&p.gizmo);
            pass.draw(0..6, 0..1);
            pass.set_viewport(0.0, 0.0, size.0 as f32, size.1 as f32, 0.0, 1.0);
        }
    }
}

/// The lattice's slab is this many cells thick at 1 cell per axis, thinner in proportion on finer
/// grids (16 cells thick at 16³, that is the whole grid; 2 at 128³; 1 from 256³), so its depth stays
/// readable.
const LATTICE_SLAB_SPAN: u32 = 256;

/// The lattice's slab for a grid, a view direction and the slice: (axis across it, first plane, last
/// plane). Across the slice's axis and centred on it when there is a slice, otherwise across the axis
/// the camera looks along most, centred in the box.
pub fn lattice_slab(grid: Grid, forward: glam::Vec3, slice: Option<Slice>) -> [u32; 3] {
    let n = grid.cells_per_axis;
    let (axis, centre) = match slice {
        Some(s) => (s.axis, s.plane(n)),
        None => {
            let f = forward.abs();
            let axis = if f.x >= f.y && f.x >= f.z {
                0
            } else if f.y >= f.z {
                1
            } else {
                2
            };
            (axis, n / 2)
        }
    };
    let thickness = (LATTICE_SLAB_SPAN / n).clamp(1, n);
    let first = centre.saturating_sub(thickness / 2).min(n - thickness);
    [axis, first, first + thickness]
}

/// The shading uniform's view fields for `options` (the renderer fills the rest; `forward` is the
/// camera's view direction).
pub fn view_fields(uniform: &mut ShadingUniform, options: &ViewOptions, grid: Grid, forward: glam::Vec3) {
    uniform.display = options.display.index();
    uniform.compare = options.compare.index();
    uniform.divider = options.divider;
    uniform.color_by = options.color_by.index();
    uniform.grid_view = options.grid.index();
    uniform.saddle = options.saddle.index();
    uniform.cells_per_axis = grid.cells_per_axis;
    uniform.cell_size = grid.cell_size();
    uniform.lattice_alpha = (4.0 / grid.cells_per_axis as f32).clamp(0.08, 0.25);
    let [axis, first, last] = lattice_slab(grid, forward, options.slice);
    uniform.lattice_slab = [axis, first, last, 0];
    match options.slice {
        Some(slice) => {
            uniform.slice_axis = slice.axis;
            uniform.slice_plane = slice.plane(grid.cells_per_axis);
        }
        None => uniform.slice_axis = 3,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lattice_is_one_instanced_draw_linear_in_the_resolution() {
        for n in [8u32, 16, 64, 128, 512] {
            let (vertices, instances) = lattice_draw(n);
            assert_eq!(instances, 3 * (n + 1));
            assert_eq!(vertices, 2 * (n + 1));
            // Lines: vertices / 2 per instance, 3 (n + 1)² in all (each grid line once).
            assert_eq!(vertices / 2 * instances, 3 * (n + 1) * (n + 1));
        }
        // Fine grids draw a thin slab across the view's main axis or the slice's.
        let grid = Grid { cells_per_axis: 128 };
        assert_eq!(lattice_slab(grid, glam::Vec3::new(0.2, -0.3, -0.9), None), [2, 63, 65]);
        let slice = Some(Slice { axis: 0, position: 1.0 });
        assert_eq!(lattice_slab(grid, glam::Vec3::Z, slice), [0, 126, 128]);
        assert_eq!(lattice_slab(Grid { cells_per_axis: 16 }, glam::Vec3::X, None), [0, 0, 16]);
        assert_eq!(lattice_slab(Grid { cells_per_axis: 512 }, glam::Vec3::Y, None), [1, 256, 257]);
        let (_, i16) = lattice_draw(16);
        let (_, i32) = lattice_draw(32);
        let (_, i64) = lattice_draw(64);
        assert_eq!(i64 - i32, 2 * (i32 - i16), "instances grow linearly");
    }
}
