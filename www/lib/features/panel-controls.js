// The panel's controls for each kind of parameter (a slider for numbers, a colour input, a checkbox,
// a select of words, a checkbox per word of a list, the slice's axis and position), and the small DOM
// helpers the panel and the features' own controls use. Each control's id is `controlId(name)`.

import { controlId } from '../core/table.js';
import { sliceKey } from './legends.js';

const FORMATS = {
  spheres: (v) => String(v),
  resolution: (v) => `${v}³`,
  speed: (v) => `${v.toFixed(2)}×`,
  shininess: (v) => String(Math.round(v)),
  'spot-angle': (v) => `${Math.round(v)}°`,
  fov: (v) => `${Math.round(v)}°`,
};
const formatNumber = (name, v) => (FORMATS[name] ?? ((x) => x.toFixed(2)))(v);

export function element(tag, properties = {}, ...children) {
  const node = Object.assign(document.createElement(tag), properties);
  node.append(...children);
  return node;
}

export function makeButton(id, text, title, onClick) {
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
 * The builders by kind: `builders[kind](name, row)` returns the control's node. `onChange(name, value)`
 * receives the person's edits; each control pushes its update (state → control) onto `updates`.
 * `maxResolution`: the largest uniform grid the device holds.
 */
export function controlBuilders(onChange, updates, { maxResolution }) {
const builders = {
  number(name, spec) {
    const input = element('input', {
      type: 'range',
      min: String(spec.sliderMin),
      max: String(name === 'resolution' ? Math.min(spec.sliderMax, maxResolution) : spec.sliderMax),
      step: String(spec.step),
    });
    const control = row(controlId(name), spec.label, input);
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
    const control = row(controlId(name), spec.label, input);
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
    const control = row(controlId(name), spec.label, input);
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
    const control = row(controlId(name), spec.label, input);
    input.addEventListener('change', () => onChange(name, input.value));
    updates.push((s) => { input.value = s[name]; });
    return control;
  },
  list(name, spec) {
    // One checkbox per light kind, in a labelled group.
    const id = controlId(name);
    const label = element('span', { id: `${id}-label`, className: 'label', textContent: spec.label });
    const boxes = spec.words.map((word) => element('input', { type: 'checkbox', id: `${id}-${word}`, value: word }));
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
    const axis = element('select', { id: `${controlId(name)}-axis`, ariaLabel: 'Slice axis' },
      ...['off', 'x', 'y', 'z'].map((a) => element('option', { value: a, textContent: a })));
    const position = element('input', { type: 'range', min: '-1', max: '1', step: '0.01' });
    position.setAttribute('aria-label', 'Slice position');
    const control = row(controlId(name), spec.label, position);
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

  builders.integer = builders.number;
  return builders;
}
