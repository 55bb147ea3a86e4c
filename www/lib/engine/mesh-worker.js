// The page's mesher worker: a second instance of the page's WebAssembly build, started in a worker,
// that meshes the frames the figures' CPU mesher would otherwise mesh on the page's thread. It is told
// which build to start (`{ build }`) and says when it is ready (or why it failed), then answers each
// `{ id, job }` (a view's packed mesh job) with the mesh's vertices and indices, handed over without a
// copy, or with what went wrong.

// The builds, as wasm.js names them; the paths are written out so that bundlers find the files.
const BUILDS = {
  webgpu: {
    glue: () => import('../../../pkg/metaballs.js'),
    wasm: () => new URL('../../../pkg/metaballs_bg.wasm', import.meta.url),
  },
  webgl2: {
    glue: () => import('../../../pkg-webgl/metaballs.js'),
    wasm: () => new URL('../../../pkg-webgl/metaballs_bg.wasm', import.meta.url),
  },
};

let started = null;
// A Rust panic in this instance: the job that raised it is answered with it.
let panic = null;
globalThis.metaballsShowPanic = (message) => { panic = message; };

async function start(build) {
  const module = await build.glue();
  await module.default({ module_or_path: build.wasm() });
  return module;
}

self.onmessage = async ({ data }) => {
  if (data.build) {
    started = start(BUILDS[data.build]);
    started.then(() => self.postMessage({ ready: true }), (error) => self.postMessage({ failed: String(error?.message ?? error) }));
    return;
  }
  const { id, job } = data;
  try {
    const module = await started;
    const [vertices, indices, blocks, cells] = module.mesh_job(job);
    self.postMessage({ id, vertices, indices, blocks, cells }, [vertices.buffer, indices.buffer]);
  } catch (error) {
    self.postMessage({ id, error: panic ?? error?.message ?? String(error) });
  }
};
