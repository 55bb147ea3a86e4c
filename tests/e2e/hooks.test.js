// The features' protocol, in Node: every hook the sources call by name (`each`, `collect`, `some`) is
// declared in www/lib/core/hooks.js, every hook declared is called, no feature of either element has a
// method named like a hook that is not one (a misspelt hook is never called: the same name in another
// case, or one letter off, two for names of eight letters or more), and the context refuses a name that
// is no hook.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readdirSync, readFileSync } from 'node:fs';
import path from 'node:path';
import { distance } from 'fastest-levenshtein';
import { HOOKS, isHook } from '../../www/lib/core/hooks.js';
import { FigureContext } from '../../www/lib/core/context.js';
import { root } from './helpers.js';

const www = path.join(root, 'www');
const sources = (dir) => readdirSync(dir, { withFileTypes: true }).flatMap((entry) => {
  const file = path.join(dir, entry.name);
  if (entry.isDirectory()) return ['package', 'examples', 'tools', 'vendor'].includes(entry.name) ? [] : sources(file);
  return entry.name.endsWith('.js') ? [file] : [];
});
const FILES = sources(www).map((file) => ({ file: path.relative(root, file), text: readFileSync(file, 'utf8') }));

// Hook names called through the context, with where.
const CALLS = FILES.flatMap(({ file, text }) => [...text.matchAll(/\.(?:each|collect|some)\('([A-Za-z]+)'/g)]
  .map((m) => ({ hook: m[1], file })));

test('every hook called is declared, and every hook declared is called', () => {
  assert.ok(CALLS.length > 20, `only ${CALLS.length} hook calls found`);
  const undeclared = CALLS.filter(({ hook }) => !isHook(hook));
  assert.deepEqual(undeclared, [], 'hooks called that hooks.js does not declare');
  const called = new Set(CALLS.map(({ hook }) => hook));
  // `changed` goes only to the features that own the setting (context.js calls it itself).
  const context = FILES.find(({ file }) => file.endsWith('core/context.js')).text;
  if (/feature\.changed\?\.\(/.test(context)) called.add('changed');
  assert.deepEqual(Object.keys(HOOKS).filter((hook) => !called.has(hook)), [], 'hooks declared that nothing calls');
});

// The features an element makes (its FEATURES list), each with the file its class is in.
function features(elementFile = 'www/metaballs-view.js') {
  const element = FILES.find(({ file }) => file === elementFile).text;
  const list = element.match(/const FEATURES = \[([^\]]+)\]/)[1].split(',').map((s) => s.trim()).filter(Boolean);
  const imports = new Map();
  for (const [, names, from] of element.matchAll(/import \{([^}]+)\} from '([^']+)'/g)) {
    for (const name of names.split(',').map((s) => s.trim().split(' as ').at(-1))) imports.set(name, from);
  }
  return list.map((name) => {
    const file = path.join('www', imports.get(name));
    const text = FILES.find((f) => f.file === file)?.text;
    assert.ok(text, `the class ${name} is in ${file}`);
    // The class's methods, with those of the classes it extends in the same file.
    const methods = [];
    for (let cls = name; cls;) {
      const start = text.indexOf(`class ${cls} `);
      assert.ok(start >= 0, `${file} has the class ${cls}`);
      // The class's body: up to the next line that closes a block at the left margin.
      const body = text.slice(start, text.indexOf('\n}', start));
      methods.push(...[...body.matchAll(/^ {2}(?:async |static |get |set )*([A-Za-z]+)\s*\(/gm)].map((m) => m[1]));
      cls = body.match(/^class \w+ extends (\w+)/)?.[1];
      if (cls && !text.includes(`class ${cls} `)) cls = null;
    }
    return { name, file, methods: [...new Set(methods)].filter((m) => m !== 'constructor') };
  });
}

test('no feature has a method named like a hook that is not one, and each hook has a feature', () => {
  const view = features();
  assert.ok(view.length >= 10, `${view.length} features found`);
  // The 2D figure's features are held to the same names.
  const plane = features('www/metaballs-2d.js');
  assert.ok(plane.length >= 5, `${plane.length} features of the 2D figure found`);
  const made = [...view, ...plane];
  const hooks = Object.keys(HOOKS);
  const nearMisses = made.flatMap(({ name, methods }) => methods.filter((m) => !isHook(m)).flatMap((m) => {
    const near = hooks.filter((hook) => m.toLowerCase() === hook.toLowerCase()
      || (Math.min(m.length, hook.length) > 4 && distance(m, hook) <= (Math.min(m.length, hook.length) >= 8 ? 2 : 1)));
    return near.map((hook) => `${name}.${m} is named like the hook ${hook}`);
  }));
  assert.deepEqual(nearMisses, []);
  const implemented = new Set(made.flatMap(({ methods }) => methods.filter(isHook)));
  assert.deepEqual(hooks.filter((hook) => !implemented.has(hook)), [], 'hooks that no feature implements');
  console.log(`${made.length} features implement the ${hooks.length} hooks`);
});

test('the context refuses a hook that is not declared, and calls one that is', () => {
  const fakeRoot = { getElementById: () => null };
  const ctx = new FigureContext({ dispatchEvent() {} }, fakeRoot, { state: {} });
  const seen = [];
  ctx.use(class { frameDrawn(now) { seen.push(now); } });
  ctx.each('frameDrawn', 5);
  assert.deepEqual(seen, [5]);
  for (const call of [() => ctx.each('frameDrawm', 1), () => ctx.some('hold'), () => ctx.collect('control')]) {
    assert.throws(call, /is not a feature hook/);
  }
});
