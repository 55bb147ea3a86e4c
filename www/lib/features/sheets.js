// A small figure's boxes as one sheet at a time. Narrower than COMPACT_PX, a figure has no room for its
// boxes side by side over the picture (the panel, the statistics, the levels, the inspector, the
// step-through, the selected sphere): each box present gets a tab in a row over the picture's lower
// left, and the one open is a sheet below the picture. The figure grows by the sheet, so the surface
// stays whole in view and nothing is drawn past the figure's box. Where the figure cannot grow (the page
// fixes its height or its aspect ratio: the full page, an iframe), the sheet covers the picture's lower
// part instead. A box that opens (a cell picked, the step-through started) becomes the sheet, and the
// statistics when no sheet is shown; closing the sheet's box, or tapping its tab again, gives the whole
// figure back to the picture.
//
// The state is the element's own (custom states: `:state(compact)`, `:state(sheet)` for a sheet below,
// `:state(over)` for a sheet over the picture), so the page's attributes and classes are untouched; the
// styles are compact-style.js's. This feature also owns the panel's `inert`: a wide figure's levels box
// and step-through cover the panel, so its controls leave the tab order while either shows.

/** Figures narrower than this, in CSS pixels, open their boxes one at a time. */
export const COMPACT_PX = 440;

/** The statistics' warnings (a full triangle budget, a neck thinner than a cell), marked on their tab. */
const WARNINGS = ['overflow', 'hud-field-warning'];

/**
 * The boxes, by id, with their tabs' names (`sheet.<id>` in the catalogues); the first open of those
 * marked `opens` is shown first.
 */
const BOXES = [
  { id: 'inspector', opens: true },
  { id: 'march', opens: true },
  { id: 'levels-box', opens: true },
  { id: 'sphere-box', opens: true },
  { id: 'hud', opens: true },
  { id: 'panel', opens: false },
];

export class FigureSheets {
  #ctx;
  #states;
  #compact = false;
  // The box shown as the sheet (its id), or null.
  #current = null;
  // Whether the sheet goes below the picture (the figure can grow) or over it.
  #below = true;
  // The tab buttons, by box id.
  #tabs = new Map();

  constructor(ctx) {
    this.#ctx = ctx;
    this.#states = ctx.states;
    ctx.$('tabs').addEventListener('click', (event) => {
      const button = event.target.closest('button[data-box]');
      if (button) this.toggle(button.dataset.box);
    });
    // Boxes open and close by their `hidden` attribute; the panel is rebuilt when its controls change.
    const watch = new MutationObserver((records) => this.#boxesChanged(records));
    for (const { id } of BOXES) {
      watch.observe(ctx.$(id), {
        attributes: true, attributeFilter: ['hidden'], attributeOldValue: true, childList: id === 'panel', subtree: id === 'hud',
      });
    }
    new ResizeObserver(([entry]) => this.#resized(entry.contentRect.width)).observe(ctx.element);
  }

  /** True while the figure opens its boxes one at a time (where the browser has custom states). */
  get compact() { return this.#compact; }

  /** The id of the box shown as the sheet, or null. */
  get current() { return this.#current; }

  /** Shows box `id` as the sheet, or closes the sheet when it is the one shown. */
  toggle(id) {
    this.#current = this.#current === id ? null : id;
    this.#render();
  }

  #open(id) { return !this.#ctx.$(id).hidden; }

  #resized(width) {
    const compact = this.#states.supported && width > 0 && width < COMPACT_PX;
    if (compact === this.#compact) return;
    this.#compact = compact;
    this.#current = compact ? (BOXES.find((box) => box.opens && this.#open(box.id))?.id ?? null) : null;
    this.#render();
  }

  #boxesChanged(records) {
    const before = this.#current;
    if (this.#compact) {
      for (const { target, type, oldValue } of records) {
        // A warning in the statistics, shown while they are not the sheet, is said aloud.
        if (WARNINGS.includes(target.id) && !target.hidden && oldValue !== null && this.#current !== 'hud') {
          this.#ctx.each('announce', target.textContent);
        }
        if (type !== 'attributes' || !BOXES.some((box) => box.id === target.id)) continue;
        const opened = !target.hidden && oldValue !== null;
        // A teaching box that opens becomes the sheet; the statistics only while no sheet is shown.
        if (opened && target.id !== 'panel' && (target.id !== 'hud' || !this.#current)) this.#current = target.id;
        if (target.hidden && this.#current === target.id) this.#current = null;
      }
    }
    const root = this.#ctx.root;
    const focusWasIn = before && this.#ctx.$(before).contains(root.activeElement);
    this.#render();
    // Focus in a sheet that went away moves to the new sheet's tab, or to the picture.
    if (focusWasIn && this.#current !== before) (this.#tabs.get(this.#current) ?? this.#ctx.canvas).focus();
  }

  #render() {
    const ctx = this.#ctx;
    const element = ctx.element;
    const shown = this.#compact && this.#current && this.#open(this.#current) ? this.#current : null;
    if (!shown) this.#current = null;
    const states = this.#states;
    if (shown && !states.has('sheet') && !states.has('over')) this.#below = true;
    states.set('compact', this.#compact);
    states.set('sheet', Boolean(shown) && this.#below);
    states.set('over', Boolean(shown) && !this.#below);
    for (const { id } of BOXES) {
      const box = ctx.$(id);
      box.classList.toggle('shown', id === shown);
      // The sheet scrolls: it takes focus, so that keys scroll it too.
      if (id === shown) box.tabIndex = 0;
      else box.removeAttribute('tabindex');
      box.style.bottom = '';
      if (id === shown) for (const details of box.querySelectorAll(':scope > details')) details.open = true;
    }
    // Below the picture only where the figure grew by the sheet, to the picture's height and the sheet's
    // (the page may fix its height or aspect ratio); else over the picture, above the tabs.
    const grown = () => Math.abs(element.clientHeight - ((element.clientWidth * 9) / 16 + ctx.$(shown).offsetHeight)) < 2;
    if (shown && this.#below && !grown()) {
      this.#below = false;
      states.set('sheet', false);
      states.set('over', true);
    }
    this.#renderTabs(shown);
    if (shown && !this.#below) ctx.$(shown).style.bottom = `${ctx.$('tabs').offsetHeight + 16}px`;
    // A wide figure's levels box and step-through cover the panel; a small one's are sheets of their own.
    ctx.$('panel').inert = !this.#compact && (this.#open('levels-box') || this.#open('march'));
  }

  // The row of tabs: one per box present, the shown one pressed; buttons kept while their boxes stay.
  #renderTabs(shown) {
    const tabs = this.#ctx.$('tabs');
    const present = this.#compact ? BOXES.filter(({ id }) => this.#open(id)) : [];
    for (const [id, button] of this.#tabs) {
      if (!present.some((box) => box.id === id)) {
        button.remove();
        this.#tabs.delete(id);
      }
    }
    const words = this.#ctx.words;
    for (const [index, { id }] of present.entries()) {
      let button = this.#tabs.get(id);
      if (!button) {
        button = document.createElement('button');
        button.type = 'button';
        button.dataset.box = id;
        button.setAttribute('aria-controls', id);
        this.#tabs.set(id, button);
      }
      button.setAttribute('aria-expanded', String(id === shown));
      // Marked by key, so that a new language words the tabs as they stand.
      const warned = id === 'hud' && WARNINGS.some((warning) => !this.#ctx.$(warning).hidden);
      button.dataset.t = warned ? 'sheet.hud-warned' : `sheet.${id}`;
      button.textContent = words.t(button.dataset.t);
      if (id === 'hud') {
        if (warned) button.dataset.tTitle = 'sheet.warning';
        else delete button.dataset.tTitle;
        button.title = warned ? words.t('sheet.warning') : '';
      }
      // Moved only when out of place (a button moved loses its focus).
      if (tabs.children[index] !== button) tabs.insertBefore(button, tabs.children[index] ?? null);
    }
    tabs.hidden = present.length === 0;
  }
}
