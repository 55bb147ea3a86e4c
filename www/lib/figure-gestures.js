// What the pointer, the wheel and the keys do on a figure: the camera orbits; a click inspects a cell,
// or in edit mode picks, adds and drags spheres; with compare=split a press on the divider drags it;
// the panel's actions have their keys. The element hands
// in its parts; this module only routes gestures between them.

import { wireCameraInput } from './camera-input.js';

/**
 * Wires gestures on `canvas` and keys on `element`. `parts`: state (the figure's settings), set(name,
 * value), actions (the panel's), flash(id, text, ms), editor, inspector, view() (the wasm view or null).
 */
export function wireFigureGestures(element, canvas, { state, set, actions, flash, editor, inspector, view }) {
  const editing = () => state.edit && view() !== null;
  // Canvas pixels per CSS pixel, along x and y.
  const scale = () => [canvas.width / Math.max(1, canvas.clientWidth), canvas.height / Math.max(1, canvas.clientHeight)];
  // The split view's divider, grabbed within a few CSS pixels of it.
  const DIVIDER_REACH = 8;
  const dividerDrag = (x) => {
    const width = Math.max(1, canvas.clientWidth);
    if (state.compare !== 'split' || Math.abs(x - state.divider * width) > DIVIDER_REACH) return null;
    return {
      move: (mx) => set('divider', Number(Math.min(0.95, Math.max(0.05, mx / width)).toFixed(3))),
      end: () => {},
    };
  };
  wireCameraInput(element, canvas, {
    get: () => ({ yaw: state.yaw, pitch: state.pitch, distance: state.distance }),
    set: (camera) => {
      for (const [name, value] of Object.entries(camera)) set(name, Number(value.toFixed(3)));
    },
  }, {
    ...actions,
    hint: (text) => flash('wheel-hint', text, 1500),
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
