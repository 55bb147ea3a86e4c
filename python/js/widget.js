// The notebook widget's front end (an anywidget module): a <metaballs-view> in the output, its settings
// kept equal to the model's traits both ways, and its statistics sent back. It follows the anywidget
// front-end contract only (a model with get, set, on, off and save_changes; send where the host has a
// kernel), so it runs in JupyterLab, Notebook 7, VS Code, Colab, marimo and MyST's static pages.
//
// The module is bundled with the element (python/build.sh, www/dist.sh). Hosts import it from a blob: URL,
// where no file sits beside it, or copy it under a name of their own (MyST), so the WebAssembly comes from
// the model's `wasm_url` when given (a folder laid out as dist/: pkg/ and pkg-webgl/), else from the kernel
// when the host has one (asked for once per page), else from beside the module's URL.
//
// Hosts differ in what their model does: MyST's static pages throw from `off`, `save_changes` and `send`.
// Those calls are made through `quietly`, so a host without them still gets a working figure.

import '../../www/metaballs-view.js';
import { quietly } from './quietly.js';
import { followLanguage } from './language.js';
import { canonical, nameOfKind, propertyName, rowOf, TABLE } from '../../www/lib/core/table.js';
import { spheresText } from '../../www/lib/features/scene-files.js';

// The setting that holds spheres placed by hand, as text.
const SPHERE_LIST = nameOfKind('spheres');

// The trait of an attribute in Python (`max-pixel-ratio` → `max_pixel_ratio`).
const traitName = (name) => rowOf(name)?.python ?? name.replace(/-/g, '_');
// Where each build's WebAssembly sits in a folder laid out as dist/ (and in the wheel's static/ folder).
const WASM_FILES = { webgpu: 'pkg/metaballs_bg.wasm', webgl2: 'pkg-webgl/metaballs_bg.wasm', levels: 'pkg-levels/metaballs_levels_bg.wasm' };
// How often the statistics (triangles, frame rate) are sent back, in ms.
const STATS_EVERY_MS = 500;

// Asks the kernel for a build's WebAssembly; the answer carries it as a binary buffer.
function fromKernel(model, build) {
  return new Promise((resolve, reject) => {
    const answer = (message, buffers) => {
      if (message?.type !== 'wasm' || message.build !== build) return;
      quietly(() => model.off('msg:custom', answer));
      // A view into the message's buffer: copied into a buffer of its own, which WebAssembly accepts.
      const view = buffers[0];
      resolve(new Uint8Array(view.buffer, view.byteOffset, view.byteLength).slice());
    };
    model.on('msg:custom', answer);
    if (!quietly(() => model.send({ type: 'wasm', build }))) reject(new Error('the host has no kernel'));
  });
}

// Where the page's WebAssembly comes from, said once per page before the first figure connects.
function tellWasmSources(model) {
  const View = customElements.get('metaballs-view');
  if (!View || globalThis.metaballsWidgetWasm) return;
  globalThis.metaballsWidgetWasm = true;
  const folder = model.get('wasm_url');
  // A folder laid out as dist/ also holds the element's module: the share box names it there.
  if (folder) View.moduleUrl = new URL('www/metaballs-view.js', new URL(folder, document.baseURI)).href;
  const beside = (build) => fetch(new URL(WASM_FILES[build], folder ? new URL(folder, document.baseURI) : import.meta.url));
  const source = (build) => () => {
    if (folder || typeof model.send !== 'function' || import.meta.url.startsWith('http')) return beside(build);
    return fromKernel(model, build).catch(() => beside(build));
  };
  // The critical points' module is asked for a few seconds after the figure starts, not when Python
  // first asks for them: a cell awaiting `w.critical_points()` then waits on nothing but the figure.
  const levels = source('levels');
  let pending = null;
  const levelsBytes = () => {
    pending ??= Promise.resolve(levels()).catch((error) => {
      pending = null;
      throw error;
    });
    return pending;
  };
  setTimeout(() => levelsBytes().catch(() => {}), 3000);
  View.wasmSources = { webgpu: source('webgpu'), webgl2: source('webgl2'), levels: levelsBytes };
}

// What Python may ask the figure (`Metaballs.save_scene()` and the rest), by the element's method names.
const CALLS = new Set(['saveScene', 'loadScene', 'exportMesh', 'picture', 'nextFrame', 'criticalPoints', 'record']);

// Runs a method Python asked for and sends the answer: a value, bytes as a binary buffer, or the error.
async function answer(model, figure, { id, method, args = [] }) {
  try {
    if (!CALLS.has(method)) throw new Error(`the figure has no method ${method}`);
    let value = await figure[method](...args);
    if (value instanceof Blob) value = new Uint8Array(await value.arrayBuffer());
    if (value instanceof Uint8Array) {
      const whole = value.byteOffset === 0 && value.byteLength === value.buffer.byteLength;
      model.send({ type: 'answer', id, bytes: true }, undefined, [whole ? value.buffer : value.slice().buffer]);
    } else {
      model.send({ type: 'answer', id, value: value ?? null });
    }
  } catch (error) {
    model.send({ type: 'answer', id, error: error?.message ?? String(error) });
  }
}

// What Python asks of a model goes to the newest figure showing it. A notebook run from the top sends
// the first questions before the model's figure is drawn: they wait for it.
const CALLS_OF = new WeakMap();
function callsOf(model) {
  let calls = CALLS_OF.get(model);
  if (!calls) {
    const asked = (message) => {
      if (message?.type !== 'call') return;
      const figure = calls.figures.at(-1);
      if (figure) answer(model, figure, message);
      else calls.waiting.push(message);
    };
    calls = { figures: [], waiting: [], asked };
    CALLS_OF.set(model, calls);
    model.on('msg:custom', asked);
  }
  return calls;
}

// Once per model, before any of its figures: from then on, questions from Python are kept. The returned
// cleanup (the model is closed) stops listening.
function initialize({ model }) {
  const { asked } = callsOf(model);
  return () => {
    quietly(() => model.off('msg:custom', asked));
    CALLS_OF.delete(model);
  };
}

function render({ model, el }) {
  tellWasmSources(model);
  const figure = document.createElement('metaballs-view');
  figure.style.display = 'block';
  figure.style.aspectRatio = '16 / 9';
  for (const { name } of TABLE) {
    const value = model.get(traitName(name));
    // A list of spheres the model holds was reported by a figure: shown again, this one keeps its
    // seeded layout (a list Python sets later places them by hand).
    if (name === SPHERE_LIST && Array.isArray(value)) continue;
    if (value !== undefined && value !== null && value !== '') write(figure, name, value);
  }
  const stopLanguage = followLanguage(model, figure);
  el.replaceChildren(figure);

  // Python → figure: a changed trait becomes the attribute. A value the figure refuses (it says why in
  // the figure; it reads attributes once its WebAssembly is there) goes back to the one it keeps, so that
  // Python reads what is drawn.
  // The spheres go to Python as the list the figure gives (`sphereList`); a list set by Python places
  // them by hand, while one the figure reports does not.
  let reporting = false;
  const listeners = TABLE.map(({ name }) => {
    const event = `change:${traitName(name)}`;
    const listener = () => {
      const value = model.get(traitName(name));
      if (name === SPHERE_LIST && (reporting || (Array.isArray(value) && !value.length))) return;
      write(figure, name, value);
    };
    model.on(event, listener);
    return [event, listener];
  });
  const reportSpheres = () => {
    reporting = true;
    try {
      model.set(traitName(SPHERE_LIST), figure.sphereList);
    } finally {
      reporting = false;
    }
  };

  // Figure → Python: every setting changed inside it (controls, gestures), and the spheres.
  const changed = (event) => {
    const name = TABLE.find((p) => propertyName(p.name) === event.detail.property)?.name;
    if (!name || model.get(traitName(name)) === event.detail.value) return;
    if (name !== SPHERE_LIST) model.set(traitName(name), event.detail.value);
    if (['spheres', 'seed', SPHERE_LIST].includes(name)) reportSpheres();
    quietly(() => model.save_changes());
  };
  figure.addEventListener('metaballs-change', changed);
  const refused = (event) => {
    const name = event.detail?.attribute && canonical(event.detail.attribute);
    const kept = name && rowOf(name) ? figure[propertyName(name)] : undefined;
    if (kept === undefined || String(model.get(traitName(name))) === String(kept)) return;
    model.set(traitName(name), kept);
    quietly(() => model.save_changes());
  };
  figure.addEventListener('metaballs-error', refused);

  const calls = callsOf(model);
  calls.figures.push(figure);
  for (const message of calls.waiting.splice(0)) answer(model, figure, message);

  const timer = setInterval(() => {
    const stats = figure.stats;
    if (!stats) return;
    const sent = { triangles: stats.triangles ?? 0, fps: Math.round((stats.fps ?? 0) * 10) / 10, adapter: stats.adapter ?? '' };
    if (Object.entries(sent).every(([k, v]) => model.get(k) === v)) return;
    for (const [k, v] of Object.entries(sent)) model.set(k, v);
    if (!(model.get(traitName(SPHERE_LIST))?.length)) reportSpheres();
    quietly(() => model.save_changes());
  }, STATS_EVERY_MS);

  // Removed with its output (a cell run again, the widget closed): the figure lets go of its renderer.
  return () => {
    calls.figures.splice(calls.figures.indexOf(figure), 1);
    clearInterval(timer);
    stopLanguage();
    for (const [event, listener] of listeners) quietly(() => model.off(event, listener));
    figure.removeEventListener('metaballs-change', changed);
    figure.removeEventListener('metaballs-error', refused);
    figure.remove();
  };
}

// Writes a trait's value as its attribute (`true`/`false` for switches, which the table accepts; a
// list of spheres as their text).
function write(figure, name, value) {
  figure.setAttribute(name, Array.isArray(value) ? spheresText(value) : String(value));
}

export default { initialize, render };
