//! `metaballs record`: a clip of the animation as a GIF or an APNG, its frames one step of 1/fps apart,
//! drawn offscreen with the scene flags of `render`.

use super::{SceneArgs, parse_size, scene_renderer};
use metaballs::offscreen::Offscreen;
use metaballs::record::{self, ClipEncoder, ClipFormat};
use metaballs::scene::params::check_f32;
use std::path::PathBuf;
use std::time::Instant;

#[derive(clap::Args)]
pub(super) struct RecordArgs {
    /// Clip file to write.
    #[arg(long)]
    out: PathBuf,
    /// gif (one palette of 256 colours) or apng (every pixel as drawn); by default the output's
    /// extension (.gif, or .png or .apng).
    #[arg(long)]
    format: Option<String>,
    /// Length of the clip in seconds, 0.1 to 60.
    #[arg(long, default_value_t = 4.0, allow_negative_numbers = true)]
    seconds: f32,
    /// Frames per second: 24, 30 or 60.
    #[arg(long, default_value_t = 30, allow_negative_numbers = true)]
    fps: u32,
    /// Frame size in pixels, WIDTHxHEIGHT.
    #[arg(long, default_value = "640x360", value_parser = parse_size)]
    size: (u32, u32),
    #[command(flatten)]
    scene: SceneArgs,
}

pub(super) fn record(args: RecordArgs) -> Result<(), Box<dyn std::error::Error>> {
    let format = match &args.format {
        Some(word) => ClipFormat::parse(word)?,
        None => ClipFormat::for_file_name(&args.out.to_string_lossy())?,
    };
    let fps = record::check_fps(args.fps)?;
    let seconds = check_f32("seconds", args.seconds, 0.1, 60.0)?;
    let frames = record::frame_count(seconds, fps);
    let (width, height) = args.size;
    if format == ClipFormat::Gif {
        record::check_gif(width, height, frames)?;
    }
    let mut offscreen = scene_renderer(&args.scene, args.size)?;
    let file = std::fs::File::create(&args.out).map_err(|e| format!("{}: {e}", args.out.display()))?;
    let clip = ClipEncoder::new(std::io::BufWriter::new(file), format, width, height, frames, fps);
    let (render_ms, encode_ms) = match clip.and_then(|clip| record_frames(&mut offscreen, clip, frames, fps))
    {
        Ok(times) => times,
        Err(error) => {
            // No half-written clip is left behind.
            let _ = std::fs::remove_file(&args.out);
            return Err(error);
        }
    };
    let bytes = std::fs::metadata(&args.out)?.len();
    println!(
        "wrote {} ({width}x{height}, {frames} frames at {fps} fps, {:.2} s, {bytes} bytes): \
         render {render_ms:.0} ms, encode {encode_ms:.0} ms on {}",
        args.out.display(),
        frames as f64 / fps as f64,
        offscreen.adapter.get_info().name,
    );
    Ok(())
}

/// Draws the clip's frames into `clip`: frame 0 is the scene at --time, as `render` draws it, each
/// next one a step of the animation later (never the wall clock, so a clip is the same on every
/// machine). Returns the milliseconds spent drawing (with reading back) and encoding.
fn record_frames<W: std::io::Write>(
    offscreen: &mut Offscreen,
    mut clip: ClipEncoder<W>,
    frames: u32,
    fps: u32,
) -> Result<(f64, f64), Box<dyn std::error::Error>> {
    let (mut render_ms, mut encode_ms) = (0.0, 0.0);
    for frame in 0..frames {
        let started = Instant::now();
        if frame > 0 {
            offscreen.renderer.update(1.0 / fps as f32)?;
        }
        let pixels = if clip.keeps_next() { offscreen.render_rgba() } else { Vec::new() };
        render_ms += started.elapsed().as_secs_f64() * 1e3;
        let started = Instant::now();
        clip.push(&pixels)?;
        encode_ms += started.elapsed().as_secs_f64() * 1e3;
    }
    let started = Instant::now();
    clip.finish()?;
    encode_ms += started.elapsed().as_secs_f64() * 1e3;
    Ok((render_ms, encode_ms))
}
