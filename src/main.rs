//! Command line: render a frame to PNG offscreen, record a clip as GIF or APNG, write the surface as a
//! mesh file, time frames.

#[cfg(not(target_arch = "wasm32"))]
mod cli {
    use clap::{Parser, Subcommand};
    use metaballs::bench;
    use metaballs::export::{self, MeshFormat};
    use metaballs::offscreen::{Offscreen, write_png};
    mod record;
    use metaballs::scene::SceneError;
    use metaballs::scene::file::{self as scene_file, SceneFile};
    use metaballs::scene::params::{check_f32, check_u32};
    use metaballs::{ParamError, Scene, Settings};
    use record::RecordArgs;
    use std::path::{Path, PathBuf};
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
        /// Write the surface as a mesh file (STL, OBJ or PLY).
        Export(ExportArgs),
        /// Record a clip of the animation as an animated GIF or PNG (APNG).
        Record(RecordArgs),
        /// Time animated frames for a table of resolutions and sphere counts.
        Bench(BenchArgs),
        /// Find the field's critical points (where blobs join, tunnels open and close), time the
        /// search, and print what each does, or the result as JSON.
        Critical(CriticalArgs),
        /// Write the element's description from the parameter table: www/lib/attributes.js,
        /// www/custom-elements.json and www/metaballs-view.d.ts.
        Manifest(ManifestArgs),
    }

    #[derive(clap::Args)]
    struct CriticalArgs {
        /// Sphere counts of the seeded layouts to search, comma-separated.
        #[arg(long, value_delimiter = ',', default_value = "5,16,64")]
        spheres: Vec<u32>,
        /// Layout seed.
        #[arg(long, default_value_t = 1)]
        seed: u64,
        /// Searches per count (the layout moves 1/30 s between them); the median time is printed.
        #[arg(long, default_value_t = 20)]
        repeat: u32,
        /// Print the last search of each count as JSON instead of the table.
        #[arg(long)]
        json: bool,
    }

    fn critical(args: CriticalArgs) -> Result<(), Box<dyn std::error::Error>> {
        use metaballs::critical::{self, json};
        if !args.json {
            println!("spheres | median ms | max ms | critical points | joins | undecided | proven complete");
        }
        for &count in &args.spheres {
            let mut scene = Scene::new(args.seed, check_u32("spheres", count, 1, 64)?)?;
            let mut times = Vec::new();
            let mut last = None;
            for _ in 0..args.repeat.max(1) {
                scene.step(1.0 / 30.0)?;
                let start = Instant::now();
                let found = critical::find(scene.spheres());
                times.push(start.elapsed().as_secs_f64() * 1e3);
                last = Some(found);
            }
            times.sort_by(f64::total_cmp);
            let found = last.expect("one search at least");
            let median = times[times.len() / 2];
            if args.json {
                println!("{}", json::to_json(&found, median));
                continue;
            }
            let joins = found.points.iter().filter(|p| p.role == critical::Role::Join).count();
            println!(
                "{count:7} | {median:9.2} | {:6.2} | {:15} | {joins:5} | {:9} | {}",
                times[times.len() - 1],
                found.points.len(),
                found.undecided,
                found.complete
            );
        }
        Ok(())
    }

    #[derive(clap::Args)]
    struct ManifestArgs {
        /// The folder to write into (the repository's www/).
        #[arg(long, default_value = "www")]
        out: PathBuf,
    }

    fn manifest(args: ManifestArgs) -> Result<(), Box<dyn std::error::Error>> {
        for (path, text) in metaballs::manifest::files() {
            let path = args.out.join(path);
            std::fs::write(&path, text).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
            println!("wrote {}", path.display());
        }
        Ok(())
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

    /// What to draw: a scene file, or a seeded layout described by flags.
    #[derive(clap::Args)]
    struct SceneArgs {
        /// A scene saved by the page (JSON): its spheres and settings replace the flags below.
        #[arg(long, conflicts_with_all = ["spheres", "iso", "resolution", "seed"])]
        scene: Option<PathBuf>,
        /// Number of spheres, 1 to 64.
        #[arg(long, default_value_t = Settings::default().sphere_count, allow_negative_numbers = true)]
        spheres: u32,
        /// Iso level of the surface.
        #[arg(long, default_value_t = Settings::default().iso, allow_negative_numbers = true)]
        iso: f32,
        /// Cells along each axis of the grid.
        #[arg(long, default_value_t = Settings::default().resolution, allow_negative_numbers = true)]
        resolution: u32,
        /// Seed of the sphere layout.
        #[arg(long, default_value_t = Settings::default().seed, allow_negative_numbers = true)]
        seed: u64,
        /// Seconds of animation before the frame, 0 to 3600.
        #[arg(long, default_value_t = 0.0, allow_negative_numbers = true)]
        time: f32,
        /// Draw without 4× multisampling.
        #[arg(long)]
        no_antialiasing: bool,
        /// Teaching view, as name=value pairs joined by & (display=wireframe&grid=cells&slice=z:0);
        /// applied after the scene file's settings.
        #[arg(long, default_value = "")]
        view: String,
    }

    #[derive(clap::Args)]
    struct RenderArgs {
        /// PNG file to write.
        #[arg(long)]
        out: PathBuf,
        #[command(flatten)]
        scene: SceneArgs,
        /// Image size in pixels, WIDTHxHEIGHT.
        #[arg(long, default_value = "960x640", value_parser = parse_size)]
        size: (u32, u32),
        /// Frames to render, 1/60 s of animation apart, timing each; the last is written.
        #[arg(long, default_value_t = 1, allow_negative_numbers = true)]
        frames: u32,
    }

    #[derive(clap::Args)]
    struct ExportArgs {
        /// Mesh file to write.
        #[arg(long)]
        out: PathBuf,
        /// stl (binary, millimetres, Z up), obj (with normals) or ply (binary, with normals); by
        /// default the output's extension, else stl.
        #[arg(long)]
        format: Option<String>,
        /// Simplify to about this many triangles first (keeping the surface closed).
        #[arg(long)]
        simplify: Option<u32>,
        /// File units per box half-width (default: 25 for STL, so the box is 50 mm; 1 for OBJ and PLY).
        #[arg(long)]
        scale: Option<f32>,
        #[command(flatten)]
        scene: SceneArgs,
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

    /// The settings and spheres the flags (or the scene file) describe, the animation run for `--time`.
    fn scene_renderer(args: &SceneArgs, size: (u32, u32)) -> Result<Offscreen, Box<dyn std::error::Error>> {
        let flags = Settings {
            sphere_count: args.spheres,
            iso: args.iso,
            resolution: args.resolution,
            seed: args.seed,
            antialiasing: !args.no_antialiasing,
            ..Settings::default()
        };
        let (settings, scene) = match &args.scene {
            Some(path) => {
                let file = read_scene(path)?;
                let settings = file.applied_to(flags).map_err(|e| in_file(path, e))?;
                let scene = Scene::from_spheres(file.spheres).map_err(|e| in_file(path, e))?;
                (settings, Some(scene.with_seed(settings.seed)))
            }
            None => (flags, None),
        };
        let settings = bench::with_view(settings, &args.view)?.validated()?;
        check_f32("time (seconds)", args.time, 0.0, 3600.0)?;
        let mut offscreen = Offscreen::blocking(settings, size.0, size.1)?;
        if let Some(scene) = scene {
            offscreen.renderer.set_scene(scene);
        }
        offscreen.renderer.update(args.time)?;
        Ok(offscreen)
    }

    fn in_file(path: &Path, error: impl std::fmt::Display) -> SceneError {
        SceneError(format!("{}: {error}", path.display()))
    }

    /// Reads a scene file, refusing one larger than a scene can be before reading it.
    fn read_scene(path: &Path) -> Result<SceneFile, Box<dyn std::error::Error>> {
        let size = std::fs::metadata(path).map_err(|e| format!("{}: {e}", path.display()))?.len();
        scene_file::check_size(size).map_err(|e| in_file(path, e))?;
        let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
        Ok(SceneFile::parse(&text).map_err(|e| in_file(path, e))?)
    }

    fn render(args: RenderArgs) -> Result<(), Box<dyn std::error::Error>> {
        check_u32("frames", args.frames, 1, 100_000)?;
        let mut offscreen = scene_renderer(&args.scene, args.size)?;
        let settings = *offscreen.renderer.settings();
        let (width, height) = args.size;
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

    fn export(args: ExportArgs) -> Result<(), Box<dyn std::error::Error>> {
        let format = match &args.format {
            Some(word) => MeshFormat::parse(word)?,
            None => MeshFormat::from_file_name(&args.out.to_string_lossy()).unwrap_or(MeshFormat::Stl),
        };
        let scale = args.scale.unwrap_or(format.default_scale());
        check_f32("scale", scale, 1e-6, 1e6)?;
        if let Some(n) = args.simplify {
            check_u32("triangle target", n, 4, u32::MAX)?;
        }
        // A figure's size: with lod=on the levels follow the camera at this size.
        let mut offscreen = scene_renderer(&args.scene, (960, 640))?;
        let started = Instant::now();
        let mesh = pollster::block_on(offscreen.renderer.extract_mesh());
        let mesh_ms = started.elapsed().as_secs_f64() * 1e3;
        let extracted = mesh.triangles.len();
        let started = Instant::now();
        let mesh = match args.simplify {
            Some(n) => export::simplified(&mesh, n as usize),
            None => mesh,
        };
        let simplify_ms = started.elapsed().as_secs_f64() * 1e3;
        let started = Instant::now();
        let bytes = export::encode(&mesh, format, scale);
        std::fs::write(&args.out, &bytes).map_err(|e| format!("{}: {e}", args.out.display()))?;
        let write_ms = started.elapsed().as_secs_f64() * 1e3;
        let open = mesh.topology().open_or_nonmanifold_edges;
        println!(
            "wrote {} ({}, {} bytes): {} triangles{}, {} vertices, {}, volume {:.4} (box units³); \
             mesh {mesh_ms:.1} ms{}, encode and write {write_ms:.1} ms on {}",
            args.out.display(),
            format.extension(),
            bytes.len(),
            mesh.triangles.len(),
            if args.simplify.is_some() { format!(" (from {extracted})") } else { String::new() },
            mesh.positions.len(),
            if open == 0 {
                "closed".to_string()
            } else {
                format!("{open} open edges (the surface meets the box)")
            },
            export::enclosed_volume(&mesh),
            if args.simplify.is_some() { format!(", simplify {simplify_ms:.1} ms") } else { String::new() },
            offscreen.adapter.get_info().name,
        );
        Ok(())
    }

    fn bench(args: BenchArgs) -> Result<(), Box<dyn std::error::Error>> {
        check_u32("frames", args.frames, 1, 100_000)?;
        for &n in args.resolutions.iter().flatten() {
            metaballs::scene::params::check_resolution(n)?;
        }
        for &n in &args.spheres {
            metaballs::scene::params::check_sphere_count(n)?;
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
                    Ok(metaballs::Settings::default().with_parameter("mesh-on", m)?.view.mesh_on)
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
            Command::Export(args) => export(args),
            Command::Record(args) => record::record(args),
            Command::Manifest(args) => manifest(args),
            Command::Critical(args) => critical(args),
        };
        match result {
            Ok(()) => ExitCode::SUCCESS,
            Err(error) => {
                eprintln!("error: {error}");
                // Bad input is a usage error (2); anything else (no GPU, I/O) is 1.
                if error.downcast_ref::<ParamError>().is_some()
                    || error.downcast_ref::<SceneError>().is_some()
                {
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
