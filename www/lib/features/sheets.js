// A small figure's boxes as one sheet at a time. Narrower than COMPACT_PX, a figure has no room for its
// boxes side by side over the picture (the panel, the statistics, the levels, the inspector, the
// step-through, the selected sphere): each box present gets a tab in a row over the picture's lower
// left, and the one open is a sheet below the picture. The figure grows by the sheet, so the surface
// stays whole in view and nothing is drawn past the figure's box. A figure whose page fixes its height
// (the full page) shows the sheet over the picture's lower part instead. A box that opens (a cell
// picked, the step-through started) becomes the sheet, and the statistics when nothing else is open;
// closing the sheet's box, or tapping its tab again, gives the whole figure back to the picture.
//
// The state is the element's own (ElementInternals custom states, `:state(compact)`, `:state(sheet)`
// for a sheet below, `:state(over)` for a sheet over the picture), so the page's attributes and classes
// are untouched; the styles are compact-style.js's.

/** Figures narrower than this, in CSS pixels, open their boxes one at a time. */
export const COMPACT_PX = 440;

/** The boxes, by id, with their tabs' names; the first open of those marked `opens` is shown first. */
const BOXES = [
  { id: 'inspector', tab: 'Cell', opens: true },
  { id: 'march', tab: 'Steps', opens: true },
  { id: 'levels-box', tab: 'Levels', opens: true },
  { id: 'sphere-box', tab: 'Sphere', opens: true },
  { id: 'hud', tab: 'Statistics', opens: true },
  { id: 'panel', tab: 'Controls', opens: false },
];

export class FigureSheets {
  #ctx;
  #states;
  #compact = false;
  // The box shown as the sheet (its id), or null.
  #current = null;
  // Whether the sheet goes below the picture (the figure's height is its aspect ratio's) or over it.
  #below = true;

  constructor(ctx) {
    this.#ctx = ctx;
    this.#states = ctx.element.attachInternals?.().states ?? null;
    const tabs = ctx.$('tabs');
    tabs.addEventListener('click', (event) => {
      const button = event.target.closest('button[data-box]');
      if (button) this.toggle(button.dataset.box);
    });
    // Boxes open and close by their `hidden` attribute; the panel and the statistics are rebuilt.
    const watch = new MutationObserver((records) => this.#boxesChanged(records));
    for (const { id } of BOXES) watch.observe(ctx.$(id), {
      attributes: true, attributeFilter: ['hidden'], attributeOldValue: true, childList: id === 'panel',
    });
    new ResizeObserver(([entry]) => this.#resized(entry.contentRect.width)).observe(ctx.element);
  }

  /** True while the figure opens its boxes one at a time. */
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
    const compact = width > 0 && width < COMPACT_PX;
    if (compact === this.#compact) return;
    this.#compact = compact;
    this.#current = compact ? (BOXES.find((box) => box.opens && this.#open(box.id))?.id ?? null) : null;
    this.#render();
  }

  #boxesChanged(records) {
    if (!this.#compact) return;
    for (const { target, type, oldValue } of records) {
      if (type !== 'attributes') continue;
      const opened = !target.hidden && oldValue !== null;
      // A teaching box that opens becomes the sheet; the statistics only when no other is open.
      if (opened && target.id !== 'panel' && (target.id !== 'hud' || !this.#current)) this.#current = target.id;
      if (target.hidden && this.#current === target.id) this.#current = null;
    }
    this.#render();
  }

  #render() {
    const ctx = this.#ctx;
    const element = ctx.element;
    const shown = this.#compact && this.#current && this.#open(this.#current) ? this.#current : null;
    if (!shown) this.#current = null;
    // Below the picture only where the figure's height follows its width (not fixed by the page).
    if (shown && !this.#states?.has('sheet') && !this.#states?.has('over')) {
      this.#below = Math.abs(element.clientHeight - (element.clientWidth * 9) / 16) < 2;
    }
    this.#set('compact', this.#compact);
    this.#set('sheet', Boolean(shown) && this.#below);
    this.#set('over', Boolean(shown) && !this.#below);
    const buttons = [];
    for (const { id, tab } of BOXES) {
      const box = ctx.$(id);
      box.classList.toggle('shown', id === shown);
      if (id === shown) for (const details of box.querySelectorAll(':scope > details')) details.open = true;
      if (!this.#compact || box.hidden) continue;
      const button = document.createElement('button');
      button.type = 'button';
      button.dataset.box = id;
      button.textContent = tab;
      button.setAttribute('aria-controls', id);
      button.setAttribute('aria-expanded', String(id === shown));
      buttons.push(button);
    }
    const tabs = ctx.$('tabs');
    // Rebuilt only when the tabs differ, so a focused tab keeps its focus.
    const key = buttons.map((b) => `${b.dataset.box}:${b.getAttribute('aria-expanded')}`).join(' ');
    if (tabs.dataset.key !== key) {
      const focused = ctx.root.activeElement?.dataset?.box;
      tabs.dataset.key = key;
      tabs.replaceChildren(...buttons);
      if (focused) buttons.find((b) => b.dataset.box === focused)?.focus();
    }
    tabs.hidden = buttons.length === 0;
  }

  #set(state, on) {
    if (!this.#states) return;
    if (on) this.#states.add(state);
    else this.#states.delete(state);
  }
}
