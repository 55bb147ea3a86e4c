// What a figure says when its WebAssembly cannot be had: the server answered with an error, the file
// is cut short or damaged, the page's Content-Security-Policy forbids compiling WebAssembly, or the
// network failed. Each message says what failed and what the page's author (or the reader) can do. A
// file served with the wrong type still starts (from its bytes, more slowly), with a notice saying so.

/** The Content-Security-Policy a page needs for the element: its modules, and WebAssembly compiled. */
export const CSP_NEEDED = "script-src 'self' 'wasm-unsafe-eval'";

/** A failure to load, with the title the figure shows over its message. */
export class AssetError extends Error {
  constructor(title, message) {
    super(message);
    this.title = title;
  }
}

const DEPLOY = "Make sure the site holds the package's pkg/ folder beside its www/ folder, as published, then reload the page.";

/**
 * Fetches the WebAssembly at `url`. Resolves to `{ source, warning }`: `source` is what the glue's
 * start takes (the Response, compiled as it streams in, or the bytes where the type is wrong), and
 * `warning` a notice for the figures, or null. Rejects with an AssetError.
 */
export async function fetchWasm(url) {
  let response;
  try {
    response = await fetch(url);
  } catch (error) {
    throw new AssetError('The figure could not load', `Its WebAssembly (${url}) could not be fetched `
      + `(${error?.message ?? error}). Check the connection and reload the page; a page on another site `
      + 'must be allowed to fetch from where the element is served.');
  }
  if (!response.ok) {
    throw new AssetError('The figure could not load', `Its WebAssembly (${url}) could not be fetched: `
      + `the server answered ${response.status}${response.statusText ? ` ${response.statusText}` : ''}. ${DEPLOY}`);
  }
  const type = response.headers.get('content-type') ?? '';
  if (/^application\/wasm\b/i.test(type)) return { source: response, warning: null };
  return {
    source: await response.arrayBuffer(),
    warning: `The server sends the figures' WebAssembly as "${type || 'no type'}" rather than application/wasm, `
      + 'so they start more slowly. Serve .wasm files as application/wasm.',
  };
}

/** The AssetError to show for `error`, thrown while loading the build whose WebAssembly is at `url`. */
export function describeLoadError(error, url) {
  if (error instanceof AssetError) return error;
  const text = `${error?.message ?? error}`;
  if (/Content Security Policy|unsafe-eval/i.test(text)) {
    return new AssetError('This page blocks WebAssembly', "The page's Content-Security-Policy does not allow "
      + `compiling WebAssembly, which the figure needs. Its script-src must include 'wasm-unsafe-eval', as in ${CSP_NEEDED}.`);
  }
  if (error?.name === 'CompileError' || error instanceof globalThis.WebAssembly?.CompileError) {
    return new AssetError('The figure could not load', `Its WebAssembly (${url}) is cut short or damaged, so `
      + `the browser cannot compile it (${text}). ${DEPLOY}`);
  }
  if (/dynamically imported module|Failed to fetch|Importing a module script failed/i.test(text)) {
    return new AssetError('The figure could not load', `Its code could not be fetched (${text}). ${DEPLOY}`);
  }
  return new AssetError('The figure could not load', text);
}
