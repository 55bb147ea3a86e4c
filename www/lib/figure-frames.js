// A figure's renderer from start to end: made when the figure first comes near the viewport (on the
// page's shared WebGPU device, or a WebGL2 device of its own), fed the changed settings before each
// frame, drawn only while on screen, sized with its canvas, let go of when the GPU is lost and made
// again from the figure's own state.

import { hub, wasmModule, within, WEBGL_WAIT } from './engine.js';
import { applySetting, isRendererSetting } from './view-settings.js';
import { picturesTaken } from './figure-look.js';
import { ContextWatch } from './context-watch.js';
import { messageBox } from './element-dom.js';
import { FigureSize } from './figure-size.js';
import { makeView } from './view-start.js';
import { releaseDelay } from './page-watch.js';

export class FigureFrames {
  #f;
  #view = null;
  // The device this figure draws with: the hub's shared WebGPU one, or a WebGL2 one of its own.
  #gpu = null;
  #starting = null;
  #near = false;
  #onScreen = false;
  #failed = false;
  #software = false;
  // The sync leader's frame whose spheres this figure last took.
  #ledFrame = -1;
  #savedSpheres = null;
  #dirty = 0;
  #stepRequested = false;
  #last = 0;
  #framesDrawn = 0;
  #held = false;
  // One frame is drawn off screen, for print, when the page is idle.
  #printOnce = false;
  // Callers waiting for the next frame (`nextFrame()`): it is drawn even off screen or when still.
  #frameWaiters = [];
  #picturesSeen = 0;
  // The canvas's WebGL2 context, lost and given back.
  #context;
  // The canvas's size, with the render scale that follows the frame times.
  #size;
  #restTimer = 0;
  #message;

  /**
   * `figure`: { element, root, canvas, settings (a FigureState), guard, hud, look (a FigureLook),
   * editor(), io(), inspector(), notice(text, ms), showPanel(), buildPanel(), emit(type, detail),
   * leader() (the sync group's leading FigureFrames, or null), loaded() (resolves once the element has read its attributes) }.
   */
  constructor(figure) {
    this.#f = figure;
    this.#message = messageBox(figure.root);
    this.#size = new FigureSize(figure.canvas, () => figure.settings.state, figure.hud);
    this.#context = new ContextWatch(figure.canvas, {
      lost: (reason) => this.suspend(reason, 'The drawing context was lost; starting again…'),
      restored: () => this.resume(),
      stop: (count) => this.fail('The drawing context keeps failing',
        `The WebGL2 context was lost ${count} times within a minute, so the figure stopped trying.`, { retry: true }),
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
  /** Spheres kept on the CPU while no renderer holds them (after a loss, or before the start). */
  get savedSpheres() { return this.#savedSpheres; }
  set savedSpheres(packed) { this.#savedSpheres = packed; }

  /** Asks for at least `frames` more frames even while paused. */
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
    if (!this.#f.element.isConnected) return;
    // The panel follows what the device allows (its largest grid, compute shaders): a figure that
    // starts builds it just after its first frame, one that cannot start as soon as it knows.
    this.#starting = this.#create().then((started) => {
      if (!started && this.#f.element.isConnected && wasmModule()) this.#f.buildPanel();
    }).finally(() => { this.#starting = null; });
  }

  /** True while a renderer is being made (the panel is built when it is done). */
  get starting() { return this.#starting !== null; }

  async #create() {
    const f = this.#f;
    let gpu;
    try {
      await f.loaded();
      gpu = await hub.deviceFor(f.element, f.canvas);
    } catch (error) {
      this.fail(error.title, error.message, { retry: Boolean(hub.stopped) });
      return false;
    }
    if (gpu === null) {
      this.#failed = true;
      this.#message.show('Paused', WEBGL_WAIT);
      return false;
    }
    if (!f.element.isConnected || this.#view) {
      hub.giveBack(f.element, gpu);
      return false;
    }
    this.#gpu = gpu;
    this.#software = Boolean(hub.adapter?.software || gpu.is_fallback());
    this.#size.software = this.#software;
    this.#size.fit();
    try {
      this.#view = makeView(f, gpu, this.#software);
    } catch (error) {
      this.fail('The figure could not start', error.message);
      return false;
    }
    f.look.forgetBackground();
    f.guard.rendererStarted();
    this.apply();
    if (this.#savedSpheres) {
      try {
        this.#view.set_spheres(this.#savedSpheres);
      } catch (error) {
        console.warn(`<metaballs-view> could not restore the spheres: ${error.message}`);
      }
      this.#savedSpheres = null;
    }
    f.editor().reset();
    this.#message.hide();
    this.#dirty = 3;
    this.#last = 0;
    // Started near the screen but not on it: it lets go again unless it comes on screen.
    if (!this.#onScreen) this.setOnScreen(false);
    hub.requestFrame();
    requestAnimationFrame(() => setTimeout(() => f.element.isConnected && f.buildPanel()));
    return true;
  }

  // Frees the renderer's GPU memory and leaves the canvas unconfigured (a WebGL2 figure gives its
  // device back, so a waiting figure can start).
  release() {
    if (this.#view) {
      this.#view.free();
      this.#view = null;
      try {
        this.#f.canvas.getContext('webgpu')?.unconfigure();
      } catch { /* the context is gone with the device, or the canvas draws with WebGL2 */ }
    }
    hub.giveBack(this.#f.element, this.#gpu);
    this.#gpu = null;
  }

  /** The device is lost: keep the scene on the CPU and let go of the GPU (`text`: what the figure says). */
  suspend(reason, text = `The GPU was lost (${reason}); starting again…`) {
    if (this.#view) {
      try {
        this.#savedSpheres = this.#view.spheres();
      } catch { /* keep what was saved before */ }
    }
    this.release();
    if (this.#near) this.#f.notice(text, 4000);
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

  /** Shows a message in the figure's box and stops drawing it. */
  fail(title, text, { retry = false } = {}) {
    this.#failed = true;
    this.release();
    this.#message.show(title, text, retry);
    this.#f.emit('metaballs-error', { message: `${title}: ${text}` });
  }

  // Pushes the changed values into the renderer. A value it refuses (a resolution beyond the device)
  // goes back to the last one that worked, with a notice.
  apply() {
    const view = this.#view;
    if (!view) return;
    const settings = this.#f.settings;
    const s = settings.state;
    for (const name of settings.changed) {
      if (name === 'balls') {
        settings.applied.balls = s.balls;
        this.#f.io().applyBalls(s.balls);
        continue;
      }
      if (!isRendererSetting(name)) continue;
      try {
        within(this.#f.element, () => applySetting(view, name, s));
        settings.applied[name] = s[name];
      } catch (error) {
        this.#f.notice(`${name} ${s[name]}: ${error.message}`);
        s[name] = settings.applied[name];
        settings.reflect(name);
        this.#f.showPanel();
      }
    }
    if (settings.changed.has('display') || settings.changed.has('compare')) this.#exactChanged();
    if (settings.changed.size) this.#dirty = Math.max(this.#dirty, 3);
    settings.changed.clear();
  }

  // The exact surface is ray cast per pixel: on a software adapter at a lower pixel ratio, said once.
  #exactChanged() {
    this.resize();
    this.#size.exactChanged((text) => this.#f.notice(text, 4000));
  }


  /**
   * One animation frame of the page: draws if the figure is on screen and has something to show.
   * Returns whether it wants the next frame too.
   */
  tick(now) {
    const view = this.#view;
    const f = this.#f;
    const asked = this.#frameWaiters.length > 0;
    const drawing = this.#onScreen || this.#printOnce || asked;
    if (!view || this.#failed || this.#held || !drawing || document.visibilityState === 'hidden') {
      return false;
    }
    // On screen but not shown (a slide of a deck that is not the current one, `visibility: hidden`):
    // nothing is drawn, and the figure keeps watching for its turn.
    if (!this.#printOnce && !asked && !f.element.checkVisibility({ visibilityProperty: true, opacityProperty: true })) {
      return true;
    }
    const state = f.settings.state;
    let animating = false;
    try {
      this.apply();
      const background = f.look.backgroundChange(now);
      if (background) {
        view.set_background(...background);
        this.#dirty = Math.max(this.#dirty, 2);
      }
      const forPrint = this.#printOnce;
      if (forPrint) {
        this.#printOnce = false;
        this.#dirty = Math.max(this.#dirty, 1);
      }
      const elapsed = this.#last ? Math.min(Math.max(now - this.#last, 0) / 1000, 0.1) : 0;
      this.#last = now;
      // A figure in a sync group that does not lead takes the leader's spheres instead of animating.
      const leader = f.leader();
      if (leader?.view && leader.framesDrawn !== this.#ledFrame) {
        this.#ledFrame = leader.framesDrawn;
        view.set_spheres(leader.view.spheres());
        this.#dirty = Math.max(this.#dirty, 1);
      }
      // A sphere being dragged holds the animation still.
      // So does a shape check that pause_on=merge waits for.
      animating = !leader && !state.paused && state.speed > 0 && !f.editor().dragging && !f.topology().holding;
      if (animating || this.#dirty > 0 || this.#stepRequested || view.needs_redraw()) {
        const dt = animating ? elapsed * state.speed : this.#stepRequested ? 1 / 60 : 0;
        this.#stepRequested = false;
        const started = performance.now();
        within(f.element, () => view.frame(dt));
        const blocked = performance.now() - started;
        this.#dirty = Math.max(0, this.#dirty - 1);
        // The picture for print, taken in this task while the canvas holds the frame.
        f.look.drawn(now, animating, this.#dirty === 0, forPrint);
        for (const resolve of this.#frameWaiters.splice(0)) resolve();
        if (forPrint && !this.#onScreen) {
          // Not a frame anyone saw: only the picture counts. A figure not near the viewport lets go
          // of its renderer again.
          if (!this.#near) this.release();
          return false;
        }
        f.guard.frameDrawn(f.settings.applied, now, blocked);
        this.#framesDrawn += 1;
        f.hud.countFrame();
        f.topology().afterFrame(now);
      } else {
        view.poll();
        // The picture for print is older than the frame on screen: draw once more and take it.
        if (f.look.printStale) this.#dirty = 1;
      }
    } catch (error) {
      this.fail('The renderer stopped', error?.message ?? String(error));
      return false;
    }
    const since = f.hud.since;
    const frameMs = f.hud.update(now, view);
    if (frameMs) {
      // Frame times measured while a picture for print was taken (on any figure: it waits for the
      // GPU) say nothing about the settings.
      const pictures = picturesTaken();
      if (!state.paused && pictures === this.#picturesSeen) f.guard.framesTimed(f.settings.applied, since, frameMs);
      this.#picturesSeen = pictures;
      if (animating && this.#size.observe(frameMs)) this.resize();
    }
    f.inspector().follow(now);
    if (state.edit) f.editor().draw();
    const error = view.gpu_error();
    if (error) {
      this.fail('The GPU reported an error', error);
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
      this.#f.notice(error.message);
    }
    this.redraw(2);
  }


  /**
   * Resolves after a frame of the current settings has been drawn: the renderer is started and a frame
   * drawn even for a figure off screen (a notebook run from the top leaves its figures above the view)
   * or still. What is asked of the figure's mesh and pictures waits for it.
   */
  async nextFrame() {
    this.start(true);
    await this.ready();
    await new Promise((resolve) => {
      this.#frameWaiters.push(resolve);
      this.#dirty = Math.max(this.#dirty, 1);
      hub.requestFrame();
    });
    // Its figures (the triangle count) come back from the GPU once it has finished the frame.
    const view = this.#view;
    const frame = view?.frames_rendered() ?? 0;
    for (let tries = 0; view && view === this.#view && tries < 50; tries += 1) {
      view.poll();
      if (this.#f.hud.readStats(view) >= frame) return;
      await view.work_done();
      await new Promise((r) => setTimeout(r, 10));
    }
  }

  /** Resolves once the renderer has started (or rejects with why it could not). */
  async ready() {
    while (!this.#view) {
      if (this.#failed) throw new Error(this.#message.text);
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
      for (const name of ['spheres', 'resolution', 'iso', 'seed', 'mesher']) this.#f.settings.changed.add(name);
      this.#dirty = 3;
      hub.requestFrame();
    }
  }
}
