// A figure as it is now, written for an author to paste: the HTML of the element (with the module's
// script tag), the iframe page's URL and an <iframe> of it, the notebook widget's call and MyST's
// {anywidget} directive, and the full page's link. Every text is made from the figure's rows of the
// parameter table (names, short names, Python names, defaults, kinds): a setting is written when it
// differs from its default, in the spelling links and scene files use, so each text reads back exactly
// and a setting added to the table is shared without a line here.

import { f32Text } from './read.js';

/** A value as its attribute, its link and its scene file write it (a number as the shortest f32). */
export function valueText(row, value) {
  if (typeof value === 'boolean') return value ? 'true' : 'false';
  if (row.kind === 'number' && typeof value === 'number') return f32Text(value);
  return String(value);
}

/**
 * The settings of `state` that differ from their defaults, in the table's order: [{ row, value, text }].
 * `chosen(row)`: false for a value the figure chose itself (for its device), which a copy chooses again.
 */
export function changedSettings(rows, state, chosen = () => true) {
  const out = [];
  for (const row of rows.rows) {
    const value = state[row.name];
    if (value === undefined || value === row.value || !chosen(row)) continue;
    const text = valueText(row, value);
    if (text === valueText(row, row.value)) continue;
    out.push({ row, value, text });
  }
  return out;
}

/**
 * A query string of `settings` ({ row, value, text }) under their short names, flags as 1 or 0, commas,
 * semicolons and colons kept readable.
 */
export function queryText(settings) {
  const query = new URLSearchParams();
  for (const { row, value, text } of settings) query.set(row.url, typeof value === 'boolean' ? (value ? '1' : '0') : text);
  const search = query.toString().replace(/%2C/g, ',').replace(/%3B/g, ';').replace(/%3A/g, ':');
  return search ? `?${search}` : '';
}

const escapeAttribute = (text) => text.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;').replace(/>/g, '&gt;');

/** An element's start and end tags with `attributes` ([name, text | true]), wrapped when long. */
export function elementHtml(tag, attributes) {
  const parts = attributes.map(([name, text]) => (text === true ? name : `${name}="${escapeAttribute(text)}"`));
  const oneLine = `<${tag}${parts.map((p) => ` ${p}`).join('')}></${tag}>`;
  if (oneLine.length <= 100) return oneLine;
  return `<${tag}\n${parts.map((p) => `  ${p}`).join('\n')}>\n</${tag}>`;
}

/** A Python literal of a setting's value. */
function pythonValue(row, value) {
  if (typeof value === 'boolean') return value ? 'True' : 'False';
  if (typeof value === 'number') return valueText(row, value);
  return JSON.stringify(String(value));
}

/** A JSON value of a setting, as the widget's model holds it. */
function jsonValue(row, value) {
  if (typeof value === 'number' && row.kind === 'number') return Number(f32Text(value));
  return value;
}

/**
 * Every text of the share box for one figure.
 * - `rows`, `state`: the figure's table (a Rows) and its values; `chosen(row)`: see changedSettings;
 * - `tag`: the element's name; `moduleUrl`: the URL its module was loaded from (absolute);
 *   `stylesheet`: the stylesheet that reserves its box before the module loads, or null;
 * - `pages`: { full, embed } absolute URLs of the full page and the iframe page;
 * - `widget`: { module, className, wasmUrl } of the notebook widget (`wasmUrl` may be null);
 * - `size`: { width, height } the figure was seen at, in CSS pixels;
 * - `poster`: the name of a poster picture to name, or null; `pageRows`: rows a full page's link
 *   leaves out (the page has its own); `iframeRows`: rows the iframe page's URL leaves out (they name
 *   things of the author's page: a sync group, a poster file);
 * - `version`: the package's version, said beside the script tag.
 */
export function shareTexts({
  rows, state, chosen, tag, moduleUrl, stylesheet = null, pages, widget, size, poster = null, pageRows = new Set(), iframeRows = new Set(), version,
}) {
  const settings = changedSettings(rows, state, chosen);
  const withPoster = poster && !settings.some((s) => s.row.name === 'poster')
    ? [...settings, { row: rows.rowOf('poster') ?? { name: 'poster', url: 'poster', python: 'poster' }, value: poster, text: poster }]
    : settings;

  const attributes = withPoster.map(({ row, value, text }) => [row.name, value === true ? true : text]);
  const html = [
    `<!-- ${tag} ${version} -->`,
    ...(stylesheet ? [`<link rel="stylesheet" href="${escapeAttribute(stylesheet)}">`] : []),
    `<script type="module" src="${escapeAttribute(moduleUrl)}"></script>`,
    elementHtml(tag, attributes),
  ].join('\n');

  const url = `${pages.embed}${queryText(settings.filter((s) => !iframeRows.has(s.row.name)))}`;
  const width = Math.max(1, Math.round(size.width));
  const height = Math.max(1, Math.round(size.height));
  const title = state.alt || 'Interactive figure';
  // As wide as seen where the page has room, narrower (at the same shape) where it has not; Copy in the
  // figure's share box may write the clipboard from inside it.
  const iframe = elementHtml('iframe', [
    ['src', url], ['width', String(width)], ['height', String(height)], ['title', title],
    ['style', `border: 0; width: 100%; max-width: ${width}px; height: auto; aspect-ratio: ${width} / ${height}`],
    ['loading', 'lazy'], ['allow', 'fullscreen; clipboard-write'],
  ]);

  const arguments_ = settings.map(({ row, value }) => `${row.python}=${pythonValue(row, value)}`);
  const call = `${widget.className}(${arguments_.join(', ')})`;
  const python = [
    `from metaballs_widget import ${widget.className}`,
    '',
    call.length <= 100 ? call : `${widget.className}(\n${arguments_.map((a) => `    ${a},`).join('\n')}\n)`,
  ].join('\n');

  const model = Object.fromEntries(settings.map(({ row, value }) => [row.python, jsonValue(row, value)]));
  if (widget.wasmUrl) model.wasm_url = widget.wasmUrl;
  const json = JSON.stringify(model, null, 2);
  // A fence longer than any run of backticks in the settings (a description may hold some).
  const fence = '`'.repeat(Math.max(3, ...[...json.matchAll(/`+/g)].map((m) => m[0].length + 1)));
  const myst = [`${fence}{anywidget} ${widget.module}`, json, fence].join('\n');

  const link = `${pages.full}${queryText(settings.filter((s) => !pageRows.has(s.row.name)))}`;
  return { html, url, iframe, python, myst, link };
}
