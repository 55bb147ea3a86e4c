// The table's reader without the WebAssembly (www/lib/core/read.js), in Node: every vector the Rust
// parser answered (www/parameter-vectors.json, written by `metaballs manifest`) reads the same: the
// same value, or the same message. The elements are given the same vectors in the browser
// (table.test.js), and the notebook's reader in python/tests.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { readValue, readsInJavaScript } from '../../www/lib/core/read.js';
import { PLANE_TABLE, TABLE } from '../../www/lib/attributes.js';
import { root } from './helpers.js';

const VECTORS = JSON.parse(readFileSync(path.join(root, 'www/parameter-vectors.json'), 'utf8'));

test('every vector of the Rust parser reads the same in the page\'s reader', () => {
  const kinds = new Set();
  for (const v of VECTORS) {
    const row = (v.table === 'plane' ? PLANE_TABLE : TABLE).find((r) => r.name === v.name);
    assert.ok(row && readsInJavaScript(row), `${v.name} is a row the reader reads`);
    kinds.add(row.kind);
    let got;
    try {
      got = { value: readValue(row, v.text, v.given ?? v.name) };
    } catch (error) {
      got = { message: error.message };
    }
    const what = `${v.table} ${v.given ?? v.name}=${JSON.stringify(v.text)}`;
    if ('value' in v) assert.ok(Object.is(got.value, v.value), `${what}: ${JSON.stringify(got)}, Rust: ${JSON.stringify(v.value)}`);
    else assert.equal(got.message, v.message, what);
  }
  // Every kind the reader reads is in the vectors, hostile texts included.
  assert.deepEqual([...kinds].sort(), ['boolean', 'choice', 'color', 'integer', 'levels', 'list', 'number', 'text']);
  for (const text of ['0x10', 'Infinity', 'no', '١٢', '1e39']) assert.ok(VECTORS.some((v) => v.text === text), text);
  assert.ok(VECTORS.length > 2000, `${VECTORS.length} vectors`);
});

test('the reader refuses the kinds with grammars of their own, naming them', () => {
  const slice = TABLE.find((r) => r.kind === 'slice');
  assert.equal(readsInJavaScript(slice), false);
  assert.throws(() => readValue(slice, 'z:0.2'), /read by the figure's WebAssembly/);
});
