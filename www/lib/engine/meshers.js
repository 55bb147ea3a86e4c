// Meshing off the page's thread: a pool of workers per page (mesh-worker.js), each a second instance of
// the page's wasm, meshes the jobs of every figure whose CPU mesher makes its mesh, so that the page's
// thread stays free while they animate. Each job goes to the worker with the fewest jobs in hand, so the
// page's figures share the pool, and a large one is cut into slabs of z, one for each worker, joined
// into the mesh one worker would make (slabs.js). The pool has one worker where the machine
// has one or two cores (the page's thread and the browser's rasteriser need theirs), and one more for
// each further core, up to four. Where the page cannot start a module worker (no Worker, the element's
// modules on another origin) or its wasm was given by the host rather than fetched from beside the
// modules (a notebook widget's, whose worker would have no file to start from), `meshWorker()` is null
// and the figures mesh on the page's thread.

import { joinSlabs, slabRanges } from './slabs.js';
import { buildFiles, wasmBesideModule, wasmModule } from './wasm.js';

/** The most mesher workers a page starts. */
const MAX_WORKERS = 4;
/** Grids of fewer cells per axis are meshed whole: the slabs' seams would cost more than they save. */
const MIN_SLAB_GRID = 64;

/** How many mesher workers a page with `cores` logical cores starts. */
export const poolSize = (cores) => Math.max(1, Math.min(MAX_WORKERS, (Number(cores) || 1) - 1));

// The pool (undefined until first asked for; null where there is none), each member
// `{ worker, ready, jobs }` with its jobs in hand, by id.
let pool;
let asked = 0;

// Every job still waiting fails with `why`, and no new one is taken.
function stop(why) {
  for (const member of pool ?? []) {
    member.worker.terminate();
    for (const { reject } of member.jobs.values()) reject(new Error(why));
    member.jobs.clear();
  }
  pool = null;
}

function start(index) {
  const { glue, wasm, compiled, worker: url } = buildFiles();
  const member = { worker: new Worker(url, { type: 'module', name: `metaballs mesher ${index + 1}` }), ready: false, jobs: new Map() };
  member.worker.onmessage = ({ data }) => {
    if (data.ready) member.ready = true;
    if (data.failed) stop(`the mesher worker could not start (${data.failed})`);
    const job = member.jobs.get(data.id);
    member.jobs.delete(data.id);
    if (!job) return;
    if (data.error) job.reject(new Error(data.error));
    else job.resolve(data.slab ?? data.shape ?? data.png ?? data.decided ?? [data.vertices, data.indices, data.blocks, data.cells]);
  };
  member.worker.onerror = (event) => {
    event.preventDefault?.();
    stop(`the mesher worker stopped (${event.message || 'it could not load'})`);
  };
  member.worker.postMessage({ glue: String(glue), wasm: String(wasm), compiled });
  return member;
}

function make() {
  try {
    // Benchmarks and tests may set the number of workers.
    const size = globalThis.metaballsMeshWorkers ?? poolSize(globalThis.navigator?.hardwareConcurrency);
    return Array.from({ length: size }, (_, i) => start(i));
  } catch {
    stop('the mesher workers could not start');
    return null;
  }
}

// The member to give the next job: the one with the fewest in hand, the first such.
const leastBusy = (members) => members.reduce((best, m) => (m.jobs.size < best.jobs.size ? m : best));

/**
 * The page's mesher workers (started on first use, once the wasm has loaded), or null where there are
 * none or, unless `starting` is true, while none has started yet (what is asked meanwhile waits until
 * one has):
 * `{ mesh(job) }` resolves with `[vertices, indices, activeBlocks, activeCells]` for `View.give_mesh`
 * (from slabs meshed by several workers, joined);
 * `{ shape(vertices, triangles) }`, `{ png(pixels, width, height) }` and `{ decided(job) }` as `meshShape`,
 * `pngOf` (look.js) and `decidedCells`.
 */
export function meshWorker(starting = false) {
  if (pool === undefined) pool = typeof Worker === 'function' && wasmBesideModule() ? make() : null;
  if (!pool) return null;
  const ready = pool.filter((m) => m.ready);
  if (!(ready.length || starting)) return null;
  const ask = (message, transfer = []) => new Promise((resolve, reject) => {
    // A started worker takes the job; while none has, the first.
    const member = leastBusy(ready.length ? ready : pool);
    asked += 1;
    member.jobs.set(asked, { resolve, reject });
    member.worker.postMessage({ id: asked, ...message }, transfer);
  });
  // A large marching-cubes job is cut into as many slabs as there are started workers, meshed at once
  // and joined here (a copy of the vertices and a pass over the indices).
  const mesh = (job) => {
    const ranges = ready.length > 1 && job[0] === 0 && job[2] >= MIN_SLAB_GRID ? slabRanges(job[2], ready.length) : [];
    if (ranges.length < 2) return ask({ job });
    return Promise.all(ranges.map((slab) => ask({ job, slab }))).then((slabs) => joinSlabs(job[2], slabs));
  };
  return {
    mesh,
    shape: (vertices, triangles) => ask({ shape: [vertices, triangles] }, [triangles.buffer]),
    png: (pixels, width, height) => ask({ png: [pixels, width, height] }, [pixels.buffer]),
    decided: (job) => ask({ decided: job }),
  };
}

/**
 * The shape of a mesh of `vertices` vertices and `triangles` (`View.mesh_triangles`): resolves to
 * `[components, genus, closed (0/1), manifold (0/1)]`, worked out on the mesher worker (the triangles
 * are handed over) or, where there is none, on the page's thread.
 */
export function meshShape(vertices, triangles) {
  const worker = meshWorker(true);
  return worker ? worker.shape(vertices, triangles) : Promise.resolve(wasmModule().mesh_shape(vertices, triangles));
}

/**
 * The cells whose triangles a case table changes in the scene of `job` (`View.cpu_job(true)`): resolves
 * to an array of [x, y, z, kind], kind bit 0 where the asymptotic decider joins a face the classic
 * table cuts, bit 1 where MC33 draws a tunnel; worked out on the mesher worker; rejects where there is
 * none (a whole mesh is made for it, too long for the page's thread).
 */
export async function decidedCells(job) {
  const worker = meshWorker(true);
  if (!worker) throw new Error('no mesher worker on this page');
  const flat = await worker.decided(job);
  return Array.from({ length: flat.length / 4 }, (_, k) => [...flat.subarray(4 * k, 4 * k + 4)]);
}

/** Whether the figures' meshes are made off the page's thread (false until a figure has asked). */
export const meshingOffThread = () => Boolean(pool?.some((m) => m.ready));
