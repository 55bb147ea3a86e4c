// Meshing off the page's thread: one worker per page (mesh-worker.js) meshes the jobs of every figure
// whose CPU mesher makes its mesh, so that the page's thread stays free while they animate. Where the
// page cannot start a module worker (no Worker, the element's modules on another origin) or its wasm
// was given by the host rather than fetched from beside the modules (a notebook widget's, whose worker
// would have no file to start from), `meshWorker()` is null and the figures mesh on the page's thread.

import { buildFiles, wasmBesideModule, wasmModule } from './wasm.js';

let worker;
// The worker has started its wasm (the page's compiled module, instantiated again): meshes asked for
// meanwhile wait for it; what asks only a ready worker (pictures for print) is done on the page's thread.
let ready = false;
let asked = 0;
const waiting = new Map();

// Every job still waiting fails with `why`, and no new one is taken.
function stop(why) {
  worker?.terminate();
  worker = null;
  for (const { reject } of waiting.values()) reject(new Error(why));
  waiting.clear();
}

function make() {
  try {
    const { glue, wasm, compiled, worker: url } = buildFiles();
    const made = new Worker(url, { type: 'module', name: 'metaballs mesher' });
    made.onmessage = ({ data }) => {
      if (data.ready) ready = true;
      if (data.failed) stop(`the mesher worker could not start (${data.failed})`);
      const job = waiting.get(data.id);
      waiting.delete(data.id);
      if (!job) return;
      if (data.error) job.reject(new Error(data.error));
      else job.resolve(data.shape ?? data.png ?? data.decided ?? [data.vertices, data.indices, data.blocks, data.cells]);
    };
    made.onerror = (event) => {
      event.preventDefault?.();
      stop(`the mesher worker stopped (${event.message || 'it could not load'})`);
    };
    made.postMessage({ glue: String(glue), wasm: String(wasm), compiled });
    return made;
  } catch {
    return null;
  }
}

/**
 * The page's mesher worker (made on first use, once the wasm has loaded), or null where there is none
 * or, unless `starting` is true, while it is still starting (what is asked of it meanwhile waits until it
 * has):
 * `{ mesh(job) }` resolves with `[vertices, indices, activeBlocks, activeCells]` for `View.give_mesh`;
 * `{ shape(vertices, triangles) }`, `{ png(pixels, width, height) }` and `{ decided(job) }` as `meshShape`,
 * `pngOf` (look.js) and `decidedCells`.
 */
export function meshWorker(starting = false) {
  if (worker === undefined) worker = typeof Worker === 'function' && wasmBesideModule() ? make() : null;
  if (!worker || !(ready || starting)) return null;
  const ask = (message, transfer = []) => new Promise((resolve, reject) => {
    asked += 1;
    waiting.set(asked, { resolve, reject });
    worker.postMessage({ id: asked, ...message }, transfer);
  });
  return {
    mesh: (job) => ask({ job }),
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
export const meshingOffThread = () => Boolean(worker) && ready;
