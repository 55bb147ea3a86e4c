//! The binding numbers of bind group 0, the one group every pass's shaders use. Each number means one
//! resource in every shader: the scene's uniforms first, then the mesh buffers the extraction passes
//! fill and the later passes read, then each pass's own. A constant is named as its WGSL variable, in
//! upper case; `tests/suite/bindings.rs` holds the shaders to these numbers.

macro_rules! bindings {
    ($($(#[$doc:meta])* $name:ident = $number:literal,)*) => {
        $($(#[$doc])* pub const $name: u32 = $number;)*

        /// Every binding above: its constant's name and its number.
        pub const ALL: &[(&str, u32)] = &[$((stringify!($name), $name)),*];
    };
}

bindings! {
    /// The grid's uniforms: resolution, box, iso, capacities (`shaders/common.wgsl`).
    GRID = 0,
    /// The spheres, centre and radius each (`shaders/common.wgsl`).
    SPHERES = 1,

    /// The mesh's counters: active blocks, vertices, indices, active cells, then the measures.
    COUNTERS = 2,
    /// Slot → block index, for the active blocks.
    ACTIVE_BLOCKS = 3,
    /// Block index → slot, or none for a skipped block.
    BLOCK_SLOTS = 4,
    /// The per-block passes' indirect dispatch.
    BLOCK_DISPATCH = 5,
    /// The field at each active block's 5³ points.
    BLOCK_VALUES = 6,
    /// Each active block's cells' cases.
    CELL_CASES = 7,
    /// The cells the surface crosses.
    ACTIVE_CELLS = 8,
    /// The per-cell passes' indirect dispatch.
    CELL_DISPATCH = 9,
    /// The vertex on each edge an active cell owns.
    EDGE_VERTICES = 10,
    /// The mesh's vertices: position, then normal.
    VERTICES = 11,
    /// The mesh's triangles, as indices into the vertices.
    INDICES = 12,
    /// The indexed indirect draw of the mesh.
    DRAW_ARGS = 13,
    /// With level of detail: each triangle's level, then the kept blocks as the views draw them.
    LOD_DATA = 14,

    /// Level selection's uniforms: the rule and the camera (`shaders/extract/lod_select.wgsl`).
    WALK = 15,
    /// Its two queues of candidate blocks.
    QUEUES = 16,
    /// Its state between dispatches and frames.
    STATE = 18,
    /// Its indirect dispatch of each level.
    WALK_DISPATCH = 19,

    /// The marching-cubes triangles of every case and choice on its ambiguous faces
    /// (`shaders/extract/marching_cubes.wgsl`).
    TRIANGLE_TABLE = 17,
    /// Marching tetrahedra's splits and cases (`shaders/extract/marching_tetrahedra.wgsl`).
    TETRA_TABLE = 21,
    /// The dual methods' crossings on the edges each active cell owns (`shaders/extract/dual.wgsl`).
    EDGE_CROSSINGS = 24,

    /// Level of detail's uniforms (`shaders/extract/lod.wgsl`).
    LOD = 20,
    /// The listed cells of the kept blocks.
    CELLS = 22,
    /// The hash table of the vertices made on edges.
    HASH = 23,
    /// The regular and transition cells' tables, in one buffer.
    LOD_TABLES = 25,
    /// The level-of-detail passes' indirect dispatches.
    LOD_DISPATCH = 26,

    /// The shading uniforms: camera, lights, what the views show (`shaders/draw/shade.wgsl`).
    SHADING = 30,
    /// The field slice's samples (`shaders/draw/overlays.wgsl`).
    SLICE_VALUES = 31,
    /// The field slice's iso contour.
    SEGMENTS = 32,
    /// The class of each marching-cubes case (`shaders/draw/views/common.wgsl`).
    CASE_CLASSES = 33,
    /// The overlay pass's counts and the views' indirect draws.
    OVERLAYS = 34,
    /// The marching-squares table.
    SQUARE_SEGMENTS = 35,
    /// What the measures pass is told of the mesh (`shaders/draw/measure.wgsl`).
    MEASURE_JOB = 36,
    /// The measures pass's indirect dispatch.
    MEASURE_DISPATCH = 37,
    /// The pixels whose exact rays are cast (`shaders/draw/views/exact.wgsl`).
    PROBE_PIXELS = 38,
    /// Where those rays hit.
    PROBE_HITS = 39,
}
