// The panel's controls for each kind of parameter (a slider for numbers, a colour input, a checkbox,
// a select of words, a checkbox per word of a list, the slice's axis and position), and the small DOM
// helpers the panel and the features' own controls use. Each control's id is `controlId(name)`. Their
// words are marked by key (`data-t`: the table's `setting.<name>` and `word.<name>.<word>`), worded
// by the panel when it is built and again when the language changes; the numbers they show are
// written as the reader writes them.

import { controlId } from '../core/table.js';
import { sliceKey } from './legends.js';

const FORMATS = {
  spheres: (w, v) => w.number(v, 0),
  resolution: (w, v) => `${w.number(v, 0)}³`,
  speed: (w, v) => `${w.fixed(v, 2)}×`,
  shininess: (w, v) => w.number(Math.round(v), 0),
  'spot-angle': (w, v) => `${w.number(Math.round(v), 0)}°`,
  fov: (w, v) => `${w.number(Math.round(v), 0)}°`,
};
// (`+ 0`: a value of -0, as a camera turned back to 0 may have, shows as 0.)
const formatNumber = (words, name, v) => (FORMATS[name] ?? ((w, x) => w.fixed(x, 2)))(words, v + 0);

export function element(tag, properties = {}, ...children) {
  const node = Object.assign(document.createElement(tag), properties);
  node.append(...children);
  return node;
}

/**
 * A button with `text` and `title`, each text as given or `{ key }`: a message's key, marked for the
 * panel to word (`data-t`, `data-t-title`).
 */
export function makeButton(id, text, title, onClick) {
  const button = element('button', { type: 'button', id });
  if (text?.key) button.dataset.t = text.key;
  else button.textContent = text;
  if (title?.key) button.dataset.tTitle = title.key;
  else if (title !== undefined) button.title = title;
  button.addEventListener('click', onClick);
  return button;
}

// One labelled row: label (worded from its key), input, output.
function row(id, labelKey, input, output = element('output')) {
  const label = element('label', { htmlFor: id });
  label.dataset.t = labelKey;
  input.id = id;
  output.id = `${id}-value`;
  output.htmlFor = id;
  return element('div', { className: 'control' }, label, input, output);
}

/**
 * The builders by kind: `builders[kind](name, row)` returns the control's node. `onChange(name, value)`
 * receives the person's edits; each control pushes its update (state → control) onto `updates`.
 * `maxResolution`: the largest uniform grid the device holds; `words()`: the figure's words now.
 */
export function controlBuilders(onChange, updates, { maxResolution, words }) {
const label = (name) => `setting.${name}`;
const builders = {
  number(name, spec) {
    const input = element('input', {
      type: 'range',
      min: String(spec.sliderMin),
      max: String(name === 'resolution' ? Math.min(spec.sliderMax, maxResolution) : spec.sliderMax),
      step: String(spec.step),
    });
    const control = row(controlId(name), label(name), input);
    const output = control.querySelector('output');
    input.addEventListener('input', () => {
      output.textContent = formatNumber(words(), name, Number(input.value));
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
      output.textContent = formatNumber(words(), name, s[name]);
    });
    return control;
  },
  color(name) {
    const input = element('input', { type: 'color' });
    const control = row(controlId(name), label(name), input);
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
  boolean(name) {
    const input = element('input', { type: 'checkbox' });
    const control = row(controlId(name), label(name), input);
    const output = control.querySelector('output');
    input.addEventListener('change', () => onChange(name, input.checked));
    updates.push((s) => {
      input.checked = s[name];
      const on = name === 'antialiasing' ? 'panel.antialiasing-on' : 'panel.on';
      output.textContent = words().t(s[name] ? on : 'panel.off');
    });
    return control;
  },
  choice(name, spec) {
    const input = element('select', {}, ...spec.words.map((w) => {
      const option = element('option', { value: w });
      option.dataset.t = `word.${name}.${w}`;
      return option;
    }));
    const control = row(controlId(name), label(name), input);
    input.addEventListener('change', () => onChange(name, input.value));
    updates.push((s) => { input.value = s[name]; });
    return control;
  },
  list(name, spec) {
    // One checkbox per light kind, in a labelled group.
    const id = controlId(name);
    const heading = element('span', { id: `${id}-label`, className: 'label' });
    heading.dataset.t = label(name);
    const boxes = spec.words.map((word) => element('input', { type: 'checkbox', id: `${id}-${word}`, value: word }));
    const named = (box) => {
      const text = element('span');
      text.dataset.t = `word.${name}.${box.value}`;
      return text;
    };
    const checks = element('div', { className: 'checks' },
      ...boxes.map((box) => element('label', { htmlFor: box.id }, box, ' ', named(box))));
    const group = element('div', { className: 'control list', role: 'group' }, heading, checks);
    group.setAttribute('aria-labelledby', heading.id);
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
    const axis = element('select', { id: `${controlId(name)}-axis` },
      ...['off', 'x', 'y', 'z'].map((a) => element('option', { value: a, textContent: a })));
    axis.dataset.tLabel = 'panel.slice-axis';
    axis.firstChild.dataset.t = 'panel.slice-off';
    const position = element('input', { type: 'range', min: '-1', max: '1', step: '0.01' });
    position.dataset.tLabel = 'panel.slice-position';
    const control = row(controlId(name), label(name), position);
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
      output.textContent = a === 'off' ? '' : words().fixed(Number(p) + 0, 2);
      key.replaceChildren(...(a === 'off' ? [] : [sliceKey(words())]));
    });
    return element('div', {}, control, key);
  },
};

  builders.integer = builders.number;
  return builders;
}
