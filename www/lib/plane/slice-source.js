// A 2D figure following a 3D figure's slice plane (`slice-of`): the plane sampled as the 3D figure
// samples it (its spheres, grid, iso level, saddle rule and placement), and what those samples depend
// on, so that the 2D figure draws again only when they change. The 3D figure is read through its
// properties only.

import { sampleSlice } from './squares.js';

/** The <metaballs-view> with id `id` near `node` (its root, else the document) that has a slice, or null. */
export function followed(node, id) {
  const view = id ? node.getRootNode().getElementById?.(id) ?? document.getElementById(id) : null;
  return view && view.localName === 'metaballs-view' && /^[xyz]:/.test(view.slice ?? '') ? view : null;
}

/** What `view`'s slice plane gives: `{ values, cells, iso, options, circles }` as the 2D figure draws them. */
export function sliceSource(view) {
  const cells = Number(view.resolution);
  const [axisName, position] = view.slice.split(':');
  const axis = 'xyz'.indexOf(axisName);
  // The plane as the 3D figure rounds it to its grid.
  const plane = Math.min(cells, Math.round((Number(position) + 1) * 0.5 * cells));
  return {
    values: sampleSlice(view.sphereList, cells, axis, plane, view.blend, view.kernel, Number(view.blobbiness)), cells, iso: Number(view.iso),
    options: { placement: view.interpolation, saddle: view.saddle }, circles: [],
  };
}

/** What the samples of `view`'s slice depend on, as text. */
export function sliceKey(view) {
  const spheres = view.sphereList.map((b) => [...b.center, b.radius, b.charge].join(',')).join(';');
  return [spheres, view.slice, view.resolution, view.iso, view.saddle, view.interpolation, view.blend, view.kernel, view.blobbiness].join('|');
}
