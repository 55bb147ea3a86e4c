//! The exact surface beside the mesh (`shaders/draw/views/exact.wgsl`): where each is drawn with
//! `compare`, and a probe that casts the view's rays for given pixels on the device, so tests can hold
//! the ray caster to a CPU one.

use super::ViewPipelines;
use crate::scene::params::view::{Compare, Display, ViewOptions};

/// The options the mesh is drawn with: with `compare`, the mesh side shows the mesh (shaded when the
/// display is `exact`).
pub fn mesh_side(options: &ViewOptions) -> ViewOptions {
    if options.compare != Compare::None && options.display == Display::Exact {
        return ViewOptions { display: Display::Shaded, ..*options };
    }
    *options
}

/// The divider's column in pixels for an output `width` pixels wide.
fn divider_x(options: &ViewOptions, width: u32) -> u32 {
    ((options.divider * width as f32).round() as u32).clamp(1, width.saturating_sub(1).max(1))
}

/// With `compare=split`, keeps the mesh's draws left of the divider.
pub fn clip_mesh(pass: &mut wgpu::RenderPass, options: &ViewOptions, (width, height): (u32, u32)) {
    if options.compare == Compare::Split {
        pass.set_scissor_rect(0, 0, divider_x(options, width), height);
    }
}

/// After the mesh: with `compare=split`, the exact surface right of the divider; with
/// `compare=overlay`, its outline over the whole view. The scissor is the whole view again after.
pub fn draw_beside_mesh(
    pass: &mut wgpu::RenderPass,
    pipelines: &ViewPipelines,
    options: &ViewOptions,
    (width, height): (u32, u32),
) {
    match options.compare {
        Compare::None => {}
        Compare::Split => {
            let x = divider_x(options, width);
            pass.set_scissor_rect(x, 0, width - x, height);
            pass.set_pipeline(&pipelines.exact);
            pass.draw(0..3, 0..1);
            pass.set_scissor_rect(0, 0, width, height);
        }
        Compare::Overlay => {
            pass.set_pipeline(&pipelines.exact_outline);
            pass.draw(0..3, 0..1);
        }
    }
}
