// The share box of both figures: a dialog that writes the figure as it is now for the places an author
// puts it (a page's HTML, an iframe for hosts that strip scripts, a notebook's Python, a MyST
// directive, the full page's link), each with a Copy button; posters at 1× and 2× of the figure's box;
// and, where the figure can make one, a recording of its animation with a progress bar and Cancel.
// Copying uses the Clipboard API; where the browser refuses, the text is selected for the reader to copy.
// Its words are the reader's language (the texts it writes are not: they are code, the same in any).

import { download } from '../core/download.js';
import { mark, relabel } from '../i18n/words.js';
import { clipFormats } from '../figure/clip.js';

const STYLE = `
dialog.share { max-width: min(640px, calc(100vw - 24px)); width: 100%; max-height: calc(100dvh - 24px);
  box-sizing: border-box; padding: 12px 14px; border: 1px solid var(--border, #3d4559); border-radius: 8px;
  background: var(--panel-solid, #0e1118); color: var(--text, #e6e9ef); font: 13px/1.4 system-ui, sans-serif; }
dialog.share::backdrop { background: rgba(0, 0, 0, 0.45); }
.share header { display: flex; align-items: center; justify-content: space-between; gap: 8px; }
.share h2 { font-size: 15px; margin: 0; }
.share h3 { font-size: 13px; margin: 12px 0 4px; }
.share button, .share select, .share input { font: inherit; min-height: 28px; min-width: 28px; color: inherit;
  background: var(--button, #232838); border: 1px solid var(--border, #3d4559); border-radius: 4px; padding: 2px 8px; }
.share button, .share select, .share input { width: auto; flex: none; margin: 0; }
.share button:hover { background: var(--button-hover, #2c3245); }
.share button:focus-visible, .share select:focus-visible, .share input:focus-visible, .share textarea:focus-visible,
.share [role=tab]:focus-visible { outline: 2px solid var(--accent, #e77661); outline-offset: 1px; }
.share [role=tablist] { display: flex; flex-wrap: wrap; gap: 4px; margin: 10px 0 6px; }
.share [role=tab][aria-selected=true] { background: var(--accent, #e77661); color: var(--on-accent, #1a0d0a); border-color: transparent; }
.share textarea { direction: ltr; text-align: left; box-sizing: border-box; width: 100%; min-height: 7.5em; resize: vertical; font: 12px/1.35 ui-monospace, monospace;
  color: inherit; background: var(--button, #232838); border: 1px solid var(--border, #3d4559); border-radius: 4px; padding: 6px; }
.share .hint, .share .status { color: var(--muted, #a9b1c2); margin: 4px 0; }
.share .row { display: flex; flex-wrap: wrap; align-items: center; gap: 6px 10px; }
.share label { display: inline-flex; align-items: center; gap: 4px; }
.share input[type=number] { width: 4.5em; }
.share progress { flex: 1 1 120px; min-width: 120px; height: 12px; accent-color: var(--accent, #e77661); }
`;

// The texts, in the order of the tabs: each tab's name is message `share.tab.<id>`, and what the text
// is for `share.hint.<id>`.
const TABS = ['html', 'iframe', 'url', 'python', 'myst', 'link'];

// A side made even, as video needs.
const even = (n) => Math.max(2, Math.round(n / 2) * 2);

// The most a GIF may hold while its palette is chosen (its frames at 2 bytes a pixel), in bytes.
const GIF_HELD_BYTES = 1e9;

const el = (tag, props = {}, ...children) => {
  const node = Object.assign(document.createElement(tag), props);
  node.append(...children);
  return node;
};

export class ShareBox {
  #root;
  #options;
  #dialog = null;
  #texts = null;
  #tab = 'html';
  #recording = null;
  // The nodes whose text is a message with fields (statuses, options), worded again in a new language.
  #said = new Map();

  /**
   * `root`: the figure's shadow root. `options`:
   * - `texts()`: the share texts now (lib/core/share-text.js);
   * - `poster(scale)`: a PNG blob of the picture at the box's size times `scale`; `posterName(scale)`;
   *   `posterSaved(name)`: true when the HTML names the poster from then on;
   * - `posterHint`: the key of the message saying what the poster is for in this figure;
   * - `words()`: the figure's words (i18n/words.js);
   * - `recorder` (or null): { size() → { width, height } seen, formats(width, height, fps) → the clip
   *   formats, record(options) → a Blob, fileName(format) }.
   */
  constructor(root, options) {
    this.#root = root;
    this.#options = options;
  }

  get isOpen() { return Boolean(this.#dialog?.open); }

  open() {
    this.#dialog ??= this.#build();
    this.refresh();
    if (!this.#dialog.open) this.#dialog.showModal();
    this.#dialog.querySelector(`[role=tab][aria-selected=true]`).focus();
  }

  close() { this.#dialog?.close(); }

  /** Words what the box shows in `words`' language (its marked nodes are worded by `relabel`). */
  language(words) {
    for (const [node, [key, fields]] of this.#said) {
      if (node.isConnected) node.textContent = words.t(key, fields);
      else this.#said.delete(node);
    }
  }

  // Sets `node`'s text to message `key` with `fields` (none: no text), and keeps it worded.
  #say(node, key, fields = {}) {
    if (!key) {
      this.#said.delete(node);
      node.textContent = '';
      return;
    }
    this.#said.set(node, [key, fields]);
    node.textContent = this.#options.words().t(key, fields);
  }

  /** Writes the texts again (the figure changed, a poster was saved). */
  refresh() {
    if (!this.#dialog) return;
    this.#texts = this.#options.texts();
    this.#show(this.#tab);
  }

  #show(tab) {
    this.#tab = tab;
    const dialog = this.#dialog;
    for (const button of dialog.querySelectorAll('[role=tab]')) {
      const selected = button.dataset.tab === tab;
      button.setAttribute('aria-selected', String(selected));
      button.tabIndex = selected ? 0 : -1;
    }
    dialog.querySelector('[role=tabpanel]').setAttribute('aria-labelledby', `share-tab-${tab}`);
    const area = dialog.querySelector('textarea');
    area.value = this.#texts[tab];
    area.rows = Math.min(12, Math.max(3, area.value.split('\n').length + 1));
    const words = this.#options.words();
    mark(area, { label: `share.tab.${tab}` }, words);
    const hint = dialog.querySelector('.hint');
    mark(hint, { text: `share.hint.${tab}` }, words);
    this.#say(dialog.querySelector('.copy-status'), null);
  }

  async #copy() {
    const dialog = this.#dialog;
    const area = dialog.querySelector('textarea');
    const status = dialog.querySelector('.copy-status');
    try {
      if (!navigator.clipboard?.writeText) throw new Error('no clipboard');
      await navigator.clipboard.writeText(area.value);
      this.#say(status, 'share.copied');
    } catch {
      area.focus();
      area.select();
      this.#say(status, 'share.copy-refused');
    }
  }

  #build() {
    const dialog = el('dialog', { className: 'share' });
    dialog.setAttribute('part', 'share');
    dialog.setAttribute('aria-labelledby', 'share-title');
    const close = mark(el('button', { type: 'button', textContent: '×' }), { title: 'share.close', label: 'share.close' });
    close.addEventListener('click', () => dialog.close());

    const tabs = mark(el('div'), { label: 'share.tabs' });
    tabs.setAttribute('role', 'tablist');
    for (const id of TABS) {
      const tab = mark(el('button', { type: 'button', id: `share-tab-${id}` }), { text: `share.tab.${id}` });
      tab.dataset.tab = id;
      tab.setAttribute('role', 'tab');
      tab.setAttribute('aria-controls', 'share-panel');
      tab.addEventListener('click', () => this.#show(id));
      tabs.append(tab);
    }
    // Arrow keys, Home and End move between the tabs, as in any tab list.
    tabs.addEventListener('keydown', (event) => {
      const index = TABS.indexOf(this.#tab);
      // Right to left, the next tab is the one on the left.
      const step = this.#options.words().rtl ? -1 : 1;
      const to = { ArrowRight: index + step, ArrowLeft: index - step, Home: 0, End: TABS.length - 1 }[event.key];
      if (to === undefined) return;
      const next = TABS[(to + TABS.length) % TABS.length];
      this.#show(next);
      tabs.querySelector(`[data-tab="${next}"]`).focus();
      event.preventDefault();
    });
    const area = el('textarea', { readOnly: true, spellcheck: false });
    area.setAttribute('wrap', 'soft');
    const copy = mark(el('button', { type: 'button', className: 'copy' }), { text: 'share.copy' });
    copy.addEventListener('click', () => this.#copy());
    const copyStatus = el('span', { className: 'status copy-status' });
    copyStatus.setAttribute('role', 'status');

    const panel = el('div', { id: 'share-panel' }, el('p', { className: 'hint' }), area, el('div', { className: 'row' }, copy, copyStatus));
    panel.setAttribute('role', 'tabpanel');
    dialog.append(
      el('style', { textContent: STYLE }),
      el('header', {}, mark(el('h2', { id: 'share-title' }), { text: 'share.title' }), close),
      tabs, panel, this.#posterSection(),
    );
    if (this.#options.recorder) dialog.append(this.#recordSection());
    // A recording under way is cancelled when the box closes.
    dialog.addEventListener('close', () => this.#recording?.abort());
    relabel(dialog, this.#options.words());
    this.#root.append(dialog);
    return dialog;
  }

  #posterSection() {
    const status = el('span', { className: 'status' });
    status.setAttribute('role', 'status');
    const button = (scale) => {
      const b = el('button', { type: 'button', className: `poster-${scale}x` });
      this.#say(b, 'share.poster-button', { scale });
      b.addEventListener('click', async () => {
        const name = this.#options.posterName(scale);
        try {
          download(await this.#options.poster(scale), name);
          const named = this.#options.posterSaved(name);
          this.refresh();
          this.#say(status, named ? 'share.poster-named' : 'share.poster-saved', { name });
        } catch (error) {
          this.#say(status, 'share.poster-failed', { reason: this.#options.words().refusal(error) });
        }
      });
      return b;
    };
    return el('section', {},
      mark(el('h3'), { text: 'share.poster' }),
      mark(el('p', { className: 'hint' }), { text: this.#options.posterHint }),
      el('div', { className: 'row' }, button(1), button(2), status));
  }

  #recordSection() {
    const recorder = this.#options.recorder;
    const seen = recorder.size();
    const sizes = [[even(seen.width), even(seen.height), 'share.record.size-seen'], [640, 360], [1280, 720], [1920, 1080]];
    const seconds = el('input', { type: 'number', min: '0.5', max: '60', step: '0.5', value: '4', className: 'seconds' });
    // An option's value is what the recorder reads; its text is worded.
    const option = (value, key, fields, selected = false) => {
      const node = el('option', { value, selected });
      this.#say(node, key, fields);
      return node;
    };
    const fps = el('select', { className: 'fps' }, ...[24, 30, 60].map((n) => option(String(n), 'share.record.fps', { fps: n }, n === 30)));
    const size = el('select', { className: 'size' },
      ...sizes.map(([w, h, key]) => option(`${w}x${h}`, key ?? 'share.record.size', { width: w, height: h })));
    const format = el('select', { className: 'format' });
    const start = mark(el('button', { type: 'button', className: 'record' }), { text: 'share.record.start' });
    const cancel = mark(el('button', { type: 'button', className: 'cancel', hidden: true }), { text: 'share.record.cancel' });
    const progress = el('progress', { max: 1, value: 0, hidden: true });
    const status = el('span', { className: 'status record-status' });
    status.setAttribute('role', 'status');
    for (const [node, key] of [[fps, 'share.record.frame-rate'], [size, 'share.record.size-label'], [format, 'share.record.format'],
      [progress, 'share.record.progress']]) {
      mark(node, { label: key });
    }
    const label = (key, input) => el('label', {}, mark(el('span'), { text: key }), input);

    const chosen = () => {
      const [w, h] = size.value.split('x').map(Number);
      return { width: w, height: h, fps: Number(fps.value), seconds: Number(seconds.value), format: format.value };
    };
    // The formats this browser writes at the size and rate chosen (the answer to the latest question).
    let asked = 0;
    const listFormats = async () => {
      const { width, height, fps: rate } = chosen();
      const question = ++asked;
      const formats = await recorder.formats(width, height, rate);
      if (question !== asked) return;
      const before = format.value;
      const words = this.#options.words();
      for (const old of format.options) this.#said.delete(old);
      // A format is named by its label (a name, as WebM or MP4), or by a message where it has one.
      format.replaceChildren(...formats.map((f) => (words.has(`share.record.format.${f.id}`)
        ? option(f.id, `share.record.format.${f.id}`) : el('option', { value: f.id, textContent: f.label }))));
      if (formats.some((f) => f.id === before)) format.value = before;
    };
    size.addEventListener('change', listFormats);
    fps.addEventListener('change', listFormats);
    listFormats().catch((error) => this.#say(status, 'share.record.unavailable', { reason: this.#options.words().refusal(error) }));

    start.addEventListener('click', async () => {
      const options = chosen();
      const controller = new AbortController();
      this.#recording = controller;
      start.disabled = true;
      cancel.hidden = false;
      progress.hidden = false;
      cancel.focus();
      progress.value = 0;
      this.#say(status, 'share.record.busy');
      const started = performance.now();
      try {
        const blob = await recorder.record({
          ...options,
          signal: controller.signal,
          onProgress: (done, count) => { progress.value = done / count; },
        });
        const name = recorder.fileName(options.format);
        download(blob, name);
        const words = this.#options.words();
        this.#say(status, 'share.record.saved', {
          name, size: words.fixed(blob.size / 1e6, 2), seconds: words.fixed((performance.now() - started) / 1000, 1),
        });
      } catch (error) {
        if (error?.name === 'AbortError') this.#say(status, 'share.record.cancelled');
        else this.#say(status, 'share.record.failed', { reason: this.#options.words().refusal(error) });
      } finally {
        this.#recording = null;
        const focused = this.#root.activeElement === cancel;
        start.disabled = false;
        cancel.hidden = true;
        progress.hidden = true;
        if (focused) start.focus();
      }
    });
    cancel.addEventListener('click', () => this.#recording?.abort());

    return el('section', { className: 'recording' },
      mark(el('h3'), { text: 'share.record.title' }),
      mark(el('p', { className: 'hint' }), { text: 'share.record.hint' }),
      el('div', { className: 'row' }, label('share.record.length', seconds), fps, size, format),
      el('div', { className: 'row' }, start, cancel, progress, status));
  }
}

/**
 * What both figures' sharing features share: the panel's `share` action, the box made when first
 * opened, and the box following the figure's changes while it is open. A subclass gives `texts()`,
 * `poster(scale)` and `boxOptions()` (the rest of the box's options).
 */
export class ShareFeature {
  #box = null;
  // The recording under way (its own abort), or null: one at a time per figure.
  #recording = null;

  constructor(ctx) {
    this.ctx = ctx;
    ctx.actions.share = () => this.open();
  }

  // A figure taken off the page stops recording and closes its box (a modal box would stay open).
  disconnected() {
    this.#recording?.abort();
    this.#box?.close();
  }

  /**
   * Runs `record(signal)`, the one recording of this figure, stopped by `signal` (the caller's) or by
   * the figure leaving the page.
   */
  async recording(signal, record) {
    if (this.#recording) throw new Error('this figure is recording already: wait for that clip, or cancel it');
    if (!this.ctx.element.isConnected) throw new Error('the figure is not on the page: put it in the document to record it');
    const own = new AbortController();
    this.#recording = own;
    try {
      return await record(signal ? AbortSignal.any([signal, own.signal]) : own.signal);
    } finally {
      this.#recording = null;
    }
  }

  refresh() { if (this.#box?.isOpen) this.#box.refresh(); }

  // The box's words with fields follow the figure's language (its marked words: ctx.speak).
  language(words) { this.#box?.language(words); }

  /** The figure's size as seen, in CSS pixels. */
  seen() {
    const { element } = this.ctx;
    return { width: element.clientWidth || 640, height: element.clientHeight || 360 };
  }

  /**
   * Paths beside the figure's module (`file`) as web addresses: from the URL it was loaded from, or,
   * for a module from elsewhere (a notebook's `blob:`), where a copy of dist/ beside the page has it.
   */
  besideModule(file) {
    const given = this.ctx.element.constructor.moduleUrl ?? '';
    const url = /^https?:/.test(given) ? given : new URL(`www/${file}`, document.baseURI).href;
    return (path) => new URL(path, url).href;
  }

  /** The settings the page gives the figure for itself (`data-share-omit="controls hud"`), not shared. */
  omitted() {
    return new Set((this.ctx.element.dataset.shareOmit ?? '').split(/\s+/).filter(Boolean));
  }

  open() {
    this.#box ??= new ShareBox(this.ctx.root, {
      texts: () => this.texts(),
      poster: (scale) => this.poster(scale),
      words: () => this.ctx.words,
      ...this.boxOptions(),
    });
    this.#box.open();
  }

  /** Writes the open box's texts again. */
  rewrite() { this.#box?.refresh(); }
}

/**
 * A recording's options checked and completed: `seconds` (0.1 to 60, default 4), `fps` (24, 30 or 60,
 * default 30), `width` and `height` (default the figure's size `seen`, made even, as video needs),
 * `format` (default the first this browser writes), and `count`, the frames.
 */
export async function clipPlan({ seconds = 4, fps = 30, width, height, format, onProgress, signal } = {}, seen) {
  if (![24, 30, 60].includes(fps)) throw new Error(`fps must be 24, 30 or 60, got ${fps}`);
  if (!(seconds >= 0.1 && seconds <= 60)) throw new Error(`seconds must be a number from 0.1 to 60, got ${seconds}`);
  width ??= even(seen.width);
  height ??= even(seen.height);
  if (!format) [{ id: format }] = await clipFormats(width, height, fps);
  const count = Math.max(1, Math.round(seconds * fps));
  // A GIF holds its frames until its palette is chosen (every second one at 60 fps).
  const held = width * height * 2 * (fps === 60 ? Math.ceil(count / 2) : count);
  if (format === 'gif' && held > GIF_HELD_BYTES) {
    throw new Error(`a GIF of ${width}×${height} for ${seconds} s at ${fps} fps is too large to make here: choose a smaller size, fewer seconds, or WebM or MP4`);
  }
  return { seconds, fps, width, height, format, count, onProgress, signal };
}
