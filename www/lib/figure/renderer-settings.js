// How the settings reach the wasm view: every renderer setting by its name, as text, through the one
// entry the view has (`set_parameter`); the level of detail and the resolution together
// (`set_parameters`), as each allows resolutions the other does not. The theme `auto` is the reader's
// colour scheme here. The other settings (speed, paused, controls, …: the table's scope 'element')
// live in the element alone.

import { resolvedTheme } from './look.js';

// Settings that are only checked together: one change sends all of them.
const TOGETHER = [['resolution', 'lod']];

const text = (name, value) => (name === 'theme' ? resolvedTheme(value) : String(value));

/** Gives `view` the value of `name` in `state`; throws with the renderer's message when it refuses. */
export function applySetting(view, name, state) {
  const group = TOGETHER.find((names) => names.includes(name));
  if (group) {
    view.set_parameters(group, group.map((n) => text(n, state[n])));
  } else {
    view.set_parameter(name, text(name, state[name]));
  }
}
