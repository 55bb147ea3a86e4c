// A figure's renderer from start to end: made when the figure first comes near the viewport (on the
// page's shared WebGPU device, or a WebGL2 device of its own), fed the changed settings before each
// frame, drawn only while on screen, sized with its canvas, let go of when the GPU is lost and made
// again from the figure's own state. Each frame is drawn here; what comes before and after it
// (background, sync, statistics, print pictures, overlays) is the features' (see core/context.js).

import { nameOfKind, RENDERER } from '../core/table.js';
import { ONE_FRAME, PICTURE_FRAMES, SETTLE_FRAMES } from '../core/redraw.js';
import { hub, WEBGL_WAIT } from '../engine/hub.js';
import { wasmModule, within } from '../engine/wasm.js';
import { releaseDelay } from '../engine/page-watch.js';
import { applySetting } from './renderer-settings.js';
import { ContextWatch } from './context-watch.js';
import { inEnglish } from '../engine/asset-errors.js';
import { messageBox } from './dom.js';
import { MeshElsewhere } from './mesh-elsewhere.js';
import { makeView } from './start.js';

// The setting that holds spheres placed by hand (the scene's feature places them).
const SPHERES = nameOfKind('spheres');

export class FigureFrames {
  #ctx;
  #loaded;
  #view = null;
  // The device this figure draws with: the hub's shared WebGPU one, or a WebGL2 one of its own.
  #gpu = null;
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
  // Animation frames this figure was given while it animated or had a frame to draw, whether it drew
  // or waited for its mesh: the page's pace, which the render scale follows.
  #animationFrames = 0;
  #held = false;
  // One frame is drawn off screen, for print, when the page is idle.
  #printOnce = false;
  // Callers waiting for the next frame (`nextFrame()`): it is drawn even off screen or when still.
  #frameWaiters = [];
  // Meshes made by the page's mesher worker.
  #elsewhere;
  // The canvas's WebGL2 context, lost and given back.
  #context;
  // The canvas's size, with the render scale that follows the frame times (a FigureSize).
  #size;
  #restTimer = 0;
  #message;

  /**
   * `ctx`: the figure's context; `size`: its FigureSize; `loaded()` resolves once the element has
   * read its attributes.
   */
  constructor(ctx, size, loaded) {
    this.#ctx = ctx;
    this.#loaded = loaded;
    this.#size = size;
    this.#message = messageBox(ctx.root, () => ctx.words);
    this.#elsewhere = new MeshElsewhere(ctx.element, () => hub.requestFrame());
    this.#context = new ContextWatch(ctx.canvas, {
      lost: (reason) => this.suspend(reason, { key: 'figure.context-lost' }),
      restored: () => this.resume(),
      stop: (count) => this.fail({ key: 'figure.context-failing' },
        { key: 'figure.context-failing-text', fields: { count } }, { retry: true }),
    });
  }

  /** The wasm view, once started. */
  get view() { return this.#view; }
  /** The device drawn with, once started. */
  get gpu() { return this.#gpu; }
  /** True on a software adapter (or a fallback one). */
  get software() { return this.#software; }
  get failed() { return this.#failed; }
  get framesDrawn() { return this.#framesDrawn; }
  get animationFrames() { return this.#animationFrames; }
  /** The spheres of the frame on screen (the scene may be a step ahead while its next mesh is made). */
  shownSpheres() { return this.#view ? this.#elsewhere.shownSpheres(this.#view) : null; }
  /** Spheres kept on the CPU while no renderer holds them (after a loss, or before the start). */
  get savedSpheres() { return this.#savedSpheres; }
  set savedSpheres(packed) { this.#savedSpheres = packed; }

  /** Asks for at least `frames` more frames even while paused (0: the next animation frame only). */
  redraw(frames) {
    this.#dirty = Math.max(this.#dirty, frames);
    hub.requestFrame();
  }

  /** Draws one frame of animation (1/60 s) at the next tick. */
  stepOnce() {
    this.#stepRequested = true;
    hub.requestFrame();
  }

  /** The figure came near the viewport: start its renderer. */
  approach() {
    this.#near = true;
    this.start();
  }

  /**
   * Draws one frame of a figure not yet near the viewport, for its picture in print, then lets go of
   * its renderer again (it starts for good when the figure comes near).
   */
  drawForPrint() {
    if (this.#failed || this.#onScreen) return;
    this.#printOnce = true;
    this.start(true);
    hub.requestFrame();
  }

  /**
   * The figure entered or left the screen. Off screen for a while, it lets go of its renderer's GPU
   * memory and keeps its scene on the CPU; back on screen, it starts again from it.
   */
  setOnScreen(onScreen) {
    this.#onScreen = onScreen;
    this.#last = 0;
    clearTimeout(this.#restTimer);
    if (onScreen) {
      this.start();
      hub.requestFrame();
    } else {
      this.#restTimer = setTimeout(() => this.#rest(), releaseDelay());
    }
  }

  #rest() {
    if (this.#onScreen || !this.#view || this.#held || this.#frameWaiters.length) return;
    // A frame for print is on its way (its mesh queued behind the figures on screen): it is let go
    // of once that frame is drawn, not before.
    if (this.#printOnce) {
      this.#restTimer = setTimeout(() => this.#rest(), releaseDelay());
      return;
    }
    try {
      this.#savedSpheres = this.#view.spheres();
    } catch { /* keep what was saved before */ }
    this.release();
  }

  /** The figure left the page: free the renderer and forget where it was. */
  detach() {
    clearTimeout(this.#restTimer);
    this.release();
    this.#near = false;
    this.#onScreen = false;
  }

  start(forPrint = false) {
    if (this.#view || this.#starting || this.#failed || this.#context.lost || !(this.#near || forPrint)) return;
    if (!this.#ctx.element.isConnected) return;
    // The panel follows what the device allows (its largest grid, compute shaders): a figure that
    // starts builds it just after its first frame, one that cannot start as soon as it knows.
    this.#starting = this.#create().then((started) => {
      if (!started && this.#ctx.element.isConnected && wasmModule()) this.#ctx.each('deviceKnown');
    }).finally(() => { this.#starting = null; });
  }

  /** True while a renderer is being made (the panel is built when it is done). */
  get starting() { return this.#starting !== null; }

  async #create() {
    const ctx = this.#ctx;
    let gpu;
    try {
      await this.#loaded();
      gpu = await hub.deviceFor(ctx.element, ctx.canvas);
      if (gpu) await hub.startTurn();
    } catch (error) {
      this.fail(error.said?.title ?? error.title, error.said?.text ?? error.message, { retry: Boolean(hub.stopped) });
      return false;
    }
    if (gpu === null) {
      this.#failed = true;
      this.#message.show({ key: 'figure.paused' }, WEBGL_WAIT);
      return false;
    }
    if (!ctx.element.isConnected || this.#view) {
      hub.giveBack(ctx.element, gpu);
      return false;
    }
    this.#gpu = gpu;
    this.#software = Boolean(hub.adapter?.software || gpu.is_fallback());
    try {
      this.#view = makeView(ctx, gpu, this.#software);
    } catch (error) {
      this.fail({ key: 'figure.could-not-start' }, error);
      return false;
    }
    ctx.each('started', this.#view);
    this.apply();
    if (this.#savedSpheres) {
      try {
        this.#view.set_spheres(this.#savedSpheres);
      } catch (error) {
        console.warn(`<metaballs-view> could not restore the spheres: ${error.message}`);
      }
      this.#savedSpheres = null;
    }
    ctx.each('restored', this.#view);
    this.#message.hide();
    this.#dirty = SETTLE_FRAMES;
    this.#last = 0;
    // Started near the screen but not on it: it lets go again unless it comes on screen.
    if (!this.#onScreen) this.setOnScreen(false);
    hub.requestFrame();
    requestAnimationFrame(() => setTimeout(() => ctx.element.isConnected && ctx.each('deviceKnown')));
    return true;
  }

  // Frees the renderer's GPU memory and leaves the canvas unconfigured (a WebGL2 figure gives its
  // device back, so a waiting figure can start).
  release() {
    this.#elsewhere.forget();
    if (this.#view) {
      this.#view.free();
      this.#view = null;
      try {
        this.#ctx.canvas.getContext('webgpu')?.unconfigure();
      } catch { /* the context is gone with the device, or the canvas draws with WebGL2 */ }
    }
    hub.giveBack(this.#ctx.element, this.#gpu);
    this.#gpu = null;
  }

  /** The device is lost: keep the scene on the CPU and let go of the GPU (`said`: what the figure says). */
  suspend(reason, said = { key: 'figure.gpu-lost', fields: { reason } }) {
    if (this.#view) {
      try {
        this.#savedSpheres = this.#view.spheres();
      } catch { /* keep what was saved before */ }
    }
    this.release();
    if (this.#near) this.#ctx.notice(this.#ctx.t(said.key, said.fields), 4000);
  }

  /** A new device is ready (or a retry was asked for): start again with the current state. */
  resume() {
    // A figure that had stopped starts a new run of losses.
    if (this.#failed) this.#context.clear();
    this.#failed = false;
    this.#message.hide();
    // One off screen starts when it comes back.
    if (this.#onScreen) this.start();
  }

  /**
   * Shows a message in the figure's box and stops drawing it: `title` and `text` are sayings
   * (engine/asset-errors.js) or text as given. The page's code is told in English.
   */
  fail(title, text, { retry = false } = {}) {
    this.#failed = true;
    this.release();
    this.#message.show(title, text, retry);
    this.#ctx.emit('metaballs-error', { message: `${inEnglish(title)}: ${inEnglish(text)}` });
  }

  /** Words the figure's message again, in `words` (its language changed). */
  reword(words) { this.#message.reword(words); }

  // Pushes the changed values into the renderer. A value it refuses (a resolution beyond the device)
  // goes back to the last one that worked, with a notice.
  apply() {
    const view = this.#view;
    if (!view) return;
    const ctx = this.#ctx;
    const { settings } = ctx;
    const s = settings.state;
    for (const name of settings.changed) {
      if (name === SPHERES) {
        settings.applied[name] = s[name];
        ctx.each('spheresGiven', s[name]);
        continue;
      }
      if (!RENDERER.has(name)) continue;
      try {
        within(ctx.element, () => applySetting(view, name, s));
        settings.applied[name] = s[name];
      } catch (error) {
        ctx.notice(ctx.t('notice.setting-refused', { name, value: String(s[name]), message: ctx.words.refusal(error) }));
        ctx.revert(name);
      }
    }
    if (settings.changed.size) this.#dirty = Math.max(this.#dirty, SETTLE_FRAMES);
    settings.changed.clear();
  }

  /**
   * One animation frame of the page: draws if the figure is on screen and has something to show.
   * Returns whether it wants the next frame too.
   */
  tick(now) {
    const view = this.#view;
    const ctx = this.#ctx;
    const asked = this.#frameWaiters.length > 0;
    const drawing = this.#onScreen || this.#printOnce || asked;
    if (!view || this.#failed || this.#held || !drawing || document.visibilityState === 'hidden') {
      return false;
    }
    // On screen but not shown (a slide of a deck that is not the current one, `visibility: hidden`):
    // nothing is drawn, and the figure keeps watching for its turn.
    if (!this.#printOnce && !asked && !ctx.element.checkVisibility({ visibilityProperty: true, opacityProperty: true })) {
      return true;
    }
    const state = ctx.state;
    let animating = false;
    try {
      this.apply();
      // The page's colours, a sync leader's spheres: what changes the picture before the frame.
      ctx.each('beforeFrame', now, view);
      const forPrint = this.#printOnce;
      if (forPrint) this.#dirty = Math.max(this.#dirty, ONE_FRAME);
      // A figure that pauses on an event steps at most a 60 Hz frame at a time, however slow the
      // frames come (each waits on a search, or on the mesher worker), so that the pause lands within
      // one such step of it.
      const longest = state['pause-on'] !== 'none' ? 1 / 60 : 0.1;
      const elapsed = this.#last ? Math.min(Math.max(now - this.#last, 0) / 1000, longest) : 0;
      this.#last = now;
      // A sphere being dragged, a shape check that pause-on waits for, or a sync leader holds the
      // animation still.
      animating = !state.paused && state.speed > 0 && !ctx.some('holds');
      // A mesh on its way from the worker is drawn when it is back, whatever else changed.
      if (animating || this.#dirty > 0 || this.#stepRequested || this.#elsewhere.pending || view.needs_redraw()) {
        this.#animationFrames += 1;
        const dt = animating ? elapsed * state.speed : this.#stepRequested ? 1 / 60 : 0;
        const step = this.#elsewhere.step(view, dt, !animating && ctx.some('holds'), longest);
        if (step === null) return true;
        this.#printOnce = false;
        this.#stepRequested = false;
        this.#dirty = Math.max(0, this.#dirty - 1);
        // What the frame will be: a picture for print of it is asked for before it is drawn.
        const frame = { animating, settled: this.#dirty === 0, forPrint, blockedMs: 0, view };
        ctx.each('beforeDraw', now, frame);
        const started = performance.now();
        within(ctx.element, () => view.frame(step));
        frame.blockedMs = performance.now() - started;
        ctx.each('drawn', now, frame);
        for (const resolve of this.#frameWaiters.splice(0)) resolve();
        if (forPrint && !this.#onScreen && !asked) {
          // Not a frame anyone saw: only the picture counts. A figure not near the viewport lets go
          // of its renderer again.
          if (!this.#near) this.release();
          return false;
        }
        this.#framesDrawn += 1;
        ctx.each('frameDrawn', now, frame);
        // The next frame's mesh is made while this one shows, unless the animation stopped with this
        // frame (paused, or held by what the frame started: a drag, pause-on's search).
        if (!state.paused && state.speed > 0 && !ctx.some('holds')) this.#elsewhere.ahead(view, longest);
      } else {
        view.poll();
        ctx.each('idle', now, view);
      }
    } catch (error) {
      this.fail({ key: 'figure.renderer-stopped' }, error instanceof Error ? error : String(error));
      return false;
    }
    // Statistics, timings, the inspector and the editor's rings follow the frame.
    ctx.each('afterTick', now, view, { animating });
    const error = view.gpu_error();
    if (error) {
      this.fail({ key: 'figure.gpu-error' }, error);
      return false;
    }
    return true;
  }

  /** The render scale in effect: 1 while the figure is still. */
  get renderScale() { return this.#size.renderScale; }

  /** Fits the canvas to its box, pixel ratio and render scale; a new size is drawn again. */
  resize(entry) {
    const size = this.#size.fit(entry);
    if (!size || !this.#view) return;
    try {
      this.#view.resize(...size);
    } catch (error) {
      this.#ctx.notice(this.#ctx.words.refusal(error));
    }
    this.redraw(PICTURE_FRAMES);
  }

  /**
   * Resolves after a frame of the current settings has been drawn: the renderer is started and a frame
   * drawn even for a figure off screen (a notebook run from the top leaves its figures above the view)
   * or still. What is asked of the figure's mesh and pictures waits for it.
   */
  async nextFrame() {
    await this.ready();
    await new Promise((resolve) => {
      this.#frameWaiters.push(resolve);
      this.#dirty = Math.max(this.#dirty, ONE_FRAME);
      hub.requestFrame();
    });
    // Its figures (the triangle count) come back from the GPU once it has finished the frame.
    const view = this.#view;
    const frame = view?.frames_rendered() ?? 0;
    for (let tries = 0; view && view === this.#view && tries < 50; tries += 1) {
      view.poll();
      if (this.#ctx.some('statsOf', view, frame)) return;
      await view.work_done();
      await new Promise((r) => setTimeout(r, 10));
    }
  }

  /**
   * Resolves once the renderer has started (or rejects with why it could not), starting it once the
   * figure is connected: a notebook's question can come before its output is attached or in view.
   */
  async ready() {
    while (!this.#view) {
      if (this.#failed) throw new Error(this.#message.text);
      this.start(true);
      await new Promise((r) => setTimeout(r, 50));
    }
  }

  /** Runs `f(view)` while the figure's own frames are held; then it goes back to its own settings. */
  async withView(f) {
    await this.ready();
    this.#held = true;
    try {
      return await f(this.#view);
    } finally {
      this.#held = false;
      for (const name of [...RENDERER, SPHERES]) this.#ctx.settings.changed.add(name);
      this.#dirty = SETTLE_FRAMES;
      hub.requestFrame();
    }
  }
}
