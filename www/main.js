// The page: starts the WebAssembly renderer on the canvas, wires the controls, camera gestures, HUD and
// URL state, and explains what is missing when WebGPU is not available.

import init, { App } from '../pkg/metaballs.js';
import { runBenchmark } from './bench.js';

const DEFAULTS = Object.freeze({
  spheres: 5,
  iso: 1.0,
  res: 64,
  seed: 1,
  speed: 1.0,
  paused: false,
  yaw: 30,
  pitch: 20,
  dist: 4.3,
  shine: 64,
  color: '#e77661',
  aa: true,
});

const $ = (id) => document.getElementById(id);
const state = { ...DEFAULTS };
let app = null;
let stopped = false;

// ---------------------------------------------------------------- messages

function showMessage(title, text) {
  $('message-title').textContent = title;
  $('message-text').textContent = text;
  $('message').hidden = false;
}

function showNotice(text) {
  const notice = $('notice');
  notice.textContent = text;
  notice.hidden = false;
  clearTimeout(showNotice.timer);
  showNotice.timer = setTimeout(() => { notice.hidden = true; }, 8000);
}

function stop(title, error) {
  stopped = true;
  showMessage(title, `${error?.message ?? error}\n\nReload the page to start again.`);
}

// A Rust panic reaches the page here (see src/web.rs), before the exception unwinds.
globalThis.metaballsShowPanic = (message) => stop('The renderer stopped', message);

// ---------------------------------------------------------------- URL state

const PARAMS = {
  spheres: { parse: parseInteger },
  iso: { parse: parseFloat },
  res: { parse: parseInteger },
  seed: { parse: parseInteger },
  speed: { parse: parseFloat, check: (v) => v >= 0 && v <= 3, range: '0 to 3' },
  paused: { parse: (s) => (s === '1' || s === 'true' ? true : s === '0' || s === 'false' ? false : NaN) },
  yaw: { parse: parseFloat },
  pitch: { parse: parseFloat },
  dist: { parse: parseFloat },
  shine: { parse: parseFloat },
  color: { parse: (s) => (/^#?[0-9a-f]{6}$/i.test(s) ? `#${s.replace('#', '').toLowerCase()}` : NaN) },
  aa: { parse: (s) => (s === '1' || s === 'true' ? true : s === '0' || s === 'false' ? false : NaN) },
};

function parseInteger(s) {
  return /^\d+$/.test(s.trim()) ? Number(s) : NaN;
}

// Reads the query string into `state`; returns the problems found, one per bad value.
function readUrl() {
  const problems = [];
  const query = new URLSearchParams(location.search);
  for (const [key, spec] of Object.entries(PARAMS)) {
    if (!query.has(key)) continue;
    const raw = query.get(key);
    const value = spec.parse(raw);
    if (typeof value === 'number' && !Number.isFinite(value)) {
      problems.push(`${key}=${raw} is not a valid value`);
    } else if (spec.check && !spec.check(value)) {
      problems.push(`${key}=${raw} must be ${spec.range}`);
    } else {
      state[key] = value;
    }
  }
  return problems;
}

function currentUrl() {
  const query = new URLSearchParams();
  for (const key of Object.keys(PARAMS)) {
    let value = state[key];
    if (value === DEFAULTS[key]) continue;
    if (typeof value === 'boolean') value = value ? 1 : 0;
    if (typeof value === 'number' && !Number.isInteger(value)) value = Number(value.toFixed(3));
    query.set(key, String(value));
  }
  // The benchmark's own parameters stay, so a reload runs it again.
  for (const [key, value] of new URLSearchParams(location.search)) {
    if (key === 'bench' || key.startsWith('bench_')) query.set(key, value);
  }
  const search = query.toString();
  return `${location.pathname}${search ? `?${search}` : ''}`;
}

let urlTimer = 0;
function saveUrl() {
  clearTimeout(urlTimer);
  urlTimer = setTimeout(() => {
    const url = currentUrl();
    history.replaceState(null, '', url);
    $('share').href = url;
  }, 150);
}

// ---------------------------------------------------------------- applying state to the renderer

// Each setter validates in Rust; a refused value keeps the previous one and explains why.
function apply(key) {
  const s = state;
  switch (key) {
    case 'spheres': app.set_sphere_count(s.spheres); break;
    case 'iso': app.set_iso(s.iso); break;
    case 'res': app.set_resolution(s.res); break;
    case 'seed': app.set_seed(s.seed); break;
    case 'yaw': case 'pitch': case 'dist': app.set_camera(s.yaw, s.pitch, s.dist); break;
    case 'shine': app.set_shininess(s.shine); break;
    case 'color': app.set_color(...hexToLinear(s.color)); break;
    case 'aa': app.set_antialiasing(s.aa); break;
    default: break;
  }
}

function applyOrRevert(key, fallback) {
  try {
    apply(key);
    return null;
  } catch (error) {
    state[key] = fallback;
    apply(key);
    return error.message;
  }
}

function hexToLinear(hex) {
  const channel = (i) => {
    const c = parseInt(hex.slice(1 + 2 * i, 3 + 2 * i), 16) / 255;
    return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
  };
  return [channel(0), channel(1), channel(2)];
}

// ---------------------------------------------------------------- controls

const CONTROLS = {
  spheres: { input: 'spheres', format: (v) => String(v) },
  iso: { input: 'iso', format: (v) => v.toFixed(2) },
  res: { input: 'resolution', format: (v) => `${v}³` },
  speed: { input: 'speed', format: (v) => `${v.toFixed(2)}×` },
  shine: { input: 'shininess', format: (v) => String(Math.round(v)) },
  color: { input: 'color', format: (v) => v },
};

function showControls() {
  for (const [key, control] of Object.entries(CONTROLS)) {
    const input = $(control.input);
    input.value = state[key];
    $(`${control.input}-value`).textContent = control.format(state[key]);
  }
  $('antialiasing').checked = state.aa;
  $('antialiasing-value').textContent = state.aa ? '4×' : 'off';
  const pause = $('pause');
  pause.setAttribute('aria-pressed', String(state.paused));
  pause.textContent = state.paused ? 'Play' : 'Pause';
  $('seed-value').textContent = state.seed;
}

// Resolution changes reallocate GPU buffers: apply the newest value once per frame, not per event.
const pending = new Map();

function wireControls() {
  for (const [key, control] of Object.entries(CONTROLS)) {
    const input = $(control.input);
    input.addEventListener('input', () => {
      const value = key === 'color' ? input.value : Number(input.value);
      $(`${control.input}-value`).textContent = control.format(value);
      pending.set(key, value);
    });
  }
  $('antialiasing').addEventListener('change', () => pending.set('aa', $('antialiasing').checked));
  $('pause').addEventListener('click', togglePause);
  $('reseed').addEventListener('click', reseed);
  $('reset-view').addEventListener('click', resetView);
}

function applyPending() {
  for (const [key, value] of pending) {
    const previous = state[key];
    state[key] = value;
    const problem = key === 'speed' ? null : applyOrRevert(key, previous);
    if (problem) showNotice(problem);
  }
  if (pending.size) {
    pending.clear();
    showControls();
    saveUrl();
  }
}

function togglePause() {
  state.paused = !state.paused;
  showControls();
  saveUrl();
}

function reseed() {
  state.seed = 1 + Math.floor(Math.random() * 1e6);
  apply('seed');
  showControls();
  saveUrl();
}

function resetView() {
  state.yaw = DEFAULTS.yaw;
  state.pitch = DEFAULTS.pitch;
  state.dist = DEFAULTS.dist;
  apply('yaw');
  saveUrl();
}

// ---------------------------------------------------------------- camera gestures

const PITCH_LIMIT = 89;
const DIST_RANGE = [1.5, 20];

function orbit(dYaw, dPitch) {
  state.yaw = ((((state.yaw + dYaw + 180) % 360) + 360) % 360) - 180;
  state.pitch = Math.max(-PITCH_LIMIT, Math.min(PITCH_LIMIT, state.pitch + dPitch));
  apply('yaw');
  saveUrl();
}

function zoom(factor) {
  state.dist = Math.max(DIST_RANGE[0], Math.min(DIST_RANGE[1], state.dist * factor));
  apply('dist');
  saveUrl();
}

function wireCamera(canvas) {
  const pointers = new Map();
  let pinchSpan = 0;
  const span = () => {
    const [a, b] = [...pointers.values()];
    return Math.hypot(a.x - b.x, a.y - b.y);
  };
  canvas.addEventListener('pointerdown', (e) => {
    canvas.setPointerCapture(e.pointerId);
    pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
    if (pointers.size === 2) pinchSpan = span();
  });
  canvas.addEventListener('pointermove', (e) => {
    const p = pointers.get(e.pointerId);
    if (!p) return;
    const dx = e.clientX - p.x;
    const dy = e.clientY - p.y;
    p.x = e.clientX;
    p.y = e.clientY;
    if (pointers.size === 1) {
      orbit(-dx * 0.3, dy * 0.3);
    } else if (pointers.size === 2) {
      const now = span();
      if (pinchSpan > 0 && now > 0) zoom(pinchSpan / now);
      pinchSpan = now;
    }
  });
  const release = (e) => {
    pointers.delete(e.pointerId);
    pinchSpan = pointers.size === 2 ? span() : 0;
  };
  canvas.addEventListener('pointerup', release);
  canvas.addEventListener('pointercancel', release);
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    zoom(Math.exp(e.deltaY * (e.deltaMode === 1 ? 0.05 : 0.0015)));
  }, { passive: false });
  canvas.addEventListener('dblclick', resetView);

  window.addEventListener('keydown', (e) => {
    // Keys go to the controls while one has focus.
    if (e.target instanceof HTMLInputElement || e.target instanceof HTMLButtonElement) return;
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    const step = e.shiftKey ? 15 : 5;
    const actions = {
      ArrowLeft: () => orbit(-step, 0), a: () => orbit(-step, 0),
      ArrowRight: () => orbit(step, 0), d: () => orbit(step, 0),
      ArrowUp: () => orbit(0, step), w: () => orbit(0, step),
      ArrowDown: () => orbit(0, -step), s: () => orbit(0, -step),
      '+': () => zoom(0.9), '=': () => zoom(0.9),
      '-': () => zoom(1 / 0.9), _: () => zoom(1 / 0.9),
      p: togglePause, ' ': togglePause,
      n: reseed, r: resetView,
    };
    const action = actions[e.key.length === 1 ? e.key.toLowerCase() : e.key];
    if (action) {
      e.preventDefault();
      action();
    }
  });
}

// ---------------------------------------------------------------- canvas size

function wireResize(canvas) {
  const resize = (width, height) => {
    width = Math.max(1, Math.round(width));
    height = Math.max(1, Math.round(height));
    if (canvas.width === width && canvas.height === height) return;
    canvas.width = width;
    canvas.height = height;
    try {
      app.resize(width, height);
    } catch (error) {
      showNotice(error.message);
    }
  };
  const observer = new ResizeObserver(([entry]) => {
    const box = entry.devicePixelContentBoxSize?.[0];
    if (box) {
      resize(box.inlineSize, box.blockSize);
    } else {
      resize(entry.contentRect.width * devicePixelRatio, entry.contentRect.height * devicePixelRatio);
    }
  });
  try {
    observer.observe(canvas, { box: 'device-pixel-content-box' });
  } catch {
    observer.observe(canvas);
  }
}

// ---------------------------------------------------------------- HUD and frame loop

const hud = { frames: 0, since: performance.now(), overflows: 0 };
const numberFormat = new Intl.NumberFormat('en');

function updateHud(now) {
  const elapsed = now - hud.since;
  if (elapsed < 500) return;
  const fps = (hud.frames * 1000) / elapsed;
  $('fps').textContent = fps.toFixed(1);
  $('frame-time').textContent = `${(elapsed / Math.max(hud.frames, 1)).toFixed(1)} ms`;
  hud.frames = 0;
  hud.since = now;
  const stats = app.stats();
  if (stats) {
    $('triangles').textContent = numberFormat.format(stats.triangles);
    $('triangles').title = `budget ${numberFormat.format(stats.max_triangles)} triangles`;
    // The buffers grow a frame after an overflow; warn only when it lasts (they hit the device's limit).
    hud.overflows = stats.overflowed ? hud.overflows + 1 : 0;
    $('overflow').hidden = hud.overflows < 2;
    stats.free();
  }
  const error = app.gpu_error();
  if (error) stop('The GPU reported an error', error);
}

let last = performance.now();
function frame(now) {
  if (stopped) return;
  const dt = Math.min(Math.max(now - last, 0) / 1000, 0.1);
  last = now;
  try {
    applyPending();
    app.frame(state.paused ? 0 : dt * state.speed);
  } catch (error) {
    stop('The renderer stopped', error);
    return;
  }
  hud.frames += 1;
  updateHud(now);
  requestAnimationFrame(frame);
}

// ---------------------------------------------------------------- start

const WEBGPU_HELP =
  'This demo draws with WebGPU, which this browser does not offer.\n' +
  'Use a current Chrome or Edge (113 or later), Safari 26, or Firefox 141 or later. ' +
  'On Linux, Chrome needs WebGPU switched on at chrome://flags/#enable-unsafe-webgpu; ' +
  'the page must also be served over https or from localhost.';

// The browser names its adapter through GPUAdapterInfo (wgpu sees only an anonymous one). Software
// adapters (SwiftShader, or any fallback adapter) draw much faster without multisampling.
async function adapterInfo() {
  try {
    const adapter = await navigator.gpu.requestAdapter();
    const info = adapter?.info;
    const words = [info?.vendor, info?.architecture, info?.description].filter(Boolean);
    const software = Boolean(info?.isFallbackAdapter || adapter?.isFallbackAdapter)
      || /swiftshader|llvmpipe|lavapipe|software/i.test(words.join(' '));
    if (words.length) return { label: `WebGPU · ${[...new Set(words)].join(' ')}`, software };
    return { label: app.adapter(), software };
  } catch {
    return { label: app.adapter(), software: false };
  }
}

async function main() {
  const canvas = $('view');
  if (!('gpu' in navigator) || !navigator.gpu) {
    showMessage('WebGPU is not available', WEBGPU_HELP);
    return;
  }
  const problems = readUrl();
  const rect = canvas.getBoundingClientRect();
  canvas.width = Math.max(1, Math.round(rect.width * devicePixelRatio));
  canvas.height = Math.max(1, Math.round(rect.height * devicePixelRatio));
  try {
    await init();
    app = await App.create(canvas);
  } catch (error) {
    showMessage('WebGPU could not start', `${error?.message ?? error}`);
    return;
  }
  if (stopped) return;

  const adapter = await adapterInfo();
  // A software adapter takes seconds per frame beyond 256 cells; the link can still ask for more.
  $('resolution').max = String(adapter.software ? Math.min(256, app.max_resolution()) : app.max_resolution());
  $('adapter').textContent = adapter.label;
  if (adapter.software && !new URLSearchParams(location.search).has('aa')) state.aa = false;
  for (const key of ['spheres', 'iso', 'res', 'seed', 'shine', 'color', 'aa']) {
    const problem = applyOrRevert(key, DEFAULTS[key]);
    if (problem) problems.push(problem);
  }
  try {
    apply('yaw');
  } catch (error) {
    // The camera is one setter: a bad angle or distance resets the view.
    problems.push(error.message);
    Object.assign(state, { yaw: DEFAULTS.yaw, pitch: DEFAULTS.pitch, dist: DEFAULTS.dist });
    apply('yaw');
  }
  if (problems.length) {
    showNotice(`Some values in the link were invalid and were replaced by defaults: ${problems.join('; ')}.`);
  }
  showControls();
  saveUrl();
  wireControls();
  wireCamera(canvas);
  wireResize(canvas);
  window.metaballs = { app, state };
  if (new URLSearchParams(location.search).has('bench')) {
    try {
      await runBenchmark(app, $('bench'));
    } catch (error) {
      stop('The benchmark stopped', error);
      return;
    }
    // Back to the settings the page had; the table stays.
    for (const key of ['spheres', 'res']) apply(key);
  }
  last = performance.now();
  requestAnimationFrame(frame);
}

main();
