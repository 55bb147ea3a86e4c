// The WebAssembly, once per page: picks WebGPU where the browser gives an adapter, else WebGL2 (a
// second wasm build, loaded only then, whose meshes come from the CPU mesher), loads that wasm a
// single time, asks for the WebGPU device while it does, and reports a Rust panic in the figure whose
// call panicked.

import { describeLoadError, fetchWasm } from './asset-errors.js';
import { fromWasm } from '../i18n/words.js';

let wasm = null;
// Each started build's linear memory, by its module.
const memories = new WeakMap();
let backend = null;
let detectedAdapter = null;

/** The wasm module in use (after `loadWasm`). */
export const wasmModule = () => wasm;

/** What this browser draws with: 'webgpu', 'webgl2' or 'none' (after `loadWasm`). */
export const backendName = () => backend;

let gallery = null;
/** The 15 classes of cases (representative, inside corners, triangles) and the cube's numbering. */
export function caseGallery() {
  gallery ??= { classes: wasm.case_gallery(), cube: wasm.cube_geometry() };
  return gallery;
}

// WebGPU where the browser gives an adapter (some expose navigator.gpu and then give none); else
// WebGL2 where a canvas gives a WebGL2 context.
async function detectBackend() {
  if (navigator.gpu) {
    try {
      detectedAdapter = await navigator.gpu.requestAdapter();
      if (detectedAdapter) return 'webgpu';
    } catch { /* no adapter */ }
  }
  try {
    const gl = document.createElement('canvas').getContext('webgl2');
    if (gl) {
      gl.getExtension('WEBGL_lose_context')?.loseContext();
      return 'webgl2';
    }
  } catch { /* no WebGL2 */ }
  return 'none';
}

let wasmReady = null;

/** True once the wasm has loaded (attributes can be read from then on). */
export const wasmLoaded = () => wasm !== null;
/** Bytes of the wasm's linear memory (it grows and never shrinks), 0 before it starts. */
export const wasmBytes = () => (wasm && memories.get(wasm)?.buffer.byteLength) ?? 0;
/** Bytes the wasm's heap holds (allocated and not freed) for every figure together, 0 before it starts. */
export const wasmHeapBytes = () => wasm?.heap_bytes() ?? 0;

// The two builds: their JavaScript and their WebAssembly, fetched together. Each path is written out
// in full where it is used, so that bundlers (Vite, webpack) find the files and copy them.
// `glueFile` is the JavaScript's own URL, for the mesher worker (which imports it by URL).
const WEBGPU_BUILD = {
  name: 'webgpu',
  glue: () => import('../../../pkg/metaballs.js'),
  glueFile: () => new URL('../../../pkg/metaballs.js', import.meta.url),
  wasm: () => new URL('../../../pkg/metaballs_bg.wasm', import.meta.url),
};
const WEBGL_BUILD = {
  name: 'webgl2',
  glue: () => import('../../../pkg-webgl/metaballs.js'),
  glueFile: () => new URL('../../../pkg-webgl/metaballs.js', import.meta.url),
  wasm: () => new URL('../../../pkg-webgl/metaballs_bg.wasm', import.meta.url),
};

/**
 * The critical points' module (pkg-levels/, lib/engine/levels.js): its JavaScript's URL and its import,
 * its WebAssembly's URL and its worker's module's, each made when asked (a module imported from a blob:
 * URL has no place to resolve them against). Named here, where the paths hold once bundled.
 */
export const LEVELS_FILES = {
  glue: () => new URL('../../../pkg-levels/metaballs_levels.js', import.meta.url),
  load: () => import('../../../pkg-levels/metaballs_levels.js'),
  wasm: () => new URL('../../../pkg-levels/metaballs_levels_bg.wasm', import.meta.url),
  worker: () => new URL('./levels-worker.js', import.meta.url),
};

// Each build's compiled WebAssembly.Module, where it was fetched from beside this module.
const compiledModules = new Map();

/**
 * The URLs of the build in use, its JavaScript (`glue`) and its WebAssembly (`wasm`), its compiled
 * WebAssembly.Module (`compiled`, or undefined where it was given by the host), and the URL of the
 * mesher worker's module (`worker`). The worker's is made here, beside the build's paths, because this
 * module keeps its place when bundled (www/dist.sh checks it), so a path relative to it holds in dist/
 * too. The URL is made apart from the `Worker` constructor: bundlers copy the file as it is (it imports
 * nothing) instead of bundling it as a worker of their own format.
 */
export function buildFiles() {
  const build = backend === 'webgl2' ? WEBGL_BUILD : WEBGPU_BUILD;
  return {
    glue: build.glueFile(),
    wasm: build.wasm(),
    compiled: compiledModules.get(build.name),
    worker: new URL('./mesh-worker.js', import.meta.url),
  };
}

// Where each build's WebAssembly comes from when not from next to the modules (see `setWasmSources`).
let wasmSources = {};

/**
 * Tells the page where the WebAssembly comes from, before the first figure connects: `{ webgpu, webgl2 }`,
 * each a function returning (a promise of) the wasm's bytes or its Response. For hosts that import the
 * element from where no file sits beside it (a notebook widget's module is imported from a blob: URL).
 */
export function setWasmSources(sources) {
  wasmSources = { ...sources };
}

/** True when the build in use was fetched from beside this module (not given by the host). */
export const wasmBesideModule = () => !wasmSources[backend];

// What the figures should be told once the wasm is in (it came with the wrong type), or null.
let warning = null;
/** A notice for every figure about how the wasm was served, or null. */
export const loadWarning = () => warning;

// Imports a build's module while its wasm is fetched, and starts the wasm; a failure says what failed
// and what to do.
async function start(build) {
  // The wasm's place beside this module, only where it is fetched from there: a module imported from
  // a blob: URL (a notebook widget's) has no place to resolve it against, and is given its wasm.
  const given = wasmSources[build.name];
  const url = given ? `the ${build.name} build's WebAssembly` : build.wasm();
  const fetched = given ? Promise.resolve({ source: given(), warning: null }) : fetchWasm(url);
  // Fetched from beside this module, it is compiled here (while the glue loads), so that the page's
  // mesher worker can be handed the compiled module rather than fetch and compile it again.
  const compiling = given ? null : fetched.then(({ source }) => (source instanceof Response
    ? WebAssembly.compileStreaming(source) : WebAssembly.compile(source)));
  compiling?.catch(() => { /* reported below */ });
  try {
    const module = await build.glue();
    const wasmFile = await fetched;
    const compiled = await compiling;
    const { memory } = await module.default({ module_or_path: compiled ?? wasmFile.source });
    if (compiled) compiledModules.set(build.name, compiled);
    warning = wasmFile.warning;
    const readable = readableErrors(module);
    memories.set(readable, memory);
    return readable;
  } catch (error) {
    throw describeLoadError(error, url);
  }
}

// A WebGPU device asked for as soon as its build has started, while the page still looks for an adapter
// (taken by the first figure that needs a device).
let earlyGpu = null;

/** The WebGPU device asked for while the wasm loaded (once: later calls give null), and the adapter. */
export function takeEarlyGpu() {
  const early = earlyGpu;
  earlyGpu = null;
  return { early, adapter: detectedAdapter };
}

// What runs once the WebGPU build is in (the page's device hub starts its device).
let afterLoad = () => {};
/** Sets what runs once the WebGPU build has loaded. */
export function whenWebgpuLoaded(f) {
  afterLoad = f;
}

/**
 * Picks the backend and loads and starts its wasm (once, however many elements ask). Where the browser
 * has WebGPU, its build is fetched and compiled, and the device requested, while the page looks for an
 * adapter: the first frame waits for the slowest of them, not their sum.
 */
export function loadWasm() {
  wasmReady ??= (async () => {
    const webgpu = navigator.gpu ? start(WEBGPU_BUILD) : null;
    earlyGpu = webgpu?.then((module) => module.Gpu.create()) ?? null;
    earlyGpu?.catch(() => { /* reported when a figure takes it */ });
    backend = await detectBackend();
    if (backend === 'webgl2') {
      webgpu?.catch(() => { /* not used */ });
      earlyGpu?.then((gpu) => gpu.free(), () => {});
      earlyGpu = null;
      wasm = await start(WEBGL_BUILD);
      return;
    }
    wasm = await (webgpu ?? start(WEBGPU_BUILD));
    if (backend === 'webgpu') afterLoad();
    else earlyGpu = null;
  })();
  return wasmReady;
}

/** Reads `text` as parameter `name`'s value; throws an Error with a message saying what is accepted. */
export function parseParameter(name, text) {
  return wasm.parse_parameter(name, text);
}

/**
 * A build's exports, whose functions and classes' methods throw (or reject with) a refusal as
 * core/read.js makes one (an English message, its code and fields: `fromWasm`) where the WebAssembly
 * throws one as its code and fields.
 */
function readableErrors(module) {
  const wrap = (f) => function readable(...args) {
    let result;
    try {
      result = f.apply(this, args);
    } catch (error) {
      throw fromWasm(error);
    }
    return result instanceof Promise ? result.catch((error) => { throw fromWasm(error); }) : result;
  };
  const exports = {};
  for (const [name, value] of Object.entries(module)) {
    exports[name] = value;
    if (typeof value !== 'function' || name === 'default' || name === 'initSync') continue;
    if (!/^[A-Z]/.test(name)) {
      exports[name] = wrap(value);
      continue;
    }
    for (const owner of [value, value.prototype]) {
      for (const key of Object.getOwnPropertyNames(owner)) {
        const { value: method, writable } = Object.getOwnPropertyDescriptor(owner, key);
        if (typeof method === 'function' && writable && key !== 'constructor') owner[key] = wrap(method);
      }
    }
  }
  return Object.freeze(exports);
}

// A Rust panic reaches the page here (see src/web/): the element whose call panicked shows it.
let current = null;
/** Runs `f` with `element` as the one a panic would be reported in. */
export function within(element, f) {
  const previous = current;
  current = element;
  try {
    return f();
  } finally {
    current = previous;
  }
}
globalThis.metaballsShowPanic = (message) => {
  if (current) current.fail({ key: 'figure.renderer-stopped' }, message);
  else console.error(`metaballs: ${message}`);
};
