// <metaballs-view>: merging spheres drawn with marching cubes, as an element a page embeds any number of
// times. Load it with one <script type="module" src=".../www/metaballs-view.js"> (or `import
// 'metaballs-view'`); every element on the page shares one GPU device, starts when it first comes near
// the viewport, draws only while on screen, takes keys only while focused, and survives a lost GPU.
// Importing it does nothing but define the element, and only where `customElements` exists (a
// server-side build imports it safely); the wasm loads when the first figure is connected.

import { makeFigureParts } from './lib/figure-parts.js';
import { caseGallery, hub, loadWarning, loadWasm, propertyName, wasmLoaded } from './lib/engine.js';
import { FigureBase } from './lib/figure-base.js';
import { wireFigureGestures } from './lib/figure-gestures.js';
import { buildPanel, listedControls } from './lib/panel.js';
import { elementStyle, flasher, TEMPLATE } from './lib/element-dom.js';
import { Hud } from './lib/hud.js';
import { CostGuard } from './lib/frame-cost.js';
import { wireDrop } from './lib/scene-files.js';
import { sweepErrors } from './lib/error-plot.js';
import { CAMERA, joinSync, leaderOf, leaveSync, shareCamera, syncMember } from './lib/sync.js';
import {
  CONTROL_NAMES, defaultOf, defaults, FigureState, NAMES, TABLE, TEXT_NAMES,
} from './lib/figure-state.js';
import { FigureFrames } from './lib/figure-frames.js';
import { FigureLook } from './lib/figure-look.js';
import { pageWatch, unwatch } from './lib/page-watch.js';

export class MetaballsView extends FigureBase {
  /** GPU memory held by every element's buffers and targets, in bytes. */
  static get gpuBytes() {
    let bytes = 0;
    for (const element of hub.elements) bytes += element.gpuBytes;
    return bytes;
  }

  // Values in effect, held by the renderer, changed, and given (attribute reflection).
  #settings = new FigureState(this);
  #state = this.#settings.state;
  // The renderer from start to end, and its frames.
  #frames;
  // Frame time per resolution and sphere count on this adapter, and changes waiting for confirmation.
  #guard;
  #hud;
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
    errorSweep: (status) => sweepErrors(() => this.#frames.view, status),
  };
  #started = false;
  #look;
  #topology;
  // This figure in its `sync` group: camera changes from the others arrive here.
  #sync = syncMember(() => this.#state.sync, (name, value) => this.#set(name, value, false));
  // Resolves once the wasm is in and the attributes given so far are read.
  #loaded = null;

  constructor() {
    super();
    this.#root = this.attachShadow({ mode: 'open', delegatesFocus: true });
    this.#root.adoptedStyleSheets = [elementStyle()];
    this.#root.innerHTML = TEMPLATE;
    this.#canvas = this.#root.getElementById('view');
    this.#look = new FigureLook(this, this.#root, this.#canvas);
    this.#look.name(this.#state);
    this.#hud = new Hud(this.#root);
    const $ = (id) => this.#root.getElementById(id);
    $('play').addEventListener('click', () => { this.play(); this.#canvas.focus(); });
    $('retry').addEventListener('click', () => hub.retry());
    this.#guard = new CostGuard(this.#root, (name, value) => this.#set(name, value));
    this.#flash = flasher(this.#root);
    this.#frames = new FigureFrames({
      element: this,
      root: this.#root,
      canvas: this.#canvas,
      settings: this.#settings,
      guard: this.#guard,
      hud: this.#hud,
      look: this.#look,
      loaded: () => this.#load(),
      editor: () => this.#editor,
      io: () => this.#io,
      inspector: () => this.#inspector,
      notice: (text, ms) => this.#notice(text, ms),
      showPanel: () => this.#showPanel(this.#state),
      buildPanel: () => this.#buildPanel(),
      emit: (type, detail) => this.#emit(type, detail),
      topology: () => this.#topology,
      leader: () => leaderOf(this.#sync)?.frames ?? null,
    });
    this.#sync.frames = this.#frames;
    ({ topology: this.#topology, inspector: this.#inspector, editor: this.#editor, io: this.#io } = makeFigureParts({
      root: this.#root,
      canvas: this.#canvas,
      frames: this.#frames,
      hud: this.#hud,
      look: this.#look,
      state: () => this.#state,
      set: (name, value) => this.#set(name, value),
      adopt: (name, value) => this.#adopt(name, value),
      pause: () => this.pause(),
      showPanel: (k) => this.#showPanel(this.#state, k),
      notice: (text, ms) => this.#notice(text, ms),
      emit: (type, detail) => this.#emit(type, detail),
    }));
    wireFigureGestures(this, this.#canvas, {
      state: this.#state,
      set: (name, value) => this.#set(name, value),
      actions: this.#actions,
      flash: this.#flash,
      editor: this.#editor,
      inspector: this.#inspector,
      view: () => this.#frames.view,
    });
    const file = this.#root.getElementById('scene-file');
    file.addEventListener('change', () => {
      if (file.files[0]) this.#io.loadFile(file.files[0]);
      file.value = '';
    });
    wireDrop(this, () => this.#state.edit || listedControls(this.#state.controls, CONTROL_NAMES).includes('scene'),
      (dropped) => this.#io.loadFile(dropped));
    new ResizeObserver(([entry]) => this.#frames.resize(entry)).observe(this.#canvas);
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
    joinSync(this.#sync);
    const watch = pageWatch();
    this.#load().then(() => {
      if (!this.isConnected) return;
      if (!this.#started) {
        this.#started = true;
        if (this.#state.autoplay === 'off' || watch.reducedMotion.matches) this.#set('paused', true);
        if (loadWarning()) this.#notice(loadWarning());
        // Very small figures start with their statistics folded, like the panel.
        this.#root.querySelector('#hud details').open = !(this.clientWidth > 0 && this.clientWidth < 300);
        // A figure without a poster is drawn once while the page is idle, so it prints as a picture.
        if (!this.#state.poster) {
          const later = globalThis.requestIdleCallback ?? ((f) => setTimeout(f, 1000));
          later(() => this.isConnected && this.#frames.drawForPrint(), { timeout: 4000 });
        }
      }
      // A figure about to start builds its panel once it knows its device (after its first frame).
      if (!this.#frames.starting) this.#buildPanel();
      this.#root.getElementById('hud').hidden = this.#state.hud !== 'on';
    }, (error) => this.fail(error?.title ?? 'The figure could not load', `${error?.message ?? error}`));
    hub.register(this);
    watch.near.observe(this);
    watch.visible.observe(this);
  }

  disconnectedCallback() {
    leaveSync(this.#sync);
    unwatch(this);
    hub.unregister(this);
    this.#frames.detach();
  }

  // Loads the wasm (once per page) and reads the attributes given before it arrived.
  #load() {
    this.#loaded ??= loadWasm().then(() => {
      for (const name of NAMES) {
        if (this.hasAttribute(name)) this.attributeChangedCallback(name, null, this.getAttribute(name));
      }
    });
    return this.#loaded;
  }

  /** The reader's colour scheme changed: a figure with `theme="auto"` follows it. */
  schemeChanged() {
    if (this.#state.theme !== 'auto') return;
    this.#settings.changed.add('theme');
    hub.requestFrame();
  }

  #emit(type, detail) {
    this.dispatchEvent(new CustomEvent(type, { detail, bubbles: true, composed: true }));
  }

  attributeChangedCallback(name, _old, text) {
    if (this.#settings.reflecting) return;
    // Before the wasm arrives only plain text is taken; the rest is read when it loads.
    if (!wasmLoaded() && !TEXT_NAMES.has(name)) return;
    if (text === null) {
      this.#settings.given.delete(name);
      this.#accept(name, defaultOf(name));
      return;
    }
    const { value, message } = this.#settings.parse(name, text);
    if (message) {
      console.warn(`<metaballs-view> ${message}`);
      this.#notice(message);
      this.#emit('metaballs-error', { message, attribute: name });
      return;
    }
    this.#settings.given.add(name);
    this.#accept(name, value);
  }

  // Takes a valid value: records it, applies it to the renderer on the next frame, tells listeners.
  #accept(name, value) {
    if (this.#state[name] === value) return;
    if (this.#guard.tooSlow(this.#state, { ...this.#state, [name]: value })) {
      this.#guard.ask(this.#state, { [name]: value });
      this.#settings.reflect(name);
      this.#showPanel(this.#state);
      return;
    }
    this.#state[name] = value;
    this.#settings.changed.add(name);
    // Spheres kept from before the renderer was let go give way to spheres the attributes now set.
    if (name === 'balls' || name === 'spheres' || name === 'seed') this.#frames.savedSpheres = null;
    // The panel is first built when the figure starts (after the attributes are read).
    if (name === 'controls' && this.#started) this.#buildPanel();
    if (name === 'hud') this.#root.getElementById('hud').hidden = value !== 'on';
    // A still figure draws at full scale; an animating one at its render scale.
    if (['max-pixel-ratio', 'min-render-scale', 'paused', 'speed'].includes(name)) this.#frames.resize();
    if (name === 'paused') this.#root.getElementById('play').hidden = !this.#showsPlayButton();
    if (name === 'edit') {
      this.#editor.reset();
      this.#inspector.deselect();
      this.#canvas.classList.toggle('editing', value);
    }
    if (name === 'poster') this.#look.setPoster(value, this.#frames.framesDrawn > 0);
    this.#look.name(this.#state);
    this.#showPanel(this.#state);
    this.#emit('metaballs-change', { property: propertyName(name), value });
    hub.requestFrame();
  }

  // A change from inside (gestures, panel, methods): reflected to the attribute, then accepted.
  #set(name, value, share = true) {
    // A new count or layout replaces hand-placed spheres with the seeded ones.
    if ((name === 'spheres' || name === 'seed') && this.#state.balls) this.#adopt('balls', '');
    this.#settings.reflect(name, value);
    this.#settings.given.add(name);
    const before = this.#state[name];
    this.#accept(name, value);
    if (this.#state[name] !== before) this.#look.announceChange(name, this.#state[name]);
    if (share && CAMERA.includes(name)) shareCamera(this.#sync, name, this.#state[name]);
  }

  #showsPlayButton() {
    return this.#state.paused && !listedControls(this.#state.controls, CONTROL_NAMES).includes('paused');
  }

  #buildPanel() {
    const names = listedControls(this.#state.controls, CONTROL_NAMES);
    const maxResolution = hub.gpu?.max_resolution() ?? 512;
    this.#showPanel = buildPanel(this.#root.getElementById('panel'), names, TABLE, this.#state,
      (name, value) => this.#set(name, value), this.#actions, {
        maxResolution: this.#frames.software ? Math.min(256, maxResolution) : maxResolution,
        withoutCompute: Boolean(this.#frames.gpu && !this.#frames.gpu.has_compute()),
        small: this.clientWidth > 0 && this.clientWidth < 560,
        gallery: caseGallery(),
      });
    this.#root.getElementById('play').hidden = !this.#showsPlayButton();
  }

  // ---------------------------------------------------------------- the renderer and its frames

  /** Called when the element first comes near the viewport: starts its renderer. */
  approach() { this.#frames.approach(); }

  /** Called as the element enters or leaves the screen. */
  setOnScreen(onScreen) { this.#frames.setOnScreen(onScreen); }

  /** The device is lost: keep the scene on the CPU and let go of the GPU. */
  suspend(reason) { this.#frames.suspend(reason); }

  /** A new device is ready (or a retry was asked for): start again with the current state. */
  resume() { this.#frames.resume(); }

  /** Shows a message in this element's box and stops drawing it. */
  fail(title, text, options) { this.#frames.fail(title, text, options); }

  /**
   * One animation frame of the page: draws if this element is on screen and has something to show.
   * Returns whether it wants the next frame too.
   */
  tick(now) { return this.#frames.tick(now); }

  // ---------------------------------------------------------------- costly settings

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
    this.#settings.applied[name] = value;
    this.#settings.reflect(name);
    this.#look.name(this.#state);
    this.#showPanel(this.#state);
    this.#emit('metaballs-change', { property: propertyName(name), value });
  }

  // Runs an action of the panel; a failure becomes a notice.
  #run(f) {
    Promise.resolve().then(f).catch((error) => this.#notice(error?.message ?? String(error)));
  }

  /** The spheres in play: [{ center: [x, y, z], radius, velocity: [x, y, z] }]. */
  get sphereList() { return this.#io.list(this.#frames.savedSpheres); }

  /** Where sphere `index` is drawn: { x, y, radius } in CSS pixels from the figure's top left, or null. */
  sphereOnScreen(index) { return this.#io.onScreen(index); }

  /** The selected sphere's index in edit mode, or -1. */
  get selectedSphere() { return this.#editor.selected; }

  /** The scene (spheres and every setting of the picture) as a JSON document. */
  saveScene() { return this.#io.save(); }

  /** Loads a scene document; throws with what is wrong, leaving the scene as it was. */
  loadScene(text) { this.#io.load(text); }

  downloadScene() { this.#io.downloadScene(); }

  /** The mesh of the current settings as `stl`, `obj` or `ply` bytes (one readback from the GPU). */
  exportMesh(format = 'stl') { return this.#io.exportMesh(format); }

  downloadMesh(format = 'stl') { return this.#io.downloadMesh(format); }

  /** A PNG blob of the view at the canvas size times `scale` (1 or 2). */
  picture(scale = 1) { return this.#io.picture(scale); }

  downloadPicture(scale = 1) { return this.#io.downloadPicture(scale); }

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
    this.#frames.stepOnce();
  }

  /** Figures of the newest frames: triangles, fps, frame time (ms), adapter, overflowed. */
  get stats() { return { ...this.#hud.stats }; }

  /** GPU memory this figure's renderer holds, in bytes (0 while it has none, as when long off screen). */
  get gpuBytes() { return this.#frames.view?.gpu_bytes() ?? 0; }

  /** The fraction of its pixel ratio the figure draws at now (lower while frames are slow). */
  get renderScale() { return this.#frames.renderScale; }

  /** Frames this element has drawn (none while off screen). */
  get framesDrawn() { return this.#frames.framesDrawn; }

  /** Resolves once the renderer has started (or rejects with why it could not). */
  ready() { return this.#frames.ready(); }

  /**
   * Resolves with the statistics of a frame drawn after the call (of the settings in effect then),
   * drawing one even when the figure is off screen or paused.
   */
  async nextFrame() {
    await this.#frames.nextFrame();
    return this.stats;
  }

  /** Resolves once the figure has a picture for print (its poster, or one of a drawn frame). */
  printable() { return this.#look.printable(); }
  /** The surface's shape now: resolves to { components, genus, closed, manifold }. */
  async topology() {
    await this.ready();
    return this.#topology.check();
  }

  /**
   * Runs `f(view)` with the wasm view while the element's own frames are held (the benchmark uses it).
   */
  withView(f) { return this.#frames.withView(f); }
}

// Safe to import twice, even from two copies of the package: the first definition stays.
if (globalThis.customElements && !customElements.get('metaballs-view')) {
  customElements.define('metaballs-view', MetaballsView);
}
