// The dual methods over the active cells, one invocation per cell, after cells.wgsl: surface nets and
// dual contouring, as core/src/extract/cpu/dual.rs, hermite.rs and qef.rs make them on the CPU.
//
// `make_dual_crossings`: each crossed cell finds the crossings on the three edges leaving its lowest
// corner (marching cubes' vertex with surface nets; the Hermite data with dual contouring) into
// edge_crossings, so each crossing is found once. `make_dual_vertices`: each crossed cell makes its one
// vertex from the crossings on its twelve edges, at their mean (surface nets) or at the minimiser of
// their quadratic error function within SLACK of the cell (dual contouring, flag FLAG_QEF); its slots in
// edge_vertices hold the vertex's index (slot 0) and, with dual contouring, its QEF's rank plus STRAYED
// where the minimiser left the cell (slot 1). `make_dual_quads`: each crossed edge leaving a cell's
// lowest corner joins the four cells around it with a quad, split along its shorter diagonal; with dual
// contouring each triangle's corners' marks go to lod_data (what color-by=rank reads), and the
// crossings are copied after the mesh's vertices, for display=normals.

// In grid.flags: dual contouring (else surface nets).
const FLAG_QEF: u32 = 128u;
// How far, in cells, a vertex may lie outside its cell (SLACK in dual.rs).
const SLACK: f32 = 0.25;
// A vertex whose minimiser left its cell (STRAYED in dual.rs).
const STRAYED: u32 = 4u;
// Singular values under this fraction of the largest are truncated (TRUNCATION in qef.rs).
const TRUNCATION: f32 = 0.1;
// The pull towards the mass point in the box-constrained minimisation (MASS_BIAS in qef.rs).
const MASS_BIAS: f32 = 1e-3;
// Regula falsi steps onto the field and the bracket that ends them (hermite.rs).
const CROSSING_STEPS: u32 = 12u;
const CROSSING_TOLERANCE: f32 = 1e-5;
// Jacobi sweeps at most (qef.rs).
const JACOBI_SWEEPS: u32 = 8u;
// Larger than any energy a box's point has.
const NO_ENERGY: f32 = 3.0e38;

@group(0) @binding(14) var<storage, read_write> lod_data: array<u32>;
// Slot s, cell c, axis k: the crossing on the edge leaving the cell's lowest corner along k, at
// ((s * 64 + c) * 3 + k) * 3: its parameter along the edge, then its normal in octahedral coordinates.
@group(0) @binding(24) var<storage, read_write> edge_crossings: array<f32>;

fn qef_on() -> bool {
    return (grid.flags & FLAG_QEF) != 0u;
}

// The crossing on the edge from grid point `a` to `b`: with surface nets, marching cubes' vertex; with
// dual contouring, where the field itself crosses iso (Illinois regula falsi from the samples'
// interpolation) and its outward normal there, the Hermite data (`hermite` in hermite.rs).
struct Crossing {
    // Its parameter along the edge, from a (0) to b (1).
    along: f32,
    normal: vec3<f32>,
}

fn crossing(a: vec3<u32>, b: vec3<u32>, fa: f32, fb: f32) -> Crossing {
    if (!qef_on() || (grid.flags & FLAG_MIDPOINT) != 0u || is_boundary(a) || is_boundary(b)) {
        return Crossing(edge_parameter(fa, fb), edge_vertex(a, b, fa, fb).normal);
    }
    let pa = grid_point(a);
    let pb = grid_point(b);
    var t0 = 0.0;
    var g0 = fa - grid.iso;
    var t1 = 1.0;
    var g1 = fb - grid.iso;
    var t = edge_parameter(fa, fb);
    var last = 0;
    for (var step = 0u; step < CROSSING_STEPS; step++) {
        if (step > 0u) {
            t = (t0 * g1 - t1 * g0) / (g1 - g0);
            if (!(t > t0 && t < t1)) {
                t = 0.5 * (t0 + t1);
            }
        }
        let g = field_at(pa + (pb - pa) * t) - grid.iso;
        if (g == 0.0 || t1 - t0 < CROSSING_TOLERANCE) {
            break;
        }
        if ((g > 0.0) == (g0 > 0.0)) {
            t0 = t;
            g0 = g;
            if (last == -1) {
                g1 *= 0.5;
            }
            last = -1;
        } else {
            t1 = t;
            g1 = g;
            if (last == 1) {
                g0 *= 0.5;
            }
            last = 1;
        }
    }
    let along = clamp(t, EDGE_MARGIN, 1.0 - EDGE_MARGIN);
    let g = outward_gradient(pa + (pb - pa) * along);
    let len2 = dot(g, g);
    var n = normalize(select(pa - pb, pb - pa, fa > grid.iso));
    if (len2 > 0.0) {
        n = g * inverseSqrt(len2);
    }
    return Crossing(along, n);
}

// The eigenvalues (in the diagonal) and unit eigenvectors (columns of `v`) of a symmetric matrix, by
// cyclic Jacobi rotations (`symmetric_eigen` in qef.rs).
struct Eigen {
    a: mat3x3<f32>,
    v: mat3x3<f32>,
}

fn symmetric_eigen(matrix: mat3x3<f32>) -> Eigen {
    var a = matrix;
    var v = mat3x3<f32>(vec3<f32>(1.0, 0.0, 0.0), vec3<f32>(0.0, 1.0, 0.0), vec3<f32>(0.0, 0.0, 1.0));
    for (var sweep = 0u; sweep < JACOBI_SWEEPS; sweep++) {
        var rotated = false;
        // The planes (0, 1), (0, 2), (1, 2).
        for (var k = 0u; k < 3u; k++) {
            let p = k / 2u;
            let q = 1u + k - p;
            let off = a[q][p];
            if (abs(off) <= 1.1920929e-10 * (abs(a[p][p]) + abs(a[q][q]))) {
                continue;
            }
            rotated = true;
            let theta = (a[q][q] - a[p][p]) / (2.0 * off);
            let t = select(-1.0, 1.0, theta >= 0.0) / (abs(theta) + sqrt(theta * theta + 1.0));
            let c = inverseSqrt(t * t + 1.0);
            let s = t * c;
            for (var i = 0u; i < 3u; i++) {
                let x = a[i][p];
                let y = a[i][q];
                a[i][p] = c * x - s * y;
                a[i][q] = s * x + c * y;
            }
            let cp = a[p];
            let cq = a[q];
            a[p] = c * cp - s * cq;
            a[q] = s * cp + c * cq;
            let vp = v[p];
            let vq = v[q];
            v[p] = c * vp - s * vq;
            v[q] = s * vp + c * vq;
        }
        if (!rotated) {
            break;
        }
    }
    return Eigen(a, v);
}

fn outside_box(point: vec3<f32>, low: vec3<f32>, high: vec3<f32>) -> bool {
    let margin = 1e-4 * max(max(high.x - low.x, high.y - low.y), high.z - low.z);
    return any(point < low - margin) || any(point > high + margin);
}

// A cell's vertex by dual contouring and its mark (`Qef::solve_in` in qef.rs): the minimiser of
// E(x) = Σ (nᵢ · (x − pᵢ))² nearest the mass point with small singular values truncated, where it lies
// within `slack` of the cell from `low` to `high`; else the minimiser over that box of E plus a slight
// pull towards the mass point, the least-energy stationary point of the box's 27 faces that lies in it.
struct Solved {
    point: vec3<f32>,
    mark: u32,
}

fn solve_qef(ata: mat3x3<f32>, atb: vec3<f32>, mass: vec3<f32>, low: vec3<f32>, high: vec3<f32>, slack: f32) -> Solved {
    let eigen = symmetric_eigen(ata);
    let values = vec3<f32>(eigen.a[0][0], eigen.a[1][1], eigen.a[2][2]);
    let floor = TRUNCATION * TRUNCATION * max(max(max(values.x, values.y), values.z), 0.0);
    var offset = vec3<f32>(0.0);
    var rank = 0u;
    for (var i = 0u; i < 3u; i++) {
        if (values[i] > floor && values[i] > 0.0) {
            let v = eigen.v[i];
            offset += v * (dot(v, atb) / values[i]);
            rank++;
        }
    }
    let point = mass + offset;
    let mark = max(rank, 1u) | select(0u, STRAYED, outside_box(point, low, high));
    let wide_low = low - slack;
    let wide_high = high + slack;
    if (!outside_box(point, wide_low, wide_high)) {
        return Solved(clamp(point, wide_low, wide_high), mark);
    }
    let trace = ata[0][0] + ata[1][1] + ata[2][2];
    let bias = MASS_BIAS * max(trace, 1.1754944e-38);
    let a = ata + mat3x3<f32>(vec3<f32>(bias, 0.0, 0.0), vec3<f32>(0.0, bias, 0.0), vec3<f32>(0.0, 0.0, bias));
    let lowest = wide_low - mass;
    let highest = wide_high - mass;
    let margin = 1e-6 * max(max(highest.x - lowest.x, highest.y - lowest.y), highest.z - lowest.z);
    var best = clamp(point - mass, lowest, highest);
    var least = NO_ENERGY;
    for (var face = 0u; face < 27u; face++) {
        // 0: free, 1: at the lower bound, 2: at the upper bound, per axis; the system's rows are A's
        // (symmetric: its columns) for the free coordinates and the bound for the others.
        let at = vec3<u32>(face % 3u, face / 3u % 3u, face / 9u);
        var m = a;
        var r = atb;
        for (var i = 0u; i < 3u; i++) {
            if (at[i] > 0u) {
                m[i] = vec3<f32>(unit(i));
                r[i] = select(highest[i], lowest[i], at[i] == 1u);
            }
        }
        // Rows m[i]: y = (r₀ m₁ × m₂ + r₁ m₂ × m₀ + r₂ m₀ × m₁) / det.
        let det = dot(m[0], cross(m[1], m[2]));
        let y = (r.x * cross(m[1], m[2]) + r.y * cross(m[2], m[0]) + r.z * cross(m[0], m[1])) / det;
        let energy = dot(y, a * y) - 2.0 * dot(y, atb);
        if (all(abs(y) < vec3<f32>(NO_ENERGY)) && all(y >= lowest - margin) && all(y <= highest + margin) && energy < least) {
            best = clamp(y, lowest, highest);
            least = energy;
        }
    }
    return Solved(mass + best, mark);
}

// The offset from a cell's lowest corner of the k-th (0 to 3) of its four edges along `axis`.
fn edge_offset(axis: u32, k: u32) -> vec3<u32> {
    return unit((axis + 1u) % 3u) * (k & 1u) + unit((axis + 2u) % 3u) * (k >> 1u);
}

// Where the crossing on the edge leaving `cell`'s lowest corner along `axis` is kept, or INVALID past
// the end of a buffer too small for every active block (the largest grids).
fn crossing_slot(cell: vec3<u32>, axis: u32) -> u32 {
    let slot = block_slots[block_index(cell / BLOCK_CELLS)];
    let at = cell % BLOCK_CELLS;
    let record = ((slot * 64u + at.x + BLOCK_CELLS * (at.y + BLOCK_CELLS * at.z)) * 3u + axis) * 3u;
    return select(INVALID, record, slot < grid.max_blocks && record + 3u <= arrayLength(&edge_crossings));
}

fn signs(v: vec2<f32>) -> vec2<f32> {
    return select(vec2<f32>(-1.0), vec2<f32>(1.0), v >= vec2<f32>(0.0));
}

// A unit vector on the octahedron |x| + |y| + |z| = 1, its lower half folded over the upper.
fn octahedral(n: vec3<f32>) -> vec2<f32> {
    let p = n.xy / (abs(n.x) + abs(n.y) + abs(n.z));
    return select(p, (1.0 - abs(p.yx)) * signs(p), n.z < 0.0);
}

fn from_octahedral(e: vec2<f32>) -> vec3<f32> {
    let z = 1.0 - abs(e.x) - abs(e.y);
    return normalize(vec3<f32>(select(e, (1.0 - abs(e.yx)) * signs(e), z < 0.0), z));
}

// The crossing kept at `record` on the edge leaving `cell` along `axis`: its point, found again from
// its parameter exactly as `crossing` found it, and its normal.
fn read_crossing(cell: vec3<u32>, axis: u32, record: u32) -> EdgeVertex {
    let pa = grid_point(cell);
    let pb = grid_point(cell + unit(axis));
    let p = pa + (pb - pa) * edge_crossings[record];
    return EdgeVertex(p, from_octahedral(vec2<f32>(edge_crossings[record + 1u], edge_crossings[record + 2u])));
}

@compute @workgroup_size(64)
fn make_dual_crossings(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) index: u32) {
    let a = active_at(workgroup, index);
    if (a.reference == INVALID) {
        return;
    }
    for (var axis = 0u; axis < 3u; axis++) {
        let fa = value_at(a.slot, a.at);
        let fb = value_at(a.slot, a.at + unit(axis));
        let record = crossing_slot(a.cell, axis);
        if ((fa > grid.iso) != (fb > grid.iso) && record != INVALID) {
            let c = crossing(a.cell, a.cell + unit(axis), fa, fb);
            let e = octahedral(c.normal);
            edge_crossings[record] = c.along;
            edge_crossings[record + 1u] = e.x;
            edge_crossings[record + 2u] = e.y;
        }
    }
}

@compute @workgroup_size(64)
fn make_dual_vertices(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) index: u32) {
    let a = active_at(workgroup, index);
    if (a.reference == INVALID || (a.reference + 1u) * 3u > arrayLength(&edge_vertices)) {
        return;
    }
    var points: array<vec3<f32>, 12>;
    var normals: array<vec3<f32>, 12>;
    var count = 0u;
    var lost = false;
    var mass = vec3<f32>(0.0);
    var normal = vec3<f32>(0.0);
    for (var axis = 0u; axis < 3u; axis++) {
        for (var k = 0u; k < 4u; k++) {
            let o = edge_offset(axis, k);
            if ((value_at(a.slot, a.at + o) > grid.iso) != (value_at(a.slot, a.at + o + unit(axis)) > grid.iso)) {
                // The edge's lowest corner is a crossed cell's, whose crossing it is.
                let record = crossing_slot(a.cell + o, axis);
                lost = lost || record == INVALID;
                let c = read_crossing(a.cell + o, axis, select(record, 0u, record == INVALID));
                points[count] = c.position;
                normals[count] = c.normal;
                mass += c.position;
                normal += c.normal;
                count++;
            }
        }
    }
    mass /= f32(max(count, 1u));
    var p = mass;
    var mark = 0u;
    if (qef_on()) {
        var ata = mat3x3<f32>(vec3<f32>(0.0), vec3<f32>(0.0), vec3<f32>(0.0));
        var atb = vec3<f32>(0.0);
        for (var i = 0u; i < count; i++) {
            let n = normals[i];
            ata += mat3x3<f32>(n * n.x, n * n.y, n * n.z);
            atb += n * dot(n, points[i] - mass);
        }
        let solved = solve_qef(ata, atb, mass, grid_point(a.cell), grid_point(a.cell + 1u), SLACK * grid.cell_size);
        p = solved.point;
        mark = solved.mark;
    }
    let len2 = dot(normal, normal);
    let n = select(vec3<f32>(0.0, 0.0, 1.0), normal * inverseSqrt(len2), len2 > 0.0);
    // A cell missing a crossing (its block past the crossings' buffer) gets no vertex.
    var vertex = INVALID;
    if (!lost) {
        vertex = atomicAdd(&counters.vertices, 1u);
        if (vertex < grid.max_vertices) {
            write_vertex(vertex, p, n);
        } else {
            vertex = INVALID;
        }
    }
    edge_vertices[a.reference * 3u] = vertex;
    edge_vertices[a.reference * 3u + 1u] = mark;
}

fn vertex_position(i: u32) -> vec3<f32> {
    return vec3<f32>(vertices[6u * i], vertices[6u * i + 1u], vertices[6u * i + 2u]);
}

// The mark of `cell`'s vertex (its slot after the vertex's).
fn cell_mark(cell: vec3<u32>) -> u32 {
    return owned_vertex(cell, 1u, 3u);
}

@compute @workgroup_size(64)
fn make_dual_quads(@builtin(workgroup_id) workgroup: vec3<u32>, @builtin(local_invocation_index) index: u32) {
    let a = active_at(workgroup, index);
    if (a.reference == INVALID) {
        return;
    }
    let first_crossing = min(atomicLoad(&counters.vertices), grid.max_vertices);
    for (var axis = 0u; axis < 3u; axis++) {
        let fa = value_at(a.slot, a.at);
        let fb = value_at(a.slot, a.at + unit(axis));
        let inside = fa > grid.iso;
        if (inside == (fb > grid.iso)) {
            continue;
        }
        let kept = crossing_slot(a.cell, axis);
        if (qef_on() && kept != INVALID) {
            // The edge's crossing, for display=normals, after the mesh's vertices where there is room.
            let record = first_crossing + atomicAdd(&counters.crossings, 1u);
            if (record < grid.max_vertices) {
                let c = read_crossing(a.cell, axis, kept);
                write_vertex(record, c.position, c.normal);
            }
        }
        let u = unit((axis + 1u) % 3u);
        let v = unit((axis + 2u) % 3u);
        if (dot(a.cell, u) == 0u || dot(a.cell, v) == 0u) {
            continue;
        }
        // The four cells around the edge, counter-clockwise seen from +axis.
        let cells = array<vec3<u32>, 4>(a.cell - u - v, a.cell - v, a.cell, a.cell - u);
        var around: array<u32, 4>;
        var marks: array<u32, 4>;
        var lost = false;
        for (var j = 0u; j < 4u; j++) {
            // Outward is +axis when the edge's near end is inside.
            let c = cells[select(3u - j, j, inside)];
            around[j] = owned_vertex(c, 0u, 3u);
            marks[j] = cell_mark(c);
            lost = lost || around[j] == INVALID;
        }
        if (lost) {
            continue;
        }
        let ac = vertex_position(around[0]) - vertex_position(around[2]);
        let bd = vertex_position(around[1]) - vertex_position(around[3]);
        // The quad's two triangles as corners of `around`, two bits each: (0, 1, 2) and (0, 2, 3)
        // across the shorter diagonal a–c, else (0, 1, 3) and (1, 2, 3).
        let split = select(0xe74u, 0xe24u, dot(ac, ac) <= dot(bd, bd));
        let first = atomicAdd(&counters.indices, 6u);
        for (var t = 0u; t < 2u; t++) {
            var triangle: vec3<u32>;
            var mark = 0u;
            for (var i = 0u; i < 3u; i++) {
                let corner = (split >> (6u * t + 2u * i)) & 3u;
                triangle[i] = around[corner];
                mark |= marks[corner] << (3u * i);
            }
            write_triangle(first + 3u * t, triangle);
            let triangle_index = first / 3u + t;
            if (qef_on() && triangle_index < min(grid.max_indices / 3u, arrayLength(&lod_data))) {
                lod_data[triangle_index] = mark;
            }
        }
    }
}
