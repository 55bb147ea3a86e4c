// The element's control panel, built from the parameter table for the controls an author lists
// (`controls="iso,resolution"`, `all` or `none`), in the table's groups (Surface, Display, Teaching,
// Light, Camera, Scene) that fold. A parameter gets the control of its kind (panel-controls.js); the
// actions and the inspector, editor and plot are built by the features that own them (their
// `controls()`). Compact and collapsible: small figures start with it folded, and it never takes more
// than a third of the figure's width. Its words are marked by key (the table's `setting.<name>`,
// `group.<group>`, `word.<name>.<word>`, `action.<name>`, and the panel's own) and worded as each
// group is filled; the figure words them again when its language changes (the numbers shown too).

import { CONTROL_NAMES, CONTROLS, rowOf } from '../core/table.js';
import { groupKey, mark, relabel } from '../i18n/words.js';
import { hub } from '../engine/hub.js';
import { colorKey } from './legends.js';
import { caseGallery } from '../engine/wasm.js';
import { controlBuilders, element, makeButton } from './panel-controls.js';

/** The control names `list` (the `controls` value) asks for, in the table's order. */
export function listedControls(list) {
  if (list === 'all') return CONTROL_NAMES;
  if (list === 'none' || !list) return [];
  const wanted = new Set(list.split(','));
  return CONTROL_NAMES.filter((name) => wanted.has(name));
}

export class Panel {
  static attributes = ['controls'];
  #ctx;
  #built = false;
  #updates = [];
  // Counts builds: the folded groups of an earlier build stop filling.
  #builds = 0;

  constructor(ctx) {
    this.#ctx = ctx;
  }

  // The panel is first built when the figure starts (after the attributes are read).
  changed() {
    if (this.#built) this.build();
  }

  // A figure about to start builds its panel once it knows its device (after its first frame); the
  // others (below the fold, paused) when the page's thread is idle, one figure at a time, so that a
  // page of many figures does not build every panel in the task that loads the wasm.
  loaded() {
    if (this.#ctx.frames.starting) return;
    const build = () => { if (!this.#built) this.build({ stepwise: true }); };
    if (typeof requestIdleCallback === 'function') requestIdleCallback(build, { timeout: 1000 });
    else setTimeout(build, 0);
  }

  deviceKnown() { this.build({ stepwise: true }); }

  refresh(state) {
    for (const update of this.#updates) update(state);
  }

  // The marked words are worded by the figure (`relabel`); the numbers and legends here.
  language() { this.refresh(this.#ctx.state); }

  /**
   * Builds the panel (emptied first) for the listed controls. `stepwise`: the folded groups are filled
   * one per task after this one (or when opened), so that a full panel is not one long task.
   */
  build({ stepwise = false } = {}) {
    const build = ++this.#builds;
    const ctx = this.#ctx;
    const { frames, state } = ctx;
    const container = ctx.$('panel');
    const names = new Set(listedControls(state.controls));
    this.#built = true;
    this.#updates = [];
    container.replaceChildren();
    container.hidden = names.size === 0;
    ctx.each('panelBuilt');
    if (!names.size) return;
    const width = ctx.element.clientWidth;
    const body = element('div', { className: 'controls' });
    const details = element('details', { open: !(width > 0 && width < 560) }, mark(element('summary'), { text: 'panel.controls' }), body);
    container.append(details);

    const maxResolution = hub.gpu?.max_resolution() ?? 512;
    const withoutCompute = Boolean(frames.gpu && !frames.gpu.has_compute());
    const builders = controlBuilders((name, value) => ctx.set(name, value), this.#updates, {
      maxResolution: frames.software ? Math.min(256, maxResolution) : maxResolution,
      words: () => ctx.words,
    });
    const own = Object.assign({}, ...ctx.collect('controls'));
    const helpers = { element, makeButton, builders, updates: this.#updates, gallery: caseGallery() };

    const groups = new Map();
    for (const control of CONTROLS.filter((c) => names.has(c.name))) {
      if (!groups.has(control.group)) groups.set(control.group, []);
      groups.get(control.group).push(control.name);
    }
    const folded = [];
    for (const [title, members] of groups) {
      const section = element('div', { className: 'group-body' });
      const group = element('details', { className: 'group', open: title === CONTROLS[0].group },
        mark(element('summary'), { text: title ? `group.${groupKey(title)}` : 'panel.more' }), section);
      body.append(group);
      let filled = false;
      const fill = () => {
        if (filled || build !== this.#builds) return;
        filled = true;
        const from = this.#updates.length;
        this.#fill(members, section, own, builders, helpers, withoutCompute);
        relabel(section, ctx.words);
        for (const update of this.#updates.slice(from)) update(ctx.state);
      };
      if (stepwise && !group.open) {
        folded.push(fill);
        group.addEventListener('toggle', fill, { once: true });
      } else {
        fill();
      }
    }
    body.append(element('slot', { name: 'panel-footer' }));
    body.append(mark(element('p', { className: 'hint' }), { text: 'panel.hint' }));
    relabel(details, ctx.words);
    const next = () => {
      if (build !== this.#builds || !folded.length) return;
      folded.shift()();
      setTimeout(next, 0);
    };
    setTimeout(next, 0);
  }

  // Fills one group's section with the controls of `members` (and the buttons among them).
  #fill(members, section, own, builders, helpers, withoutCompute) {
    const buttons = element('div', { className: 'buttons' });
    for (const name of members) {
      if (own[name]) {
        for (const node of [own[name](helpers)].flat()) {
          const isButton = node.tagName === 'BUTTON' || (node.tagName === 'SPAN' && node.classList.contains('buttons'));
          (isButton ? buttons : section).append(node);
        }
        continue;
      }
      const spec = rowOf(name);
      const control = builders[spec.kind](name, spec);
      if (withoutCompute && spec.compute) {
        for (const input of control.querySelectorAll('input, select')) input.disabled = true;
        control.dataset.tTitle = 'panel.needs-webgpu';
        control.classList.add('unavailable');
      }
      section.append(control);
      if (name === 'color-by') {
        const key = element('div', { className: 'key' });
        const classNames = helpers.gallery.classes.map((k) => k.name);
        this.#updates.push((s) => key.replaceChildren(...[colorKey(s, classNames, this.#ctx.words)].filter(Boolean)));
        section.append(key);
      }
    }
    if (buttons.childElementCount) section.append(buttons);
  }
}

