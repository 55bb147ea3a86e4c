// The 2D figure's full page (`squares.html`) and its iframe page (`embed-2d.html`): one <metaballs-2d> whose attributes come from the link's
// query string (`?circles=0.3,0.1,0.35;-0.35,-0.2,0.3&iso=1.2&resolution=12&saddle=decider`), kept in the
// URL as the person changes them, so a link reproduces the figure. Bad values in a link get the
// figure's notice and its defaults, as any bad attribute does.

import { queryText } from './lib/core/share-text.js';

const element = document.querySelector('metaballs-2d');
const Figure = customElements.get('metaballs-2d') ?? await customElements.whenDefined('metaballs-2d');
// The full page always has every control, so its links do not carry `controls`; the iframe page
// (embed-2d.html) shows what its link asks for.
const chromeless = document.body.dataset.page === 'embed-2d';
const names = Figure.observedAttributes.filter((name) => (chromeless || name !== 'controls') && name !== 'slice-of');
document.getElementById('open-share')?.addEventListener('click', () => element.openShare());

// What the page's markup gives stays out of the link.
const given = new Map(names.map((name) => [name, element.getAttribute(name)]));
const query = new URLSearchParams(location.search);
for (const name of names) {
  if (query.has(name)) element.setAttribute(name, query.get(name));
}

let timer = 0;
function saveUrl() {
  clearTimeout(timer);
  timer = setTimeout(() => {
    const settings = names.map((name) => ({ row: { url: name }, text: element.getAttribute(name) }))
      .filter(({ row, text }) => text !== null && text !== given.get(row.url));
    history.replaceState(null, '', `${location.pathname}${queryText(settings)}`);
  }, 150);
}
element.addEventListener('metaballs-change', saveUrl);
saveUrl();
