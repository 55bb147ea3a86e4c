// The GPU, once per page: holds the one WebGPU device every <metaballs-view> on the page draws with
// (WebGL2 has a device per canvas), drives all of them from one requestAnimationFrame loop (which stops
// when none needs a frame), and rebuilds every view on a new device when the device is lost.

import { inEnglish } from './asset-errors.js';
import { LossCount } from './losses.js';
import { meshWorker } from './meshers.js';
import { backendName, loadWasm, takeEarlyGpu, wasmModule, whenWebgpuLoaded } from './wasm.js';

/** What a browser needs for the figures (a saying, engine/asset-errors.js). */
const HELP = { key: 'figure.webgpu-help' };

/** WebGL2 figures drawing at once: browsers allow a page only a few WebGL contexts (16 in Chromium). */
export const MAX_WEBGL_FIGURES = 8;

/**
 * How long one animation frame's task draws figures before it leaves the rest to the next one, in ms
 * (a task over 50 ms is a long task, which holds up the page's input and scrolling).
 */
export const TASK_SHARE_MS = 12;

/** What a WebGL2 figure waiting for a device says (a saying, engine/asset-errors.js). */
export const WEBGL_WAIT = { key: 'figure.webgl-wait', fields: { count: MAX_WEBGL_FIGURES } };

// An Error whose message is `said` in English, and which keeps `said` for the figure's box.
const failure = (said, title) => Object.assign(new Error(inEnglish(said)), { said: { title, text: said } });

class Hub {
  constructor() {
    this.gpu = null;
    this.starting = null;
    this.adapter = null;
    this.elements = new Set();
    this.devicesCreated = 0;
    this.losses = new LossCount();
    this.recovering = false;
    // Why the figures stopped trying (a saying, engine/asset-errors.js), or null.
    this.stopped = null;
    this.frameRequested = false;
    // The figure that draws first in the next animation frame (one left over from the last).
    this.nextInLine = 0;
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
    if (this.stopped) return Promise.reject(failure(this.stopped));
    this.starting ??= this.#start().finally(() => { this.starting = null; });
    return this.starting;
  }

  async #start() {
    await loadWasm();
    if (backendName() !== 'webgpu') throw failure(HELP);
    const { early, adapter } = takeEarlyGpu();
    this.adapter = describeAdapter(adapter);
    // A software adapter's figures mesh on the CPU: their worker starts while the device and the views
    // are made, not when the first frame asks for it.
    if (this.adapter.software) meshWorker(true);
    let gpu;
    try {
      gpu = await (early ?? wasmModule().Gpu.create());
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
      webgl = backendName() === 'webgl2';
      return webgl ? await this.#acquireWebgl(element, canvas) : await this.acquire();
    } catch (error) {
      const none = backendName() === 'none';
      const title = { key: none ? 'figure.no-gpu' : webgl ? 'figure.webgl-failed' : 'figure.webgpu-failed' };
      const detail = error?.said?.text ?? `${error?.message ?? error}`;
      const said = none ? HELP : { key: 'figure.gpu-start-failed', fields: { detail, help: HELP } };
      throw Object.assign(failure(said, title), { title: inEnglish(title) });
    }
  }

  // The turn of the figure that asked last (`startTurn`).
  #lastTurn = Promise.resolve();

  /**
   * Resolves in a task of its own, after those of the figures that asked before: a figure makes its
   * view (its buffers, pipelines and first settings) in its turn, so that figures starting together
   * (a lecture's first screen) do not add up to one long task of the page's thread.
   */
  startTurn() {
    const turn = this.#lastTurn.then(() => new Promise((resolve) => setTimeout(resolve, 0)));
    this.#lastTurn = turn;
    return turn;
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
    // WebGL2 figures mesh on the CPU (see #start).
    meshWorker(true);
    try {
      return await wasmModule().Gpu.create_webgl(canvas);
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
        for (const element of this.elements) element.fail({ key: 'figure.gpu-error' }, error);
      }
    }
    // The figures draw in turn until the task has run its share of the page's thread; the rest draw
    // in the next animation frame, first in line, so that no figure waits twice.
    const started = performance.now();
    const elements = [...this.elements];
    const first = this.nextInLine % Math.max(elements.length, 1);
    let wanted = false;
    for (let k = 0; k < elements.length; k++) {
      const at = (first + k) % elements.length;
      if (k > 0 && performance.now() - started > TASK_SHARE_MS) {
        this.nextInLine = at;
        wanted = true;
        break;
      }
      if (elements[at].tick(now)) wanted = true;
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
      this.stopped = { key: 'figure.gpu-failing-text', fields: { count: losses, reason: String(reason) } };
      for (const element of this.elements) element.fail({ key: 'figure.gpu-failing' }, this.stopped, { retry: true });
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
      this.stopped = { key: 'figure.gpu-gone-text', fields: { reason: String(reason) } };
      for (const element of this.elements) element.fail({ key: 'figure.gpu-gone' }, this.stopped, { retry: true });
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
whenWebgpuLoaded(() => hub.acquire().catch(() => { /* reported when a figure asks */ }));

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

