// Sharing a 3D figure: its share box (the panel's `share` action, `openShare()`), the texts it writes
// (`shareText()`: HTML, iframe, Python, MyST, link), posters at the figure's size (`poster(scale)`), and
// recordings of its animation (`record(options)`), whose frames are made one animation step of 1/fps
// apart whatever the machine's speed, at the size asked for, and encoded in the browser.

import { TABLE, VERSION } from '../attributes.js';
import { nameOfKind, VIEW_ROWS } from '../core/table.js';
import { shareTexts } from '../core/share-text.js';
import { download } from '../core/download.js';
import { wasmModule, within } from '../engine/wasm.js';
import { pngOf } from '../figure/look.js';
import { clipFormats, encodeClip } from '../figure/clip.js';
import { clipPlan, ShareFeature } from './share-box.js';

// The rows the full page sets itself (it always has every control and the statistics).
const PAGE_ROWS = new Set(['controls', 'hud']);
// The rows the iframe page does not take from its link: a sync group and a poster name the author's
// page, not the figure.
const IFRAME_ROWS = new Set(['sync', 'poster']);
const POSTER_TEXT = TABLE.find((row) => row.name === 'poster');
// The setting that holds spheres placed by hand, as text.
const SPHERE_LIST = nameOfKind('spheres');
// The poster's file name at `scale` times the figure's size.
const posterFile = (scale) => (scale === 1 ? 'metaballs-poster.png' : `metaballs-poster@${scale}x.png`);

export class Share extends ShareFeature {
  // The poster saved from the share box, named in its HTML from then on.
  #posterName = null;

  controls() {
    return {
      share: ({ makeButton }) => {
        const { ctx } = this;
        const button = makeButton('share', ctx.t('share.button'), ctx.t('share.button-title'), () => this.open());
        Object.assign(button.dataset, { t: 'share.button', tTitle: 'share.button-title' });
        return button;
      },
    };
  }

  boxOptions() {
    return {
      posterName: posterFile,
      // Named in the HTML unless the author gave a poster of their own.
      posterSaved: (name) => {
        this.#posterName = name;
        return !this.ctx.state.poster;
      },
      posterHint: 'share.poster-hint.view',
      recorder: {
        size: () => this.seen(),
        formats: (width, height, fps) => clipFormats(width, height, fps),
        record: (options) => this.record(options),
        fileName: (format) => `metaballs.${format === 'gif' ? 'gif' : format.split('-')[0]}`,
      },
    };
  }

  /** The share box's texts for the figure as it is now. */
  texts() {
    const { settings } = this.ctx;
    const at = this.besideModule('metaballs-view.js');
    const now = this.#stateNow();
    const omitted = this.omitted();
    return shareTexts({
      rows: VIEW_ROWS,
      state: now,
      // What the author or the reader set, and spheres placed by hand; not what the figure chose for
      // its device (a software adapter's antialiasing), which a copy chooses again for its own.
      chosen: (row) => !omitted.has(row.name)
        && (settings.given.has(row.name) || row.name === SPHERE_LIST || (row.name === 'spheres' && Boolean(now[SPHERE_LIST]))),
      tag: 'metaballs-view',
      moduleUrl: at('metaballs-view.js'),
      stylesheet: at('metaballs-view.css'),
      pages: { full: at('../index.html'), embed: at('../embed.html') },
      widget: { module: at('../widget.js'), className: 'Metaballs', wasmUrl: at('../') },
      size: this.seen(),
      poster: POSTER_TEXT ? this.#posterName : null,
      pageRows: PAGE_ROWS,
      iframeRows: IFRAME_ROWS,
      version: VERSION,
    });
  }

  // The settings, and for a paused figure its spheres where they are now (the moment the author
  // paused at), as a hand-placed list.
  #stateNow() {
    const { state, view } = this.ctx;
    if (!state.paused || !view) return state;
    const packed = view.spheres();
    return { ...state, [SPHERE_LIST]: wasmModule().spheres_text(packed), spheres: packed.length / 7 };
  }

  /** A PNG of the view at the figure's box (CSS pixels) times `scale`. */
  async poster(scale = 1) {
    if (!(scale > 0 && scale <= 4)) throw new Error(`poster scale must be a number from 0 to 4, got ${scale}`);
    await this.ctx.frames.nextFrame();
    const { width, height } = this.seen();
    const [w, h] = [Math.round(width * scale), Math.round(height * scale)];
    return pngOf(await this.ctx.view.render_pixels(w, h), w, h);
  }

  async downloadPoster(scale = 1) {
    const name = posterFile(scale);
    download(await this.poster(scale), name);
    this.#posterName = name;
    this.rewrite();
  }

  /**
   * A clip of the animation: `seconds` × `fps` frames, frame i after i steps of speed/fps seconds from
   * the scene now (a paused figure's spheres move too), at width × height, in `format` (the first this
   * browser writes when not given). The figure's spheres are back where they were afterwards.
   */
  async record(options = {}) {
    const { format, width, height, fps, count, onProgress, signal } = await clipPlan(options, this.seen());
    const ctx = this.ctx;
    const speed = ctx.state.speed;
    const started = performance.now();
    const blob = await this.recording(signal, (stop) => ctx.frames.withView(async (view) => {
      const spheres = view.spheres();
      // The frame the scene is at (a 60 fps GIF asks for every second frame only).
      let at = 0;
      try {
        return await encodeClip({
          format, width, height, fps, count, onProgress, signal: stop,
          frame: async (i) => {
            // The renderer let go (the figure left the page, or its GPU was lost): the clip stops.
            if (ctx.frames.view !== view) throw new Error('the figure stopped drawing (it left the page or lost its GPU): no clip was made');
            if (i > at) within(ctx.element, () => view.frame(((i - at) * speed) / fps));
            at = i;
            return view.render_pixels(width, height);
          },
        });
      } finally {
        // The figure goes on from where it was: on this renderer, or on the next one made.
        if (ctx.frames.view === view) view.set_spheres(spheres);
        else ctx.frames.savedSpheres = spheres;
      }
    }));
    ctx.emit('metaballs-record', { format, width, height, fps, frames: count, bytes: blob.size, ms: performance.now() - started });
    return blob;
  }
}
