//! `metaballs record`: clips read back with the `gif` and `png` crates. A GIF has one palette for the
//! clip, loops, and lasts as long as asked in whole hundredths; an APNG's first frame is the frame
//! `render` draws for the same flags; both hold one frame per animation step, and the figure moves
//! between them. Bad input is refused with what is accepted.

use crate::common;

use common::*;
use metaballs::offscreen::read_png;
use metaballs::record::{ClipEncoder, ClipFormat, frame_count, gif_delay};
use std::path::Path;

/// The scene of every clip here: small and coarse, so that it draws fast.
const FLAGS: &[&str] = &["--size", "64x36", "--resolution", "24", "--seconds", "0.5", "--fps", "24"];
const FRAMES: usize = 12;
const PIXELS: usize = 64 * 36;

fn record(out: &Path, extra: &[&str]) -> String {
    let mut args = vec!["record", "--out", out.to_str().unwrap()];
    args.extend(FLAGS);
    args.extend(extra);
    let (code, stdout, stderr) = cli(&args);
    assert_eq!(code, 0, "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
    stdout
}

/// The GIF's frames as RGB through its global palette, after checking what the file says of itself.
fn read_gif(path: &Path) -> Vec<Vec<u8>> {
    let file = std::fs::File::open(path).unwrap();
    let mut decoder = gif::DecodeOptions::new().read_info(std::io::BufReader::new(file)).unwrap();
    assert_eq!((decoder.width(), decoder.height()), (64, 36));
    let palette = decoder.global_palette().expect("a global palette").to_vec();
    assert!(palette.len().is_multiple_of(3) && palette.len() <= 3 * 256, "{} palette bytes", palette.len());
    let (mut frames, mut delays) = (Vec::new(), Vec::new());
    while let Some(frame) = decoder.read_next_frame().unwrap() {
        assert_eq!((frame.left, frame.top, frame.width, frame.height), (0, 0, 64, 36));
        assert!(frame.palette.is_none(), "frame {} has a palette of its own", frames.len());
        assert_eq!(frame.buffer.len(), PIXELS);
        delays.push(frame.delay);
        let rgb: Vec<u8> =
            frame.buffer.iter().flat_map(|&i| palette[3 * i as usize..][..3].to_vec()).collect();
        frames.push(rgb);
    }
    assert_eq!(decoder.repeat(), gif::Repeat::Infinite);
    assert_eq!(frames.len(), FRAMES);
    assert_eq!(delays.iter().map(|&d| d as u32).sum::<u32>(), 50, "delays {delays:?}");
    assert_eq!(delays, [4, 4, 4, 4, 4, 5, 4, 4, 4, 4, 4, 5]);
    frames
}

/// The APNG's frames, RGBA, after checking its animation and frame controls.
fn read_apng(path: &Path) -> Vec<Vec<u8>> {
    let file = std::fs::File::open(path).unwrap();
    let mut reader = png::Decoder::new(std::io::BufReader::new(file)).read_info().unwrap();
    let info = reader.info();
    assert_eq!((info.width, info.height), (64, 36));
    assert_eq!((info.color_type, info.bit_depth), (png::ColorType::Rgba, png::BitDepth::Eight));
    assert!(info.srgb.is_some(), "no sRGB chunk");
    let animation = info.animation_control.expect("an acTL chunk");
    assert_eq!(animation.num_frames as usize, FRAMES);
    assert_eq!(animation.num_plays, 0, "loops forever");
    let mut frames = Vec::new();
    for _ in 0..FRAMES {
        let mut pixels = vec![0; reader.output_buffer_size().unwrap()];
        let out = reader.next_frame(&mut pixels).unwrap();
        pixels.truncate(out.buffer_size());
        let control = reader.info().frame_control.expect("an fcTL chunk");
        assert_eq!((control.width, control.height, control.x_offset, control.y_offset), (64, 36, 0, 0));
        assert_eq!((control.delay_num, control.delay_den), (1, 24));
        assert_eq!(pixels.len(), 4 * PIXELS);
        frames.push(pixels);
    }
    assert!(reader.next_frame(&mut vec![0; 4 * PIXELS]).is_err(), "more frames than acTL says");
    frames
}

/// The mean and largest difference per channel of two images, RGB of the first against RGB or RGBA.
fn difference(rgb: &[u8], other: &[u8], other_channels: usize) -> (f64, u8) {
    let (mut sum, mut max) = (0u64, 0u8);
    for (a, b) in rgb.chunks_exact(3).zip(other.chunks_exact(other_channels)) {
        for c in 0..3 {
            let d = a[c].abs_diff(b[c]);
            sum += d as u64;
            max = max.max(d);
        }
    }
    (sum as f64 / (3 * PIXELS) as f64, max)
}

#[test]
fn clip_lengths_and_gif_delays() {
    assert_eq!(frame_count(0.5, 24), 12);
    assert_eq!(frame_count(4.0, 30), 120);
    assert_eq!(frame_count(0.1, 24), 2);
    assert_eq!(frame_count(0.01, 24), 1);
    let thirty: Vec<u16> = (0..6).map(|i| gif_delay(i, 30)).collect();
    assert_eq!(thirty, [3, 3, 4, 3, 3, 4]);
    let sixty: Vec<u16> = (0..6).map(|i| gif_delay(i, 60)).collect();
    assert_eq!(sixty, [1, 2, 2, 1, 2, 2]);
    for fps in [24, 30, 60] {
        let total: u32 = (0..fps * 7).map(|i| gif_delay(i, fps) as u32).sum();
        assert_eq!(total, 700, "7 s at {fps} fps");
    }
    assert_eq!(ClipFormat::from_file_name("a.GIF"), Some(ClipFormat::Gif));
    assert_eq!(ClipFormat::from_file_name("a.png"), Some(ClipFormat::Apng));
    assert_eq!(ClipFormat::from_file_name("a.apng"), Some(ClipFormat::Apng));
    assert_eq!(ClipFormat::from_file_name("a.mp4"), None);
    assert_eq!(ClipFormat::from_file_name("gif"), None);
}

#[test]
fn the_cli_records_a_gif_and_an_apng_of_the_animation() {
    let dir = scratch_dir("metaballs-record");
    let gif_path = dir.join("clip.gif");
    let stdout = record(&gif_path, &[]);
    let bytes = std::fs::metadata(&gif_path).unwrap().len();
    let expected = format!("(64x36, 12 frames at 24 fps, 0.50 s, {bytes} bytes): render ");
    assert!(stdout.starts_with("wrote ") && stdout.contains(&expected), "{stdout}");
    let gif_frames = read_gif(&gif_path);

    let apng_path = dir.join("clip.png");
    record(&apng_path, &[]);
    let apng_frames = read_apng(&apng_path);

    // Frame 0 is what `render` draws for the same flags.
    let still = dir.join("still.png");
    let (code, _, stderr) =
        cli(&["render", "--out", still.to_str().unwrap(), "--size", "64x36", "--resolution", "24"]);
    assert_eq!(code, 0, "{stderr}");
    let (width, height, rendered) = read_png(&still).unwrap();
    assert_eq!((width, height), (64, 36));
    let off_by = rendered.iter().zip(&apng_frames[0]).map(|(a, b)| a.abs_diff(*b)).max().unwrap();
    assert!(off_by <= 1, "the APNG's first frame differs from the render by up to {off_by}");

    for (i, (gif, apng)) in gif_frames.iter().zip(&apng_frames).enumerate() {
        // The same frames, the GIF's through its 256 colours.
        let (mean, max) = difference(gif, apng, 4);
        assert!(
            mean < 1.0 && max < 48,
            "frame {i}: the GIF is off the APNG by {mean:.2} on average, {max} at most"
        );
        if i > 0 {
            // The animation moves: enough pixels change from one step to the next.
            let changed = |frames: &[Vec<u8>], channels: usize| {
                frames[i - 1]
                    .chunks_exact(channels)
                    .zip(frames[i].chunks_exact(channels))
                    .filter(|(a, b)| a != b)
                    .count()
            };
            assert!(changed(&apng_frames, 4) > 10, "APNG frames {} and {i} are alike", i - 1);
            assert!(changed(&gif_frames, 3) > 10, "GIF frames {} and {i} are alike", i - 1);
        }
    }

    // `--format` overrides the extension; `.apng` is an APNG.
    let named = dir.join("clip.apng");
    record(&named, &["--seed", "7"]);
    assert_eq!(read_apng(&named).len(), FRAMES);
    let forced = dir.join("clip.bin");
    record(&forced, &["--format", "gif"]);
    assert_eq!(read_gif(&forced), gif_frames, "the same flags make the same GIF");
    std::fs::remove_dir_all(dir).unwrap();
}

#[test]
fn the_cli_refuses_bad_clips() {
    let dir = scratch_dir("metaballs-record-bad");
    let gif = dir.join("never.gif");
    let gif = gif.to_str().unwrap();
    let mp4 = dir.join("clip.mp4");
    let mp4 = mp4.to_str().unwrap();
    let cases: &[(&[&str], &str)] = &[
        (&["--out", gif, "--fps", "25"], "frame rate (fps) must be one of 24, 30, 60, got \"25\""),
        (&["--out", mp4], "must be a name ending in .gif, .png or .apng (or --format gif or apng)"),
        (&["--out", gif, "--format", "webm"], "clip format must be one of gif, apng, got \"webm\""),
        (&["--out", gif, "--seconds", "0"], "seconds must be between 0.1 and 60"),
        (&["--out", gif, "--seconds", "61"], "seconds must be between 0.1 and 60"),
        (&["--out", gif, "--size", "8192x8192", "--seconds", "60"], "GIF clip must be at most 4 GiB"),
        (&["--out", gif, "--spheres", "0"], "between 1 and 64"),
    ];
    for (flags, expected) in cases {
        let mut args = vec!["record"];
        args.extend(*flags);
        let (code, _, stderr) = cli(&args);
        assert_eq!(code, 2, "{flags:?}: {stderr}");
        assert!(stderr.contains(expected), "{flags:?}: {stderr:?} should contain {expected:?}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
    assert!(std::fs::read_dir(&dir).unwrap().next().is_none(), "a refused clip left a file");
    std::fs::remove_dir_all(dir).unwrap();
}

/// Browsers show a GIF frame shorter than 2/100 s for 1/10 s: a 60 fps GIF keeps every second frame,
/// each shown for 1/30 s, so it plays at its length in a browser.
#[test]
fn a_gif_at_60_fps_keeps_every_second_frame() {
    let mut bytes = Vec::new();
    let mut clip = ClipEncoder::new(&mut bytes, ClipFormat::Gif, 4, 2, 12, 60).expect("a clip");
    for i in 0..12u8 {
        clip.push(&[i * 20, 255 - i * 20, 40, 255].repeat(8)).expect("a frame");
    }
    clip.finish().expect("the clip is written");
    let mut options = gif::DecodeOptions::new();
    options.set_color_output(gif::ColorOutput::RGBA);
    let mut decoder = options.read_info(bytes.as_slice()).expect("a GIF");
    let mut kept = Vec::new();
    while let Some(frame) = decoder.read_next_frame().expect("a frame") {
        kept.push((frame.delay, frame.buffer[0]));
    }
    let delays: Vec<u16> = kept.iter().map(|k| k.0).collect();
    assert_eq!(delays, [3, 3, 4, 3, 3, 4], "12 frames at 60 fps last 20/100 s");
    // The frames kept are 0, 2, 4, …: their red rises by 40 a frame (within the palette's error).
    for (k, (_, red)) in kept.iter().enumerate() {
        assert!((*red as i32 - 40 * k as i32).abs() <= 8, "frame {k}: red {red}");
    }
}
