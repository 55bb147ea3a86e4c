//! Clips of the animation as files a page or a slide shows without a player: an animated GIF or an
//! animated PNG (APNG), fed RGBA frames one animation step apart.
//!
//! An APNG keeps every pixel as drawn and is written frame by frame. A GIF has at most 256 colours:
//! one palette serves the whole clip (the global colour table), chosen from pixels of every frame, so
//! the frames are held until the last one arrives, then mapped to it and written.

use crate::ParamError;
use crate::scene::params::check_u32;
use std::io::Write;

/// The frame rates a clip can have.
pub const FRAME_RATES: [u32; 3] = [24, 30, 60];

/// The most memory a GIF's held frames may take, in bytes (3 a pixel).
pub const GIF_HELD_BYTES: u64 = 4 << 30;

/// Pixels of the clip the GIF's palette is learnt from, at most.
const PALETTE_SAMPLE: u64 = 1 << 20;

/// An animated image format.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClipFormat {
    /// Animated GIF: one palette of at most 256 colours for the clip, delays in hundredths of a
    /// second, looping forever.
    Gif,
    /// Animated PNG: RGBA8 frames as drawn, looping forever.
    Apng,
}

impl ClipFormat {
    pub const WORDS: &[&str] = &["gif", "apng"];

    /// Reads `gif` or `apng` (any case; `png` is taken for `apng`); the error says what is accepted.
    pub fn parse(word: &str) -> Result<ClipFormat, ParamError> {
        match word.trim().to_ascii_lowercase().as_str() {
            "gif" => Ok(Self::Gif),
            "apng" | "png" => Ok(Self::Apng),
            _ => Err(ParamError::Invalid {
                name: "clip format",
                value: word.to_string(),
                expected: format!("one of {}", Self::WORDS.join(", ")).into(),
            }),
        }
    }

    /// The format a file name asks for by its extension: `.gif`, or `.png` or `.apng`.
    pub fn from_file_name(name: &str) -> Option<ClipFormat> {
        let (_, extension) = name.rsplit_once('.')?;
        Self::parse(extension).ok()
    }

    /// The format a file name asks for; the error names the extensions accepted.
    pub fn for_file_name(name: &str) -> Result<ClipFormat, ParamError> {
        Self::from_file_name(name).ok_or_else(|| ParamError::Invalid {
            name: "clip file name",
            value: name.to_string(),
            expected: "a name ending in .gif, .png or .apng (or --format gif or apng)".to_string().into(),
        })
    }

    /// The word `parse` reads for the format.
    pub fn name(self) -> &'static str {
        Self::WORDS[self as usize]
    }
}

/// Checks that `fps` is one of [`FRAME_RATES`].
pub fn check_fps(fps: u32) -> Result<u32, ParamError> {
    if FRAME_RATES.contains(&fps) {
        return Ok(fps);
    }
    let rates: Vec<String> = FRAME_RATES.iter().map(u32::to_string).collect();
    Err(ParamError::Invalid {
        name: "frame rate (fps)",
        value: fps.to_string(),
        expected: format!("one of {}", rates.join(", ")).into(),
    })
}

/// The frames of a clip `seconds` long: the nearest whole number, at least one.
pub fn frame_count(seconds: f32, fps: u32) -> u32 {
    ((seconds as f64 * fps as f64).round() as u32).max(1)
}

/// How long frame `index` is shown in a GIF, in hundredths of a second. GIF delays are whole
/// hundredths, so the ends of the frames are rounded down from their exact times and each delay is
/// the difference: at 30 fps 3, 3, 4, …; at 60 fps 1, 2, 2, … (a clip at 60 fps keeps every second
/// frame at 30 instead: see `ClipEncoder::push`); at 24 fps 4, 4, 4, 4, 5, …. The clip then lasts as
/// long as it should to within a hundredth.
pub fn gif_delay(index: u32, fps: u32) -> u16 {
    let end = |frames: u64| frames * 100 / fps as u64;
    (end(index as u64 + 1) - end(index as u64)) as u16
}

/// Writes a clip of `frames` frames of `width` × `height` to any writer, fed one RGBA8 frame at a
/// time (rows top to bottom, as `Offscreen` reads them back).
pub struct ClipEncoder<W: Write> {
    width: u32,
    height: u32,
    frames: u32,
    fps: u32,
    fed: u32,
    kind: Kind<W>,
}

enum Kind<W: Write> {
    /// The frames held as RGB until the palette is chosen, and the pixels sampled for it.
    Gif {
        out: W,
        held: Vec<Vec<u8>>,
        sample: Vec<u8>,
        stride: u64,
    },
    Apng(png::Writer<W>),
}

impl<W: Write> ClipEncoder<W> {
    /// Starts a clip; an APNG's header is written at once. A GIF is refused where [`check_gif`]
    /// refuses it.
    pub fn new(
        out: W,
        format: ClipFormat,
        width: u32,
        height: u32,
        frames: u32,
        fps: u32,
    ) -> Result<Self, Box<dyn std::error::Error>> {
        check_fps(fps)?;
        if frames == 0 || width == 0 || height == 0 {
            return Err("a clip needs at least one frame of at least one pixel".into());
        }
        let kind = match format {
            ClipFormat::Gif => {
                check_gif(width, height, frames)?;
                let pixels = width as u64 * height as u64 * frames as u64;
                let stride = pixels.div_ceil(PALETTE_SAMPLE).max(1);
                Kind::Gif { out, held: Vec::new(), sample: Vec::new(), stride }
            }
            ClipFormat::Apng => {
                let mut encoder = png::Encoder::new(out, width, height);
                encoder.set_color(png::ColorType::Rgba);
                encoder.set_depth(png::BitDepth::Eight);
                encoder.set_source_srgb(png::SrgbRenderingIntent::Perceptual);
                // Zero plays: loop forever.
                encoder.set_animated(frames, 0)?;
                encoder.set_frame_delay(1, fps as u16)?;
                Kind::Apng(encoder.write_header()?)
            }
        };
        Ok(Self { width, height, frames, fps, fed: 0, kind })
    }

    /// Whether the next frame is kept: browsers show a GIF frame shorter than 2/100 s for 1/10 s,
    /// so a 60 fps GIF keeps every second frame, each shown 1/30 s, and lasts as long. A frame not
    /// kept need not be drawn: `push` takes any bytes for it.
    pub fn keeps_next(&self) -> bool {
        !(matches!(self.kind, Kind::Gif { .. }) && self.fps == 60 && self.fed % 2 == 1)
    }

    /// Adds the next frame.
    pub fn push(&mut self, rgba: &[u8]) -> Result<(), Box<dyn std::error::Error>> {
        if self.fed == self.frames {
            return Err(format!("the clip has {} frames already", self.frames).into());
        }
        if !self.keeps_next() {
            self.fed += 1;
            return Ok(());
        }
        let expected = self.width as usize * self.height as usize * 4;
        if rgba.len() != expected {
            return Err(format!("a frame has {} bytes, expected {expected}", rgba.len()).into());
        }
        match &mut self.kind {
            Kind::Gif { held, sample, stride, .. } => {
                // Every `stride`-th pixel of the clip, counted across frames, so that all of them
                // have a say in the palette.
                let first = self.fed as u64 * (self.width as u64 * self.height as u64);
                let offset = ((*stride - first % *stride) % *stride) as usize;
                for pixel in rgba.chunks_exact(4).skip(offset).step_by(*stride as usize) {
                    sample.extend_from_slice(&[pixel[0], pixel[1], pixel[2], 255]);
                }
                held.push(rgba.chunks_exact(4).flat_map(|p| [p[0], p[1], p[2]]).collect());
            }
            Kind::Apng(writer) => writer.write_image_data(rgba)?,
        }
        self.fed += 1;
        Ok(())
    }

    /// Writes what is left (all of a GIF) and flushes the writer. To keep the bytes in memory, pass
    /// `&mut Vec<u8>` as the writer.
    pub fn finish(self) -> Result<(), Box<dyn std::error::Error>> {
        if self.fed != self.frames {
            return Err(format!("the clip has {} of its {} frames", self.fed, self.frames).into());
        }
        match self.kind {
            Kind::Gif { out, held, sample, .. } => {
                let fps = if self.fps == 60 { 30 } else { self.fps };
                write_gif(out, self.width as u16, self.height as u16, fps, held, &sample)
            }
            Kind::Apng(writer) => Ok(writer.finish()?),
        }
    }
}

/// Refuses a GIF wider or taller than its 16-bit sizes hold, or whose frames, held until its palette
/// is chosen, would take more than [`GIF_HELD_BYTES`].
pub fn check_gif(width: u32, height: u32, frames: u32) -> Result<(), ParamError> {
    for (name, side) in [("GIF width", width), ("GIF height", height)] {
        check_u32(name, side, 1, u16::MAX as u32)?;
    }
    if width as u64 * height as u64 * 3 * frames as u64 <= GIF_HELD_BYTES {
        return Ok(());
    }
    Err(ParamError::Invalid {
        name: "GIF clip",
        value: format!("{frames} frames of {width}x{height}"),
        expected: format!(
            "at most {} GiB of frames (3 bytes a pixel), which are held until its palette is chosen; \
             make it shorter or smaller, or write an APNG",
            GIF_HELD_BYTES >> 30
        )
        .into(),
    })
}

/// Learns one palette from `sample` (RGBA), maps every held frame to it and writes the GIF.
fn write_gif<W: Write>(
    out: W,
    width: u16,
    height: u16,
    fps: u32,
    held: Vec<Vec<u8>>,
    sample: &[u8],
) -> Result<(), Box<dyn std::error::Error>> {
    // Sample factor 1: every sampled pixel trains the network (the sample is already thinned).
    let quant = color_quant::NeuQuant::new(1, 256, sample);
    let mut encoder = gif::Encoder::new(out, width, height, &quant.color_map_rgb())?;
    encoder.set_repeat(gif::Repeat::Infinite)?;
    // The palette entry of each colour met so far (u16::MAX: not yet looked up); shaded frames
    // repeat most of their colours, and the network's search is the slow part.
    let mut nearest = vec![u16::MAX; 1 << 24];
    let mut indices = Vec::with_capacity(width as usize * height as usize);
    for (index, rgb) in held.into_iter().enumerate() {
        indices.clear();
        for p in rgb.chunks_exact(3) {
            let key = (p[0] as usize) << 16 | (p[1] as usize) << 8 | p[2] as usize;
            if nearest[key] == u16::MAX {
                nearest[key] = quant.index_of(&[p[0], p[1], p[2], 255]) as u16;
            }
            indices.push(nearest[key] as u8);
        }
        let frame = gif::Frame {
            width,
            height,
            delay: gif_delay(index as u32, fps),
            buffer: std::borrow::Cow::Borrowed(&indices),
            ..gif::Frame::default()
        };
        encoder.write_frame(&frame)?;
    }
    encoder.into_inner()?.flush()?;
    Ok(())
}
