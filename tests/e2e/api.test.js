// The author's API of both elements is the one their manifests declare, in Node: every public method
// and property each element's class writes (www/metaballs-view.js, www/metaballs-2d.js) is in
// custom-elements.json and in its TypeScript declarations (metaballs-view.d.ts, metaballs-2d.d.ts, all
// written by `metaballs manifest` from src/manifest/api.rs and plane.rs), and every member they declare
// is on the element, as a member of its class or as the property of a row of its table. The calls the
// page's hub makes on each 3D figure are not the author's and are listed here; a new public member fails
// until it is declared, documented and typed.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { VIEW_ROWS } from '../../www/lib/core/table.js';
import { Rows } from '../../www/lib/core/rows.js';
import { PLANE_TABLE } from '../../www/lib/attributes.js';
import { root } from './helpers.js';

const read = (file) => readFileSync(path.join(root, file), 'utf8');
// What the page's hub (www/lib/engine/) calls on every 3D figure: not part of the author's API.
const HUB_CALLS = ['approach', 'setOnScreen', 'suspend', 'resume', 'fail', 'tick', 'schemeChanged'];
const CALLBACKS = ['constructor', 'connectedCallback', 'disconnectedCallback', 'attributeChangedCallback'];
const manifest = JSON.parse(read('www/custom-elements.json'));

const ELEMENTS = [
  { tag: 'metaballs-view', file: 'www/metaballs-view.js', className: 'MetaballsView', typings: 'www/metaballs-view.d.ts', rows: VIEW_ROWS, hub: HUB_CALLS },
  { tag: 'metaballs-2d', file: 'www/metaballs-2d.js', className: 'Metaballs2d', typings: 'www/metaballs-2d.d.ts', rows: new Rows(PLANE_TABLE), hub: [] },
];

// The public members an element's class writes itself (not static, not private), by name.
function classMembers({ file, className }) {
  const text = read(file);
  const start = text.indexOf(`export class ${className} `);
  const body = text.slice(start, text.indexOf('\n}', start));
  return new Set([...body.matchAll(/^ {2}(?!static )(?:async |get |set )*([A-Za-z]+)\s*\(/gm)].map((m) => m[1]));
}

const declarationOf = (tag) => manifest.modules.flatMap((m) => m.declarations ?? []).find((d) => d.tagName === tag);

for (const element of ELEMENTS) {
  test(`every public member of <${element.tag}> is declared in its manifest and typed, and nothing else is`, () => {
    const members = classMembers(element);
    assert.ok(members.size > 12, `${members.size} members read from the class`);
    const engine = readdirSync(path.join(root, 'www/lib/engine')).map((f) => read(`www/lib/engine/${f}`)).join('\n');
    for (const call of element.hub) {
      assert.ok(members.has(call), `the hub's call ${call} is not on the element`);
      assert.ok(engine.includes(`.${call}(`), `nothing in www/lib/engine calls ${call}: it is not the hub's`);
    }
    const declared = declarationOf(element.tag).members;
    const typings = read(element.typings);
    const start = typings.indexOf(`export declare class ${element.className}`);
    const typed = typings.slice(start, typings.indexOf('\n}', start));
    const names = new Set(declared.map((m) => m.name));
    const undeclared = [...members].filter((m) => !names.has(m) && !element.hub.includes(m) && !CALLBACKS.includes(m));
    assert.deepEqual(undeclared, [], 'public members of the element that its manifest does not declare');
    const properties = new Set(element.rows.names.map((name) => element.rows.propertyName(name)));
    const absent = declared.filter((m) => !members.has(m.name) && !properties.has(m.name)).map((m) => m.name);
    assert.deepEqual(absent, [], 'members the manifest declares that the element does not have');
    for (const name of properties) assert.ok(names.has(name), `the setting's property ${name} is not declared`);
    const untyped = declared.filter((m) => !new RegExp(`^ {2}(?:readonly |get |set )?${m.name}\\b`, 'm').test(typed))
      .map((m) => m.name);
    assert.deepEqual(untyped, [], `members the manifest declares that ${element.typings} does not type`);
    for (const m of declared) assert.ok(m.description?.length > 10, `${m.name} has no description in the manifest`);
    // The spellings of earlier versions stay as properties, and are not declared again.
    for (const [old] of element.rows.oldProperties) assert.ok(!names.has(old), `${old} (an earlier spelling) is declared`);
  });
}

test('both elements send one change event: the property, the attribute and the value, as typed', () => {
  for (const { tag, typings } of ELEMENTS) {
    const event = declarationOf(tag).events.find((e) => e.name === 'metaballs-change');
    assert.match(event.type.text, /property: string; attribute: string; value: number \| boolean \| string/, tag);
    assert.match(read(typings), /'metaballs-change': CustomEvent<\{ property: string; attribute: string; value/, tag);
  }
  // Sent from one place, by the figure context both elements are built on.
  const sources = ['www/metaballs-view.js', 'www/metaballs-2d.js', ...readdirSync(path.join(root, 'www/lib'), { recursive: true })
    .filter((f) => f.endsWith('.js')).map((f) => `www/lib/${f}`)];
  const senders = sources.filter((file) => read(file).includes("'metaballs-change'"));
  assert.deepEqual(senders, ['www/lib/core/context.js']);
  assert.match(read('www/lib/core/context.js'), /emit\('metaballs-change', \{ property: this\.settings\.rows\.propertyName\(name\), attribute: name, value \}\)/);
  for (const { file } of ELEMENTS) assert.match(read(file), /new FigureContext\(this, root, new FigureState\(this, /, file);
});
