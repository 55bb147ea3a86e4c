// What a figure says when its WebAssembly cannot be had: the server answered with an error, the file
// is cut short or damaged, the page's Content-Security-Policy forbids compiling WebAssembly, or the
// network failed. Each message says what failed and what the page's author (or the reader) can do. A
// file served with the wrong type still starts (from its bytes, more slowly), with a notice saying so.
//
// A failure's words are said twice: in English for the page's code (the Error's message and title, the
// `metaballs-error` event) and in the reader's language in the figure's box. Both come from one
// "saying": `{ key, fields }`, a message of the catalogues (i18n/words.js), whose fields may be
// sayings too.

import { ENGLISH } from '../i18n/words.js';

/** The Content-Security-Policy a page needs for the element: its modules, and WebAssembly compiled. */
export const CSP_NEEDED = "script-src 'self' 'wasm-unsafe-eval'";

/** `said` (a saying, an Error, or text as given) worded with `words`; '' for none. */
export function say(words, said) {
  if (said === null || said === undefined) return '';
  if (said instanceof Error) return words.refusal(said);
  if (typeof said !== 'object' || !said.key) return String(said);
  const fields = {};
  for (const [name, value] of Object.entries(said.fields ?? {})) fields[name] = value?.key ? say(words, value) : value;
  return words.t(said.key, fields);
}

/** `said` in English: what the page's code and the console are told. */
export const inEnglish = (said) => say(ENGLISH, said);

/**
 * A failure to load, with the title the figure shows over its message (in English); `said` holds both
 * as sayings (`{ title, text }`), for the reader's language.
 */
export class AssetError extends Error {
  constructor(title, text) {
    super(inEnglish(text));
    this.title = inEnglish(title);
    this.said = { title, text };
  }
}

const COULD_NOT_LOAD = { key: 'figure.could-not-load' };
const DEPLOY = { key: 'figure.deploy' };

// The warnings given so far, by their English text: what each is made of.
const warnings = new Map();

/** The saying of a warning `fetchWasm` gave (by its English text), or the text itself. */
export const warningSaid = (text) => warnings.get(text) ?? text;

/**
 * Fetches the WebAssembly at `url`. Resolves to `{ source, warning }`: `source` is what the glue's
 * start takes (the Response, compiled as it streams in, or the bytes where the type is wrong), and
 * `warning` a notice for the figures (in English; `warningSaid` gives its words), or null. Rejects
 * with an AssetError.
 */
export async function fetchWasm(url) {
  let response;
  try {
    response = await fetch(url);
  } catch (error) {
    throw new AssetError(COULD_NOT_LOAD, { key: 'figure.fetch-failed', fields: { url: String(url), detail: `${error?.message ?? error}` } });
  }
  if (!response.ok) {
    const status = `${response.status}${response.statusText ? ` ${response.statusText}` : ''}`;
    throw new AssetError(COULD_NOT_LOAD, { key: 'figure.server-answered', fields: { url: String(url), status, deploy: DEPLOY } });
  }
  const type = response.headers.get('content-type') ?? '';
  if (/^application\/wasm\b/i.test(type)) return { source: response, warning: null };
  const said = { key: 'notice.wasm-type', fields: { type: type || { key: 'notice.no-type' } } };
  const warning = inEnglish(said);
  warnings.set(warning, said);
  return { source: await response.arrayBuffer(), warning };
}

/** The AssetError to show for `error`, thrown while loading the build whose WebAssembly is at `url`. */
export function describeLoadError(error, url) {
  if (error instanceof AssetError) return error;
  const text = `${error?.message ?? error}`;
  if (/Content Security Policy|unsafe-eval/i.test(text)) {
    return new AssetError({ key: 'figure.wasm-blocked' }, { key: 'figure.csp', fields: { csp: CSP_NEEDED } });
  }
  if (error?.name === 'CompileError' || error instanceof globalThis.WebAssembly?.CompileError) {
    return new AssetError(COULD_NOT_LOAD, { key: 'figure.wasm-damaged', fields: { url: String(url), detail: text, deploy: DEPLOY } });
  }
  if (/dynamically imported module|Failed to fetch|Importing a module script failed/i.test(text)) {
    return new AssetError(COULD_NOT_LOAD, { key: 'figure.code-unfetched', fields: { detail: text, deploy: DEPLOY } });
  }
  return new AssetError(COULD_NOT_LOAD, text);
}
