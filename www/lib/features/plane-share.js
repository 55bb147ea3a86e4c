// Sharing a 2D figure: its share box (the panel's `share` action, `openShare()`), the texts it writes
// (`shareText()`: HTML, iframe, Python, MyST, link), pictures of it at 1× and 2× of its box
// (`makePoster(scale)`), drawn from its vector picture, and clips of its circles moving (`record()`).

import { VERSION } from '../attributes.js';
import { shareTexts } from '../core/share-text.js';
import { circlesExactText, moveCircles } from '../plane/circles.js';
import { paint } from '../plane/picture.js';
import { clipFormats, encodeClip } from '../figure/clip.js';
import { clipPlan, ShareFeature } from './share-box.js';

// The rows the full page sets itself.
const PAGE_ROWS = new Set(['controls', 'slice-of']);
// The rows the iframe page does not take from its link: a followed 3D figure is on the author's page.
const IFRAME_ROWS = new Set(['slice-of']);

export class PlaneShare extends ShareFeature {
  boxOptions() {
    return {
      posterName: (scale) => (scale === 1 ? 'metaballs-2d.png' : `metaballs-2d@${scale}x.png`),
      posterSaved: () => false,
      posterHint: 'share.poster-hint.plane',
      recorder: {
        size: () => this.seen(),
        formats: (width, height, fps) => clipFormats(width, height, fps),
        record: (options) => this.record(options),
        fileName: (format) => `metaballs-2d.${format === 'gif' ? 'gif' : format.split('-')[0]}`,
      },
    };
  }

  texts() {
    const { element, state, settings } = this.ctx;
    const at = this.besideModule('metaballs-2d.js');
    const omitted = this.omitted();
    // A paused figure's circles where they are now (the moment the author paused at).
    const now = state.paused ? { ...state, circles: circlesExactText(element.circleList) } : state;
    return shareTexts({
      rows: settings.rows,
      state: now,
      chosen: (row) => !omitted.has(row.name) && (settings.given.has(row.name) || row.name === 'circles'),
      tag: 'metaballs-2d',
      moduleUrl: at('metaballs-2d.js'),
      stylesheet: at('metaballs-view.css'),
      pages: { full: at('../squares.html'), embed: at('../embed-2d.html') },
      widget: { module: at('../widget-2d.js'), className: 'Metaballs2d', wasmUrl: null },
      size: this.seen(),
      pageRows: PAGE_ROWS,
      iframeRows: IFRAME_ROWS,
      version: VERSION,
    });
  }

  /** A PNG of the picture (square, the canvas's side in CSS pixels times `scale`), drawn from its SVG. */
  async poster(scale = 1) {
    if (!(scale > 0 && scale <= 4)) throw new Error(`poster scale must be a number from 0 to 4, got ${scale}`);
    const canvas = this.ctx.canvas;
    const side = Math.max(1, Math.round((canvas.clientWidth || 480) * scale));
    const url = URL.createObjectURL(new Blob([this.ctx.frames.svg(side)], { type: 'image/svg+xml' }));
    try {
      const image = new Image(side, side);
      image.src = url;
      await image.decode();
      const out = Object.assign(document.createElement('canvas'), { width: side, height: side });
      out.getContext('2d').drawImage(image, 0, 0, side, side);
      return await new Promise((resolve, reject) => out.toBlob((b) => (b ? resolve(b) : reject(new Error('the browser could not encode the PNG'))), 'image/png'));
    } finally {
      URL.revokeObjectURL(url);
    }
  }

  /**
   * A clip of the circles moving: frame i after i steps of speed/fps seconds from where they are now
   * (a paused figure's circles move too), the square picture centred on its background at width ×
   * height. The figure's own animation holds still meanwhile, and its circles are back where they
   * were afterwards.
   */
  async record(options = {}) {
    const { format, width, height, fps, count, onProgress, signal } = await clipPlan(options, this.seen());
    const { frames, state } = this.ctx;
    const list = frames.parts.circles.list;
    const kept = list.map((c) => ({ ...c }));
    const canvas = new OffscreenCanvas(width, height);
    const context = canvas.getContext('2d', { willReadFrequently: true });
    const side = Math.min(width, height);
    let at = 0;
    return this.recording(signal, async (stop) => {
      frames.held = true;
      try {
        return await encodeClip({
          format, width, height, fps, count, onProgress, signal: stop,
          frame: async (i) => {
            // A frame a task: the page paints the progress and takes a click on Cancel between them.
            await new Promise((resolve) => setTimeout(resolve, 0));
            if (i > at) moveCircles(list, ((i - at) * state.speed) / fps);
            at = i;
            const { shapes } = frames.picture(side);
            context.fillStyle = shapes[0].fill;
            context.fillRect(0, 0, width, height);
            context.save();
            context.translate((width - side) / 2, (height - side) / 2);
            paint(context, shapes);
            context.restore();
            return context.getImageData(0, 0, width, height).data;
          },
        });
      } finally {
        list.forEach((c, k) => Object.assign(c, kept[k]));
        frames.held = false;
        frames.redraw();
      }
    });
  }
}
