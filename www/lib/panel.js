// The element's control panel, built from the parameter table for the controls an author lists
// (`controls="iso,resolution"`, `all` or `none`). Compact and collapsible: small figures start with it
// folded, and it never takes more than a third of the figure's width.

const FORMATS = {
  spheres: (v) => String(v),
  iso: (v) => v.toFixed(2),
  resolution: (v) => `${v}³`,
  speed: (v) => `${v.toFixed(2)}×`,
  shininess: (v) => String(Math.round(v)),
  color: (v) => v,
};

/** The control names `list` (the `controls` value) asks for, in the table's order. */
export function listedControls(list, all) {
  if (list === 'all') return all;
  if (list === 'none' || !list) return [];
  const wanted = new Set(list.split(','));
  return all.filter((name) => wanted.has(name));
}

/**
 * Builds the panel into `container` (emptied first) for `names`. `table` is the parameter table,
 * `state` the element's values, `onChange(name, value)` receives the person's edits and `actions` the
 * buttons (togglePause, reseed, resetView). Returns `show(state)` to bring the controls up to date.
 */
export function buildPanel(container, names, table, state, onChange, actions, { maxResolution, small }) {
  container.replaceChildren();
  container.hidden = names.length === 0;
  if (!names.length) return () => {};
  const details = document.createElement('details');
  details.open = !small;
  const summary = document.createElement('summary');
  summary.textContent = 'Controls';
  details.append(summary);
  const body = document.createElement('div');
  body.className = 'controls';
  details.append(body);
  container.append(details);

  const byName = Object.fromEntries(table.map((p) => [p.name, p]));
  const updates = [];
  const buttons = document.createElement('div');
  buttons.className = 'buttons';

  for (const name of names) {
    const spec = byName[name];
    if (name in FORMATS) {
      const row = document.createElement('div');
      row.className = 'control';
      const label = document.createElement('label');
      label.htmlFor = name;
      label.textContent = spec.label;
      const input = document.createElement('input');
      input.id = name;
      const output = document.createElement('output');
      output.id = `${name}-value`;
      output.htmlFor = name;
      if (spec.kind === 'color') {
        input.type = 'color';
      } else {
        input.type = 'range';
        input.min = String(spec.sliderMin);
        input.max = String(name === 'resolution' ? Math.min(spec.sliderMax, maxResolution) : spec.sliderMax);
        input.step = String(spec.step);
      }
      input.addEventListener('input', () => {
        const value = spec.kind === 'color' ? input.value : Number(input.value);
        output.textContent = FORMATS[name](value);
        onChange(name, value);
      });
      row.append(label, input, output);
      body.append(row);
      updates.push((s) => {
        input.value = String(s[name]);
        output.textContent = FORMATS[name](s[name]);
      });
    } else if (name === 'antialiasing') {
      const row = document.createElement('div');
      row.className = 'control';
      const label = document.createElement('label');
      label.htmlFor = 'antialiasing';
      label.textContent = spec.label;
      const input = document.createElement('input');
      input.type = 'checkbox';
      input.id = 'antialiasing';
      const output = document.createElement('output');
      output.id = 'antialiasing-value';
      input.addEventListener('change', () => onChange('antialiasing', input.checked));
      row.append(label, input, output);
      body.append(row);
      updates.push((s) => {
        input.checked = s.antialiasing;
        output.textContent = s.antialiasing ? '4×' : 'off';
      });
    } else if (name === 'paused') {
      const button = makeButton('pause', 'Pause', 'Pause or play (P)', actions.togglePause);
      buttons.append(button);
      updates.push((s) => {
        button.setAttribute('aria-pressed', String(s.paused));
        button.textContent = s.paused ? 'Play' : 'Pause';
      });
    } else if (name === 'seed') {
      buttons.append(makeButton('reseed', 'New layout', 'Draw a new random layout (N)', actions.reseed));
      const seed = document.createElement('p');
      seed.className = 'seed';
      seed.innerHTML = 'Layout <span id="seed-value"></span>';
      updates.push((s) => { seed.querySelector('span').textContent = String(s.seed); });
      body.append(seed);
    } else if (name === 'view') {
      buttons.append(makeButton('reset-view', 'Reset view', 'Reset the camera (R or double-click)', actions.resetView));
    }
  }
  if (buttons.childElementCount) body.append(buttons);
  const footer = document.createElement('slot');
  footer.name = 'panel-footer';
  body.append(footer);
  const hint = document.createElement('p');
  hint.className = 'hint';
  hint.textContent = 'Drag to orbit · click, then wheel to zoom · arrows to turn · double-click to reset';
  body.append(hint);

  const show = (s) => { for (const update of updates) update(s); };
  show(state);
  return show;
}

function makeButton(id, text, title, onClick) {
  const button = document.createElement('button');
  button.type = 'button';
  button.id = id;
  button.textContent = text;
  button.title = title;
  button.addEventListener('click', onClick);
  return button;
}
