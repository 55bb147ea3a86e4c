// The WebAssembly and the GPU, once per page: picks WebGPU where the browser gives an adapter, else
// WebGL2 (a second wasm build, loaded only then, whose meshes come from the CPU mesher), loads that wasm
// a single time, holds the one WebGPU device every <metaballs-view> on the page draws with (WebGL2 has
// a device per canvas), drives all of them from one requestAnimationFrame loop (which stops when none
// needs a frame), and rebuilds every view on a new device when the device is lost.

import { LossCount } from './losses.js';
import { describeLoadError, fetchWasm } from './asset-errors.js';

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
const WEBGPU_BUILD = {
  name: 'webgpu',
  glue: () => import('../../pkg/metaballs.js'),
  wasm: () => new URL('../../pkg/metaballs_bg.wasm', import.meta.url),
};
const WEBGL_BUILD = {
  name: 'webgl2',
  glue: () => import('../../pkg-webgl/metaballs.js'),
  wasm: () => new URL('../../pkg-webgl/metaballs_bg.wasm', import.meta.url),
};

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
  fetched.catch(() => { /* reported below */ });
  try {
    const module = await build.glue();
    const wasmFile = await fetched;
    memories.set(module, (await module.default({ module_or_path: wasmFile.source })).memory);
    warning = wasmFile.warning;
    return module;
  } catch (error) {
    throw describeLoadError(error, url);
  }
}

// A WebGPU device asked for as soon as its build has started, while the page still looks for an adapter
// (taken by the first figure that needs a device).
let earlyGpu = null;

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
    if (backend === 'webgpu') hub.acquire().catch(() => { /* reported when a figure asks */ });
    else earlyGpu = null;
  })();
  return wasmReady;
}

/** The property name of an attribute (`max-pixel-ratio` → `maxPixelRatio`). */
export const propertyName = (name) => name.replace(/-([a-z])/g, (_, c) => c.toUpperCase());

/** Reads `text` as parameter `name`'s value; throws an Error with a message saying what is accepted. */
export function parseParameter(name, text) {
  return wasm.parse_parameter(name, text);
}

export const WEBGPU_HELP =
  'This figure draws with WebGPU or, without it, WebGL2; this browser offers neither. ' +
  'Use a current Chrome or Edge (113 or later), Safari 26, or Firefox 141 or later. ' +
  'On Linux, Chrome needs WebGPU switched on at chrome://flags/#enable-unsafe-webgpu; ' +
  'the page must also be served over https or from localhost.';

/** WebGL2 figures drawing at once: browsers allow a page only a few WebGL contexts (16 in Chromium). */
export const MAX_WEBGL_FIGURES = 8;

/** What a WebGL2 figure waiting for a device says. */
export const WEBGL_WAIT = 'This browser has no WebGPU, so the figures draw with WebGL2, which allows a page '
  + `only a few drawing contexts: ${MAX_WEBGL_FIGURES} figures are drawing already. This one starts when `
  + 'one of them is removed.';

class Hub {
  constructor() {
    this.gpu = null;
    this.starting = null;
    this.adapter = null;
    this.elements = new Set();
    this.devicesCreated = 0;
    this.losses = new LossCount();
    this.recovering = false;
    this.stopped = null;
    this.frameRequested = false;
    // WebGL2 figures holding a device now, and those waiting for one to be given back.
    this.webglHolders = new Set();
    this.webglWaiting = new Set();
  }

  /** Devices alive now (0 or 1). */
  get devices() {
    return this.gpu ? 1 : 0;
  }

  /** The shared device, created on first use; rejects with a message when WebGPU is missing. */
  acquire() {
    if (this.gpu) return Promise.resolve(this.gpu);
    if (this.stopped) return Promise.reject(new Error(this.stopped));
    this.starting ??= this.#start().finally(() => { this.starting = null; });
    return this.starting;
  }

  async #start() {
    await loadWasm();
    if (backend !== 'webgpu') throw new Error(WEBGPU_HELP);
    this.adapter = describeAdapter(detectedAdapter);
    const early = earlyGpu;
    earlyGpu = null;
    let gpu;
    try {
      gpu = await (early ?? wasm.Gpu.create());
    } catch (error) {
      throw new Error(`${error?.message ?? error}`);
    }
    gpu.set_software(this.adapter.software);
    this.devicesCreated += 1;
    this.gpu = gpu;
    return gpu;
  }

  /**
   * The device `element` draws on `canvas` with: the shared WebGPU one, or with WebGL2 one of its own
   * (null while `MAX_WEBGL_FIGURES` others hold one). Rejects with an Error whose `title` says what
   * could not start and whose message says why and what a browser needs.
   */
  async deviceFor(element, canvas) {
    let webgl = false;
    try {
      await loadWasm();
      webgl = backend === 'webgl2';
      return webgl ? await this.#acquireWebgl(element, canvas) : await this.acquire();
    } catch (error) {
      const none = backend === 'none';
      const failure = new Error(none ? WEBGPU_HELP : `${error?.message ?? error}\n\n${WEBGPU_HELP}`);
      failure.title = none ? 'Neither WebGPU nor WebGL2 is available'
        : webgl ? 'WebGL2 could not start' : 'WebGPU could not start';
      throw failure;
    }
  }

  /** Takes back what `deviceFor` gave `element`: a WebGL2 device is freed and its place passed on. */
  giveBack(element, gpu) {
    if (this.webglHolders.has(element)) {
      try {
        gpu?.free();
      } catch { /* already gone */ }
    }
    this.#releaseWebgl(element);
  }

  async #acquireWebgl(element, canvas) {
    if (!this.webglHolders.has(element) && this.webglHolders.size >= MAX_WEBGL_FIGURES) {
      this.webglWaiting.add(element);
      return null;
    }
    this.webglWaiting.delete(element);
    this.webglHolders.add(element);
    this.adapter = { label: 'WebGL2', software: false };
    try {
      return await wasm.Gpu.create_webgl(canvas);
    } catch (error) {
      this.#releaseWebgl(element);
      throw new Error(`${error?.message ?? error}`);
    }
  }

  // `element` gave its WebGL2 device back (or stopped waiting): the first figure waiting starts.
  #releaseWebgl(element) {
    this.webglWaiting.delete(element);
    if (!this.webglHolders.delete(element)) return;
    const [next] = this.webglWaiting;
    if (next) next.resume();
  }

  register(element) {
    this.elements.add(element);
    this.requestFrame();
  }

  unregister(element) {
    this.elements.delete(element);
  }

  /** Schedules one animation frame for every element that wants one (none when none does). */
  requestFrame() {
    if (this.frameRequested) return;
    this.frameRequested = true;
    requestAnimationFrame((now) => this.#frame(now));
  }

  #frame(now) {
    this.frameRequested = false;
    if (this.gpu && !this.recovering) {
      const lost = this.gpu.lost();
      if (lost) {
        this.#recover(lost);
        return;
      }
      const error = this.gpu.gpu_error();
      if (error && !this.reportedError) {
        this.reportedError = true;
        for (const element of this.elements) element.fail('The GPU reported an error', error);
      }
    }
    let wanted = false;
    for (const element of this.elements) {
      if (element.tick(now)) wanted = true;
    }
    if (wanted) this.requestFrame();
  }

  // Every view leaves the lost device (keeping its state on the CPU), then, after a pause that doubles
  // with each loss, all move to a new device. Too many losses in a short time stop the retries.
  async #recover(reason) {
    this.recovering = true;
    console.warn(`metaballs: ${reason}; starting again on a new device`);
    for (const element of this.elements) element.suspend(reason);
    try { this.gpu.free(); } catch { /* already gone */ }
    this.gpu = null;
    const losses = this.losses.record();
    if (this.losses.exhausted) {
      this.recovering = false;
      this.stopped = `The GPU was lost ${losses} times within a minute (${reason}), so the figures stopped trying.`;
      for (const element of this.elements) element.fail('The GPU keeps failing', this.stopped, { retry: true });
      return;
    }
    for (let attempt = 0; attempt < 6; attempt++) {
      await new Promise((r) => setTimeout(r, this.losses.backoff(attempt)));
      try {
        await this.acquire();
        break;
      } catch (error) {
        console.warn(`metaballs: no new device yet (${error?.message ?? error})`);
      }
    }
    this.recovering = false;
    if (!this.gpu) {
      this.stopped = `The GPU was lost (${reason}) and no new device could be had.`;
      for (const element of this.elements) element.fail('The GPU is gone', this.stopped, { retry: true });
      return;
    }
    for (const element of this.elements) element.resume();
    this.requestFrame();
  }

  /** After the hub gave up: try again from scratch (an element's "Try again" button). */
  retry() {
    this.stopped = null;
    this.losses.clear();
    this.reportedError = false;
    for (const element of this.elements) element.resume();
  }
}

/** The one hub of this page. */
export const hub = new Hub();

// The browser names its adapter through GPUAdapterInfo (wgpu sees only an anonymous one). Software
// adapters (SwiftShader, llvmpipe, or any fallback adapter) draw much faster without multisampling, at
// lower pixel ratios and with the CPU mesher.
function describeAdapter(adapter) {
  try {
    const info = adapter?.info;
    const words = [info?.vendor, info?.architecture, info?.description].filter(Boolean);
    const software = Boolean(info?.isFallbackAdapter || adapter?.isFallbackAdapter)
      || /swiftshader|llvmpipe|lavapipe|software/i.test(words.join(' '));
    return { label: `WebGPU · ${words.length ? [...new Set(words)].join(' ') : 'adapter'}`, software };
  } catch {
    return { label: 'WebGPU', software: false };
  }
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
  if (current) current.fail('The renderer stopped', message);
  else console.error(`metaballs: ${message}`);
};
