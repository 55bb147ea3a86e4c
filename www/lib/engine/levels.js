// The critical points of a figure's field and the surface's measures along the iso level, from the
// critical points' own WebAssembly module (pkg-levels/, loaded on first use: the drawing build does not
// carry it). Worked out on the topology worker (levels-worker.js) where the page can start one beside
// the modules, else on the page's thread (a notebook widget's, whose module comes from a blob: URL and
// is given its wasm by the host, `setLevelsSource`).

import { LEVELS_FILES as files } from './wasm.js';

let worker;
let ready = null;
let asked = 0;
const waiting = new Map();
let mainThread = null;
let given = null;

/** Where the module's WebAssembly comes from when not from beside the modules: a function returning its bytes. */
export function setLevelsSource(source) {
  given = source;
}


function startWorker() {
  try {
    const made = new Worker(files.worker(), { type: 'module', name: 'metaballs topology' });
    ready = new Promise((resolve, reject) => {
      made.onmessage = ({ data }) => {
        if (data.ready) resolve(made);
        if (data.failed) {
          made.terminate();
          reject(new Error(`the topology worker could not start (${data.failed})`));
        }
        const job = waiting.get(data.id);
        if (!job) return;
        waiting.delete(data.id);
        if (data.error) job.reject(new Error(data.error));
        else job.resolve(data);
      };
      made.onerror = (event) => {
        event.preventDefault?.();
        made.terminate();
        const why = new Error(`the topology worker stopped (${event.message || 'it could not load'})`);
        reject(why);
        for (const job of waiting.values()) job.reject(why);
        waiting.clear();
      };
    });
    made.postMessage({ glue: String(files.glue()), wasm: String(files.wasm()) });
    return made;
  } catch {
    return null;
  }
}

async function onThisThread() {
  mainThread ??= files.load().then(async (module) => {
    await module.default({ module_or_path: given ? await given() : files.wasm() });
    return module;
  });
  // A load that failed is tried again next time.
  return mainThread.catch((error) => {
    mainThread = null;
    throw error;
  });
}

async function ask(message) {
  if (worker === undefined) worker = typeof Worker === 'function' && !given ? startWorker() : null;
  if (worker) {
    try {
      await ready;
      return await new Promise((resolve, reject) => {
        asked += 1;
        waiting.set(asked, { resolve, reject });
        worker.postMessage({ id: asked, ...message });
      });
    } catch (error) {
      if (!/could not start|stopped/.test(error.message)) throw error;
      worker = null;
    }
  }
  const module = await onThisThread();
  if (message.critical) {
    const begun = performance.now();
    const json = module.critical_points(message.critical);
    return { json, milliseconds: performance.now() - begun };
  }
  return { values: module.measures(...message.measures) };
}

/** Packs spheres (`{ center: [x, y, z], radius, charge }`) as the module reads them. */
export function packSpheres(spheres) {
  return Float32Array.from(spheres.flatMap((s) => [...s.center, s.charge < 0 ? -s.radius : s.radius]));
}

/**
 * The critical points of `packed` spheres' field (`packSpheres`): resolves to the search's result
 * (`points`, `tree`, `bands`, `complete`, …, see levels/src/lib.rs) with `milliseconds` it took.
 */
export async function criticalPoints(packed) {
  const { json, milliseconds } = await ask({ critical: packed });
  return { ...JSON.parse(json), milliseconds };
}

/** The surface's area and enclosed volume at each level, meshed at `n`³: `[[area, volume], …]`. */
export async function measuresAlong(packed, levels, n) {
  const { values } = await ask({ measures: [packed, Float32Array.from(levels), n] });
  return levels.map((_, k) => [values[2 * k], values[2 * k + 1]]);
}

/** The band of `result.bands` holding `iso`: its counts `{ blobs, cavities, genus, surfaces }`. */
export function countsAt(result, iso) {
  return result.bands.find((b) => iso < (b.above ?? Infinity) && iso > b.below) ?? null;
}
