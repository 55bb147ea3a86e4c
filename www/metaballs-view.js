// <metaballs-view>: merging spheres drawn with marching cubes, as an element a page embeds any number of
// times. Load it with one <script type="module" src=".../www/metaballs-view.js">; every element on the
// page shares one GPU device, starts when it first comes near the viewport, draws only while on screen,
// takes keys only while focused, and survives a lost GPU.

import {
  caseGallery, hub, loadWasm, parameterTable, parseParameter, propertyName, wasmModule, within, WEBGL_WAIT,
} from './lib/engine.js';
import { Inspector } from './lib/inspector.js';
import { wireCameraInput } from './lib/camera-input.js';
import { buildPanel, listedControls } from './lib/panel.js';
import { elementStyle, flasher, TEMPLATE } from './lib/element-dom.js';
import { Hud } from './lib/hud.js';
import { applySetting, isRendererSetting } from './lib/view-settings.js';
import { canvasPixels, pixelRatio } from './lib/canvas-size.js';
import { CostGuard } from './lib/frame-cost.js';
import { SphereEditor } from './lib/editor.js';
import { wireDrop } from './lib/scene-files.js';
import { SceneIO } from './lib/scene-io.js';

const wasmError = await loadWasm().then(() => null, (error) => error);
const TABLE = wasmError ? [] : parameterTable();
const NAMES = TABLE.map((p) => p.name);
const CONTROL_NAMES = TABLE.find((p) => p.name === 'controls')?.words ?? [];
const GALLERY = wasmError ? { classes: [], cube: { corners: [], edges: [] } } : caseGallery();
// Settings a renderer takes at creation; every other renderer setting is applied after.
const CREATION = new Set(['spheres', 'iso', 'resolution', 'seed', 'antialiasing']);

/** The default values of every parameter, typed. */
function defaults() {
  return Object.fromEntries(TABLE.map((p) => [p.name, parseParameter(p.name, p.default)]));
}

// A shared pair of observers: one starts elements as they come near the viewport, the other tells
// whether each is on screen at all.
const nearObserver = new IntersectionObserver((entries) => {
  for (const entry of entries) if (entry.isIntersecting) entry.target.approach();
}, { rootMargin: '200px' });
const visibleObserver = new IntersectionObserver((entries) => {
  for (const entry of entries) entry.target.setOnScreen(entry.isIntersecting);
});
document.addEventListener('visibilitychange', () => hub.requestFrame());

const reducedMotion = matchMedia('(prefers-reduced-motion: reduce)');

export class MetaballsView extends HTMLElement {
  static get observedAttributes() {
    return NAMES;
  }

  /** GPU devices alive on this page (all elements share one). */
  static get devices() { return hub.devices; }
  /** GPU devices created on this page so far (more than one only after a device was lost). */
  static get devicesCreated() { return hub.devicesCreated; }
  /** Renderers alive on the shared device. */
  static get liveRenderers() { return hub.gpu?.live_renderers() ?? 0; }
  /** Pipeline sets compiled on the shared device (not one per element). */
  static get pipelineSets() { return hub.gpu?.pipeline_sets_built() ?? 0; }
  /** GPU memory held by every element's buffers and targets, in bytes. */
  static get gpuBytes() {
    let bytes = 0;
    for (const element of hub.elements) bytes += element.#view?.gpu_bytes() ?? 0;
    return bytes;
  }
  /** Destroys the shared device, as a driver reset would (for testing recovery). */
  static destroyDevice() { hub.gpu?.destroy(); hub.requestFrame(); }

  #state = defaults();
  #applied = { ...this.#state };
  #changed = new Set();
  #given = new Set();
  #view = null;
  // The device this figure draws with: the hub's shared WebGPU one, or a WebGL2 one of its own.
  #gpu = null;
  // Frame time per resolution and sphere count on this adapter, and changes waiting for confirmation.
  #guard;
  #starting = null;
  #near = false;
  #onScreen = false;
  #failed = false;
  #software = false;
  #savedSpheres = null;
  #dirty = 0;
  #stepRequested = false;
  #last = 0;
  #framesDrawn = 0;
  #hud;
  #held = false;
  #reflecting = false;
  #showPanel = () => {};
  // Shows a message in one of the shadow root's boxes for a while: flash(id, text, ms).
  #flash;
  #root;
  #canvas;
  #inspector;
  #editor;
  #io;
  // What the panel's buttons and the keys do.
  #actions = {
    togglePause: () => (this.#state.paused ? this.play() : this.pause()),
    reseed: () => this.#set('seed', 1 + Math.floor(Math.random() * 1e6)),
    resetView: () => this.resetView(),
    step: () => this.step(),
    saveScene: () => this.#run(() => this.downloadScene()),
    loadScene: () => this.#root.getElementById('scene-file').click(),
    exportMesh: (format) => this.#run(() => this.downloadMesh(format)),
    picture: (scale) => this.#run(() => this.downloadPicture(scale)),
  };
  #started = false;

  constructor() {
    super();
    this.#root = this.attachShadow({ mode: 'open', delegatesFocus: true });
    this.#root.adoptedStyleSheets = [elementStyle];
    this.#root.innerHTML = TEMPLATE;
    this.#canvas = this.#root.getElementById('view');
    this.#hud = new Hud(this.#root);
    const $ = (id) => this.#root.getElementById(id);
    $('play').addEventListener('click', () => { this.play(); this.#canvas.focus(); });
    $('retry').addEventListener('click', () => hub.retry());
    this.#guard = new CostGuard(this.#root, (name, value) => this.#set(name, value));
    this.#flash = flasher(this.#root);
    this.#inspector = new Inspector(this.#root, GALLERY.cube, {
      view: () => this.#view,
      iso: () => this.#state.iso,
      onShow: (report) => {
        this.#dirty = Math.max(this.#dirty, 2);
        hub.requestFrame();
        this.dispatchEvent(new CustomEvent('metaballs-inspect', { detail: { cell: report } }));
      },
      onClass: (k) => this.#showPanel(this.#state, k),
    });
    this.#editor = new SphereEditor(this.#root, {
      view: () => this.#view,
      scale: () => this.#canvas.width / Math.max(1, this.#canvas.clientWidth),
      edited: () => this.#io.edited(),
      redraw: () => { this.#dirty = Math.max(this.#dirty, 1); hub.requestFrame(); },
      notice: (text) => this.#notice(text),
    });
    this.#io = new SceneIO({
      view: () => this.#view,
      state: () => this.#state,
      set: (name, value) => this.#set(name, value),
      adopt: (name, value) => this.#adopt(name, value),
      apply: () => this.#apply(),
      restoreLater: (packed) => { this.#savedSpheres = packed; },
      changed: () => { this.#dirty = Math.max(this.#dirty, 2); hub.requestFrame(); },
      editor: this.#editor,
      canvas: this.#canvas,
      ready: () => this.ready(),
      notice: (text, ms) => this.#notice(text, ms),
      emit: (type, detail) => this.dispatchEvent(new CustomEvent(type, { detail })),
    });
    const editing = () => this.#state.edit && this.#view !== null;
    wireCameraInput(this, this.#canvas, {
      get: () => ({ yaw: this.#state.yaw, pitch: this.#state.pitch, distance: this.#state.distance }),
      set: (camera) => {
        for (const [name, value] of Object.entries(camera)) this.#set(name, Number(value.toFixed(3)));
      },
    }, {
      ...this.#actions,
      hint: (text) => this.#flash('wheel-hint', text, 1500),
      pick: (x, y, e) => (editing() ? this.#editor.click(x, y, e.shiftKey)
        : this.#inspector.pick(x * (this.#canvas.width / Math.max(1, this.#canvas.clientWidth)),
          y * (this.#canvas.height / Math.max(1, this.#canvas.clientHeight)))),
      deselect: () => this.deselect(),
      grab: (x, y) => (editing() ? this.#editor.grab(x, y) : null),
      hold: (x, y) => editing() && this.#editor.add(x, y),
      hover: (x, y) => editing() && this.#editor.hover(x, y),
      leave: () => this.#editor.leave(),
      wheel: (deltaY) => editing() && this.#editor.wheel(deltaY),
      remove: () => editing() && this.#editor.remove(),
      freeze: () => editing() && this.#editor.toggleFreeze(),
    });
    const file = this.#root.getElementById('scene-file');
    file.addEventListener('change', () => {
      if (file.files[0]) this.#io.loadFile(file.files[0]);
      file.value = '';
    });
    wireDrop(this, () => this.#state.edit || listedControls(this.#state.controls, CONTROL_NAMES).includes('scene'),
      (dropped) => this.#io.loadFile(dropped));
    new ResizeObserver(([entry]) => this.#resize(entry)).observe(this.#canvas);
  }

  // Properties mirror the attributes (camelCase for dashed names): reading gives the value in effect,
  // writing goes through the same checks as the attribute.
  static {
    for (const name of NAMES) {
      Object.defineProperty(this.prototype, propertyName(name), {
        get() { return this.#state[name]; },
        set(value) { this.setAttribute(name, String(value)); },
      });
    }
  }

  // ---------------------------------------------------------------- lifecycle

  connectedCallback() {
    if (wasmError) {
      this.fail('The figure could not load', `${wasmError?.message ?? wasmError}`);
      return;
    }
    if (!this.#started) {
      this.#started = true;
      if (this.#state.autoplay === 'off' || reducedMotion.matches) this.#set('paused', true);
      // Very small figures start with their statistics folded, like the panel.
      this.#root.querySelector('#hud details').open = !(this.clientWidth > 0 && this.clientWidth < 300);
    }
    this.#buildPanel();
    this.#root.getElementById('hud').hidden = this.#state.hud !== 'on';
    hub.register(this);
    nearObserver.observe(this);
    visibleObserver.observe(this);
  }

  disconnectedCallback() {
    nearObserver.unobserve(this);
    visibleObserver.unobserve(this);
    hub.unregister(this);
    this.#release();
    this.#near = false;
    this.#onScreen = false;
  }

  attributeChangedCallback(name, _old, text) {
    if (this.#reflecting || wasmError) return;
    if (text === null) {
      this.#given.delete(name);
      this.#accept(name, parseParameter(name, TABLE.find((p) => p.name === name).default));
      return;
    }
    let value;
    try {
      value = parseParameter(name, text);
    } catch (error) {
      const message = `${name}="${text}": ${error.message}; keeping ${this.#format(name)}`;
      console.warn(`<metaballs-view> ${message}`);
      this.#notice(message);
      return;
    }
    this.#given.add(name);
    this.#accept(name, value);
  }

  // Takes a valid value: records it, applies it to the renderer on the next frame, tells listeners.
  #accept(name, value) {
    if (this.#state[name] === value) return;
    if (this.#guard.tooSlow(this.#state, { ...this.#state, [name]: value })) {
      this.#guard.ask(this.#state, { [name]: value });
      this.#reflect(name);
      this.#showPanel(this.#state);
      return;
    }
    this.#state[name] = value;
    this.#changed.add(name);
    if (name === 'controls') this.#buildPanel();
    if (name === 'hud') this.#root.getElementById('hud').hidden = value !== 'on';
    if (name === 'max-pixel-ratio') this.#resize();
    if (name === 'paused') this.#root.getElementById('play').hidden = !this.#showsPlayButton();
    if (name === 'edit') {
      this.#editor.reset();
      this.#inspector.deselect();
      this.#canvas.classList.toggle('editing', value);
    }
    this.#showPanel(this.#state);
    this.dispatchEvent(new CustomEvent('metaballs-change', { detail: { property: propertyName(name), value } }));
    hub.requestFrame();
  }

  // A change from inside (gestures, panel, methods): reflected to the attribute, then accepted.
  #set(name, value) {
    // A new count or layout replaces hand-placed spheres with the seeded ones.
    if ((name === 'spheres' || name === 'seed') && this.#state.balls) this.#adopt('balls', '');
    this.#reflect(name, value);
    this.#given.add(name);
    this.#accept(name, value);
  }

  #format(name) {
    const value = this.#state[name];
    return typeof value === 'string' ? `"${value}"` : String(value);
  }

  #showsPlayButton() {
    return this.#state.paused && !listedControls(this.#state.controls, CONTROL_NAMES).includes('paused');
  }

  #buildPanel() {
    const names = listedControls(this.#state.controls, CONTROL_NAMES);
    const maxResolution = hub.gpu?.max_resolution() ?? 512;
    this.#showPanel = buildPanel(this.#root.getElementById('panel'), names, TABLE, this.#state,
      (name, value) => this.#set(name, value), this.#actions, {
        maxResolution: this.#software ? Math.min(256, maxResolution) : maxResolution,
        withoutCompute: Boolean(this.#gpu && !this.#gpu.has_compute()),
        small: this.clientWidth > 0 && this.clientWidth < 560,
        gallery: GALLERY,
      });
    this.#root.getElementById('play').hidden = !this.#showsPlayButton();
  }

  // ---------------------------------------------------------------- starting and stopping

  /** Called when the element first comes near the viewport: starts its renderer. */
  approach() {
    this.#near = true;
    this.#start();
  }

  /** Called as the element enters or leaves the screen. */
  setOnScreen(onScreen) {
    this.#onScreen = onScreen;
    this.#last = 0;
    if (onScreen) hub.requestFrame();
  }

  #start() {
    if (this.#view || this.#starting || this.#failed || !this.#near || !this.isConnected) return;
    this.#starting = this.#create().finally(() => { this.#starting = null; });
  }

  async #create() {
    let gpu;
    try {
      gpu = await hub.deviceFor(this, this.#canvas);
    } catch (error) {
      this.fail(error.title, error.message, { retry: Boolean(hub.stopped) });
      return;
    }
    if (gpu === null) {
      this.#failed = true;
      this.#showMessage('Paused', WEBGL_WAIT);
      return;
    }
    if (!this.isConnected || this.#view) {
      hub.giveBack(this, gpu);
      return;
    }
    this.#gpu = gpu;
    const webgl = !gpu.has_compute();
    this.#software = Boolean(hub.adapter?.software || gpu.is_fallback());
    this.#hud.setAdapter(hub.adapter?.label ?? 'WebGPU');
    if (this.#software && !this.#given.has('antialiasing')) this.#state.antialiasing = false;
    this.#guard.start(this.#software || webgl);
    for (const name of this.#guard.startAffordably(this.#state, defaults())) this.#reflect(name);
    this.#sizeCanvas();
    const s = this.#state;
    const create = (resolution) => within(this, () => wasmModule().View.create(
      gpu, this.#canvas, s.spheres, s.iso, resolution, s.seed, s.antialiasing));
    try {
      this.#view = create(s.resolution);
    } catch (error) {
      // Most likely a resolution beyond this device: start at the default and say why.
      const fallback = parseParameter('resolution', TABLE.find((p) => p.name === 'resolution').default);
      this.#notice(`resolution ${s.resolution}: ${error.message}`);
      s.resolution = fallback;
      try {
        this.#view = create(fallback);
      } catch (again) {
        this.fail('The figure could not start', again.message);
        return;
      }
    }
    this.#applied = { ...s };
    this.#changed = new Set(NAMES.filter((name) => (isRendererSetting(name) && !CREATION.has(name))
      || (name === 'balls' && s.balls)));
    this.#apply();
    if (this.#savedSpheres) {
      try {
        this.#view.set_spheres(this.#savedSpheres);
      } catch (error) {
        console.warn(`<metaballs-view> could not restore the spheres: ${error.message}`);
      }
      this.#savedSpheres = null;
    }
    this.#editor.reset();
    this.#buildPanel();
    this.#hideMessage();
    this.#dirty = 3;
    this.#last = 0;
    hub.requestFrame();
  }

  // Frees the renderer's GPU memory and leaves the canvas unconfigured (a WebGL2 figure gives its
  // device back, so a waiting figure can start).
  #release() {
    if (this.#view) {
      this.#view.free();
      this.#view = null;
      try {
        this.#canvas.getContext('webgpu')?.unconfigure();
      } catch { /* the context is gone with the device, or the canvas draws with WebGL2 */ }
    }
    hub.giveBack(this, this.#gpu);
    this.#gpu = null;
  }

  /** The device is lost: keep the scene on the CPU and let go of the GPU. */
  suspend(reason) {
    if (this.#view) {
      try {
        this.#savedSpheres = this.#view.spheres();
      } catch { /* keep what was saved before */ }
    }
    this.#release();
    if (this.#near) this.#notice(`The GPU was lost (${reason}); starting again…`, 4000);
  }

  /** A new device is ready (or a retry was asked for): start again with the current state. */
  resume() {
    this.#failed = false;
    this.#hideMessage();
    this.#start();
  }

  /** Shows a message in this element's box and stops drawing it. */
  fail(title, text, { retry = false } = {}) {
    this.#failed = true;
    this.#release();
    this.#showMessage(title, text, retry);
    this.dispatchEvent(new CustomEvent('metaballs-error', { detail: { message: `${title}: ${text}` } }));
  }

  #showMessage(title, text, retry = false) {
    const $ = (id) => this.#root.getElementById(id);
    $('message-title').textContent = title;
    $('message-text').textContent = text;
    $('retry').hidden = !retry;
    $('message').hidden = false;
  }

  #hideMessage() {
    this.#root.getElementById('message').hidden = true;
  }

  // ---------------------------------------------------------------- frames

  // Pushes the changed values into the renderer. A value it refuses (a resolution beyond the device)
  // goes back to the last one that worked, with a notice.
  #apply() {
    const view = this.#view;
    if (!view) return;
    const s = this.#state;
    for (const name of this.#changed) {
      if (name === 'balls') {
        this.#applied.balls = s.balls;
        this.#io.applyBalls(s.balls);
        continue;
      }
      if (!isRendererSetting(name)) continue;
      try {
        within(this, () => applySetting(view, name, s));
        this.#applied[name] = s[name];
      } catch (error) {
        this.#notice(`${name} ${s[name]}: ${error.message}`);
        s[name] = this.#applied[name];
        this.#reflect(name);
        this.#showPanel(s);
      }
    }
    if (this.#changed.size) this.#dirty = Math.max(this.#dirty, 3);
    this.#changed.clear();
  }

  // Writes a value to its attribute without taking it in again.
  #reflect(name, value = this.#state[name]) {
    this.#reflecting = true;
    try {
      this.setAttribute(name, String(value));
    } finally {
      this.#reflecting = false;
    }
  }

  /**
   * One animation frame of the page: draws if this element is on screen and has something to show.
   * Returns whether it wants the next frame too.
   */
  tick(now) {
    const view = this.#view;
    if (!view || this.#failed || this.#held || !this.#onScreen || document.visibilityState === 'hidden') {
      return false;
    }
    try {
      this.#apply();
      const elapsed = this.#last ? Math.min(Math.max(now - this.#last, 0) / 1000, 0.1) : 0;
      this.#last = now;
      // A sphere being dragged holds the animation still.
      const animating = !this.#state.paused && this.#state.speed > 0 && !this.#editor.dragging;
      if (animating || this.#dirty > 0 || this.#stepRequested || view.needs_redraw()) {
        const dt = animating ? elapsed * this.#state.speed : this.#stepRequested ? 1 / 60 : 0;
        this.#stepRequested = false;
        const started = performance.now();
        within(this, () => view.frame(dt));
        const blocked = performance.now() - started;
        if (blocked > 100) this.#observeCost(blocked);
        this.#framesDrawn += 1;
        this.#hud.countFrame();
        this.#dirty = Math.max(0, this.#dirty - 1);
      } else {
        view.poll();
      }
    } catch (error) {
      this.fail('The renderer stopped', error?.message ?? String(error));
      return false;
    }
    const frameMs = this.#hud.update(now, view);
    if (frameMs && !this.#state.paused) this.#observeCost(frameMs);
    this.#inspector.follow(now);
    if (this.#state.edit) this.#editor.draw();
    const error = view.gpu_error();
    if (error) {
      this.fail('The GPU reported an error', error);
      return false;
    }
    return true;
  }

  // ---------------------------------------------------------------- costly settings

  #observeCost(ms) {
    this.#guard.observe(this.#applied, ms);
  }

  /** The change waiting for the person's confirmation (a slow frame), or null. */
  get pendingChange() { return this.#guard.pending ? { ...this.#guard.pending } : null; }

  // ---------------------------------------------------------------- the cell inspector

  /** Selects cell (x, y, z) for the inspector; returns its report (null outside the grid). */
  inspectCell(x, y, z) { return this.#inspector.select(x, y, z); }

  /** Lets go of the inspected cell or the selected sphere (also Esc, the × button, or a click on the background). */
  deselect() {
    if (!this.#editor.deselect()) this.#inspector.deselect();
  }

  /** What marching cubes decided in the inspected cell, as last shown; null when none is selected. */
  get inspected() { return this.#inspector.report; }

  // ---------------------------------------------------------------- hands on the scene

  // Takes a value that already holds in the renderer (the spheres after an edit): no setter runs.
  #adopt(name, value) {
    if (this.#state[name] === value) return;
    this.#state[name] = value;
    this.#applied[name] = value;
    this.#reflect(name);
    this.#showPanel(this.#state);
    this.dispatchEvent(new CustomEvent('metaballs-change', { detail: { property: propertyName(name), value } }));
  }

  // Runs an action of the panel; a failure becomes a notice.
  #run(f) {
    Promise.resolve().then(f).catch((error) => this.#notice(error?.message ?? String(error)));
  }

  /** The spheres in play: [{ center: [x, y, z], radius, velocity: [x, y, z] }]. */
  get sphereList() { return this.#io.list(this.#savedSpheres); }

  /** Where sphere `index` is drawn: { x, y, radius } in CSS pixels from the figure's top left, or null. */
  sphereOnScreen(index) { return this.#io.onScreen(index); }

  /** The selected sphere's index in edit mode, or -1. */
  get selectedSphere() { return this.#editor.selected; }

  /** The scene (spheres and every setting of the picture) as a JSON document. */
  saveScene() { return this.#io.save(); }

  /** Loads a scene document; throws with what is wrong, leaving the scene as it was. */
  loadScene(text) { this.#io.load(text); }

  downloadScene() { this.#io.downloadScene(); }

  /** The mesh of the current frame as `stl`, `obj` or `ply` bytes (one readback from the GPU). */
  exportMesh(format = 'stl') { return this.#io.exportMesh(format); }

  downloadMesh(format = 'stl') { return this.#io.downloadMesh(format); }

  /** A PNG blob of the view at the canvas size times `scale` (1 or 2). */
  picture(scale = 1) { return this.#io.picture(scale); }

  downloadPicture(scale = 1) { return this.#io.downloadPicture(scale); }

  // ---------------------------------------------------------------- size

  #ratio() {
    return pixelRatio(this.#state['max-pixel-ratio'], this.#software);
  }

  #sizeCanvas() {
    [this.#canvas.width, this.#canvas.height] = canvasPixels(this.#canvas, this.#ratio());
  }

  #resize(entry) {
    const [width, height] = canvasPixels(this.#canvas, this.#ratio(), entry);
    if (this.#canvas.width === width && this.#canvas.height === height) return;
    this.#canvas.width = width;
    this.#canvas.height = height;
    if (!this.#view) return;
    try {
      this.#view.resize(width, height);
    } catch (error) {
      this.#notice(error.message);
    }
    this.#dirty = Math.max(this.#dirty, 2);
    hub.requestFrame();
  }

  // ---------------------------------------------------------------- notices

  #notice(text, ms = 8000) {
    this.#flash('notice', text, ms);
  }

  /** Shows a short message inside the figure (pages use it for problems with their links). */
  showNotice(text, ms = 8000) {
    this.#notice(text, ms);
  }

  // ---------------------------------------------------------------- API for authors

  play() { this.#set('paused', false); }

  pause() { this.#set('paused', true); }

  /** Back to the default camera. */
  resetView() {
    const d = defaults();
    for (const name of ['yaw', 'pitch', 'distance']) this.#set(name, d[name]);
  }

  /** Draws one frame of animation (1/60 s) and stays paused. */
  step() {
    if (!this.#state.paused) this.pause();
    this.#stepRequested = true;
    hub.requestFrame();
  }

  /** Figures of the newest frames: triangles, fps, frame time (ms), adapter, overflowed. */
  get stats() { return { ...this.#hud.stats }; }

  /** Frames this element has drawn (none while off screen). */
  get framesDrawn() { return this.#framesDrawn; }

  /** Resolves once the renderer has started (or rejects with why it could not). */
  async ready() {
    while (!this.#view) {
      if (this.#failed) throw new Error(this.#root.getElementById('message-text').textContent);
      await new Promise((r) => setTimeout(r, 50));
    }
  }

  /**
   * Runs `f(view)` with the wasm view while the element's own frames are held (the benchmark uses it).
   */
  async withView(f) {
    await this.ready();
    this.#held = true;
    try {
      return await f(this.#view);
    } finally {
      this.#held = false;
      // Whatever `f` changed, the figure goes back to its own settings.
      for (const name of ['spheres', 'resolution', 'iso', 'seed', 'mesher']) this.#changed.add(name);
      this.#dirty = 3;
      hub.requestFrame();
    }
  }
}

if (!customElements.get('metaballs-view')) customElements.define('metaballs-view', MetaballsView);
