//! What the shaders read each frame: the grid and the spheres for the compute passes; the camera,
//! the lights and the view options for the shading and the teaching views.

use super::Renderer;
use crate::draw::uniforms::{LightUniform, ShadingUniform};
use crate::draw::views;
use crate::extract::uniforms::GridUniform;
use crate::scene::BOX_HALF_EXTENT;
use crate::scene::math;
use crate::scene::params::Settings;
use crate::scene::params::view::{Blend, CaseTable, Interpolation, March, Method, Projection, Split};
use glam::{Mat4, UVec3, Vec3};

impl Renderer {
    pub(super) fn write_uniforms(&self) {
        let grid = self.grid();
        let spheres = self.scene.spheres();
        let capacity = self.stage.buffers.capacity;
        let grid_uniform = GridUniform {
            box_min: [-BOX_HALF_EXTENT; 3],
            cell_size: grid.cell_size(),
            iso: self.settings.iso,
            cells_per_axis: grid.cells_per_axis,
            sphere_count: spheres.len() as u32,
            max_blocks: capacity.blocks,
            max_vertices: capacity.vertices,
            max_indices: capacity.indices,
            max_cells: capacity.cells,
            flags: (self.settings.view.interpolation == Interpolation::Midpoint) as u32
                | ((self.settings.view.blend == Blend::Max) as u32) << 1
                | ((self.settings.view.case_table != CaseTable::Classic) as u32) << 2
                | ((self.settings.view.case_table == CaseTable::Mc33) as u32) << 3
                | self.settings.view.kernel.index() << 4
                | ((self.settings.view.split == Split::Five) as u32) << 6
                | ((self.settings.view.method == Method::DualContouring) as u32) << 7,
            march: March::on_grid(self.settings.view.march, grid.cells_per_axis).unwrap_or([u32::MAX; 3]),
            blobbiness: self.settings.view.blobbiness,
        };
        self.queue.write_buffer(&self.scene_buffers.grid, 0, bytemuck::bytes_of(&grid_uniform));
        let packed: Vec<[f32; 4]> = spheres.iter().map(|s| s.to_gpu()).collect();
        self.queue.write_buffer(&self.scene_buffers.spheres, 0, bytemuck::cast_slice(&packed));

        let s = &self.settings;
        let eye = s.camera.eye();
        let mut shading = ShadingUniform {
            view_proj: self.view_projection().to_cols_array_2d(),
            inverse_view_proj: self.view_projection().inverse().to_cols_array_2d(),
            view: self.camera_view().view().to_cols_array_2d(),
            camera_position: eye.to_array(),
            ambient: s.material.ambient,
            camera_forward: (-eye).normalize().to_array(),
            orthographic: (s.view.projection == Projection::Orthographic) as u32,
            base_color: s.material.base_color.to_array(),
            diffuse: s.material.diffuse,
            specular: s.material.specular,
            shininess: s.material.shininess,
            encode_srgb: self.target.encodes_srgb() as u32,
            box_half_extent: BOX_HALF_EXTENT,
            viewport: self.target.viewport(),
            iso: s.iso,
            selected: self.teaching.selected.is_some() as u32,
            selected_cell: self.teaching.selected.unwrap_or(UVec3::ZERO).to_array(),
            lod_blocks_offset: self.stage.buffers.lod_blocks_offset(),
            lights: lights(&self.settings),
            background_top: s.view.background()[0],
            background_bottom: s.view.background()[1],
            ..Default::default()
        };
        views::view_fields(&mut shading, &views::shown(&s.view), grid, (-eye).normalize());
        self.queue.write_buffer(self.shade.uniform(), 0, bytemuck::bytes_of(&shading));
    }

    /// Where world point `p` lands in the output, in pixels from the top left.
    pub fn project(&self, p: Vec3) -> glam::Vec2 {
        self.camera_view().project(p)
    }

    /// The camera's projection times its view: perspective, or orthographic with the same framing at
    /// the box's centre.
    pub(super) fn view_projection(&self) -> Mat4 {
        self.camera_view().view_projection()
    }
}

/// The lights `settings` turn on: the point light where the settings put it, in white; a cool
/// directional light from the upper left; a warm spot from the front left aimed at the box's centre.
fn lights(settings: &Settings) -> [LightUniform; 3] {
    let on = settings.view.lights;
    let spot_position = Vec3::new(-1.8, 2.6, 2.6);
    let half_angle = settings.view.spot_angle.to_radians();
    [
        LightUniform {
            position: settings.light_position.to_array(),
            kind: if on.point { 1 } else { 0 },
            color: [1.0; 3],
            ..Default::default()
        },
        LightUniform {
            kind: if on.directional { 2 } else { 0 },
            direction: Vec3::new(0.8, -1.0, -0.3).normalize().to_array(),
            color: [0.55, 0.62, 0.85],
            ..Default::default()
        },
        LightUniform {
            position: spot_position.to_array(),
            kind: if on.spot { 3 } else { 0 },
            direction: (-spot_position).normalize().to_array(),
            cos_outer: math::cos(half_angle),
            color: [1.0, 0.8, 0.5],
            cos_inner: math::cos(half_angle * (1.0 - settings.view.spot_softness)),
        },
    ]
}
