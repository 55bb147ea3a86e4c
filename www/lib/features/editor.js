// Hands on the spheres (the `edit` attribute): hovering rings the sphere under the pointer, dragging
// it moves it in the plane facing the camera (the animation holds still meanwhile), Shift-click on
// empty space adds one, Delete or Backspace removes the selected one, the wheel or the slider changes
// its radius, F freezes it or lets it move again, N makes it subtract its term (a dent) or add it again. On touch, a long press on a sphere selects and drags
// it, and on empty space adds one.
// Everything is computed by the wasm view on the CPU from the sphere list: no mesh is read back. The
// selected sphere's box speaks the figure's language, and is made again when the language changes.

import { LIMITS, rowOf } from '../core/table.js';
import { ONE_FRAME } from '../core/redraw.js';

// The radii the scene accepts, and the slider's step.
const RADIUS = { min: LIMITS.radius[0], max: LIMITS.radius[1], step: 0.01 };

function make(tag, properties = {}, ...children) {
  const node = Object.assign(document.createElement(tag), properties);
  node.append(...children);
  return node;
}

export class SphereEditor {
  static attributes = ['edit'];
  #ctx;
  #root;
  #hooks;
  #hovered = -1;
  #selected = -1;
  #dragging = false;
  // Velocities of frozen spheres, to give back when they are let go.
  #frozen = new Map();
  #box;
  #rings;

  constructor(ctx) {
    this.#ctx = ctx;
    this.#root = ctx.root;
    // What the editor reaches: the wasm view, device pixels per CSS pixel, the figure after every
    // change to the spheres (the scene's feature adopts them), a frame without a change, a refusal's notice.
    this.#hooks = {
      view: () => ctx.view,
      scale: () => ctx.canvas.width / Math.max(1, ctx.canvas.clientWidth),
      edited: () => ctx.each('spheresEdited'),
      redraw: () => ctx.redraw(ONE_FRAME),
      notice: (error) => ctx.notice(ctx.words.refusal(error)),
    };
    this.#rings = ctx.$('edit-overlay');
    this.#box = ctx.$('sphere-box');
  }

  changed(name, value) {
    this.reset();
    this.#ctx.canvas.classList.toggle('editing', value);
  }

  /** A sphere being dragged holds the animation still. */
  holds() { return this.#dragging; }

  afterTick() {
    if (this.#ctx.state.edit) this.draw();
  }

  /** A new renderer, or spheres replaced: nothing stays selected. */
  restored() { this.reset(); }

  spheresReplaced() { this.reset(); }

  language() { this.#showBox(); }

  controls() {
    return {
      edit: ({ element, builders }) => {
        const hint = element('p', { className: 'hint', textContent: this.#ctx.t('editor.hint') });
        hint.dataset.t = 'editor.hint';
        return [builders.boolean('edit', rowOf('edit')), hint];
      },
    };
  }

  /** The selected sphere's index, or -1. */
  get selected() { return this.#selected; }

  /** True while a sphere is being dragged (the animation holds still). */
  get dragging() { return this.#dragging; }

  #px(x, y) {
    const s = this.#hooks.scale();
    return [x * s, y * s];
  }

  #pick(x, y) {
    return this.#hooks.view()?.pick_sphere(...this.#px(x, y)) ?? -1;
  }

  /** The pointer moved over the figure with no button down (CSS pixels). */
  hover(x, y) {
    const index = this.#pick(x, y);
    if (index !== this.#hovered) {
      this.#hovered = index;
      this.draw();
    }
  }

  leave() {
    this.#hovered = -1;
    this.draw();
  }

  /** A press at (x, y): over a sphere, selects it and returns the drag; otherwise null (orbit). */
  grab(x, y) {
    const index = this.#pick(x, y);
    if (index < 0) return null;
    this.select(index);
    this.#dragging = true;
    let last = this.#px(x, y);
    return {
      move: (mx, my) => {
        const next = this.#px(mx, my);
        this.#try(() => this.#hooks.view()?.move_sphere(this.#selected, ...last, ...next));
        last = next;
        this.#hooks.redraw();
      },
      end: () => {
        this.#dragging = false;
        this.#hooks.edited();
        this.#showBox();
      },
    };
  }

  /** A click (a press that did not move): Shift on empty space adds a sphere there; else selects. */
  click(x, y, shift) {
    const index = this.#pick(x, y);
    if (index < 0 && shift) {
      this.add(x, y);
      return;
    }
    this.select(index);
  }

  /** Adds a still sphere under (x, y) at the depth of the box's centre and selects it; true if added. */
  add(x, y) {
    const added = this.#try(() => this.#hooks.view()?.add_sphere(...this.#px(x, y)));
    if (added === null || added === undefined) return false;
    this.#hooks.edited();
    this.select(added);
    return true;
  }

  /** The wheel over the figure: with a sphere selected, its radius (true: the wheel was used). */
  wheel(deltaY) {
    if (this.#selected < 0) return false;
    const radius = this.#radius();
    this.setRadius(radius * Math.exp(-deltaY * 0.001));
    return true;
  }

  select(index) {
    this.#selected = index;
    this.#showBox();
    this.draw();
  }

  deselect() {
    if (this.#selected < 0) return false;
    this.select(-1);
    return true;
  }

  remove() {
    if (this.#selected < 0) return;
    const index = this.#selected;
    if (this.#try(() => this.#hooks.view()?.remove_sphere(index)) === null) return;
    this.#frozen.clear();
    this.#selected = -1;
    this.#hovered = -1;
    this.#hooks.edited();
    this.#showBox();
    this.draw();
  }

  setRadius(radius) {
    if (this.#selected < 0) return;
    const r = Math.min(RADIUS.max, Math.max(RADIUS.min, radius));
    this.#try(() => this.#hooks.view()?.set_sphere_radius(this.#selected, r));
    this.#hooks.edited();
    this.#showBox();
  }

  /** Freezes the selected sphere (velocity zero) or lets it move again. */
  toggleFreeze() {
    const index = this.#selected;
    const sphere = this.#sphere(index);
    if (!sphere) return;
    const moving = sphere.slice(4).some((v) => v !== 0);
    let velocity = [0, 0, 0];
    if (moving) {
      this.#frozen.set(index, sphere.slice(4));
    } else {
      // Its old velocity, or (a sphere added by hand) a gentle one in a random direction.
      const angle = Math.random() * 2 * Math.PI;
      velocity = this.#frozen.get(index) ?? [0.3 * Math.cos(angle), 0.15, 0.3 * Math.sin(angle)];
      this.#frozen.delete(index);
    }
    this.#try(() => this.#hooks.view()?.set_sphere_velocity(index, ...velocity));
    this.#hooks.edited();
    this.#showBox();
  }

  /** Makes the selected sphere subtract its term from the field (charge −1), or add it again. */
  toggleCharge() {
    const sphere = this.#sphere(this.#selected);
    if (!sphere) return;
    this.#try(() => this.#hooks.view()?.set_sphere_charge(this.#selected, sphere[3] < 0 ? 1 : -1));
    this.#hooks.edited();
    this.#showBox();
  }

  // Runs a view call; a refusal becomes a notice (the scene stays as it was). Returns the result, or
  // null when refused.
  #try(f) {
    try {
      return f();
    } catch (error) {
      this.#hooks.notice(error);
      return null;
    }
  }

  #sphere(index) {
    const spheres = this.#hooks.view()?.spheres();
    return spheres && index >= 0 && 7 * index < spheres.length ? Array.from(spheres.slice(7 * index, 7 * index + 7)) : null;
  }

  // The page carries a subtracting sphere's radius negative.
  #radius() {
    return Math.abs(this.#sphere(this.#selected)?.[3] ?? 0.2);
  }

  /** The view was rebuilt or its spheres replaced: nothing stays selected. */
  reset() {
    this.#selected = -1;
    this.#hovered = -1;
    this.#dragging = false;
    this.#frozen.clear();
    this.#showBox();
    this.draw();
  }

  #showBox() {
    const sphere = this.#sphere(this.#selected);
    this.#box.hidden = !sphere;
    if (!sphere) return;
    const { words } = this.#ctx;
    const t = (key, fields) => words.t(key, fields);
    const count = (this.#hooks.view()?.spheres().length ?? 0) / 7;
    const moving = sphere.slice(4).some((v) => v !== 0);
    const subtracts = sphere[3] < 0;
    const radius = Math.abs(sphere[3]);
    const slider = make('input', { type: 'range', id: 'sphere-radius' });
    slider.min = String(RADIUS.min);
    slider.max = String(RADIUS.max);
    slider.step = String(RADIUS.step);
    slider.value = String(radius);
    const output = make('output', { htmlFor: 'sphere-radius', textContent: words.fixed(radius, 2) });
    slider.addEventListener('input', () => {
      output.textContent = words.fixed(Number(slider.value), 2);
      this.setRadius(Number(slider.value));
    });
    const freeze = make('button', { type: 'button', id: 'sphere-freeze', textContent: t(moving ? 'editor.freeze' : 'editor.let-move') });
    freeze.title = t('editor.freeze-title');
    freeze.addEventListener('click', () => this.toggleFreeze());
    const charge = make('button', { type: 'button', id: 'sphere-charge', textContent: t(subtracts ? 'editor.add' : 'editor.subtract') });
    charge.title = t(subtracts ? 'editor.add-title' : 'editor.subtract-title');
    charge.setAttribute('aria-pressed', String(subtracts));
    charge.addEventListener('click', () => this.toggleCharge());
    const remove = make('button', { type: 'button', id: 'sphere-remove', textContent: t('editor.remove') });
    remove.title = t('editor.remove-title');
    remove.addEventListener('click', () => this.remove());
    const close = make('button', { type: 'button', className: 'close', textContent: '×', title: t('editor.close-title') });
    close.addEventListener('click', () => this.deselect());
    const [x, y, z] = sphere.slice(0, 3).map((c) => words.fixed(c === 0 ? 0 : c, 2));
    const where = `editor.where.${moving ? 'moving' : 'still'}${subtracts ? '-subtracts' : ''}`;
    this.#box.replaceChildren(
      make('header', {}, make('h3', { textContent: t('editor.title', { index: this.#selected + 1, count }) }), close),
      make('p', { textContent: t(where, { x, y, z }) }),
      make('div', { className: 'control' }, make('label', { htmlFor: 'sphere-radius', textContent: t('editor.radius') }), slider, output),
      make('div', { className: 'buttons' }, freeze, charge, remove),
      make('p', { className: 'hint', textContent: t('editor.box-hint') }),
    );
  }

  /** Rings the hovered and the selected sphere where they are now (called every frame). */
  draw() {
    const view = this.#hooks.view();
    const s = this.#hooks.scale();
    const ring = (id, index) => {
      const circle = this.#rings.getElementById(id);
      const at = index >= 0 && view ? view.sphere_on_screen(index) : null;
      circle.toggleAttribute('hidden', !at);
      if (!at) return;
      circle.setAttribute('cx', String(at[0] / s));
      circle.setAttribute('cy', String(at[1] / s));
      circle.setAttribute('r', String(Math.max(4, at[2] / s)));
    };
    ring('hover-ring', this.#hovered !== this.#selected ? this.#hovered : -1);
    ring('selected-ring', this.#selected);
  }
}
