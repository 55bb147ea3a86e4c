// Files in and out of a figure: scene documents (saved, loaded from a picker or dropped on the
// figure), the mesh as STL, OBJ or PLY, and PNG pictures at the canvas size or twice it. Checking and
// encoding happen in the wasm; this module moves bytes between it and the browser.

import { wasmModule } from '../engine/wasm.js';

const MESH_TYPES = { stl: 'model/stl', obj: 'model/obj', ply: 'application/ply' };

/** Reads a dropped or picked file as a scene document's text; throws when it is too large. */
export async function readSceneFile(file) {
  wasmModule().check_scene_size(file.size);
  return file.text();
}

/** A blob of mesh file `bytes` in `format`. */
export const meshBlob = (bytes, format) => new Blob([bytes], { type: MESH_TYPES[format] });

/**
 * Wires dropping files on `target`: `accept()` says whether drops are taken now; `load(file)` takes
 * the first file dropped. While a file is dragged over, `target` has the `dropping` class.
 */
export function wireDrop(target, accept, load) {
  const hasFiles = (e) => accept() && [...(e.dataTransfer?.types ?? [])].includes('Files');
  target.addEventListener('dragover', (e) => {
    if (!hasFiles(e)) return;
    e.preventDefault();
    e.dataTransfer.dropEffect = 'copy';
    target.classList.add('dropping');
  });
  target.addEventListener('dragleave', () => target.classList.remove('dropping'));
  target.addEventListener('drop', (e) => {
    target.classList.remove('dropping');
    if (!hasFiles(e)) return;
    e.preventDefault();
    const [file] = e.dataTransfer.files;
    if (file) load(file);
  });
}
