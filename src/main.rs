//! Command line: render a frame to PNG offscreen.

#[cfg(not(target_arch = "wasm32"))]
mod cli {
    use clap::{Parser, Subcommand};
    use metaballs::bench;
    use metaballs::offscreen::{Offscreen, write_png};
    use metaballs::params::{check_f32, check_u32};
    use metaballs::{ParamError, Settings};
    use std::path::PathBuf;
    use std::process::ExitCode;
    use std::time::Instant;

    #[derive(Parser)]
    #[command(name = "metaballs", version, about = "Marching cubes of merging spheres on the GPU")]
    struct Cli {
        #[command(subcommand)]
        command: Command,
    }

    #[derive(Subcommand)]
    enum Command {
        /// Render one frame offscreen and write it as a PNG.
        Render(RenderArgs),
        /// Time animated frames for a table of resolutions and sphere counts.
        Bench(BenchArgs),
    }

    #[derive(clap::Args)]
    struct BenchArgs {
        /// Also write the table as a JSON array of records to this file.
        #[arg(long)]
        json: Option<PathBuf>,
        /// Frames timed per row (after three warm-up frames).
        #[arg(long, default_value_t = 30, allow_negative_numbers = true)]
        frames: u32,
        /// Resolutions (cells per axis), comma-separated; by default 32, 64, 128, 256, and 512 where the
        /// device holds it (not on software adapters).
        #[arg(long, value_delimiter = ',', allow_negative_numbers = true)]
        resolutions: Option<Vec<u32>>,
        /// Sphere counts, comma-separated.
        #[arg(long, value_delimiter = ',', default_value = "1,5,16,64", allow_negative_numbers = true)]
        spheres: Vec<u32>,
        /// Frame size in pixels, WIDTHxHEIGHT.
        #[arg(long, default_value = "960x640", value_parser = parse_size)]
        size: (u32, u32),
        /// Skip timing the CPU oracle.
        #[arg(long)]
        no_oracle: bool,
        /// Draw without 4× multisampling.
        #[arg(long)]
        no_antialiasing: bool,
        /// A teaching view to measure, as name=value pairs joined by & (display=wireframe&grid=cells);
        /// repeat the flag for several. Without it, the plain shaded surface.
        #[arg(long = "view")]
        views: Vec<String>,
        /// Meshers to measure, comma-separated: gpu (compute passes), cpu (the CPU mesher), auto (the
        /// CPU on software adapters, else the GPU).
        #[arg(long, value_delimiter = ',', default_value = "auto")]
        mesher: Vec<String>,
    }

    #[derive(clap::Args)]
    struct RenderArgs {
        /// PNG file to write.
        #[arg(long)]
        out: PathBuf,
        /// Number of spheres, 1 to 64.
        #[arg(long, default_value_t = Settings::default().sphere_count, allow_negative_numbers = true)]
        spheres: u32,
        /// Iso level of the surface.
        #[arg(long, default_value_t = Settings::default().iso, allow_negative_numbers = true)]
        iso: f32,
        /// Cells along each axis of the grid.
        #[arg(long, default_value_t = Settings::default().resolution, allow_negative_numbers = true)]
        resolution: u32,
        /// Image size in pixels, WIDTHxHEIGHT.
        #[arg(long, default_value = "960x640", value_parser = parse_size)]
        size: (u32, u32),
        /// Seed of the sphere layout.
        #[arg(long, default_value_t = Settings::default().seed, allow_negative_numbers = true)]
        seed: u64,
        /// Seconds of animation before the frame, 0 to 3600.
        #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
        time: f32,
        /// Draw without 4× multisampling.
        #[arg(long)]
        no_antialiasing: bool,
        /// Frames to render, 1/60 s of animation apart, timing each; the last is written.
        #[arg(long, default_value_t = 1, allow_negative_numbers = true)]
        frames: u32,
        /// Teaching view, as name=value pairs joined by & (display=wireframe&grid=cells&slice=z:0).
        #[arg(long, default_value = "")]
        view: String,
    }

    fn parse_size(text: &str) -> Result<(u32, u32), String> {
        let (w, h) = text
            .split_once(['x', 'X'])
            .ok_or_else(|| format!("size must look like 960x640, got {text:?}"))?;
        let parse = |s: &str, what: &str| {
            s.trim()
                .parse::<u32>()
                .ok()
                .filter(|&v| (1..=8192).contains(&v))
                .ok_or_else(|| format!("{what} must be a whole number from 1 to 8192, got {s:?}"))
        };
        Ok((parse(w, "width")?, parse(h, "height")?))
    }

    fn render(args: RenderArgs) -> Result<(), Box<dyn std::error::Error>> {
        let settings = Settings {
            sphere_count: args.spheres,
            iso: args.iso,
            resolution: args.resolution,
            seed: args.seed,
            antialiasing: !args.no_antialiasing,
            ..Settings::default()
        };
        let settings = bench::with_view(settings, &args.view)?.validated()?;
        check_f32("time (seconds)", args.time, 0.0, 3600.0)?;
        check_u32("frames", args.frames, 1, 100_000)?;
        let (width, height) = args.size;
        let mut offscreen = Offscreen::blocking(settings, width, height)?;
        offscreen.renderer.update(args.time)?;
        // Each frame is timed from submission to the GPU going idle; the first includes pipeline
        // warm-up, so the median is reported.
        let mut frame_ms = Vec::new();
        for frame in 0..args.frames {
            if frame > 0 {
                offscreen.renderer.update(1.0 / 60.0)?;
            }
            let started = Instant::now();
            offscreen.render();
            offscreen.device.poll(wgpu::PollType::wait_indefinitely())?;
            frame_ms.push(started.elapsed().as_secs_f64() * 1e3);
        }
        frame_ms.sort_by(f64::total_cmp);
        let median = frame_ms[frame_ms.len() / 2];
        let pixels = offscreen.last_frame_rgba();
        pollster::block_on(offscreen.renderer.flush_stats());
        write_png(&args.out, width, height, &pixels)?;
        let stats = offscreen.renderer.stats().unwrap_or_default();
        println!(
            "wrote {} ({width}x{height}): {} spheres, iso {}, {} cells per axis, {} triangles{}, \
             {median:.1} ms per frame (median of {}) on {}",
            args.out.display(),
            settings.sphere_count,
            settings.iso,
            settings.resolution,
            stats.triangles,
            if stats.overflowed() { " (budget overflowed: some triangles were dropped)" } else { "" },
            frame_ms.len(),
            offscreen.adapter.get_info().name,
        );
        Ok(())
    }

    fn bench(args: BenchArgs) -> Result<(), Box<dyn std::error::Error>> {
        check_u32("frames", args.frames, 1, 100_000)?;
        for &n in args.resolutions.iter().flatten() {
            metaballs::params::check_resolution(n)?;
        }
        for &n in &args.spheres {
            metaballs::params::check_sphere_count(n)?;
        }
        let plan = bench::Plan {
            resolutions: args.resolutions,
            sphere_counts: args.spheres,
            frames: args.frames,
            size: args.size,
            oracle: !args.no_oracle,
            antialiasing: !args.no_antialiasing,
            views: args.views,
            meshers: args
                .mesher
                .iter()
                .map(|m| -> Result<_, metaballs::ParamError> {
                    Ok(metaballs::Settings::default().with_parameter("mesher", m)?.view.mesher)
                })
                .collect::<Result<_, _>>()?,
        };
        for view in &plan.views {
            bench::with_view(metaballs::Settings::default(), view)?;
        }
        let mut printed_header = false;
        let (adapter, timed, records) = bench::run(&plan, |record| {
            if !printed_header {
                println!("{}", bench::header(record.stage_ms.is_some()));
                printed_header = true;
            }
            println!("{}", bench::row(record));
        })?;
        println!(
            "{} frames of {}x{} per row on {adapter}; {}",
            plan.frames,
            plan.size.0,
            plan.size.1,
            if timed {
                "stage times from GPU timestamp queries (medians)"
            } else {
                "this adapter has no timestamp queries: whole frames timed with a queue sync"
            }
        );
        if let Some(path) = args.json {
            std::fs::write(&path, serde_json::to_string_pretty(&records)?)?;
            println!("wrote {}", path.display());
        }
        Ok(())
    }

    pub fn main() -> ExitCode {
        let cli = Cli::parse();
        let result = match cli.command {
            Command::Render(args) => render(args),
            Command::Bench(args) => bench(args),
        };
        match result {
            Ok(()) => ExitCode::SUCCESS,
            Err(error) => {
                eprintln!("error: {error}");
                // Bad input is a usage error (2); anything else (no GPU, I/O) is 1.
                if error.downcast_ref::<ParamError>().is_some() {
                    ExitCode::from(2)
                } else {
                    ExitCode::FAILURE
                }
            }
        }
    }
}

#[cfg(not(target_arch = "wasm32"))]
fn main() -> std::process::ExitCode {
    cli::main()
}

#[cfg(target_arch = "wasm32")]
fn main() {}
