// What a figure shows besides its frames: the poster before the first frame, a picture of its latest
// frame for print (a WebGPU canvas prints blank), its accessible name, a polite announcement of what a
// control did, and the background colours a page gives through CSS custom properties. `Look` is the
// feature that keeps them up to date as the settings change and frames are drawn.

import { nameOfKind, rowOf } from '../core/table.js';
import { ONE_FRAME, PICTURE_FRAMES } from '../core/redraw.js';
import { meshWorker } from '../engine/meshers.js';

// The setting that holds spheres placed by hand, as text (`;` between spheres).
const SPHERE_LIST = nameOfKind('spheres');

// A figure refreshes its print picture at most this often while it animates (taking one waits for the
// GPU to finish the frame); a still figure takes one once it has settled.
const PRINT_EVERY_MS = 5000;
// The first picture waits this long after the first frame: while the device still compiles and draws
// the first frames, taking one would hold the page until they are done.
const FIRST_PICTURE_MS = 1000;
// The page's custom properties are read again at most this often.
const STYLE_EVERY_MS = 500;

// Pictures taken on this page so far (frame times that include one are not a figure's cost).
let pictures = 0;
/** How many pictures for print the figures on this page have taken. */
export const picturesTaken = () => pictures;

/** The colour scheme a `theme` value stands for here: `auto` follows the reader's preference. */
export const resolvedTheme = (theme) => (theme === 'auto'
  ? (matchMedia('(prefers-color-scheme: light)').matches ? 'light' : 'dark') : theme);

// The page's worker has not failed to encode a picture.
let workerEncodes = true;

/**
 * A PNG blob of RGBA8 `pixels` of `width` × `height`, encoded off the page's thread where the browser
 * has OffscreenCanvas.
 */
export async function pngOf(pixels, width, height) {
  // On the page's worker where there is one (the pixels are handed over); a worker that cannot encode
  // is not asked again.
  const worker = workerEncodes ? meshWorker(true) : null;
  if (worker) {
    return worker.png(pixels, width, height).catch((error) => {
      workerEncodes = false;
      throw error;
    });
  }
  const image = new ImageData(new Uint8ClampedArray(pixels.buffer, pixels.byteOffset, pixels.byteLength), width, height);
  // A canvas kept in memory (`willReadFrequently`): one drawn on the GPU would wait for it.
  const options = { willReadFrequently: true };
  if (globalThis.OffscreenCanvas) {
    const canvas = new OffscreenCanvas(width, height);
    canvas.getContext('2d', options).putImageData(image, 0, 0);
    return canvas.convertToBlob({ type: 'image/png' });
  }
  const canvas = Object.assign(document.createElement('canvas'), { width, height });
  canvas.getContext('2d', options).putImageData(image, 0, 0);
  return new Promise((resolve, reject) => {
    canvas.toBlob((blob) => (blob ? resolve(blob) : reject(new Error('the browser could not encode the PNG'))), 'image/png');
  });
}

export class FigureLook {
  #element;
  #root;
  #canvas;
  #poster;
  #print;
  #printUrl = null;
  #printedAt = -Infinity;
  #firstPictureAt = Infinity;
  #printStale = true;
  #encoding = false;
  // The view keeps a copy of the frame being drawn, of this size.
  #copying = false;
  #copySize = [0, 0];
  #styleAt = -Infinity;
  #background = '|';
  #printable = null;
  #resolvePrintable = () => {};
  #words;

  /** `words()`: the figure's words now (i18n/words.js). */
  constructor(element, root, canvas, words) {
    this.#words = words;
    this.#element = element;
    this.#root = root;
    this.#canvas = canvas;
    this.#poster = root.getElementById('poster');
    this.#print = root.getElementById('print-frame');
    this.#printable = new Promise((resolve) => { this.#resolvePrintable = resolve; });
    this.#poster.addEventListener('load', () => this.#resolvePrintable());
  }

  /** Resolves once the figure has a picture for print, decoded: its poster, or a picture of a drawn frame. */
  printable() { return this.#printable; }

  /** Shows `url` (an image) until the first frame, and in print until a frame is drawn; '' for none. */
  setPoster(url, drawn) {
    if (url) {
      this.#poster.src = new URL(url, document.baseURI).href;
    } else {
      this.#poster.removeAttribute('src');
    }
    this.#poster.hidden = !url || drawn;
  }

  /** The accessible name: the author's `alt`, else what the figure shows. */
  name(state) {
    const words = this.#words();
    const spheres = state[SPHERE_LIST] ? state[SPHERE_LIST].split(';').length : state.spheres;
    const parts = [
      words.t('figure.name-spheres', { count: spheres }),
      words.t('figure.name-iso', { iso: words.number(state.iso, 2) }),
      words.t('figure.name-cells', { resolution: state.resolution }),
    ];
    if (state.display !== 'shaded') parts.push(words.t(`word.display.${state.display}`));
    if (state.paused) parts.push(words.t('figure.name-paused'));
    this.#canvas.setAttribute('aria-label', state.alt || words.t('figure.name', { what: words.list(parts, 'unit') }));
  }

  /** Announces a change made from inside the figure: "iso level 0.8", "paused". */
  announceChange(name, value) {
    const words = this.#words();
    if (name === 'paused') {
      this.announce(words.t(value ? 'figure.announce-paused' : 'figure.announce-playing'));
      return;
    }
    // Spoken: the label, in English in lower case as in a sentence (other languages keep their own
    // capitals: German nouns keep theirs).
    const label = rowOf(name) ? words.t(`setting.${name}`) : name;
    const setting = words.chain[0].startsWith('en') ? label.toLowerCase() : label;
    if (typeof value === 'boolean') {
      this.announce(words.t(value ? 'figure.announce-on' : 'figure.announce-off', { setting }));
      return;
    }
    const word = `word.${name}.${value}`;
    const shown = typeof value === 'number' ? value : words.has(word) ? words.t(word) : String(value);
    this.announce(words.t('figure.announce-value', { setting, value: shown }));
  }

  /** Says `text` to screen readers, politely (what a control just did). */
  announce(text) {
    const region = this.#root.getElementById('announce');
    // A new node each time, so the same words twice are announced twice.
    region.replaceChildren(document.createElement('span'));
    region.firstChild.textContent = text;
  }

  /**
   * The page's background colours for the drawn picture (`--metaballs-background-top` and `-bottom`,
   * `#rrggbb`), read at most every half second: `[top, bottom]` when they changed since last asked.
   */
  backgroundChange(now, force = false) {
    if (!force && now - this.#styleAt < STYLE_EVERY_MS) return null;
    this.#styleAt = now;
    const style = getComputedStyle(this.#element);
    const read = (name) => style.getPropertyValue(name).trim();
    const pair = [read('--metaballs-background-top'), read('--metaballs-background-bottom')];
    const key = pair.join('|');
    if (key === this.#background) return null;
    this.#background = key;
    return pair;
  }

  /**
   * Whether the picture for print is taken of the frame about to be drawn: every few seconds while
   * animating, else once no more frames are due (`settled`); at once for a frame drawn only for print
   * (`forPrint`), else not in the first second after the first frame; never while the canvas is not
   * shown (as in print, where the picture taken before stands in for it).
   */
  #due(now, { animating, settled, forPrint }) {
    if (this.#firstPictureAt === Infinity) this.#firstPictureAt = forPrint ? now : now + FIRST_PICTURE_MS;
    return !this.#encoding && this.#canvas.checkVisibility() && (forPrint || (now >= this.#firstPictureAt
      && (animating ? now - this.#printedAt >= PRINT_EVERY_MS : settled)));
  }

  /** A frame is about to be drawn by `frame.view`: when its picture is due, the view keeps a copy. */
  beforeDraw(now, frame) {
    this.#copying = this.#due(now, frame) && frame.view.keep_picture();
    if (this.#copying) this.#copySize = [this.#canvas.width, this.#canvas.height];
  }

  /**
   * A frame was just drawn (this task): hides the poster, and takes its picture for print when due. The
   * view's copy of the frame is read back and encoded without waiting on the page's thread; a canvas
   * that cannot be copied from (WebGL2) gives its own, while it still holds the frame.
   */
  drawn(now, frame) {
    this.#poster.hidden = true;
    if (!this.#due(now, frame)) {
      this.#printStale = true;
      // A figure not shown now prints as it is: whoever waits for its picture waits no longer.
      if (!this.#canvas.checkVisibility()) this.#resolvePrintable();
      return;
    }
    const copied = this.#copying;
    this.#copying = false;
    const copy = copied ? frame.view.kept_picture() : null;
    if (copied && !copy) {
      // The canvas was not ready for the frame (it is configured again): the next one is taken.
      this.#printStale = true;
      return;
    }
    this.#printedAt = now;
    this.#printStale = false;
    this.#encoding = true;
    pictures += 1;
    const [width, height] = this.#copySize;
    const picture = copy
      ? copy.then((pixels) => pngOf(pixels, width, height))
      : new Promise((resolve) => this.#canvas.toBlob(resolve));
    picture.catch(() => null).then(async (blob) => {
      if (blob) {
        // Decoded before it takes the last one's place, so that the print picture is never blank
        // while the next one loads, and printable once it can be printed.
        const url = URL.createObjectURL(blob);
        const next = new Image();
        next.src = url;
        await next.decode().catch(() => {});
        if (this.#printUrl) URL.revokeObjectURL(this.#printUrl);
        this.#printUrl = url;
        this.#print.src = url;
        this.#resolvePrintable();
      }
      this.#encoding = false;
    });
  }

  /** True when the print picture is older than the last frame (the figure then draws once more). */
  get printStale() {
    return this.#printStale && !this.#encoding && performance.now() >= this.#firstPictureAt
      && this.#canvas.checkVisibility();
  }

  /** A new renderer starts from the theme's background: the page's colours are sent again. */
  forgetBackground() {
    this.#background = null;
    this.#styleAt = -Infinity;
  }
}

/** The feature: the poster, the print picture, the accessible name and the page's colours. */
export class Look extends FigureLook {
  static attributes = ['poster', 'theme'];
  #ctx;

  constructor(ctx) {
    super(ctx.element, ctx.root, ctx.canvas, () => ctx.words);
    this.#ctx = ctx;
    this.name(ctx.state);
  }

  changed(name, value) {
    if (name === 'poster') this.setPoster(value, this.#ctx.frames.framesDrawn > 0);
  }

  refresh(state) { this.name(state); }

  language() { this.name(this.#ctx.state); }

  madeInside(name, value) { this.announceChange(name, value); }

  /** The first start: a figure without a poster is drawn once while the page is idle, so it prints as a picture. */
  firstStart() {
    if (this.#ctx.state.poster) return;
    const later = globalThis.requestIdleCallback ?? ((f) => setTimeout(f, 1000));
    later(() => this.#ctx.element.isConnected && this.#ctx.frames.drawForPrint(), { timeout: 4000 });
  }

  /** The reader's colour scheme changed: a figure with `theme="auto"` follows it. */
  schemeChanged() {
    if (this.#ctx.state.theme !== 'auto') return;
    this.#ctx.settings.changed.add('theme');
    this.#ctx.redraw(0);
  }

  started() { this.forgetBackground(); }

  beforeFrame(now, view) {
    const background = this.backgroundChange(now);
    if (!background) return;
    view.set_background(...background);
    this.#ctx.redraw(PICTURE_FRAMES);
  }


  // The picture for print is older than the frame on screen: draw once more and take it.
  idle() {
    if (this.printStale) this.#ctx.redraw(ONE_FRAME);
  }
}
