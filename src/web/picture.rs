//! Pictures of the frames a canvas shows, for print: the frame's texture is copied on the GPU before
//! it is presented and read back later, so that taking one never waits for the device on the page's
//! thread (a canvas's own `toBlob` does).

use super::{Polling, View};
use crate::device::TextureCopy;
use wasm_bindgen::prelude::*;

/// Whether the next frame is copied, and the copy of the latest one asked for.
#[derive(Default)]
pub(super) struct FramePicture {
    /// The canvas's textures can be copied from (WebGPU canvases can; WebGL2 ones may not).
    copyable: bool,
    wanted: bool,
    kept: Option<(TextureCopy, bool)>,
}

impl FramePicture {
    pub fn new(copyable: bool) -> FramePicture {
        FramePicture { copyable, ..FramePicture::default() }
    }

    /// What the canvas's textures are configured for beyond drawing into them.
    pub fn usage(&self) -> wgpu::TextureUsages {
        if self.copyable { wgpu::TextureUsages::COPY_SRC } else { wgpu::TextureUsages::empty() }
    }

    /// Copies `texture` (the frame about to be presented) when a picture of it was asked for.
    pub fn frame_drawn(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, texture: &wgpu::Texture) {
        if !std::mem::take(&mut self.wanted) {
            return;
        }
        let bgra =
            matches!(texture.format(), wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb);
        self.kept = Some((TextureCopy::submit(device, queue, texture), bgra));
    }
}

#[wasm_bindgen]
impl View {
    /// Asks for a copy of the next frame (`kept_picture` reads it); false where the canvas cannot be
    /// copied from, and the page takes its picture another way.
    pub fn keep_picture(&mut self) -> bool {
        self.picture.wanted = self.picture.copyable;
        self.picture.copyable
    }

    /// The RGBA pixels of the frame `keep_picture` asked for, rows top to bottom, read back without
    /// waiting on the page's thread; none when no frame was copied since.
    pub fn kept_picture(&mut self) -> Option<js_sys::Promise> {
        let (copy, bgra) = self.picture.kept.take()?;
        let device = self.device.clone();
        Some(wasm_bindgen_futures::future_to_promise(async move {
            let _polling = Polling::start(&device);
            let mut pixels = copy
                .texels(&device)
                .await
                .ok_or_else(|| JsValue::from_str("the device was lost before the frame was read back"))?;
            // The canvas shows the frame opaque, whatever alpha the passes left.
            for texel in pixels.chunks_exact_mut(4) {
                if bgra {
                    texel.swap(0, 2);
                }
                texel[3] = 255;
            }
            Ok(js_sys::Uint8Array::from(pixels.as_slice()).into())
        }))
    }
}
