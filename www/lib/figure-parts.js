// The parts a figure is made of besides its frames: the shape watch (topology and pause_on), the cell
// inspector, the sphere editor and the scene's files. Each reaches the renderer through the figure's
// frames; the element hands in how to change its settings and show messages.

import { caseGallery } from './engine.js';
import { Inspector } from './inspector.js';
import { SphereEditor } from './editor.js';
import { SceneIO } from './scene-io.js';
import { TopologyWatch } from './topology-watch.js';

/**
 * `p`: { root, canvas, frames (a FigureFrames), hud, look, state(), set(name, value), adopt(name, value),
 * pause(), showPanel(caseClass), notice(text, ms), emit(type, detail) }. Returns { topology, inspector,
 * editor, io }.
 */
export function makeFigureParts(p) {
  const view = () => p.frames.view;
  const topology = new TopologyWatch({
    view,
    state: p.state,
    hud: p.hud,
    announce: (text) => p.look.announce(text),
    pause: p.pause,
  });
  const inspector = new Inspector(p.root, () => caseGallery().cube, {
    view,
    iso: () => p.state().iso,
    onShow: (report) => {
      p.frames.redraw(2);
      p.emit('metaballs-inspect', { cell: report });
    },
    onClass: p.showPanel,
  });
  let io = null;
  const editor = new SphereEditor(p.root, {
    view,
    scale: () => p.canvas.width / Math.max(1, p.canvas.clientWidth),
    edited: () => io.edited(),
    redraw: () => p.frames.redraw(1),
    notice: (text) => p.notice(text),
  });
  io = new SceneIO({
    view,
    state: p.state,
    set: p.set,
    adopt: p.adopt,
    apply: () => p.frames.apply(),
    restoreLater: (packed) => { p.frames.savedSpheres = packed; },
    changed: () => p.frames.redraw(2),
    editor,
    canvas: p.canvas,
    ready: () => p.frames.nextFrame(),
    notice: p.notice,
    emit: p.emit,
  });
  return { topology, inspector, editor, io };
}
