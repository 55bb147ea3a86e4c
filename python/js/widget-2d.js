// The 2D notebook widget's front end (an anywidget module): a <metaballs-2d> in the output, its
// settings kept equal to the model's traits both ways, and Python's questions (the contours, the SVG)
// answered. It follows the anywidget front-end contract only, as widget.js does; the 2D figure needs no
// WebAssembly, so nothing is fetched.

import '../../www/metaballs-2d.js';
import { quietly } from './quietly.js';
import { followLanguage } from './language.js';
import { PLANE_TABLE } from '../../www/lib/attributes.js';

// What Python may ask the figure, by the element's method names.
const CALLS = new Set(['contours', 'toSVG']);

// A trait's value as the attribute's text (`true`/`false` for switches); null removes the attribute.
const text = (value) => (value === null || value === undefined || value === '' ? null : String(value));

function render({ model, el }) {
  const figure = document.createElement('metaballs-2d');
  figure.style.maxWidth = '560px';
  const write = (name) => {
    const value = text(model.get(name.replace(/-/g, '_')));
    if (value === null) figure.removeAttribute(name);
    else if (figure.getAttribute(name) !== value) figure.setAttribute(name, value);
  };
  for (const { name } of PLANE_TABLE) write(name);
  const stopLanguage = followLanguage(model, figure);
  el.replaceChildren(figure);

  // Python → figure: a changed trait becomes the attribute.
  const listeners = PLANE_TABLE.map(({ name }) => {
    const event = `change:${name.replace(/-/g, '_')}`;
    const listener = () => write(name);
    model.on(event, listener);
    return [event, listener];
  });
  // Figure → Python: a setting changed inside it (its panel, circles added, moved or removed).
  // The event carries the value typed as the trait holds it (the table's reader made it).
  const changed = (event) => {
    const { attribute, value } = event.detail;
    if (!PLANE_TABLE.some((r) => r.name === attribute)) return;
    model.set(attribute.replace(/-/g, '_'), value);
    quietly(() => model.save_changes());
  };
  figure.addEventListener('metaballs-change', changed);
  // Python's questions.
  const asked = async (message) => {
    if (message?.type !== 'call') return;
    const { id, method, args = [] } = message;
    try {
      if (!CALLS.has(method)) throw new Error(`the figure has no method ${method}`);
      model.send({ type: 'answer', id, value: await figure[method](...args) });
    } catch (error) {
      model.send({ type: 'answer', id, error: String(error?.message ?? error) });
    }
  };
  model.on('msg:custom', asked);
  return () => {
    stopLanguage();
    for (const [event, listener] of listeners) quietly(() => model.off(event, listener));
    quietly(() => model.off('msg:custom', asked));
    figure.removeEventListener('metaballs-change', changed);
    figure.remove();
  };
}

export default { render };
