//! The benchmark: an animated scene rendered offscreen for a table of resolutions and sphere counts,
//! with GPU time per stage where the adapter has timestamp queries, and the CPU oracle on the same
//! scenes for comparison.

use crate::device::timing::{STAGES, StageTimes};
use crate::extract::reference::{self, Grid};
use crate::offscreen::Offscreen;
use crate::scene::params::MAX_UNIFORM_RESOLUTION;
use crate::scene::params::ViewOptions;
use crate::scene::params::view::MeshOn;
use crate::{ParamError, Settings};
use serde::Serialize;
use std::time::Instant;

/// One row of the table.
#[derive(Clone, Debug, Serialize)]
pub struct Record {
    /// The teaching view measured (`display=wireframe&grid=cells`), empty for the plain surface.
    pub view: String,
    /// The mesher that made the mesh: `gpu` or `cpu`.
    pub mesher: String,
    pub resolution: u32,
    pub spheres: u32,
    /// Median wall time of a whole frame, submission to GPU idle, in milliseconds.
    pub frame_ms: f64,
    /// Median CPU time of a frame: level selection, encoding and submission, in milliseconds.
    pub cpu_ms: f64,
    /// Median GPU time per stage (`STAGES` order), when the adapter has timestamp queries.
    pub stage_ms: Option<[f64; 5]>,
    /// Median time of mesh generation: GPU time of every stage but shading where the adapter has
    /// timestamp queries, else wall time of the mesh alone (for the CPU mesher, meshing and upload)
    /// up to GPU idle.
    pub mesh_ms: f64,
    pub triangles: u32,
    pub vertices: u32,
    /// Cells that emitted triangles, as a fraction of the grid.
    pub active_cell_fraction: f64,
    /// Blocks the empty-space test kept, as a fraction of the grid's blocks.
    pub active_block_fraction: f64,
    /// GPU memory held by the mesh buffers.
    pub mesh_bytes: u64,
    /// Cells meshed: every cell of the blocks the bounds kept, and with level of detail their
    /// transition cells.
    pub cells_processed: u64,
    /// With level of detail, the selected blocks per level, finest first.
    pub lod_blocks: Option<Vec<u32>>,
    /// Wall time of the CPU oracle on the same scene, in milliseconds.
    pub oracle_ms: Option<f64>,
}

/// What to run.
pub struct Plan {
    /// `None`: 32, 64, 128, 256, and 512 where the device holds it (not on software adapters, where it
    /// takes seconds per frame).
    pub resolutions: Option<Vec<u32>>,
    pub sphere_counts: Vec<u32>,
    pub frames: u32,
    pub size: (u32, u32),
    pub oracle: bool,
    pub antialiasing: bool,
    /// Teaching views to measure, each as `name=value` pairs joined by `&` (as in a link); empty for
    /// the plain shaded surface alone.
    pub views: Vec<String>,
    /// Meshers to measure (`gpu`, `cpu`, `auto`).
    pub meshers: Vec<MeshOn>,
}

/// `base` with the view `spec` (`display=wireframe&grid=cells`) applied.
pub fn with_view(base: Settings, spec: &str) -> Result<Settings, ParamError> {
    let mut settings = base;
    for pair in spec.split('&').filter(|p| !p.is_empty()) {
        let (name, value) = pair.split_once('=').ok_or_else(|| ParamError::Invalid {
            name: "view",
            value: pair.to_string(),
            expected: "name=value pairs joined by &, such as display=wireframe&grid=cells".into(),
        })?;
        settings = settings.with_parameter(name, value)?;
    }
    Ok(settings)
}

fn median(values: &mut [f64]) -> f64 {
    values.sort_by(f64::total_cmp);
    values[values.len() / 2]
}

/// Runs the plan on one device, calling `report` after each row.
pub fn run(
    plan: &Plan,
    mut report: impl FnMut(&Record),
) -> Result<(String, bool, Vec<Record>), Box<dyn std::error::Error>> {
    let (width, height) = plan.size;
    let base = Settings { antialiasing: plan.antialiasing, ..Settings::default() };
    let mut offscreen = Offscreen::blocking(base, width, height)?;
    let timed = offscreen.renderer.enable_timing();
    let info = offscreen.adapter.get_info();
    let resolutions = plan.resolutions.clone().unwrap_or_else(|| {
        let mut list = vec![32, 64, 128, 256];
        if offscreen.renderer.max_resolution() >= 512 && info.device_type != wgpu::DeviceType::Cpu {
            list.push(512);
        }
        list
    });
    let adapter = info.name;
    let mut records = Vec::new();
    let plain = [String::new()];
    let views = if plan.views.is_empty() { &plain[..] } else { &plan.views[..] };
    for view in views {
        for &mesher in &plan.meshers {
            for &resolution in &resolutions {
                for &spheres in &plan.sphere_counts {
                    let mut settings =
                        with_view(Settings { resolution, sphere_count: spheres, ..base }, view)?;
                    settings.view.mesh_on = mesher;
                    // Level of detail is measured next to the uniform grid as fine, where it fits.
                    let mut runs = vec![(settings, view.clone())];
                    if settings.view.lod && resolution <= offscreen.renderer.max_resolution() {
                        let uniform =
                            Settings { view: ViewOptions { lod: false, ..settings.view }, ..settings };
                        runs.push((uniform, format!("{view} (uniform)")));
                    }
                    for (settings, name) in runs {
                        offscreen.renderer.set_settings(settings)?;
                        let mut record = measure(&mut offscreen, plan, timed)?;
                        record.view = name;
                        report(&record);
                        records.push(record);
                    }
                }
            }
        }
    }
    Ok((adapter, timed, records))
}

fn measure(offscreen: &mut Offscreen, plan: &Plan, timed: bool) -> Result<Record, ParamError> {
    let settings = *offscreen.renderer.settings();
    // Warm up: pipelines compile, and the buffers grow to the surface.
    for _ in 0..3 {
        offscreen.render();
        pollster::block_on(offscreen.renderer.flush_stats());
    }
    let mut frame_ms = Vec::new();
    let mut cpu_ms = Vec::new();
    let mut stages: Vec<StageTimes> = Vec::new();
    for _ in 0..plan.frames.max(1) {
        offscreen.renderer.update(1.0 / 60.0)?;
        let started = Instant::now();
        offscreen.render_for_timing();
        cpu_ms.push(started.elapsed().as_secs_f64() * 1e3);
        if timed {
            stages.extend(pollster::block_on(offscreen.renderer.read_timing()));
        } else {
            let _ = offscreen.device.poll(wgpu::PollType::wait_indefinitely());
        }
        frame_ms.push(started.elapsed().as_secs_f64() * 1e3);
    }
    pollster::block_on(offscreen.renderer.flush_stats());
    let stats = offscreen.renderer.stats().unwrap_or_default();
    let on_device = offscreen.renderer.mesh_capabilities().needs_compute;
    // Level of detail selects its blocks in the first stage, where a uniform grid has none, and has no
    // second (the selection keeps only blocks the surface may cross): a stage a frame does not run
    // keeps the time an earlier row wrote there, so it is left out.
    let runs = |i: usize| {
        let computed = i + 1 < STAGES.len();
        let missing = if settings.view.lod { i == 1 } else { i == 0 };
        // An extractor on the CPU runs no compute pass: only the shading stage is timed.
        !missing && (on_device || !computed)
    };
    let stage_ms = (!stages.is_empty()).then(|| {
        std::array::from_fn(|i| {
            if runs(i) { median(&mut stages.iter().map(|s| s.stages_ms[i]).collect::<Vec<_>>()) } else { 0.0 }
        })
    });
    let mesh_ms = if on_device && !stages.is_empty() {
        let meshing =
            |s: &StageTimes| (0..STAGES.len() - 1).filter(|&i| runs(i)).map(|i| s.stages_ms[i]).sum();
        median(&mut stages.iter().map(meshing).collect::<Vec<_>>())
    } else {
        let mut times: Vec<f64> = (0..plan.frames.max(1))
            .map(|_| {
                let started = Instant::now();
                offscreen.renderer.extract();
                let _ = offscreen.device.poll(wgpu::PollType::wait_indefinitely());
                started.elapsed().as_secs_f64() * 1e3
            })
            .collect();
        median(&mut times)
    };
    let lod = offscreen.renderer.lod_summary();
    // Every cell of the kept blocks (uniform blocks of 4³ cells, LOD blocks of 8³), and the transition
    // cells where the LOD mesher counts them.
    let cells_processed = match &lod {
        None => stats.active_blocks as u64 * 64,
        Some(l) => l.cells_processed.unwrap_or(stats.active_blocks as u64 * 512),
    };
    let oracle_ms = (plan.oracle && settings.resolution <= MAX_UNIFORM_RESOLUTION).then(|| {
        let started = Instant::now();
        let mesh = reference::extract(
            offscreen.renderer.scene().spheres(),
            settings.iso,
            Grid { cells_per_axis: settings.resolution },
        );
        std::hint::black_box(mesh.triangle_count());
        started.elapsed().as_secs_f64() * 1e3
    });
    Ok(Record {
        view: String::new(),
        mesher: offscreen.renderer.mesh_source().into(),
        resolution: settings.resolution,
        spheres: settings.sphere_count,
        frame_ms: median(&mut frame_ms),
        cpu_ms: median(&mut cpu_ms),
        stage_ms,
        mesh_ms,
        triangles: stats.triangles,
        vertices: stats.vertices,
        active_cell_fraction: stats.active_cells as f64 / stats.total_cells.max(1) as f64,
        active_block_fraction: stats.active_blocks as f64 / stats.total_blocks.max(1) as f64,
        mesh_bytes: stats.mesh_bytes,
        cells_processed,
        lod_blocks: lod.map(|l| l.blocks),
        oracle_ms,
    })
}

/// The table's heading.
pub fn header(timed: bool) -> String {
    let stages = if timed {
        STAGES.iter().map(|s| format!("{:>9}", truncate(s))).collect::<Vec<_>>().join(" ")
    } else {
        String::new()
    };
    format!(
        "{:<36} {:>7} {:>5} {:>7} {:>9} {:>7} {} {:>9} {:>10} {:>9} {:>11} {:>8} {:>9} {:>10}  {}",
        "view",
        "mesher",
        "cells",
        "spheres",
        "frame ms",
        "CPU ms",
        stages,
        "mesh ms",
        "triangles",
        "vertices",
        "cells done",
        "blocks %",
        "mesh MiB",
        "oracle ms",
        "LOD blocks per level"
    )
}

fn truncate(s: &str) -> &str {
    &s[..s.len().min(9)]
}

/// One row of the table.
pub fn row(r: &Record) -> String {
    let stages = r.stage_ms.map(|s| s.iter().map(|v| format!("{v:>9.2}")).collect::<Vec<_>>().join(" "));
    format!(
        "{:<36} {:>7} {:>5} {:>7} {:>9.2} {:>7.3} {} {:>9.2} {:>10} {:>9} {:>11} {:>8.2} {:>9.1} {:>10}  {}",
        if r.view.is_empty() { "shaded" } else { &r.view },
        r.mesher,
        r.resolution,
        r.spheres,
        r.frame_ms,
        r.cpu_ms,
        stages.unwrap_or_default(),
        r.mesh_ms,
        r.triangles,
        r.vertices,
        r.cells_processed,
        100.0 * r.active_block_fraction,
        r.mesh_bytes as f64 / 1048576.0,
        r.oracle_ms.map(|v| format!("{v:.1}")).unwrap_or_else(|| "-".into()),
        r.lod_blocks.as_ref().map(|b| format!("{b:?}")).unwrap_or_default(),
    )
}
