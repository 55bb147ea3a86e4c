// The element's control panel, built from the parameter table for the controls an author lists
// (`controls="iso,resolution"`, `all` or `none`), in groups — Surface, Display, Teaching, Light, Camera
// — that fold. Compact and collapsible: small figures start with it folded, and it never takes more
// than a third of the figure's width.

import { colorKey, sliceKey } from './legends.js';
import { buildGallery } from './inspector.js';
import { plotErrors } from './error-plot.js';

const GROUPS = [
  ['Surface', ['spheres', 'iso', 'resolution', 'lod', 'lod_pixels', 'lod_freeze', 'mesher', 'speed', 'seed', 'paused', 'pause_on', 'step', 'view']],
  ['Display', ['display', 'grid', 'color_by', 'ambiguous', 'color', 'theme', 'antialiasing']],
  ['Teaching', ['slice', 'interpolation', 'blend', 'inspector', 'error_plot']],
  ['Light', ['light', 'spot_angle', 'spot_softness', 'ambient', 'diffuse', 'specular', 'shininess']],
  ['Camera', ['projection', 'fov']],
  ['Scene', ['edit', 'scene', 'export']],
];

// Views drawn from the compute passes' buffers, and the choice of mesher: without compute shaders
// (WebGL2) the CPU makes every mesh and these are shown disabled, saying why.
const NEED_COMPUTE = new Set(['display', 'grid', 'color_by', 'ambiguous', 'slice', 'mesher']);
const WITHOUT_COMPUTE = 'Needs WebGPU (compute shaders); this browser draws with WebGL2 and meshes on the CPU';

const FORMATS = {
  spheres: (v) => String(v),
  resolution: (v) => `${v}³`,
  speed: (v) => `${v.toFixed(2)}×`,
  shininess: (v) => String(Math.round(v)),
  spot_angle: (v) => `${Math.round(v)}°`,
  fov: (v) => `${Math.round(v)}°`,
};
const formatNumber = (name, v) => (FORMATS[name] ?? ((x) => x.toFixed(2)))(v);

/** The control names `list` (the `controls` value) asks for, in the table's order. */
export function listedControls(list, all) {
  if (list === 'all') return all;
  if (list === 'none' || !list) return [];
  const wanted = new Set(list.split(','));
  return all.filter((name) => wanted.has(name));
}

function element(tag, properties = {}, ...children) {
  const node = Object.assign(document.createElement(tag), properties);
  node.append(...children);
  return node;
}

function makeButton(id, text, title, onClick) {
  const button = element('button', { type: 'button', id, textContent: text, title });
  button.addEventListener('click', onClick);
  return button;
}

// One labelled row: label, input, output.
function row(id, labelText, input, output = element('output')) {
  const label = element('label', { htmlFor: id, textContent: labelText });
  input.id = id;
  output.id = `${id}-value`;
  output.htmlFor = id;
  return element('div', { className: 'control' }, label, input, output);
}

/**
 * Builds the panel into `container` (emptied first) for `names`. `table` is the parameter table,
 * `state` the element's values, `onChange(name, value)` receives the person's edits and `actions` the
 * buttons (togglePause, reseed, resetView, step). `gallery` is the case gallery's data. Returns
 * `show(state, inspectedClass)` to bring the controls up to date.
 */
export function buildPanel(container, names, table, state, onChange, actions, options) {
  const { maxResolution, small, gallery, withoutCompute = false } = options;
  container.replaceChildren();
  container.hidden = names.length === 0;
  if (!names.length) return () => {};
  const body = element('div', { className: 'controls' });
  const details = element('details', { open: !small }, element('summary', { textContent: 'Controls' }), body);
  container.append(details);

  const byName = Object.fromEntries(table.map((p) => [p.name, p]));
  const wanted = new Set(names);
  const updates = [];

  const controls = {
    number(name, spec) {
      const input = element('input', {
        type: 'range',
        min: String(spec.sliderMin),
        max: String(name === 'resolution' ? Math.min(spec.sliderMax, maxResolution) : spec.sliderMax),
        step: String(spec.step),
      });
      const control = row(name, spec.label, input);
      const output = control.querySelector('output');
      input.addEventListener('input', () => {
        output.textContent = formatNumber(name, Number(input.value));
        onChange(name, Number(input.value));
      });
      updates.push((s) => {
        // With level of detail the grid is finest near the camera only, so it goes up to the table's
        // limit; a uniform grid stops at what the device holds.
        if (name === 'resolution') {
          input.max = String(s.lod ? spec.max : Math.min(spec.sliderMax, maxResolution));
          // LOD blocks hold 8 cells a side.
          input.step = s.lod ? '8' : String(spec.step);
        }
        input.value = String(s[name]);
        output.textContent = formatNumber(name, s[name]);
      });
      return control;
    },
    color(name, spec) {
      const input = element('input', { type: 'color' });
      const control = row(name, spec.label, input);
      const output = control.querySelector('output');
      input.addEventListener('input', () => {
        output.textContent = input.value;
        onChange(name, input.value);
      });
      updates.push((s) => {
        input.value = s[name];
        output.textContent = s[name];
      });
      return control;
    },
    boolean(name, spec) {
      const input = element('input', { type: 'checkbox' });
      const control = row(name, spec.label, input);
      const output = control.querySelector('output');
      input.addEventListener('change', () => onChange(name, input.checked));
      updates.push((s) => {
        input.checked = s[name];
        output.textContent = name === 'antialiasing' ? (s[name] ? '4×' : 'off') : (s[name] ? 'on' : 'off');
      });
      return control;
    },
    choice(name, spec) {
      const input = element('select', {}, ...spec.words.map((w) => element('option', { value: w, textContent: w })));
      const control = row(name, spec.label, input);
      input.addEventListener('change', () => onChange(name, input.value));
      updates.push((s) => { input.value = s[name]; });
      return control;
    },
    list(name, spec) {
      // One checkbox per light kind, in a labelled group.
      const label = element('span', { id: `${name}-label`, className: 'label', textContent: spec.label });
      const boxes = spec.words.map((word) => element('input', { type: 'checkbox', id: `${name}-${word}`, value: word }));
      const checks = element('div', { className: 'checks' },
        ...boxes.map((box) => element('label', { htmlFor: box.id }, box, ` ${box.value}`)));
      const group = element('div', { className: 'control list', role: 'group' }, label, checks);
      group.setAttribute('aria-labelledby', label.id);
      group.addEventListener('change', () => {
        const on = boxes.filter((b) => b.checked).map((b) => b.value);
        onChange(name, on.length ? on.join(',') : 'none');
      });
      updates.push((s) => {
        const on = s[name] === 'all' ? spec.words : s[name].split(',');
        for (const box of boxes) box.checked = on.includes(box.value);
      });
      return group;
    },
    slice(name, spec) {
      // An axis (or off) and a position along it; the value is `off` or `axis:position`.
      const axis = element('select', { id: `${name}-axis`, ariaLabel: 'Slice axis' },
        ...['off', 'x', 'y', 'z'].map((a) => element('option', { value: a, textContent: a })));
      const position = element('input', { type: 'range', min: '-1', max: '1', step: '0.01' });
      position.setAttribute('aria-label', 'Slice position');
      const control = row(name, spec.label, position);
      const output = control.querySelector('output');
      control.insertBefore(axis, position);
      control.classList.add('slice');
      const key = element('div', { className: 'key' });
      const send = () => {
        onChange(name, axis.value === 'off' ? 'off' : `${axis.value}:${Number(position.value)}`);
      };
      axis.addEventListener('change', send);
      position.addEventListener('input', send);
      updates.push((s) => {
        const [a, p] = s[name] === 'off' ? ['off', '0'] : s[name].split(':');
        axis.value = a;
        position.value = p;
        position.disabled = a === 'off';
        output.textContent = a === 'off' ? '' : Number(p).toFixed(2);
        key.replaceChildren(...(a === 'off' ? [] : [sliceKey()]));
      });
      return element('div', {}, control, key);
    },
  };

  controls.integer = controls.number;
  const classNames = gallery.classes.map((k) => k.name);
  const extras = {
    paused: () => {
      const button = makeButton('pause', 'Pause', 'Pause or play (P)', actions.togglePause);
      updates.push((s) => {
        button.setAttribute('aria-pressed', String(s.paused));
        button.textContent = s.paused ? 'Play' : 'Pause';
      });
      return button;
    },
    step: () => makeButton('step', 'Step', 'One frame forward, paused (.)', actions.step),
    seed: () => makeButton('reseed', 'New layout', 'Draw a new random layout (N)', actions.reseed),
    view: () => makeButton('reset-view', 'Reset view', 'Reset the camera (R or double-click)', actions.resetView),
    scene: () => element('span', { className: 'buttons' },
      makeButton('save-scene', 'Save scene', 'Download the scene as a JSON file', actions.saveScene),
      makeButton('load-scene', 'Load scene…', 'Open a scene file (or drop one on the figure)', actions.loadScene)),
    export: () => element('span', { className: 'buttons' },
      ...['stl', 'obj', 'ply'].map((f) => makeButton(`export-${f}`, f.toUpperCase(),
        `Download the surface as ${f.toUpperCase()}`, () => actions.exportMesh(f))),
      makeButton('picture', 'PNG', 'Download a picture at the figure\'s size', () => actions.picture(1)),
      makeButton('picture-2x', 'PNG 2×', 'Download a picture at twice the size', () => actions.picture(2))),
  };
  let galleryList = null;
  // The class of the inspected cell, marked in the gallery.
  let shownClass = null;
  const markCurrent = () => {
    for (const figure of galleryList?.children ?? []) {
      figure.classList.toggle('current', figure.dataset.class === String(shownClass));
    }
  };

  for (const [title, members] of GROUPS) {
    const present = members.filter((name) => wanted.has(name));
    if (!present.length) continue;
    const section = element('div', { className: 'group-body' });
    const group = element('details', { className: 'group', open: title === 'Surface' },
      element('summary', { textContent: title }), section);
    const buttons = element('div', { className: 'buttons' });
    for (const name of present) {
      if (name in extras) {
        buttons.append(extras[name]());
      } else if (name === 'edit') {
        section.append(controls.boolean(name, byName[name]));
        section.append(element('p', {
          className: 'hint',
          textContent: 'Drag a sphere to move it · Shift-click to add one · Delete removes · wheel: radius',
        }));
      } else if (name === 'error_plot') {
        const status = element('p', { className: 'hint', role: 'status' });
        const plot = element('figure', { className: 'error-plot' });
        const button = makeButton('error-plot', 'Error vs resolution',
          'Mesh these spheres at 8³ to 64³ on the CPU and plot the distance to the exact surface', async () => {
            button.disabled = true;
            try {
              const result = await actions.errorSweep((text) => { status.textContent = text; });
              const { svg, lines } = plotErrors(result);
              const caption = element('figcaption', {});
              caption.innerHTML = '<span style="color:#4aa3ff">■</span> linear · <span style="color:#ff9f43">■</span> midpoint · solid RMS, dashed max<br>';
              caption.append(lines.join(' · '), ` · triangles ∝ n^${result.slopes.triangles?.toFixed(2)}`);
              plot.replaceChildren(svg, caption);
            } catch (error) {
              status.textContent = `The plot stopped: ${error?.message ?? error}`;
            } finally {
              button.disabled = false;
            }
          });
        section.append(element('div', { className: 'buttons' }, button), status, plot);
      } else if (name === 'inspector') {
        section.append(element('p', { className: 'hint', textContent: 'Click the surface to inspect a cell (Esc to let go).' }));
        const cases = element('details', { className: 'cases' }, element('summary', { textContent: 'The 15 cases' }));
        // Drawn while the page is idle (or when opened first), not before the figure's first frame.
        const fill = () => {
          if (galleryList || !cases.isConnected) return;
          galleryList = buildGallery(gallery);
          cases.append(galleryList);
          markCurrent();
        };
        cases.addEventListener('toggle', fill, { once: true });
        (globalThis.requestIdleCallback ?? setTimeout)(fill);
        section.append(cases);
      } else {
        const spec = byName[name];
        const control = controls[spec.kind](name, spec);
        if (withoutCompute && NEED_COMPUTE.has(name)) {
          for (const input of control.querySelectorAll('input, select')) input.disabled = true;
          control.title = WITHOUT_COMPUTE;
          control.classList.add('unavailable');
        }
        section.append(control);
        if (name === 'color_by') {
          const key = element('div', { className: 'key' });
          updates.push((s) => key.replaceChildren(...[colorKey(s, classNames)].filter(Boolean)));
          section.append(key);
        }
      }
    }
    if (wanted.has('seed') && title === 'Surface') {
      const seed = element('p', { className: 'seed', innerHTML: 'Layout <span id="seed-value"></span>' });
      updates.push((s) => { seed.querySelector('span').textContent = String(s.seed); });
      section.append(seed);
    }
    if (buttons.childElementCount) section.append(buttons);
    body.append(group);
  }
  body.append(element('slot', { name: 'panel-footer' }));
  body.append(element('p', {
    className: 'hint',
    textContent: 'Drag to orbit · click, then wheel to zoom · arrows to turn · double-click to reset',
  }));

  const show = (s, inspectedClass = shownClass) => {
    shownClass = inspectedClass;
    for (const update of updates) update(s);
    markCurrent();
  };
  show(state);
  return show;
}
