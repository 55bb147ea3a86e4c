// How each parameter reaches the wasm view: one setter call per renderer setting. The others (speed,
// paused, controls, hud, autoplay, max-pixel-ratio, alt, poster, sync) live in the element alone.

import { resolvedTheme } from './look.js';

function hexToLinear(hex) {
  const channel = (i) => {
    const c = parseInt(hex.slice(1 + 2 * i, 3 + 2 * i), 16) / 255;
    return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
  };
  return [channel(0), channel(1), channel(2)];
}

// The view options, light strengths and field of view go through one setter by name, as text.
const BY_NAME = [
  'display', 'grid', 'color_by', 'slice', 'ambiguous', 'interpolation', 'blend', 'light', 'spot_angle',
  'spot_softness', 'ambient', 'diffuse', 'specular', 'projection', 'fov', 'mesher', 'lod_pixels', 'lod_freeze',
  'compare', 'divider', 'extractor',
];

const SETTERS = {
  spheres: (view, s) => view.set_sphere_count(s.spheres),
  iso: (view, s) => view.set_iso(s.iso),
  // Each allows resolutions the other does not: both at once.
  resolution: (view, s) => view.set_grid(s.resolution, s.lod),
  lod: (view, s) => view.set_grid(s.resolution, s.lod),
  seed: (view, s) => view.set_seed(s.seed),
  yaw: (view, s) => view.set_camera(s.yaw, s.pitch, s.distance),
  pitch: (view, s) => view.set_camera(s.yaw, s.pitch, s.distance),
  distance: (view, s) => view.set_camera(s.yaw, s.pitch, s.distance),
  shininess: (view, s) => view.set_shininess(s.shininess),
  color: (view, s) => view.set_color(...hexToLinear(s.color)),
  antialiasing: (view, s) => view.set_antialiasing(s.antialiasing),
  // `auto` is the reader's colour scheme here.
  theme: (view, s) => view.set_parameter('theme', resolvedTheme(s.theme)),
  ...Object.fromEntries(BY_NAME.map((name) => [name, (view, s) => view.set_parameter(name, String(s[name]))])),
};

/** Gives `view` the value of `name` in `state`; throws with the renderer's message when it refuses. */
export function applySetting(view, name, state) {
  SETTERS[name](view, state);
}
