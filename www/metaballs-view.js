// <metaballs-view>: merging spheres drawn with marching cubes, as an element a page embeds any number of
// times. Load it with one <script type="module" src=".../www/metaballs-view.js"> (or `import
// 'metaballs-view'`); every element on the page shares one GPU device, starts when it first comes near
// the viewport, draws only while on screen, takes keys only while focused, and survives a lost GPU.
// Importing it does nothing but define the element, and only where `customElements` exists (a
// server-side build imports it safely); the wasm loads when the first figure is connected.
//
// The element is a figure context (lib/core/context.js) with its features (lib/features/ and the
// look, lib/figure/look.js), each owning its settings, its reaction to their changes, its part of each
// frame and its methods; the renderer and its frames are lib/figure/frames.js.

import { canonical, nameOfKind, rowOf, TABLE, TEXT_NAMES, VIEW_ROWS } from './lib/core/table.js';
import { FigureState } from './lib/core/state.js';
import { customStates, defineSettingProperties, flasher, takeAttribute } from './lib/core/element.js';
import { watchLanguage } from './lib/core/language.js';
import { readsInJavaScript, readValue } from './lib/core/read.js';
import { FigureContext } from './lib/core/context.js';
import { hub } from './lib/engine/hub.js';
import { say, warningSaid } from './lib/engine/asset-errors.js';
import { loadWarning, loadWasm, parseParameter, wasmLoaded } from './lib/engine/wasm.js';
import { FigureBase } from './lib/engine/element-base.js';
import { pageWatch, unwatch } from './lib/engine/page-watch.js';
import { elementStyle, TEMPLATE } from './lib/figure/dom.js';
import { FigureFrames } from './lib/figure/frames.js';
import { FigureSize } from './lib/figure/size.js';
import { FigureDetail } from './lib/figure/detail.js';
import { Look } from './lib/figure/look.js';
import { Camera } from './lib/features/camera.js';
import { ErrorPlot } from './lib/features/error-plot.js';
import { Guard } from './lib/features/guard.js';
import { Hud } from './lib/features/hud.js';
import { Inspector } from './lib/features/inspector.js';
import { Stepper } from './lib/features/stepper.js';
import { Panel } from './lib/features/panel.js';
import { Playback } from './lib/features/playback.js';
import { SceneFiles, spheresText } from './lib/features/scene-files.js';
import { SphereEditor } from './lib/features/editor.js';
import { Sync } from './lib/features/sync.js';
import { TableChange } from './lib/features/table-change.js';
import { TopologyWatch } from './lib/features/topology.js';
import { IsoLevels } from './lib/features/levels.js';
import { FigureSheets } from './lib/features/sheets.js';
import { Share } from './lib/features/share.js';

// The setting that holds spheres placed by hand, as text.
const SPHERE_LIST = nameOfKind('spheres');

// A setting's text read by the table's reader, or by the wasm's parser for slices, cells and spheres.
const readSetting = (spelling, text) => {
  const row = rowOf(spelling);
  return readsInJavaScript(row) ? readValue(row, text, spelling) : parseParameter(spelling, text);
};

// The features every figure has, in the order they hear of changes and frames.
const FEATURES = [FigureSize, FigureDetail, Look, Guard, Hud, Playback, Camera, Inspector, Stepper, SphereEditor,
  SceneFiles, TopologyWatch, IsoLevels, TableChange, Sync, ErrorPlot, Share, Panel, FigureSheets];

export class MetaballsView extends FigureBase {
  /** Where this module was loaded from: the share box's script tags and pages are found from it. */
  static moduleUrl = import.meta.url;

  /** GPU memory held by every element's buffers and targets, in bytes. */
  static get gpuBytes() {
    let bytes = 0;
    for (const element of hub.elements) bytes += element.gpuBytes;
    return bytes;
  }

  #ctx;
  #frames;
  #unwatchLanguage = null;
  #started = false;
  // Resolves once the wasm is in and the attributes given so far are read.
  #loaded = null;

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open', delegatesFocus: true });
    root.adoptedStyleSheets = [elementStyle()];
    root.innerHTML = TEMPLATE;
    const ctx = new FigureContext(this, root, new FigureState(this, VIEW_ROWS, readSetting), customStates(this));
    this.#ctx = ctx;
    ctx.flash = flasher(root);
    for (const Feature of FEATURES) ctx.use(Feature);
    this.#frames = new FigureFrames(ctx, ctx.get(FigureSize), () => this.#load());
    ctx.frames = this.#frames;
    ctx.get(Camera).wire();
    ctx.$('retry').addEventListener('click', () => hub.retry());
    new ResizeObserver(([entry]) => this.#frames.resize(entry)).observe(ctx.canvas);
  }

  // Properties mirror the attributes (the table's `property`): reading gives the value in effect,
  // writing goes through the same checks as the attribute. The spellings of earlier versions
  // (`color_by`, `balls`) are kept as properties that forward to the same setting.
  static {
    defineSettingProperties(this, VIEW_ROWS, (element) => element.#ctx.state);
  }

  // ---------------------------------------------------------------- lifecycle

  connectedCallback() {
    const watch = pageWatch();
    this.#unwatchLanguage = watchLanguage(this, (words) => {
      this.#ctx.speak(words);
      this.#frames.reword(words);
    });
    this.#ctx.each('connected');
    this.#load().then(() => {
      if (!this.isConnected) return;
      if (!this.#started) {
        this.#started = true;
        if (loadWarning()) this.#ctx.notice(say(this.#ctx.words, warningSaid(loadWarning())));
        this.#ctx.each('firstStart');
      }
      this.#ctx.each('loaded');
    }, (error) => this.fail(error?.said?.title ?? error?.title ?? { key: 'figure.could-not-load' },
      error?.said?.text ?? `${error?.message ?? error}`));
    hub.register(this);
    watch.near.observe(this);
    watch.visible.observe(this);
  }

  disconnectedCallback() {
    this.#unwatchLanguage?.();
    this.#ctx.each('disconnected');
    unwatch(this);
    hub.unregister(this);
    this.#frames.detach();
  }

  // Loads the wasm (once per page) and reads the attributes given before it arrived.
  #load() {
    this.#loaded ??= loadWasm().then(() => {
      for (const row of TABLE) {
        const [spelling] = this.#ctx.settings.present(row.name);
        if (spelling) this.attributeChangedCallback(spelling, null, this.getAttribute(spelling));
      }
    });
    return this.#loaded;
  }

  /** The reader's colour scheme changed: a figure with `theme="auto"` follows it. */
  schemeChanged() { this.#ctx.get(Look).schemeChanged(); }

  attributeChangedCallback(spelling, _old, text) {
    // Before the wasm arrives only plain text is taken; the rest is read when it loads.
    if (!wasmLoaded() && !TEXT_NAMES.has(canonical(spelling))) return;
    takeAttribute(this.#ctx, 'metaballs-view', spelling, text);
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

  /**
   * Shows a message in this element's box and stops drawing it: `title` and `text` are text, or
   * sayings worded in the reader's language (`{ key, fields }`, lib/engine/asset-errors.js).
   */
  fail(title, text, options) { this.#frames.fail(title, text, options); }

  /**
   * One animation frame of the page: draws if this element is on screen and has something to show.
   * Returns whether it wants the next frame too.
   */
  tick(now) { return this.#frames.tick(now); }

  // ---------------------------------------------------------------- costly settings

  /** The change waiting for the person's confirmation (a slow frame), or null. */
  get pendingChange() { return this.#ctx.get(Guard).pending; }

  // ---------------------------------------------------------------- the cell inspector

  /** Selects cell (x, y, z) for the inspector; returns its report (null outside the grid). */
  inspectCell(x, y, z) { return this.#ctx.get(Inspector).select(x, y, z); }

  /** Lets go of the inspected cell or the selected sphere (also Esc, the × button, or a click on the background). */
  deselect() {
    if (!this.#ctx.get(SphereEditor).deselect()) this.#ctx.get(Inspector).deselect();
  }

  /**
   * The field's critical points for the spheres now, found with proof off the page's thread: resolves
   * to { points: [{ position, value, index, role, eigenvalues, ends, inBox }], tree: [{ value, children,
   * point, spheres }], bands: [{ above, below, blobs, cavities, genus, surfaces }], complete, undecided,
   * wallLevel, milliseconds, iso, counts } (`counts`: the band holding the iso level).
   */
  criticalPoints() { return this.#ctx.get(IsoLevels).result(); }

  /** What marching cubes decided in the inspected cell, as last shown; null when none is selected. */
  get inspected() { return this.#ctx.get(Inspector).report; }

  // ---------------------------------------------------------------- hands on the scene

  /**
   * The spheres in play: [{ center: [x, y, z], radius, velocity: [x, y, z], charge }]. Set to such a
   * list (or to their text) to place them by hand.
   */
  get sphereList() { return this.#ctx.get(SceneFiles).list(this.#frames.savedSpheres); }

  set sphereList(value) {
    this.setAttribute(this.#ctx.settings.present(SPHERE_LIST)[0] ?? SPHERE_LIST,
      Array.isArray(value) ? spheresText(value) : String(value));
  }

  /** Where sphere `index` is drawn: { x, y, radius } in CSS pixels from the figure's top left, or null. */
  sphereOnScreen(index) { return this.#ctx.get(SceneFiles).onScreen(index); }

  /** The selected sphere's index in edit mode, or -1. */
  get selectedSphere() { return this.#ctx.get(SphereEditor).selected; }

  /** The scene (spheres and every setting of the picture) as a JSON document. */
  saveScene() { return this.#ctx.get(SceneFiles).save(); }

  /** Loads a scene document; throws with what is wrong, leaving the scene as it was. */
  loadScene(text) { this.#ctx.get(SceneFiles).load(text); }

  downloadScene() { this.#ctx.get(SceneFiles).downloadScene(); }

  /** The mesh of the current settings as `stl`, `obj` or `ply` bytes (one readback from the GPU). */
  exportMesh(format = 'stl') { return this.#ctx.get(SceneFiles).exportMesh(format); }

  downloadMesh(format = 'stl') { return this.#ctx.get(SceneFiles).downloadMesh(format); }

  /** A PNG blob of the view at the canvas size times `scale` (1 or 2). */
  picture(scale = 1) { return this.#ctx.get(SceneFiles).picture(scale); }

  downloadPicture(scale = 1) { return this.#ctx.get(SceneFiles).downloadPicture(scale); }

  // ---------------------------------------------------------------- sharing

  /** The figure as it is now, written to paste: { html, url, iframe, python, myst, link }. */
  shareText() { return this.#ctx.get(Share).texts(); }

  /** A PNG of the view at the figure's size (CSS pixels) times `scale`, the picture `poster` expects. */
  makePoster(scale = 1) { return this.#ctx.get(Share).poster(scale); }

  downloadPoster(scale = 1) { return this.#ctx.get(Share).downloadPoster(scale); }

  /** A clip of the animation: { seconds, fps, width, height, format, onProgress, signal } → a Blob. */
  record(options) { return this.#ctx.get(Share).record(options); }

  /** Opens the share box. */
  openShare() { this.#ctx.get(Share).open(); }

  // ---------------------------------------------------------------- notices

  /** Shows a short message inside the figure (pages use it for problems with their links). */
  showNotice(text, ms = 8000) { this.#ctx.notice(text, ms); }

  // ---------------------------------------------------------------- API for authors

  play() { this.#ctx.get(Playback).play(); }

  pause() { this.#ctx.get(Playback).pause(); }

  /** Back to the default camera. */
  resetView() { this.#ctx.get(Camera).resetView(); }

  /** Draws one frame of animation (1/60 s) and stays paused. */
  step() { this.#ctx.get(Playback).step(); }

  /** Figures of the newest frames: triangles, fps, frame time (ms), adapter, overflowed. */
  get stats() { return { ...this.#ctx.get(Hud).stats }; }

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
  printable() { return this.#ctx.get(Look).printable(); }

  /** The surface's shape now: resolves to { components, genus, closed, manifold }. */
  async topology() {
    await this.ready();
    return this.#ctx.get(TopologyWatch).check();
  }

  /**
   * Runs `f(view)` with the wasm view while the element's own frames are held (the benchmark uses it).
   */
  withView(f) { return this.#frames.withView(f); }
}

/**
 * Adds a language, or overrides some of a language's words, for every figure on the page:
 * `registerTranslation('nl', { 'setting.iso': 'Isoniveau', … })`; `englishWords` is every English
 * message by its key (docs/embedding.md, "Languages").
 */
export { registerTranslation, EN as englishWords } from './lib/i18n/words.js';

// Safe to import twice, even from two copies of the package: the first definition stays.
if (globalThis.customElements && !customElements.get('metaballs-view')) {
  customElements.define('metaballs-view', MetaballsView);
}
