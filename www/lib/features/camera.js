// The camera and what the pointer, the wheel and the keys do on a figure: the camera orbits; a click
// inspects a cell, or in edit mode picks, adds and drags spheres; with compare=split a press on the
// divider drags it; the panel's actions have their keys. This feature routes gestures between the
// inspector and the editor, and owns the reset of the view.

import { clampTo, defaults } from '../core/table.js';
import { SphereEditor } from './editor.js';
import { wireCameraInput } from './gestures.js';
import { Inspector } from './inspector.js';

/** The settings of the camera (a gesture moves them; a sync group shares them). */
export const CAMERA = ['yaw', 'pitch', 'distance'];

export class Camera {
  #ctx;

  constructor(ctx) {
    this.#ctx = ctx;
    ctx.actions.resetView = () => this.resetView();
  }

  /** Back to the default camera. */
  resetView() {
    const d = defaults();
    for (const name of CAMERA) this.#ctx.set(name, d[name]);
  }

  controls() {
    return {
      view: ({ makeButton }) => makeButton('reset-view', { key: 'action.view' }, { key: 'play.reset-title' }, this.#ctx.actions.resetView),
    };
  }

  /** Wires the gestures, once every feature they reach is made. */
  wire() {
    const ctx = this.#ctx;
    wireFigureGestures(ctx, ctx.get(SphereEditor), ctx.get(Inspector));
  }
}

function wireFigureGestures(ctx, editor, inspector) {
  const { element, canvas, state, actions } = ctx;
  const set = (name, value) => ctx.set(name, value);
  const view = () => ctx.view;
  const editing = () => state.edit && view() !== null;
  // Canvas pixels per CSS pixel, along x and y.
  const scale = () => [canvas.width / Math.max(1, canvas.clientWidth), canvas.height / Math.max(1, canvas.clientHeight)];
  // The split view's divider, grabbed within a few CSS pixels of it.
  const DIVIDER_REACH = 8;
  const dividerDrag = (x) => {
    const width = Math.max(1, canvas.clientWidth);
    if (state.compare !== 'split' || Math.abs(x - state.divider * width) > DIVIDER_REACH) return null;
    return {
      move: (mx) => set('divider', Number(clampTo('divider', mx / width).toFixed(3))),
      end: () => {},
    };
  };
  wireCameraInput(element, canvas, {
    get: () => ({ yaw: state.yaw, pitch: state.pitch, distance: state.distance }),
    set: (camera) => {
      for (const [name, value] of Object.entries(camera)) set(name, Number(clampTo(name, value).toFixed(3)));
    },
  }, {
    ...actions,
    hint: (key) => ctx.flash('wheel-hint', ctx.t(key), 1500),
    pick: (x, y, e) => {
      if (editing()) return editor.click(x, y, e.shiftKey);
      const [sx, sy] = scale();
      return inspector.pick(x * sx, y * sy);
    },
    deselect: () => element.deselect(),
    grab: (x, y) => dividerDrag(x) ?? (editing() ? editor.grab(x, y) : null),
    hold: (x, y) => editing() && editor.add(x, y),
    hover: (x, y) => editing() && editor.hover(x, y),
    leave: () => editor.leave(),
    wheel: (deltaY) => editing() && editor.wheel(deltaY),
    remove: () => editing() && editor.remove(),
    freeze: () => editing() && editor.toggleFreeze(),
    charge: () => editing() && editor.toggleCharge(),
  });
}
