// The full page and the iframe page: one <metaballs-view> whose attributes come from the link's query
// string (`?spheres=9&iso=0.8&res=96&seed=7&paused=1`, short or long names), kept in the URL as the
// person changes them, plus the benchmark mode (`?bench`). Bad values in a link are reported inside the
// figure and replaced by defaults.

import { backendName, loadWasm, parseParameter } from './lib/engine/wasm.js';
import { propertyName, spellingsOf, TABLE as table } from './lib/core/table.js';
import { queryText, valueText } from './lib/core/share-text.js';
import { runBenchmark } from './bench.js';

// The key a link gives a parameter under: its short name, its name, or an old spelling.
const keyIn = (query, spec) => [spec.url, spec.name, ...(spec.aliases ?? [])].find((key) => query.has(key)) ?? null;

const element = document.querySelector('metaballs-view');
// Plain text (the poster, the description) is taken at once, so the poster shows while the wasm loads.
const early = new URLSearchParams(location.search);
for (const spec of table.filter((p) => p.kind === 'text')) {
  const key = keyIn(early, spec);
  if (key !== null) element.setAttribute(spec.name, early.get(key));
}
loadWasm().then(start, () => { /* the figure says why */ });

function start() {
  const query = new URLSearchParams(location.search);
  // The iframe page shows what the link asks for and nothing more; the full page always has every
  // control and the statistics, so its links do not carry `controls` or `hud`.
  const chromeless = document.body.dataset.page === 'embed';
  const inLinks = (spec) => chromeless || (spec.name !== 'controls' && spec.name !== 'hud');

  const problems = [];
  for (const spec of table.filter(inLinks)) {
    const key = keyIn(query, spec);
    if (key === null) continue;
    const raw = query.get(key);
    try {
      parseParameter(key, raw);
      element.setAttribute(spec.name, raw);
    } catch (error) {
      problems.push(`${key}=${raw}: ${error.message}`);
    }
  }
  if (problems.length) {
    element.showNotice(`Some values in the link were invalid and were replaced by defaults: ${problems.join('; ')}.`);
  }

  const MAX_LINK_SPHERES = 16;

  // The full page's "share or embed" opens the figure's share box.
  document.getElementById('open-share')?.addEventListener('click', () => element.openShare());

  // Changes go back into the link (short names, defaults left out), so a link reproduces the view.
  const share = document.getElementById('share');
  let urlTimer = 0;
  function saveUrl() {
    clearTimeout(urlTimer);
    urlTimer = setTimeout(() => {
      const settings = [];
      for (const spec of table.filter(inLinks)) {
        // Spheres placed by hand are read as the text their attribute holds (`sphereList` is a list).
        const value = spec.kind === 'spheres'
          ? spellingsOf(spec.name).map((n) => element.getAttribute(n)).find((v) => v !== null) ?? ''
          : element[propertyName(spec.name)];
        if (value === parseParameter(spec.name, spec.default)) continue;
        // Hand-placed spheres ride in the link for small scenes; larger ones go in a scene file.
        if (spec.kind === 'spheres' && value.split(';').length > MAX_LINK_SPHERES) continue;
        settings.push({ row: spec, value, text: valueText(spec, value) });
      }
      const bench = [...query].filter(([key]) => key === 'bench' || key.startsWith('bench_'));
      const search = queryText([...settings, ...bench.map(([key, text]) => ({ row: { url: key }, text }))]);
      const url = `${location.pathname}${search}`;
      history.replaceState(null, '', url);
      if (share) share.href = url;
    }, 150);
  }
  element.addEventListener('metaballs-change', saveUrl);
  saveUrl();

  // reveal.js tells an iframe on a slide when the slide starts and stops being shown: the figure
  // pauses while its slide is away and plays again when it comes back (unless it was paused before).
  let pausedBySlide = false;
  window.addEventListener('message', (event) => {
    if (event.data === 'slide:stop' && !element.paused) {
      pausedBySlide = true;
      element.pause();
    } else if (event.data === 'slide:start' && pausedBySlide) {
      pausedBySlide = false;
      element.play();
    }
  });

  // For tests and the console.
  window.metaballs = { element };

  if (query.has('bench')) {
    const container = document.getElementById('bench');
    // The figure goes back to its own settings afterwards; the table stays.
    element.withView((view) => runBenchmark(view, container, { hasCompute: backendName() === 'webgpu' })).catch(
      (error) => element.fail('The benchmark stopped', error?.message ?? String(error)),
    );
  }
}
