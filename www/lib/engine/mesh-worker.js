// The page's mesher worker: a second instance of the page's WebAssembly build, started in a worker,
// that meshes the frames the figures' CPU mesher would otherwise mesh on the page's thread. It is told
// where the build's JavaScript and WebAssembly are (`{ glue, wasm }`, whole URLs: the file imports
// nothing itself, so it works wherever a bundler copies it) and says when it is ready (or why it
// failed), then answers each `{ id, job }` (a view's packed mesh job) with the mesh's vertices and
// indices, handed over without a copy, and each `{ id, shape: [vertex count, triangles] }` with the
// mesh's shape (`mesh_shape`: blobs, genus, closed, manifold), or with what went wrong.

let started = null;
// A Rust panic in this instance: the job that raised it is answered with it.
let panic = null;
globalThis.metaballsShowPanic = (message) => { panic = message; };

async function start({ glue, wasm }) {
  const module = await import(glue);
  await module.default({ module_or_path: wasm });
  return module;
}

self.onmessage = async ({ data }) => {
  if (data.glue) {
    started = start(data);
    started.then(() => self.postMessage({ ready: true }), (error) => self.postMessage({ failed: String(error?.message ?? error) }));
    return;
  }
  const { id, job, shape } = data;
  try {
    const module = await started;
    if (shape) {
      self.postMessage({ id, shape: module.mesh_shape(...shape) });
      return;
    }
    const [vertices, indices, blocks, cells] = module.mesh_job(job);
    self.postMessage({ id, vertices, indices, blocks, cells }, [vertices.buffer, indices.buffer]);
  } catch (error) {
    self.postMessage({ id, error: panic ?? error?.message ?? String(error) });
  }
};
