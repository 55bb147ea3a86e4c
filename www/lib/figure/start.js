// Making a figure's wasm view on the device it was given: the settings a device calls for first (the
// features' `starting` hook: no multisampling on a software adapter unless asked, a resolution and
// sphere count its frames can afford), then the view, at the default resolution with a notice when the
// device refuses the one asked for; and the settings marked for the new view to take.

import { CREATION, defaultOf, nameOfKind, RENDERER } from '../core/table.js';
import { wasmModule, within } from '../engine/wasm.js';

const SPHERES = nameOfKind('spheres');

/**
 * Makes the view of the figure whose context is `ctx` on `gpu`; `software` tells a software adapter.
 * Throws an Error saying why when even the default resolution cannot start.
 */
export function makeView(ctx, gpu, software) {
  const { settings } = ctx;
  const s = settings.state;
  if (software && !settings.given.has('antialiasing')) s.antialiasing = false;
  ctx.each('starting', { software, compute: gpu.has_compute() });
  // The settings the table gives the renderer when it is made, by name and as text.
  const create = (resolution) => {
    const names = [...CREATION];
    const texts = names.map((name) => String(name === 'resolution' ? resolution : s[name]));
    return within(ctx.element, () => wasmModule().View.create(gpu, ctx.canvas, names, texts));
  };
  let view;
  try {
    // With level of detail the resolution may be beyond a uniform grid's: the view starts uniform and
    // takes both from the `lod` setting.
    view = create(s.lod ? defaultOf('resolution') : s.resolution);
  } catch (error) {
    // Most likely a resolution beyond this device: start at the default and say why.
    const fallback = defaultOf('resolution');
    ctx.notice(ctx.t('notice.resolution-refused', { resolution: String(s.resolution), message: ctx.words.refusal(error) }));
    s.resolution = fallback;
    view = create(fallback);
  }
  // Every renderer setting not given at creation is applied to the new view.
  settings.applied = { ...s };
  settings.changed = new Set([...RENDERER].filter((name) => !CREATION.has(name)));
  if (s[SPHERES]) settings.changed.add(SPHERES);
  return view;
}
