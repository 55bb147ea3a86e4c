// The figures' catalogues (www/lib/i18n/), without a browser: every shipped language has every key of
// English (made from the parameter tables and the code's messages), no key English lacks, the same
// placeholders, and the plural forms its language needs; every key the code names exists in English; the
// language chains, the directions and the formats are the reader's.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync, statSync } from 'node:fs';
import path from 'node:path';
import { root } from './helpers.js';
import { chainOf, EN, fromWasm, SHIPPED, tableMessages, Words } from '../../www/lib/i18n/words.js';
import { readValue } from '../../www/lib/core/read.js';
import { TABLE } from '../../www/lib/attributes.js';

const placeholders = (text) => new Set([...text.matchAll(/\{([a-zA-Z0-9_]+)\}/g)].map((m) => m[1]));
const forms = (message) => (typeof message === 'string' ? [message] : Object.values(message));
const union = (message) => new Set(forms(message).flatMap((form) => [...placeholders(form)]));

for (const [lang, load] of Object.entries(SHIPPED)) {
  test(`the ${lang} catalogue has every key of English, with its placeholders and ${lang}'s plural forms`, async () => {
    const catalogue = (await load()).default;
    const categories = new Intl.PluralRules(lang).resolvedOptions().pluralCategories;
    const missing = Object.keys(EN).filter((key) => !Object.hasOwn(catalogue, key));
    assert.deepEqual(missing, [], `${lang} lacks ${missing.length} keys`);
    const extra = Object.keys(catalogue).filter((key) => !Object.hasOwn(EN, key));
    assert.deepEqual(extra, [], `${lang} has keys English has not`);
    for (const [key, english] of Object.entries(EN)) {
      const message = catalogue[key];
      if (typeof english === 'string') {
        assert.equal(typeof message, 'string', `${lang} ${key}: a text, as in English`);
        assert.deepEqual(placeholders(message), placeholders(english), `${lang} ${key}: the placeholders of "${english}"`);
        continue;
      }
      assert.equal(typeof message, 'object', `${lang} ${key}: plural forms, as in English`);
      for (const category of categories) assert.equal(typeof message[category], 'string', `${lang} ${key}: the "${category}" form`);
      const wanted = union(english);
      for (const [category, form] of Object.entries(message)) {
        assert.ok(categories.includes(category), `${lang} ${key}: ${lang} has no "${category}" form`);
        // A form for one thing may say the number in words; every other field is in every form.
        const own = placeholders(form);
        for (const name of wanted) if (name !== 'count') assert.ok(own.has(name), `${lang} ${key}.${category}: {${name}}`);
        for (const name of own) assert.ok(wanted.has(name), `${lang} ${key}.${category}: {${name}} is not a field of the message`);
      }
    }
  });
}

// Each language is kept in English's parts, so a key is found in the same file in every language.
const PARTS = ['core', 'figure', 'teaching', 'scene', 'plane'];
for (const lang of Object.keys(SHIPPED)) {
  test(`the ${lang} catalogue's parts hold the keys of English's parts, and table.js those of the tables`, async () => {
    const keys = async (file) => Object.keys((await import(file)).default).sort();
    for (const part of PARTS) {
      assert.deepEqual(await keys(`../../www/lib/i18n/${lang}/${part}.js`), await keys(`../../www/lib/i18n/en/${part}.js`), `${lang}/${part}.js`);
    }
    assert.deepEqual(await keys(`../../www/lib/i18n/${lang}/table.js`), Object.keys(tableMessages()).sort(), `${lang}/table.js`);
  });
}

// The field's terms, which every shipped catalogue's glossary translates once.
const TERMS = ['iso level', 'marching cubes', 'marching squares', 'surface nets', 'genus', 'saddle', 'blob', 'critical point'];

for (const [lang, load] of Object.entries(SHIPPED)) {
  test(`the ${lang} catalogue says each of the field's terms as its glossary does, wherever English says it`, async () => {
    const { default: catalogue, glossary } = await load();
    assert.deepEqual(Object.keys(glossary ?? {}).sort(), [...TERMS].sort(), `${lang}: a glossary of the field's terms`);
    const unlike = [];
    for (const [term, own] of Object.entries(glossary)) {
      const said = new RegExp(term.replace(/ /g, '\\s+'), 'i');
      for (const [key, english] of Object.entries(EN)) {
        // Placeholders are not words (`{saddle}` is a field, said by its value).
        if (!forms(english).some((form) => said.test(form.replace(/\{[^}]*\}/g, '')))) continue;
        for (const form of forms(catalogue[key] ?? '')) {
          if (!form.toLowerCase().includes(own.toLowerCase())) unlike.push(`${key}: "${own}" (${term}) not in "${form}"`);
        }
      }
    }
    assert.deepEqual(unlike, [], `${lang}: the glossary's terms`);
  });
}

test('English has plural forms wherever a message counts, and every key the code names', () => {
  for (const [key, message] of Object.entries(EN)) {
    if (typeof message === 'object') assert.equal(typeof message.other, 'string', `${key}: an "other" form`);
  }
  // Keys the code names literally: t('…') and the data-t attributes of its markup.
  const files = [];
  const walk = (dir) => {
    for (const name of readdirSync(dir)) {
      const file = path.join(dir, name);
      if (statSync(file).isDirectory()) walk(file);
      else if (name.endsWith('.js')) files.push(file);
    }
  };
  walk(path.join(root, 'www/lib'));
  files.push(path.join(root, 'www/metaballs-view.js'), path.join(root, 'www/metaballs-2d.js'));
  const named = new Set();
  for (const file of files.filter((f) => !f.includes(`${path.sep}i18n${path.sep}`))) {
    const text = readFileSync(file, 'utf8');
    for (const m of text.matchAll(/\bt\(\s*'([a-z][a-z0-9.-]*)'/g)) named.add(m[1]);
    for (const m of text.matchAll(/data-t(?:-label|-title)?="([a-z][a-z0-9.-]*)"/g)) named.add(m[1]);
  }
  const unknown = [...named].filter((key) => !Object.hasOwn(EN, key));
  assert.deepEqual(unknown, [], 'keys the code names that English lacks');
  assert.ok(named.size > 50, `the code names ${named.size} keys`);
});

test('a language falls back through its region, its language and English, key by key', async () => {
  assert.deepEqual(chainOf('de-AT'), ['de-at', 'de', 'en']);
  assert.deepEqual(chainOf('pt'), ['pt', 'pt-br', 'en']);
  assert.deepEqual(chainOf('zh-TW'), ['zh-tw', 'zh', 'en'], 'Traditional Chinese is not given Simplified');
  assert.ok(chainOf('zh-Hans-CN').includes('zh-cn'));
  assert.deepEqual(chainOf('not a tag!'), ['en']);
  assert.equal(new Words('ar').dir, 'rtl');
  assert.equal(new Words('ja').dir, 'ltr');
  assert.equal(new Words('he-IL').dir, 'rtl');
  assert.equal(new Words('xx').t('no.such.key'), 'no.such.key');
});

test('a refused value is worded for the reader, its numbers written as the language writes them', () => {
  const iso = TABLE.find((row) => row.name === 'iso');
  let refused;
  try { readValue(iso, '-1'); } catch (error) { refused = error; }
  assert.equal(refused.message, 'iso level must be between 0.05 and 20, got -1', 'English for the console');
  assert.equal(new Words('en').refusal(refused), refused.message, 'English readers read the same');
  assert.match(new Words('de').refusal(refused), /0,05/);
  // The WebAssembly's refusals come as codes and fields, a place before them.
  const S = '\u001f';
  const wasm = fromWasm(new Error(`spheres[0].radius: out-of-range${S}sphere radius${S}-0.3${S}0.01${S}1`));
  assert.equal(wasm.message, 'spheres[0].radius: sphere radius must be between 0.01 and 1, got -0.3');
  assert.match(new Words('fr').refusal(wasm), /^spheres\[0\]\.radius: .*0,01/);
  const plain = new Error('something else');
  assert.equal(fromWasm(plain), plain);
});
