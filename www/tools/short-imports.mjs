// Gives the WebAssembly's imports from its JavaScript glue short names, in both files of a wasm-bindgen
// output folder: `node www/tools/short-imports.mjs pkg`. wasm-bindgen names each import
// `__wbg_NAME_HASH`, with 16 hex digits of hash that do not compress: several hundred of them are about
// 5 KB of the gzipped wasm. The imports become `a`, `b`, … `Z`, `aa`, … in the wasm's import section
// and in the glue's table of imports, where each name appears once, as a key (checked: the script
// refuses a glue that uses a name anywhere else, and then changes nothing).

import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';

const dir = process.argv[2];
if (!dir) throw new Error('usage: node www/tools/short-imports.mjs OUT_DIR (a wasm-bindgen --target web output)');
const wasmPath = path.join(dir, 'metaballs_bg.wasm');
const jsPath = path.join(dir, 'metaballs.js');
const wasm = readFileSync(wasmPath);
let js = readFileSync(jsPath, 'utf8');

// Unsigned LEB128, as the wasm binary format writes lengths and counts.
function readU32(bytes, at) {
  let value = 0;
  let shift = 0;
  for (;;) {
    const byte = bytes[at++];
    value += (byte & 0x7f) * 2 ** shift;
    shift += 7;
    if (byte < 0x80) return [value, at];
  }
}
function u32(value) {
  const out = [];
  do {
    let byte = value & 0x7f;
    value = Math.floor(value / 128);
    if (value > 0) byte |= 0x80;
    out.push(byte);
  } while (value > 0);
  return Buffer.from(out);
}
function readName(bytes, at) {
  const [length, start] = readU32(bytes, at);
  return [bytes.subarray(start, start + length).toString('utf8'), start + length];
}
const name = (text) => Buffer.concat([u32(Buffer.byteLength(text)), Buffer.from(text, 'utf8')]);

// The sections, as [id, body].
const sections = [];
for (let at = 8; at < wasm.length;) {
  const id = wasm[at];
  const [size, start] = readU32(wasm, at + 1);
  sections.push([id, wasm.subarray(start, start + size)]);
  at = start + size;
}

// The export names: the glue calls them as `wasm.NAME`, so an import of the same name keeps its own.
const exported = new Set();
for (const [id, body] of sections.filter(([id]) => id === 7)) {
  let [count, at] = readU32(body, 0);
  for (; count > 0; count--) {
    let field;
    [field, at] = readName(body, at);
    exported.add(field);
    at = readU32(body, at + 1)[1];
  }
}

// 'a' … 'Z', 'aa' … : keys of the table of imports, where nothing else of the glue can clash with them
// (the imports left as they are keep their long names).
const LETTERS = 'abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ';
function* shortNames() {
  for (let length = 1; ; length++) {
    for (let n = 0; n < LETTERS.length ** length; n++) {
      let text = '';
      for (let k = 0, m = n; k < length; k++, m = Math.floor(m / LETTERS.length)) text = LETTERS[m % LETTERS.length] + text;
      yield text;
    }
  }
}
const fresh = shortNames();

// The import section with the glue's imports renamed; the other entries' bytes as they were.
const renames = new Map();
const rebuilt = sections.map(([id, body]) => {
  if (id !== 2) return [id, body];
  const parts = [];
  let [count, at] = readU32(body, 0);
  parts.push(u32(count));
  for (; count > 0; count--) {
    let module, field;
    [module, at] = readName(body, at);
    [field, at] = readName(body, at);
    const start = at;
    const kind = body[at++];
    // Limits: a flags byte, the minimum, and the maximum when bit 0 of the flags is set.
    const limits = (from) => {
      const next = readU32(body, from + 1)[1];
      return body[from] & 1 ? readU32(body, next)[1] : next;
    };
    if (kind === 0) at = readU32(body, at)[1]; // a function: its type index
    else if (kind === 1) at = limits(at + 1); // a table: its element type, its limits
    else if (kind === 2) at = limits(at); // a memory: its limits
    else if (kind === 3) at += 2; // a global: its value type and mutability
    else throw new Error(`short-imports: import ${module}.${field} is of kind ${kind}, which this script does not read`);
    const renamed = module === './metaballs_bg.js' && !exported.has(field) ? fresh.next().value : field;
    if (renamed !== field) renames.set(field, renamed);
    parts.push(name(module), name(renamed), body.subarray(start, at));
  }
  if (at !== body.length) throw new Error('short-imports: the import section has bytes after its last entry');
  return [id, Buffer.concat(parts)];
});

// Each renamed import appears in the glue once, as the key of its function in the table of imports.
for (const [field, renamed] of renames) {
  const uses = js.match(new RegExp(`(?<![\\w$])${field}(?![\\w$])`, 'g')) ?? [];
  const key = new RegExp(`\\n(\\s*)${field}: function\\(`);
  if (uses.length !== 1 || !key.test(js)) {
    throw new Error(`short-imports: ${jsPath} uses ${field} ${uses.length} times, not once as its key; nothing changed`);
  }
  js = js.replace(key, `\n$1${renamed}: function(`);
}

const out = [wasm.subarray(0, 8)];
for (const [id, body] of rebuilt) out.push(Buffer.from([id]), u32(body.length), body);
writeFileSync(wasmPath, Buffer.concat(out));
writeFileSync(jsPath, js);
console.log(`short-imports: ${renames.size} imports of ${wasmPath} renamed`);
