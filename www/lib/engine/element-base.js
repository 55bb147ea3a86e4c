// What every <metaballs-view> on a page shares, as static members of the element's base class: the one
// GPU device and what it holds, where the WebAssembly comes from, and the attributes the element
// watches (every parameter, under its name and its old spellings). Where the DOM is missing (a
// server-side build), the class still loads and is never defined.

import { setLevelsSource } from './levels.js';
import { SPELLINGS } from '../core/table.js';
import { hub } from './hub.js';
import { setWasmSources, wasmBytes, wasmHeapBytes } from './wasm.js';
import { frameBudget, releaseDelay, setFrameBudget, setReleaseDelay } from './page-watch.js';
import { meshingOffThread } from './meshers.js';

const Base = globalThis.HTMLElement ?? class {};

export class FigureBase extends Base {
  /** Every parameter's name and the old spellings still accepted. */
  static get observedAttributes() {
    return SPELLINGS;
  }

  /** GPU devices alive on this page (all elements share one). */
  static get devices() { return hub.devices; }
  /** GPU devices created on this page so far (more than one only after a device was lost). */
  static get devicesCreated() { return hub.devicesCreated; }
  /** Renderers alive on the shared device. */
  static get liveRenderers() { return hub.gpu?.live_renderers() ?? 0; }
  /** Bytes of WebAssembly memory the figures share (it grows and never shrinks). */
  static get wasmBytes() { return wasmBytes(); }
  /** Bytes the figures hold in that memory (allocated and not freed). */
  static get wasmHeapBytes() { return wasmHeapBytes(); }
  /** True once the figures' CPU meshes are made by the page's mesher worker, off the page's thread. */
  static get meshingOffThread() { return meshingOffThread(); }
  /** Pipeline sets compiled on the shared device (not one per element). */
  static get pipelineSets() { return hub.gpu?.pipeline_sets_built() ?? 0; }
  /**
   * Where the WebAssembly comes from when not from beside this module (set before the first figure
   * connects): `{ webgpu, webgl2, levels }`, functions returning the wasm's bytes or Response, or
   * promises of them (`levels`: the critical points' module).
   */
  static set wasmSources(sources) {
    setWasmSources(sources);
    if (sources.levels) setLevelsSource(sources.levels);
  }
  /**
   * The time between the page's frames the figures aim for, in ms (30): a figure whose frames take
   * longer lowers its render scale, down to its `min-render-scale`, and then, with level of detail,
   * draws larger cells, up to its `max-lod-pixels`.
   */
  static get frameBudget() { return frameBudget(); }
  static set frameBudget(ms) { setFrameBudget(ms); }
  /** How long a figure stays off screen before it lets go of its GPU memory, in ms (30 000). */
  static get releaseAfter() { return releaseDelay(); }
  static set releaseAfter(ms) { setReleaseDelay(ms); }
  /** Destroys the shared device, as a driver reset would (for testing recovery). */
  static destroyDevice() { hub.gpu?.destroy(); hub.requestFrame(); }
}
