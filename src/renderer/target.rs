//! What a renderer draws into: textures of one format and size.

use super::limits::check_size;
use crate::scene::params::ParamError;

/// The format and size of the texture views a renderer draws into.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Target {
    pub format: wgpu::TextureFormat,
    /// Width and height in pixels.
    pub size: (u32, u32),
}

impl Target {
    /// A `width` × `height` target of `format`, if a device of `limits` holds textures that large.
    pub fn new(
        limits: &wgpu::Limits,
        format: wgpu::TextureFormat,
        width: u32,
        height: u32,
    ) -> Result<Self, ParamError> {
        check_size(limits, width, height)?;
        Ok(Self { format, size: (width, height) })
    }

    /// Takes a new size, if a device of `limits` holds it; returns whether it changed.
    pub fn resize(&mut self, limits: &wgpu::Limits, width: u32, height: u32) -> Result<bool, ParamError> {
        check_size(limits, width, height)?;
        let changed = (width, height) != self.size;
        self.size = (width, height);
        Ok(changed)
    }

    /// The size as floating-point pixels, as the shaders take it.
    pub fn viewport(&self) -> [f32; 2] {
        [self.size.0 as f32, self.size.1 as f32]
    }

    /// True when the shader encodes sRGB itself: the format stores the values as written.
    pub fn encodes_srgb(&self) -> bool {
        !self.format.is_srgb()
    }
}
