//! Meshing a frame somewhere else than where it is drawn (the page's mesher worker): the frame's job
//! packed as numbers, meshed from them by the same CPU meshers, and the mesh handed back to the
//! extractor that draws it, which takes it in place of meshing when the job is still the frame's.

use super::{CpuMesher, CpuMeshing};
#[cfg(any(not(target_arch = "wasm32"), not(feature = "webgpu")))]
use super::{DualContouringMesher, SurfaceNetsMesher, TetraMesher};
use crate::extract::extractor::{GivenMesh, Job};
use crate::extract::kernel::Terms;
use crate::extract::reference::{Construction, Grid};
use crate::scene::Sphere;
use crate::scene::decimal::num;
use crate::scene::params::view::{Blend, CaseTable, Interpolation, Kernel, Method, Split};
use glam::Vec3;

/// Numbers before the spheres: method, iso level, cells per axis, interpolation, blend, case table,
/// kernel, blobbiness, split.
const HEAD: usize = 9;
/// Numbers per sphere: centre, radius, charge.
const PER_SPHERE: usize = 5;
/// The finest grid a job may ask for (the largest a device holds without level of detail is smaller).
const MAX_CELLS: f32 = 1024.0;

/// `job` meshed by a mesher of `method`, as numbers: method, iso, cells per axis, interpolation,
/// blend, case table, kernel, blobbiness, split, then centre, radius and charge of each sphere.
pub fn pack(method: Method, job: &Job) -> Vec<f32> {
    let construction = job.construction;
    let mut packed = Vec::with_capacity(HEAD + PER_SPHERE * job.spheres.len());
    packed.extend([
        method.index() as f32,
        job.iso,
        job.grid.cells_per_axis as f32,
        construction.interpolation.index() as f32,
        construction.terms.blend.index() as f32,
        construction.case_table.index() as f32,
        construction.terms.kernel.index() as f32,
        construction.terms.blobbiness,
        // Only marching tetrahedra is cut: another method's job is the same under either split.
        if method == Method::MarchingTetrahedra { construction.split.index() as f32 } else { 0.0 },
    ]);
    for s in job.spheres {
        packed.extend([s.center.x, s.center.y, s.center.z, s.radius, s.charge]);
    }
    packed
}

/// The CPU meshers of one thread, kept between jobs so that their buffers are reused.
#[derive(Default)]
pub struct Meshers {
    marching_cubes: CpuMesher,
    #[cfg(any(not(target_arch = "wasm32"), not(feature = "webgpu")))]
    others: Others,
    /// The last job was marching cubes.
    marched: bool,
}

impl Meshers {
    /// Meshes a packed job; says what is wrong with one that is not a job.
    pub fn mesh(&mut self, packed: &[f32]) -> Result<GivenMesh, String> {
        let (method, spheres, iso, grid, construction) = unpack(packed)?;
        let job = Job { spheres: &spheres, iso, grid, construction, lod: None, teaching: false };
        self.marched = method == Method::MarchingCubes;
        let mesher: &mut dyn CpuMeshed = match method {
            Method::MarchingCubes => &mut self.marching_cubes,
            #[cfg(any(not(target_arch = "wasm32"), not(feature = "webgpu")))]
            Method::SurfaceNets => &mut self.others.surface_nets,
            #[cfg(any(not(target_arch = "wasm32"), not(feature = "webgpu")))]
            Method::DualContouring => &mut self.others.dual_contouring,
            #[cfg(any(not(target_arch = "wasm32"), not(feature = "webgpu")))]
            Method::MarchingTetrahedra => &mut self.others.tetrahedra,
            // The WebGPU page meshes every method but marching cubes in compute shaders alone.
            #[cfg(all(target_arch = "wasm32", feature = "webgpu"))]
            _ => return Err(format!("{} meshes on the GPU in this build", method.word())),
        };
        mesher.mesh_it(&job);
        Ok(mesher.given(packed.to_vec()))
    }

    /// Meshes the layers of cells `from..to` of a packed marching-cubes job (a slab of it, one of
    /// `slab_ranges`'): its vertices, triangles and active blocks and cells as `mesh` gives them, and the
    /// grid edge each vertex lies on (point index times three plus the axis), to join the slabs by.
    pub fn mesh_slab(&mut self, packed: &[f32], from: u32, to: u32) -> Result<SlabMesh<'_>, String> {
        let (method, spheres, iso, grid, construction) = unpack(packed)?;
        let n = grid.cells_per_axis;
        if method != Method::MarchingCubes {
            return Err(format!("only marching cubes meshes in slabs, not {}", method.word()));
        }
        if !(from < to && to <= n) {
            return Err(format!("a slab of layers {from} to {to} is not within a grid of {n} cells"));
        }
        self.marched = true;
        let mesher = &mut self.marching_cubes;
        mesher.mesh_layers(&spheres, iso, grid, construction, from..to);
        let stats = mesher.stats();
        Ok(SlabMesh {
            vertices: &mesher.vertices,
            indices: &mesher.indices,
            keys: mesher.vertex_keys(),
            counts: [stats.active_blocks, stats.active_cells],
        })
    }

    /// The cells of the last job's mesh whose triangles the asymptotic decider or MC33 changes, with
    /// their kind (`CpuMesher::decided_cells`), whatever its table; none after a job of another method.
    pub fn decided_cells(&self) -> &[[u32; 4]] {
        if self.marched { self.marching_cubes.decided_cells() } else { &[] }
    }
}

/// The meshers of the methods other than marching cubes, which the WebGPU page's WebAssembly leaves
/// out (it meshes them in compute shaders).
#[cfg(any(not(target_arch = "wasm32"), not(feature = "webgpu")))]
#[derive(Default)]
struct Others {
    surface_nets: SurfaceNetsMesher,
    dual_contouring: DualContouringMesher,
    tetrahedra: TetraMesher,
}

/// A slab's mesh (`Meshers::mesh_slab`), borrowed from the mesher that made it.
pub struct SlabMesh<'a> {
    pub vertices: &'a [f32],
    pub indices: &'a [u32],
    /// The grid edge of each vertex.
    pub keys: &'a [u32],
    /// Active blocks and cells.
    pub counts: [u32; 2],
}

/// A CPU mesher as the job runner sees it.
trait CpuMeshed {
    fn mesh_it(&mut self, job: &Job);
    fn given(&self, job: Vec<f32>) -> GivenMesh;
}

impl<M: CpuMeshing> CpuMeshed for M {
    fn mesh_it(&mut self, job: &Job) {
        self.mesh_job(job);
    }

    fn given(&self, job: Vec<f32>) -> GivenMesh {
        let (blocks, cells) = self.blocks_and_cells();
        GivenMesh {
            job,
            vertices: self.vertices().to_vec(),
            indices: self.indices().to_vec(),
            counts: [blocks, cells],
        }
    }
}

type Unpacked = (Method, Vec<Sphere>, f32, Grid, Construction);

fn unpack(packed: &[f32]) -> Result<Unpacked, String> {
    let word = |at: usize, words: &[&str]| -> Result<usize, String> {
        let value = packed[at];
        (value >= 0.0 && (value as usize) < words.len() && value.fract() == 0.0)
            .then_some(value as usize)
            .ok_or_else(|| {
                format!("a packed mesh job has {} where a choice of {} belongs", num(value), words.join(", "))
            })
    };
    if packed.len() < HEAD || !(packed.len() - HEAD).is_multiple_of(PER_SPHERE) {
        return Err(format!("a packed mesh job has {} numbers: 9 and then 5 per sphere", packed.len()));
    }
    let method = Method::ALL[word(0, Method::WORDS)?];
    let interpolation = Interpolation::ALL[word(3, Interpolation::WORDS)?];
    let blend = Blend::ALL[word(4, Blend::WORDS)?];
    let case_table = CaseTable::ALL[word(5, CaseTable::WORDS)?];
    let terms = Terms { blend, kernel: Kernel::ALL[word(6, Kernel::WORDS)?], blobbiness: packed[7] };
    // A term must fall with distance for the bounds to hold: Blinn's B is positive.
    if !(terms.blobbiness > 0.0 && terms.blobbiness.is_finite()) {
        return Err(format!(
            "a packed mesh job has blobbiness {}, not a positive number",
            num(terms.blobbiness)
        ));
    }
    let split = Split::ALL[word(8, Split::WORDS)?];
    let cells = packed[2];
    if !((1.0..=MAX_CELLS).contains(&cells) && cells.fract() == 0.0) {
        return Err(format!("a packed mesh job has {} cells per axis", num(cells)));
    }
    let spheres = packed[HEAD..]
        .chunks_exact(PER_SPHERE)
        .map(|s| Sphere {
            center: Vec3::new(s[0], s[1], s[2]),
            radius: s[3],
            velocity: Vec3::ZERO,
            charge: s[4],
        })
        .collect();
    let grid = Grid { cells_per_axis: cells as u32 };
    Ok((
        method,
        spheres,
        packed[1],
        grid,
        Construction { interpolation, terms, case_table, march: None, split },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::Scene;

    #[test]
    fn a_job_meshed_from_its_numbers_is_the_mesh_of_the_job() {
        let scene = Scene::new(7, 5).unwrap();
        let construction = Construction {
            interpolation: Interpolation::Linear,
            terms: Terms { kernel: Kernel::Wyvill, ..Terms::default() },
            case_table: CaseTable::Decider,
            march: None,
            split: Split::Five,
        };
        let job = Job {
            spheres: scene.spheres(),
            iso: 0.9,
            grid: Grid { cells_per_axis: 24 },
            construction,
            lod: None,
            teaching: false,
        };
        for &method in Method::ALL {
            let packed = pack(method, &job);
            let given = Meshers::default().mesh(&packed).unwrap();
            let mut direct: Box<dyn CpuMeshed> = match method {
                Method::MarchingCubes => Box::<CpuMesher>::default(),
                Method::SurfaceNets => Box::<SurfaceNetsMesher>::default(),
                Method::DualContouring => Box::<DualContouringMesher>::default(),
                Method::MarchingTetrahedra => Box::<TetraMesher>::default(),
            };
            direct.mesh_it(&job);
            assert_eq!(given, direct.given(packed.clone()), "{method:?}");
            assert!(!given.indices.is_empty());
        }
    }

    #[test]
    fn numbers_that_are_not_a_job_are_refused_with_what_is_wrong() {
        let mut meshers = Meshers::default();
        assert!(meshers.mesh(&[0.0, 1.0]).unwrap_err().contains("2 numbers"));
        let refused = |packed: [f32; 9]| Meshers::default().mesh(&packed).unwrap_err();
        assert!(refused([7.0, 1.0, 8.0, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0]).contains("marching_cubes"));
        assert!(refused([0.0, 1.0, 8.0, 0.0, 0.0, 3.0, 0.0, 2.0, 0.0]).contains("classic, decider, mc33"));
        assert!(refused([0.0, 1.0, 0.5, 0.0, 0.0, 0.0, 0.0, 2.0, 0.0]).contains("cells per axis"));
        assert!(
            refused([0.0, 1.0, 8.0, 0.0, 0.0, 0.0, 3.0, 2.0, 0.0]).contains("inverse_square, blinn, wyvill")
        );
        assert!(refused([0.0, 1.0, 8.0, 0.0, 0.0, 0.0, 0.0, 2.0, 2.0]).contains("six, five"));
        for blobbiness in [0.0, -1.0, f32::NAN, f32::INFINITY] {
            assert!(
                refused([0.0, 1.0, 8.0, 0.0, 0.0, 0.0, 1.0, blobbiness, 0.0]).contains("blobbiness"),
                "{blobbiness}"
            );
        }
    }
}
