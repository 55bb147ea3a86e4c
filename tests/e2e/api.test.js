// The author's API of <metaballs-view> is the one its manifest declares, in Node: every public method
// and property the element's class writes (www/metaballs-view.js) is in custom-elements.json and in
// metaballs-view.d.ts (both written by `metaballs manifest` from src/manifest/api.rs), and every member
// they declare is on the element, as a member of its class or as the property of a row of the
// parameter table. The calls the page's hub makes on each figure are not the author's and are listed
// here; a new public member fails until it is declared, documented and typed.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync } from 'node:fs';
import path from 'node:path';
import { NAMES, OLD_PROPERTIES, propertyName } from '../../www/lib/core/table.js';
import { root } from './helpers.js';

const read = (file) => readFileSync(path.join(root, file), 'utf8');
// What the page's hub (www/lib/engine/) calls on every figure: not part of the author's API.
const HUB_CALLS = ['approach', 'setOnScreen', 'suspend', 'resume', 'fail', 'tick', 'schemeChanged'];
const CALLBACKS = ['constructor', 'connectedCallback', 'disconnectedCallback', 'attributeChangedCallback'];

// The public members the element's class writes itself (not static, not private), by name.
function classMembers() {
  const text = read('www/metaballs-view.js');
  const start = text.indexOf('export class MetaballsView ');
  const body = text.slice(start, text.indexOf('\n}', start));
  return new Set([...body.matchAll(/^ {2}(?!static )(?:async |get |set )*([A-Za-z]+)\s*\(/gm)].map((m) => m[1]));
}

const manifest = JSON.parse(read('www/custom-elements.json'));
const declared = manifest.modules.flatMap((m) => m.declarations ?? []).find((d) => d.tagName === 'metaballs-view').members;
const typed = read('www/metaballs-view.d.ts');
const viewClass = typed.slice(typed.indexOf('export declare class MetaballsView'), typed.indexOf('\n}', typed.indexOf('export declare class MetaballsView')));

test('every public member of the element is declared in its manifest and typed, and nothing else is', () => {
  const members = classMembers();
  assert.ok(members.size > 30, `${members.size} members read from the class`);
  const engine = readdirSync(path.join(root, 'www/lib/engine')).map((f) => read(`www/lib/engine/${f}`)).join('\n');
  for (const call of HUB_CALLS) {
    assert.ok(members.has(call), `the hub's call ${call} is not on the element`);
    assert.ok(engine.includes(`.${call}(`), `nothing in www/lib/engine calls ${call}: it is not the hub's`);
  }
  const names = new Set(declared.map((m) => m.name));
  const undeclared = [...members].filter((m) => !names.has(m) && !HUB_CALLS.includes(m) && !CALLBACKS.includes(m));
  assert.deepEqual(undeclared, [], 'public members of the element that its manifest does not declare');
  const properties = new Set(NAMES.map(propertyName));
  const absent = declared.filter((m) => !members.has(m.name) && !properties.has(m.name)).map((m) => m.name);
  assert.deepEqual(absent, [], 'members the manifest declares that the element does not have');
  const untyped = declared.filter((m) => !new RegExp(`^ {2}(?:readonly |get |set )?${m.name}\\b`, 'm').test(viewClass))
    .map((m) => m.name);
  assert.deepEqual(untyped, [], 'members the manifest declares that metaballs-view.d.ts does not type');
  for (const m of declared) assert.ok(m.description?.length > 10, `${m.name} has no description in the manifest`);
  // The spellings of earlier versions stay as properties, and are not declared again.
  for (const [old] of OLD_PROPERTIES) assert.ok(!names.has(old), `${old} (an earlier spelling) is declared`);
});

test('the change event carries the property, the attribute and the value, as typed', () => {
  const event = manifest.modules.flatMap((m) => m.declarations ?? []).find((d) => d.tagName === 'metaballs-view')
    .events.find((e) => e.name === 'metaballs-change');
  assert.match(event.type.text, /property: string; attribute: string; value/);
  assert.match(typed, /'metaballs-change': CustomEvent<\{ property: string; attribute: string; value/);
  assert.match(read('www/lib/core/context.js'), /emit\('metaballs-change', \{ property: propertyName\(name\), attribute: name, value \}\)/);
});
