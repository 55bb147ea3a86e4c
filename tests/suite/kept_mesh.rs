//! A CPU mesher's mesh is kept for the job that made it: a frame of the same job (the camera turned, a
//! view changed, a still figure drawn again) draws it without meshing, and any change to the job (a
//! sphere moved, the iso level, the grid, the construction) meshes anew. Part way through the march a
//! frame always meshes; the benchmarks' `forget_mesh` makes the next frame mesh whatever it kept; a
//! mesh made elsewhere for the frame's job is taken in place of meshing.

use crate::common;

use common::scenes::random_scenes;
use metaballs::Sphere;
use metaballs::extract::Extractor;
use metaballs::extract::cpu::elsewhere::Meshers;
use metaballs::extract::cpu::{CpuMeshExtractor, CpuMesher, CpuMeshing, elsewhere::pack};
use metaballs::extract::extractor::{GivenMesh, Job};
use metaballs::extract::mesh::IndexedMesh;
use metaballs::extract::reference::{Construction, Grid};
use metaballs::scene::params::view::Method;
use std::sync::atomic::{AtomicUsize, Ordering};

/// How many meshes the counting mesher has made, over every test of this module's one thread of it.
static MESHED: AtomicUsize = AtomicUsize::new(0);

/// The CPU's marching cubes, counting the meshes it makes.
#[derive(Default)]
struct Counting(CpuMesher);

impl CpuMeshing for Counting {
    const NAME: &'static str = "counting";
    const METHOD: Method = Method::MarchingCubes;
    fn mesh_job(&mut self, job: &Job) {
        MESHED.fetch_add(1, Ordering::SeqCst);
        CpuMeshing::mesh_job(&mut self.0, job);
    }
    fn vertices(&self) -> &[f32] {
        self.0.vertices()
    }
    fn indices(&self) -> &[u32] {
        self.0.indices()
    }
    fn blocks_and_cells(&self) -> (u32, u32) {
        self.0.blocks_and_cells()
    }
    fn to_indexed(&self) -> IndexedMesh {
        CpuMeshing::to_indexed(&self.0)
    }
    fn install(&mut self, mesh: GivenMesh) {
        CpuMeshing::install(&mut self.0, mesh);
    }
}

/// Prepares `job` and says whether the mesher meshed for it.
fn meshed(extractor: &mut CpuMeshExtractor<Counting>, job: &Job) -> bool {
    let before = MESHED.load(Ordering::SeqCst);
    extractor.prepare(job);
    MESHED.load(Ordering::SeqCst) > before
}

#[test]
fn a_frame_of_the_same_job_draws_the_kept_mesh_and_any_change_meshes_anew() {
    let scene = random_scenes(1).remove(0);
    let job = scene.job();
    let mut extractor = CpuMeshExtractor::<Counting>::default();
    assert!(meshed(&mut extractor, &job), "the first frame meshes");
    assert!(!meshed(&mut extractor, &job), "a frame of the same job meshed again");
    assert!(!meshed(&mut extractor, &job), "a third frame of the same job meshed again");

    let mut moved = scene.spheres.clone();
    moved[0] = Sphere { center: moved[0].center + glam::Vec3::splat(1e-3), ..moved[0] };
    let changes = [
        Job { spheres: &moved, ..job },
        Job { iso: job.iso * 1.01, ..job },
        Job { grid: Grid { cells_per_axis: scene.resolution + 1 }, ..job },
        Job { construction: Construction { march: Some([1, 1, 1]), ..job.construction }, ..job },
    ];
    for changed in &changes {
        assert!(meshed(&mut extractor, changed), "a changed job drew the kept mesh");
        assert!(meshed(&mut extractor, &job), "back to the first job drew the changed job's mesh");
    }
    // Part way through the march, every frame meshes: its mesh is not the whole job's.
    assert!(meshed(&mut extractor, &changes[3]));
    assert!(meshed(&mut extractor, &changes[3]), "a frame part way through the march drew a kept mesh");

    assert!(meshed(&mut extractor, &job));
    extractor.forget_mesh();
    assert!(meshed(&mut extractor, &job), "forget_mesh kept the mesh");

    // A mesh made elsewhere for the job is taken without meshing, and kept.
    let packed = pack(Method::MarchingCubes, &job);
    let given = Meshers::default().mesh(&packed).unwrap();
    extractor.forget_mesh();
    extractor.give_mesh(given);
    assert!(!meshed(&mut extractor, &job), "a mesh made elsewhere for the job was meshed again");
    assert!(!meshed(&mut extractor, &job));
}

/// The picture of a still CPU-meshed scene at `yaw`, drawn by a renderer of its own.
fn fresh_picture(settings: metaballs::Settings, yaw: f32) -> Vec<u8> {
    let mut settings = settings;
    settings.camera.yaw_degrees = yaw;
    common::with_renderer(settings, 160, 120, |o| o.render_rgba())
}

#[test]
fn a_kept_mesh_turned_or_drawn_after_another_extractor_is_the_picture_of_a_fresh_renderer() {
    use metaballs::scene::params::view::MeshOn;
    let mut settings = common::settings(3, 6, 40, 1.0);
    settings.antialiasing = false;
    settings.view.mesh_on = MeshOn::Cpu;
    let (turned, after_gpu) = common::with_renderer(settings, 160, 120, |o| {
        o.render_rgba();
        // The camera turned: the same job, its vertices already in the buffers.
        let mut next = settings;
        next.camera.yaw_degrees = 75.0;
        o.renderer.set_settings(next).unwrap();
        let turned = o.render_rgba();
        // The GPU's mesh in the same buffers, then the CPU's kept mesh again.
        next.view.mesh_on = MeshOn::Gpu;
        o.renderer.set_settings(next).unwrap();
        o.render_rgba();
        assert_eq!(o.renderer.mesh_source(), "gpu");
        next.view.mesh_on = MeshOn::Cpu;
        next.camera.yaw_degrees = 120.0;
        o.renderer.set_settings(next).unwrap();
        let after_gpu = o.render_rgba();
        assert_eq!(o.renderer.mesh_source(), "cpu");
        (turned, after_gpu)
    });
    assert!(turned == fresh_picture(settings, 75.0), "the turned kept mesh differs from a fresh renderer's");
    assert!(
        after_gpu == fresh_picture(settings, 120.0),
        "the kept mesh after the GPU's differs from a fresh renderer's"
    );
}
