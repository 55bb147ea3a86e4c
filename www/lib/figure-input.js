// One figure's input layer: camera gestures and keys (lib/camera-input.js) routed to the cell
// inspector, or in edit mode to the sphere editor (lib/editor.js); the scene file picker and file drops
// going to the figure's scene I/O (lib/scene-io.js). The element passes its state through `figure`.

import { wireCameraInput } from './camera-input.js';
import { SphereEditor } from './editor.js';
import { SceneIO } from './scene-io.js';
import { wireDrop } from './scene-files.js';

/**
 * Wires input on `host` (the element), its shadow `root` and `canvas`. `figure` has view(), state(),
 * set(name, value), adopt(name, value), apply(), restoreLater(packed), redraw(frames), notice(text, ms),
 * hint(text), ready(), acceptsFiles(), deselect(), the inspector, and the panel's `actions`. Returns
 * the sphere editor and the scene I/O.
 */
export function wireFigureInput(host, root, canvas, figure) {
  const scale = () => canvas.width / Math.max(1, canvas.clientWidth);
  let io = null;
  const editor = new SphereEditor(root, {
    view: figure.view,
    scale,
    edited: () => io.edited(),
    redraw: () => figure.redraw(1),
    notice: (text) => figure.notice(text),
  });
  io = new SceneIO({
    view: figure.view,
    state: figure.state,
    set: figure.set,
    adopt: figure.adopt,
    apply: figure.apply,
    restoreLater: figure.restoreLater,
    changed: () => figure.redraw(2),
    editor,
    canvas,
    ready: figure.ready,
    notice: figure.notice,
    emit: (type, detail) => host.dispatchEvent(new CustomEvent(type, { detail })),
  });
  const editing = () => figure.state().edit && figure.view() !== null;
  wireCameraInput(host, canvas, {
    get: () => {
      const { yaw, pitch, distance } = figure.state();
      return { yaw, pitch, distance };
    },
    set: (camera) => {
      for (const [name, value] of Object.entries(camera)) figure.set(name, Number(value.toFixed(3)));
    },
  }, {
    ...figure.actions,
    hint: figure.hint,
    pick: (x, y, e) => (editing() ? editor.click(x, y, e.shiftKey)
      : figure.inspector.pick(x * scale(), y * (canvas.height / Math.max(1, canvas.clientHeight)))),
    deselect: figure.deselect,
    grab: (x, y) => (editing() ? editor.grab(x, y) : null),
    hold: (x, y) => editing() && editor.add(x, y),
    hover: (x, y) => editing() && editor.hover(x, y),
    leave: () => editor.leave(),
    wheel: (deltaY) => editing() && editor.wheel(deltaY),
    remove: () => editing() && editor.remove(),
    freeze: () => editing() && editor.toggleFreeze(),
  });
  const file = root.getElementById('scene-file');
  file.addEventListener('change', () => {
    if (file.files[0]) io.loadFile(file.files[0]);
    file.value = '';
  });
  wireDrop(host, figure.acceptsFiles, (dropped) => io.loadFile(dropped));
  return { editor, io };
}
