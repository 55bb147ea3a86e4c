// The benchmark in the browser (`?bench`, optionally `&bench_resolutions=32,64&bench_spheres=1,5&bench_frames=10`
// and `&bench_meshers=gpu,cpu`): the same fixed sequence as `metaballs bench`, for each mesher the
// adapter has (the GPU's compute passes and the CPU mesher; WebGL2 has only the CPU), timed with the
// GPU queue synchronised after each frame, then a row per mesher with level of detail at `bench_lod`
// cells per axis (1024 unless given; 0 for none) and 16 spheres. The CPU mesher's rows also time it
// alone, as the mesher worker runs it (no upload, no GPU). Shows a table, says which mesher `auto` picks
// here, and logs the records as JSON on the console (a line starting with "metaballs-bench ") for
// headless runs.

import { wasmModule } from './lib/engine/wasm.js';

const median = (values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];

function listParam(query, key, fallback) {
  if (!query.has(key)) return fallback;
  const values = query.get(key).split(',').map(Number);
  return values.every((v) => Number.isInteger(v) && v > 0) ? values : fallback;
}

async function timeFrames(view, frames, step) {
  const times = [];
  for (let i = 0; i < frames; i++) {
    const start = performance.now();
    step();
    await view.work_done();
    times.push(performance.now() - start);
  }
  return median(times);
}

// The CPU mesher alone, as the page's mesher worker runs it: the frame's job meshed into arrays handed
// to JavaScript, with no upload and no GPU to wait for (what three.js's `MarchingCubes` does in its
// `update()`); the median over `frames` meshes, in milliseconds.
function meshedAlone(view, frames) {
  const job = view.cpu_job(true);
  const times = [];
  for (let i = 0; i < frames; i++) {
    const start = performance.now();
    wasmModule().mesh_job(job);
    times.push(performance.now() - start);
  }
  return median(times);
}

function showTable(container, records, status) {
  const rows = records.map((r) => `<tr><td>${r.mesher}</td><td>${r.resolution}${r.lod ? ' LOD' : ''}</td><td>${r.spheres}</td><td>${r.frame_ms.toFixed(1)}</td>`
    + `<td>${r.mesh_ms.toFixed(1)}</td><td>${r.alone_ms?.toFixed(1) ?? '–'}</td><td>${r.triangles}</td><td>${(100 * r.active_cell_fraction).toFixed(2)}</td>`
    + `<td>${(100 * r.active_block_fraction).toFixed(1)}</td><td>${(r.mesh_bytes / 1048576).toFixed(1)}</td></tr>`);
  container.innerHTML = `<h2>Benchmark</h2><p>${status}</p><table><thead><tr><th>mesher</th><th>cells</th><th>spheres</th>`
    + '<th>frame ms</th><th>mesh ms</th><th>mesher alone ms</th><th>triangles</th><th>cells %</th><th>blocks %</th><th>mesh MiB</th>'
    + `</tr></thead><tbody>${rows.join('')}</tbody></table>`;
}

export async function runBenchmark(view, container, { hasCompute = true } = {}) {
  const query = new URLSearchParams(location.search);
  const wanted = query.has('bench_meshers') ? query.get('bench_meshers').split(',') : ['gpu', 'cpu'];
  const meshers = wanted.filter((m) => (m === 'cpu' || (m === 'gpu' && hasCompute)));
  const maxResolution = view.max_resolution();
  const resolutions = listParam(query, 'bench_resolutions', [32, 64, 128, 256]).filter((n) => n <= maxResolution);
  const sphereCounts = listParam(query, 'bench_spheres', [1, 5, 16, 64]);
  const frames = listParam(query, 'bench_frames', [10])[0];
  container.hidden = false;
  const records = [];
  for (const resolution of resolutions) {
    for (const spheres of sphereCounts) {
      for (const mesher of meshers) {
        showTable(container, records, `Running ${resolution}³ cells × ${spheres} spheres, ${mesher} mesher…`);
        view.set_parameter('mesh-on', mesher);
        view.set_parameter('resolution', String(resolution));
        view.set_parameter('spheres', String(spheres));
        // Warm up: pipelines compile and the buffers grow to the surface.
        await timeFrames(view, 3, () => view.frame(1 / 60));
        const frame_ms = await timeFrames(view, frames, () => view.frame(1 / 60));
        const mesh_ms = await timeFrames(view, frames, () => view.extract());
        const alone_ms = view.mesh_source() === 'cpu' ? meshedAlone(view, frames) : null;
        await timeFrames(view, 2, () => view.frame(0));
        const stats = view.stats();
        const [blocks, cells] = view.active_fractions();
        records.push({
          mesher: view.mesh_source(),
          resolution,
          spheres,
          frame_ms,
          mesh_ms,
          alone_ms,
          triangles: stats?.triangles ?? 0,
          active_cell_fraction: cells,
          active_block_fraction: blocks,
          mesh_bytes: view.mesh_bytes(),
        });
        stats?.free();
      }
    }
  }
  // Level of detail: the finest cells near the camera at a resolution no uniform grid holds.
  // `bench_lod=0`: no row with level of detail.
  const lodResolution = query.get('bench_lod') === '0' ? 0 : listParam(query, 'bench_lod', [1024])[0];
  for (const mesher of lodResolution ? meshers : []) {
    showTable(container, records, `Running ${lodResolution}³ cells with level of detail × 16 spheres, ${mesher} mesher…`);
    view.set_parameter('mesh-on', mesher);
    view.set_parameter('spheres', '16');
    view.set_parameters(['resolution', 'lod'], [String(lodResolution), 'true']);
    await timeFrames(view, 3, () => view.frame(1 / 60));
    const frame_ms = await timeFrames(view, frames, () => view.frame(1 / 60));
    const mesh_ms = await timeFrames(view, frames, () => view.extract());
    await timeFrames(view, 2, () => view.frame(0));
    const stats = view.stats();
    const levels = [...view.lod_levels()];
    records.push({
      mesher: view.mesh_source(),
      lod: true,
      resolution: lodResolution,
      spheres: 16,
      frame_ms,
      mesh_ms,
      triangles: stats?.triangles ?? 0,
      active_cell_fraction: 0,
      active_block_fraction: 0,
      mesh_bytes: view.mesh_bytes(),
      blocks_per_level: levels.slice(1).filter((_, i) => i % 2 === 0),
    });
    stats?.free();
    view.set_parameters(['resolution', 'lod'], [String(resolutions.at(-1) ?? 64), 'false']);
  }
  view.set_parameter('mesh-on', 'auto');
  await timeFrames(view, 1, () => view.frame(0));
  const auto = view.mesh_source();
  showTable(container, records, `${frames} frames per row, medians; the GPU queue is synchronised after each frame. `
    + `Here mesher=auto uses the ${auto.toUpperCase()} mesher.`);
  console.log(`metaballs-bench ${JSON.stringify(records)}`);
  console.log(`metaballs-bench-auto ${auto}`);
  return records;
}
