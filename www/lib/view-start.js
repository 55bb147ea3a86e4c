// Making a figure's wasm view on the device it was given: the settings a device calls for first (no
// multisampling on a software adapter unless asked; a resolution and sphere count its frames can
// afford), then the view, at the default resolution with a notice when the device refuses the one
// asked for; and the settings marked for the new view to take.

import { hub, wasmModule, within } from './engine.js';
import { isRendererSetting } from './view-settings.js';
import { CREATION, NAMES, defaultOf, defaults } from './figure-state.js';

/**
 * Makes the view of figure `f` (see FigureFrames) on `gpu`; `software` tells a software adapter.
 * Throws an Error saying why when even the default resolution cannot start.
 */
export function makeView(f, gpu, software) {
  const settings = f.settings;
  f.hud.setAdapter(hub.adapter?.label ?? 'WebGPU');
  if (software && !settings.given.has('antialiasing')) settings.state.antialiasing = false;
  f.guard.start(software || !gpu.has_compute());
  for (const name of f.guard.startAffordably(settings.state, defaults())) settings.reflect(name);
  const s = settings.state;
  const create = (resolution) => within(f.element, () => wasmModule().View.create(
    gpu, f.canvas, s.spheres, s.iso, resolution, s.seed, s.antialiasing));
  let view;
  try {
    // With level of detail the resolution may be beyond a uniform grid's: the view starts uniform and
    // takes both from the `lod` setting.
    view = create(s.lod ? defaultOf('resolution') : s.resolution);
  } catch (error) {
    // Most likely a resolution beyond this device: start at the default and say why.
    const fallback = defaultOf('resolution');
    f.notice(`resolution ${s.resolution}: ${error.message}`);
    s.resolution = fallback;
    view = create(fallback);
  }
  // Every renderer setting not given at creation is applied to the new view.
  settings.applied = { ...s };
  settings.changed = new Set(NAMES.filter((name) => (isRendererSetting(name) && !CREATION.has(name))
    || (name === 'balls' && s.balls)));
  return view;
}
