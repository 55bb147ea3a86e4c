// The 2D figure's panel (`controls="iso,resolution,saddle,…"` or `all`): a folding box over the
// figure's corner with a control per setting, each built from the setting's row of the 2D figure's
// table (slider, words, flag): the shared settings, further levels, what to show, the step-through,
// and a hint on adding or removing circles. Each control sets the figure's attribute, so its checks,
// notice and link apply as to a value given in the page. Its words are the reader's language (the
// table's labels and words by their keys); the values it sets are the table's words, in any.

import { PLANE_TABLE } from '../attributes.js';
import { EN, relabel } from '../i18n/words.js';
import { numeral, SHOWN } from './picture.js';
import { shownList } from './frames.js';
import { PlaneInside } from './plane-circles.js';
import { PlaneScene } from './scene-file.js';

/** The panel's controls, in order (the words of the table's `controls` row); `all` lists them all. */
export const PANEL_CONTROLS = PLANE_TABLE.find((row) => row.name === 'controls').words;

const STYLE = `
.panel { position: absolute; top: 8px; inset-inline-start: 8px; max-width: min(260px, calc(100% - 16px));
  max-height: calc(100% - 16px); overflow: auto; z-index: 1; border-radius: 6px;
  font: 12.5px/1.4 system-ui, sans-serif; color: var(--metaballs-text, #d7dbe4);
  background: var(--metaballs-panel-background, rgba(20, 23, 31, 0.92)); }
.panel summary { padding: 4px 8px; cursor: pointer; }
.panel .rows { display: grid; grid-template-columns: auto minmax(0, 1fr) auto; gap: 4px 6px; align-items: center;
  padding: 2px 8px 8px; }
/* Labels wrap only where a language's words run long: the controls keep their room. */
.panel label, .panel .label { max-width: 9em; overflow-wrap: anywhere; }
.panel button { overflow-wrap: anywhere; }
.panel input[type=range] { width: 100%; }
.panel input[type=checkbox] { justify-self: start; }
.panel .checks { grid-column: 2 / 4; display: flex; flex-wrap: wrap; gap: 0 8px; }
.panel .wide { grid-column: 2 / 4; }
.panel button, .panel select, .panel input { font: inherit; }
.panel output { font-variant-numeric: tabular-nums; min-width: 3em; text-align: end; }`;

// A setting's label, and a word of its row, by key: the 2D figure's own where its row says otherwise
// than the 3D figure's (i18n/words.js, `tableMessages`).
const labelKey = (name) => (EN[`plane.setting.${name}`] === undefined ? `setting.${name}` : `plane.setting.${name}`);
const wordKey = (name, word) => (EN[`plane.word.${name}.${word}`] === undefined ? `word.${name}.${word}` : `plane.word.${name}.${word}`);

/**
 * Builds the panel into `host` with the controls named in `names`; `rowOf(name)` gives a setting's
 * row of the 2D figure's table; `figure` is `{ get(name) (the value in effect, as text), set(name, text),
 * action(name), words() (the figure's words, i18n/words.js) }`. Returns `update()`, which shows the
 * values in effect in the figure's language (its marked words are `relabel`'s).
 */
export function planePanel(host, names, rowOf, figure, controlId = (name) => name) {
  const rows = names.map((name) => {
    // Named as in earlier versions (`control-levels`), so that styles and scripts still find it.
    const id = `control-${controlId(name)}`;
    const row = rowOf(name);
    if (name === 'show') {
      return `<span class="label" data-t="${labelKey(name)}"></span><span class="checks" role="group" data-t-label="${labelKey(name)}">${SHOWN.map((w) => `<label><input type="checkbox" data-show="${w}"> <span data-t="${wordKey(name, w)}"></span></label>`).join('')}</span>`;
    }
    const label = `<label for="${id}" data-t="${labelKey(name)}"></label>`;
    if (row?.kind === 'levels') return `${label}<input id="${id}" class="wide" data-name="${name}" data-example>`;
    if (name === 'step-through') return '<span></span><button type="button" class="wide" data-action="step-through" data-t="action.step-through"></button>';
    if (name === 'circles') return '<span></span><span class="wide" data-t="plane.circles-hint"></span>';
    if (name === 'share') return '<span></span><button type="button" class="wide" data-action="share" data-t="share.button"></button>';
    if (name === 'scene') {
      return '<span class="label" data-t="plane.scene"></span><span class="checks"><button type="button" data-action="save-scene" data-t="scene.save"></button>'
        + '<button type="button" data-action="load-scene" data-t="scene.load"></button><input type="file" accept=".json,application/json" hidden></span>';
    }
    if (row.kind === 'boolean') return `${label}<input type="checkbox" id="${id}" data-name="${name}"><span></span>`;
    if (row.kind === 'choice') {
      return `${label}<select id="${id}" data-name="${name}" class="wide">${row.words.map((w) => `<option value="${w}" data-t="${wordKey(name, w)}"></option>`).join('')}</select>`;
    }
    // A number without a slider's range (the seed) is typed in.
    if (row.sliderMax <= row.sliderMin) {
      return `${label}<input type="number" id="${id}" class="wide" data-name="${name}" min="${row.min}" max="${row.max}" step="1">`;
    }
    return `${label}<input type="range" id="${id}" data-name="${name}" min="${row.sliderMin}" max="${row.sliderMax}" step="${row.step || 1}"><output for="${id}"></output>`;
  });
  host.innerHTML = `<style>${STYLE}</style><details class="panel" part="panel"><summary data-t="setting.controls"></summary><div class="rows">${rows.join('')}</div></details>`;
  relabel(host, figure.words());
  const panel = host.querySelector('.panel');
  const inputs = [...panel.querySelectorAll('[data-name]')];
  const shows = [...panel.querySelectorAll('[data-show]')];
  // On the panel itself, made anew with each `controls`, so a rebuilt panel hears each event once.
  // A slider's value as the language writes numbers.
  const show = (output, text) => { output.textContent = numeral(figure.words(), text); };
  panel.addEventListener('input', (e) => {
    const input = e.target;
    if (input.type === 'range') show(input.nextElementSibling, input.value);
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
    // An example of levels, written as the setting reads them.
    for (const input of panel.querySelectorAll('[data-example]')) input.placeholder = figure.words().t('plane.levels-example');
    for (const input of inputs) {
      if (input === host.getRootNode().activeElement) continue;
      const value = figure.get(input.dataset.name);
      if (input.type === 'checkbox') input.checked = value === 'true';
      else input.value = value;
      if (input.type === 'range') show(input.nextElementSibling, value);
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
      words: () => ctx.words,
    }, (name) => ctx.settings.rows.controlId(name));
    const file = host.querySelector('input[type=file]');
    file?.addEventListener('change', () => ctx.get(PlaneScene).loadFile(file));
    this.#update();
  }

  refresh() { this.#update?.(); }

  // Its marked words are worded by ctx.speak; the values shown, here.
  language() { this.#update?.(); }
}
