// Shared by the level-of-detail passes (shaders/extract/lod_select.wgsl, shaders/extract/lod.wgsl):
// the counters as they use them (`CounterBlock` in src/extract/uniforms.rs) and their indirect
// dispatches.

// The counters; from word 64 (byte 256, LEVEL_COUNTS_OFFSET) the triangles of each level, then the
// leaves of each level.
struct LodCounters {
    active_blocks: atomic<u32>,
    vertices: atomic<u32>,
    indices: atomic<u32>,
    active_cells: atomic<u32>,
    // The selection ran out of room: this frame meshes nothing and keeps the mesh it had.
    lod_overflowed: u32,
    // Levels at or below it were held back from splitting.
    lod_floor: u32,
    _pad: array<u32, 58>,
    level_triangles: array<atomic<u32>, 12>,
    level_blocks: array<atomic<u32>, 12>,
}

@group(0) @binding(2) var<storage, read_write> counters: LodCounters;

struct DispatchIndirect {
    x: u32,
    y: u32,
    z: u32,
}

// Workgroups for `count`, in rows of at most DISPATCH_ROW (`slot_of` reads them back).
fn rows(count: u32) -> DispatchIndirect {
    return DispatchIndirect(min(count, DISPATCH_ROW), (count + DISPATCH_ROW - 1u) / DISPATCH_ROW, 1u);
}
