// The page's mesher worker: a second instance of the page's WebAssembly build, started in a worker,
// that meshes the frames the figures' CPU mesher would otherwise mesh on the page's thread. It is told
// where the build's JavaScript and WebAssembly are (`{ glue, wasm }`, whole URLs: the file imports
// nothing itself, so it works wherever a bundler copies it) and given the page's compiled module
// (`compiled`, so it only instantiates it) where there is one, and says when it is ready (or why it
// failed), then answers each `{ id, job }` (a view's packed mesh job) with the mesh's vertices and
// indices, handed over without a copy, each `{ id, job, slab: [from, to] }` with the mesh of the
// layers of cells from `from` to `to` and the grid edge of each vertex (`mesh_slab`, for slabs.js), each `{ id, shape: [vertex count, triangles] }` with the
// mesh's shape (`mesh_shape`: blobs, genus, closed, manifold) and each `{ id, png: [pixels, width,
// height] }` (RGBA8 rows, top first) with the picture as a PNG blob, each `{ id, decided: job }` (a
// view's `cpu_job(true)`) with the cells whose triangles the asymptotic decider or MC33 changes, with
// their kind (`mesh_job`'s last part), or with what went wrong.

let started = null;
// A Rust panic in this instance: the job that raised it is answered with it.
let panic = null;
globalThis.metaballsShowPanic = (message) => { panic = message; };

// Encoded in a canvas of this thread's own: on the page's thread, putting the pixels in a canvas takes
// tens of milliseconds at a large figure's size.
async function encodePng(pixels, width, height) {
  if (typeof OffscreenCanvas !== 'function') throw new Error('this browser has no OffscreenCanvas in workers');
  const canvas = new OffscreenCanvas(width, height);
  const image = new ImageData(new Uint8ClampedArray(pixels.buffer, pixels.byteOffset, pixels.byteLength), width, height);
  canvas.getContext('2d').putImageData(image, 0, 0);
  return canvas.convertToBlob({ type: 'image/png' });
}

async function start({ glue, wasm, compiled }) {
  const module = await import(glue);
  await module.default({ module_or_path: compiled ?? wasm });
  return module;
}

self.onmessage = async ({ data }) => {
  if (data.glue) {
    started = start(data);
    started.then(() => self.postMessage({ ready: true }), (error) => self.postMessage({ failed: String(error?.message ?? error) }));
    return;
  }
  const { id, job, slab, shape, png, decided } = data;
  try {
    if (png) {
      self.postMessage({ id, png: await encodePng(...png) });
      return;
    }
    const module = await started;
    if (shape) {
      self.postMessage({ id, shape: module.mesh_shape(...shape) });
      return;
    }
    if (decided) {
      const cells = module.mesh_job(decided)[4];
      self.postMessage({ id, decided: cells }, [cells.buffer]);
      return;
    }
    if (slab) {
      const [vertices, indices, blocks, cells, keys] = module.mesh_slab(job, ...slab);
      self.postMessage({ id, slab: [slab[0], vertices, indices, keys, blocks, cells] },
        [vertices.buffer, indices.buffer, keys.buffer]);
      return;
    }
    const [vertices, indices, blocks, cells] = module.mesh_job(job);
    self.postMessage({ id, vertices, indices, blocks, cells }, [vertices.buffer, indices.buffer]);
  } catch (error) {
    self.postMessage({ id, error: panic ?? error?.message ?? String(error) });
  }
};
