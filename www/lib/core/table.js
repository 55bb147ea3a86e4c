// The parameter table as the element reads it: every setting's canonical name, the old spellings still
// accepted (aliases), its property, default, range, panel group and scope. The table itself
// (attributes.js) is written from Rust by `metaballs manifest`, so the element knows its attributes,
// defaults and ranges before the wasm arrives; nothing here names a setting.

import { CONTROLS, LIMITS, TABLE } from '../attributes.js';
import { Rows } from './rows.js';

export { CONTROLS, LIMITS, TABLE };

/** The 3D figure's rows by every spelling. */
export const VIEW_ROWS = new Rows(TABLE);

/** Canonical attribute names, in panel order. */
export const NAMES = VIEW_ROWS.names;

/** Every spelling an attribute may be given under: the names, short names and older spellings. */
export const SPELLINGS = VIEW_ROWS.spellings;

/** The table's row for a name or any of its aliases, or undefined. */
export const rowOf = (spelling) => VIEW_ROWS.rowOf(spelling);

/** The canonical name of a name or alias (itself when unknown). */
export const canonical = (spelling) => VIEW_ROWS.canonical(spelling);

/** The spellings of one parameter: its name first, then its short name and older spellings. */
export const spellingsOf = (name) => VIEW_ROWS.spellingsOf(name);

/** The element's property for a parameter (`max-pixel-ratio` → `maxPixelRatio`). */
export const propertyName = (spelling) => VIEW_ROWS.propertyName(spelling);

/** Property spellings kept from earlier versions (`color_by`, `spot_angle`, `balls`) → canonical name. */
export const OLD_PROPERTIES = VIEW_ROWS.oldProperties;

/** Attributes of plain text (a description, a URL): taken as written, even before the wasm arrives. */
export const TEXT_NAMES = VIEW_ROWS.textNames;

/** Settings a renderer takes when it is made. */
export const CREATION = new Set(TABLE.filter((p) => p.scope === 'creation').map((p) => p.name));

/** Settings of the renderer: given when it is made, or applied after. */
export const RENDERER = new Set(TABLE.filter((p) => p.scope === 'creation' || p.scope === 'renderer').map((p) => p.name));

/** The name of the row of `kind` (the one setting of that kind: `spheres` for the sphere list). */
export const nameOfKind = (kind) => TABLE.find((p) => p.kind === kind)?.name;

/** The names the `controls` attribute can list, in panel order. */
export const CONTROL_NAMES = CONTROLS.map((c) => c.name);

/** The default values of every parameter, typed. */
export const defaults = () => VIEW_ROWS.defaults();

/** The default value of one parameter, typed. */
export const defaultOf = (name) => rowOf(name).value;

/** The range a parameter accepts: [min, max]. */
export const rangeOf = (name) => {
  const row = rowOf(name);
  return [row.min, row.max];
};

/** Keeps `value` within parameter `name`'s range. */
export const clampTo = (name, value) => {
  const [min, max] = rangeOf(name);
  return Math.min(max, Math.max(min, value));
};

/** The id of a parameter's control in the panel (see Rows.controlId). */
export const controlId = (name) => VIEW_ROWS.controlId(name);
