// The topology worker: the critical points' module (pkg-levels/, built from levels/) started in a
// worker, so that the search never blocks the page's thread. It is told where the module's JavaScript
// and WebAssembly are (`{ glue, wasm }`, whole URLs: the file imports nothing itself), says when it is
// ready (or why it failed), then answers each `{ id, critical: packed spheres }` with the search's JSON
// and the milliseconds it took, and each `{ id, measures: [packed, levels, n] }` with the area and
// volume at each level.

let started = null;

self.onmessage = async ({ data }) => {
  if (data.glue) {
    started = import(data.glue).then(async (module) => {
      await module.default({ module_or_path: data.wasm });
      return module;
    });
    started.then(() => self.postMessage({ ready: true }), (error) => self.postMessage({ failed: String(error?.message ?? error) }));
    return;
  }
  const { id, critical, measures } = data;
  try {
    const module = await started;
    if (critical) {
      const begun = performance.now();
      const json = module.critical_points(critical);
      self.postMessage({ id, json, milliseconds: performance.now() - begun });
    } else {
      const values = module.measures(...measures);
      self.postMessage({ id, values }, [values.buffer]);
    }
  } catch (error) {
    self.postMessage({ id, error: String(error?.message ?? error) });
  }
};
