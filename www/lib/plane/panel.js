// The 2D figure's panel (`controls="iso,resolution,saddle,…"` or `all`): a folding box over the
// figure's corner with a control per setting, each built from the setting's row of the 2D figure's
// table (slider, words, flag): the shared settings, further levels, what to show, the step-through,
// and a hint on adding or removing circles. Each control sets the figure's attribute, so its checks,
// notice and link apply as to a value given in the page.

import { PLANE_TABLE } from '../attributes.js';
import { SHOWN } from './picture.js';
import { shownList } from './frames.js';
import { PlaneInside } from './plane-circles.js';
import { PlaneScene } from './scene-file.js';

/** The panel's controls, in order (the words of the table's `controls` row); `all` lists them all. */
export const PANEL_CONTROLS = PLANE_TABLE.find((row) => row.name === 'controls').words;

const STYLE = `
.panel { position: absolute; top: 8px; left: 8px; max-width: min(260px, calc(100% - 16px));
  max-height: calc(100% - 16px); overflow: auto; z-index: 1; border-radius: 6px;
  font: 12.5px/1.4 system-ui, sans-serif; color: var(--metaballs-text, #d7dbe4);
  background: var(--metaballs-panel-background, rgba(20, 23, 31, 0.92)); }
.panel summary { padding: 4px 8px; cursor: pointer; }
.panel .rows { display: grid; grid-template-columns: auto minmax(0, 1fr) auto; gap: 4px 6px; align-items: center;
  padding: 2px 8px 8px; }
.panel label, .panel .label { white-space: nowrap; }
.panel input[type=range] { width: 100%; }
.panel input[type=checkbox] { justify-self: start; }
.panel .checks { grid-column: 2 / 4; display: flex; flex-wrap: wrap; gap: 0 8px; }
.panel .wide { grid-column: 2 / 4; }
.panel button, .panel select, .panel input { font: inherit; }
.panel output { font-variant-numeric: tabular-nums; min-width: 3em; text-align: right; }`;

const html = (text) => String(text).replace(/&/g, '&amp;').replace(/</g, '&lt;').replace(/"/g, '&quot;');

/**
 * Builds the panel into `host` with the controls named in `names`; `rowOf(name)` gives a setting's
 * row of the 2D figure's table; `figure` is `{ get(name) (the value in effect, as text), set(name, text),
 * action(name) }`. Returns `update()`, which shows the values in effect.
 */
export function planePanel(host, names, rowOf, figure, controlId = (name) => name) {
  const rows = names.map((name) => {
    // Named as in earlier versions (`control-levels`), so that styles and scripts still find it.
    const id = `control-${controlId(name)}`;
    const row = rowOf(name);
    if (name === 'show') {
      return `<span class="label">Show</span><span class="checks" role="group" aria-label="Show">${SHOWN.map((w) => `<label><input type="checkbox" data-show="${w}"> ${w}</label>`).join('')}</span>`;
    }
    if (row?.kind === 'levels') {
      return `<label for="${id}">${html(row.label)}</label><input id="${id}" class="wide" data-name="${name}" placeholder="e.g. 0.6,1.6">`;
    }
    if (name === 'step-through') return '<span></span><button type="button" class="wide" data-action="step-through">Step through the march</button>';
    if (name === 'circles') return '<span></span><span class="wide">Double-click to add a circle or remove one; drag to move it.</span>';
    if (name === 'share') return '<span></span><button type="button" class="wide" data-action="share">Share…</button>';
    if (name === 'scene') {
      return '<span class="label">Scene</span><span class="checks"><button type="button" data-action="save-scene">Save scene</button>'
        + '<button type="button" data-action="load-scene">Load scene…</button><input type="file" accept=".json,application/json" hidden></span>';
    }
    if (row.kind === 'boolean') return `<label for="${id}">${html(row.label)}</label><input type="checkbox" id="${id}" data-name="${name}"><span></span>`;
    if (row.kind === 'choice') {
      return `<label for="${id}">${html(row.label)}</label><select id="${id}" data-name="${name}" class="wide">${row.words.map((w) => `<option>${w}</option>`).join('')}</select>`;
    }
    // A number without a slider's range (the seed) is typed in.
    if (row.sliderMax <= row.sliderMin) {
      return `<label for="${id}">${html(row.label)}</label><input type="number" id="${id}" class="wide" data-name="${name}" min="${row.min}" max="${row.max}" step="1">`;
    }
    return `<label for="${id}">${html(row.label)}</label><input type="range" id="${id}" data-name="${name}" min="${row.sliderMin}" max="${row.sliderMax}" step="${row.step || 1}"><output for="${id}"></output>`;
  });
  host.innerHTML = `<style>${STYLE}</style><details class="panel" part="panel"><summary>Controls</summary><div class="rows">${rows.join('')}</div></details>`;
  const panel = host.querySelector('.panel');
  const inputs = [...panel.querySelectorAll('[data-name]')];
  const shows = [...panel.querySelectorAll('[data-show]')];
  // On the panel itself, made anew with each `controls`, so a rebuilt panel hears each event once.
  panel.addEventListener('input', (e) => {
    const input = e.target;
    if (input.type === 'range') input.nextElementSibling.textContent = input.value;
  });
  panel.addEventListener('change', (e) => {
    const input = e.target;
    if (input.dataset.show) {
      figure.set('show', shows.filter((s) => s.checked).map((s) => s.dataset.show).join(',') || 'contour');
    } else if (input.dataset.name) {
      figure.set(input.dataset.name, input.type === 'checkbox' ? String(input.checked) : input.value);
    }
  });
  panel.addEventListener('click', (e) => {
    const action = e.target.closest('[data-action]')?.dataset.action;
    if (action) figure.action(action);
  });
  return () => {
    for (const input of inputs) {
      if (input === host.getRootNode().activeElement) continue;
      const value = figure.get(input.dataset.name);
      if (input.type === 'checkbox') input.checked = value === 'true';
      else input.value = value;
      if (input.type === 'range') input.nextElementSibling.textContent = value;
    }
    const shown = shownList(figure.get('show'));
    for (const s of shows) s.checked = shown.includes(s.dataset.show);
  };
}

/**
 * The panel as a feature of the 2D figure: built from `controls` (the table's reader has checked the
 * names), showing the values in effect after every change, each control setting its value as the
 * figure's attribute would be set, each button running the figure's action of its name.
 */
export class PlanePanel {
  static attributes = ['controls'];
  #ctx;
  #update = null;

  constructor(ctx) { this.#ctx = ctx; }

  changed(_name, text) {
    const names = text === 'all' ? PANEL_CONTROLS : text === 'none' ? [] : text.split(',');
    const host = this.#ctx.root.querySelector('.controls');
    this.#update = null;
    host.replaceChildren();
    if (names.length === 0) return;
    const ctx = this.#ctx;
    this.#update = planePanel(host, names, (name) => ctx.settings.rows.rowOf(name), {
      get: (name) => String(ctx.state[name]),
      set: (name, value) => ctx.get(PlaneInside).setText(name, value),
      action: (name) => (name === 'load-scene' ? host.querySelector('input[type=file]').click() : ctx.actions[name]()),
    }, (name) => ctx.settings.rows.controlId(name));
    const file = host.querySelector('input[type=file]');
    file?.addEventListener('change', () => ctx.get(PlaneScene).loadFile(file));
    this.#update();
  }

  refresh() { this.#update?.(); }
}
