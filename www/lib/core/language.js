// Which language a figure speaks and which way its boxes run, and the watch that tells it when the page
// changes either. The language is the element's `lang`, else its nearest ancestor's (across shadow
// roots), else the document's, else the browser's. The direction is the nearest `dir` (ltr or rtl) where
// it is nearer than that `lang`, else the language's. Figures reword themselves when a `lang` or `dir`
// anywhere in the document changes (a site's language switcher), when the browser's language changes and
// when a catalogue arrives or is registered.

import { catalogueVersion, directionOfLanguage, loadLanguage, onCatalogues, Words } from '../i18n/words.js';

// The element itself, then its ancestors, crossing out of shadow roots into their hosts.
function* upward(node) {
  for (let n = node; n;) {
    yield n;
    n = n.parentElement ?? n.getRootNode?.().host ?? null;
  }
}

/** `{ lang, dir }` for `element`, as the page gives them. */
export function languageOf(element) {
  let dir = null;
  for (const node of upward(element)) {
    const d = node.getAttribute?.('dir')?.toLowerCase();
    if (!dir && (d === 'ltr' || d === 'rtl')) dir = d;
    const lang = node.getAttribute?.('lang');
    if (lang) return { lang, dir: dir ?? directionOfLanguage(lang) };
    // `lang=""` says the language is unknown: the browser's is taken.
    if (lang === '') break;
  }
  const lang = globalThis.navigator?.language || 'en';
  return { lang, dir: dir ?? directionOfLanguage(lang) };
}

const watchers = new Set();
const WATCHED = { attributes: true, attributeFilter: ['lang', 'dir'], subtree: true };
let observer = null;

function tellAll() {
  for (const watcher of [...watchers]) watcher();
}

/**
 * Calls `onChange(words)` with `element`'s words now and whenever its language, its direction or a
 * catalogue of it changes; returns a function that stops watching.
 */
export function watchLanguage(element, onChange) {
  let last = null;
  const check = () => {
    const { lang, dir } = languageOf(element);
    if (last && last.lang === lang && last.dir === dir && last.version === catalogueVersion()) return;
    loadLanguage(lang);
    last = new Words(lang, dir);
    onChange(last);
  };
  watchers.add(check);
  if (!observer && globalThis.MutationObserver && globalThis.document) {
    observer = new MutationObserver(tellAll);
    observer.observe(document, WATCHED);
    globalThis.addEventListener?.('languagechange', tellAll);
    onCatalogues(tellAll);
  }
  // The shadow roots the element sits in are watched too (a `lang` set inside a component's own tree).
  for (const node of upward(element)) {
    const root = node.getRootNode?.();
    if (root && root !== document && root !== node && root.host) observer?.observe(root, WATCHED);
  }
  check();
  return () => watchers.delete(check);
}
