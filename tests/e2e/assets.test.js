// A page whose WebAssembly cannot be had: served by a test server that answers 404 for it, cuts it
// short, sends it with the wrong type, or serves the page under a Content-Security-Policy without
// 'wasm-unsafe-eval'. Every figure says what failed and what to do (no endless wait); the wrong type
// still draws, with a notice; and the policy the README gives (script-src 'self' 'wasm-unsafe-eval')
// draws.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import { createServer } from 'node:http';
import { readFile } from 'node:fs/promises';
import path from 'node:path';
import { useServerAndBrowser, root, openClosedAfterEach, freePort } from './helpers.js';

useServerAndBrowser();
const open = openClosedAfterEach({ viewport: { width: 840, height: 600 } });

const TYPES = {
  '.html': 'text/html', '.js': 'text/javascript', '.wasm': 'application/wasm', '.css': 'text/css',
  '.json': 'application/json', '.png': 'image/png',
};

// /<fault>/<path in the repository>: the repository's files, with the fault on every .wasm (or, for
// the policies, on every response).
const FAULTS = {
  ok: {},
  missing: { wasm: () => ({ status: 404, body: 'Not Found', type: 'text/plain' }) },
  cut: { wasm: (bytes) => ({ body: bytes.subarray(0, bytes.length >> 1) }) },
  mime: { wasm: () => ({ type: 'text/plain' }) },
  csp: { headers: { 'Content-Security-Policy': "script-src 'self'" } },
  cspok: { headers: { 'Content-Security-Policy': "script-src 'self' 'wasm-unsafe-eval'" } },
};

let server;
let base;
before(async () => {
  const port = await freePort();
  server = createServer(async (request, response) => {
    const [, fault, ...rest] = new URL(request.url, 'http://x').pathname.split('/');
    const rule = FAULTS[fault];
    const file = path.join(root, ...rest);
    if (!rule || !file.startsWith(root)) {
      response.writeHead(404).end();
      return;
    }
    let bytes;
    try {
      bytes = await readFile(file);
    } catch {
      response.writeHead(404).end();
      return;
    }
    const ext = path.extname(file);
    const answer = { status: 200, body: bytes, type: TYPES[ext] ?? 'application/octet-stream' };
    if (ext === '.wasm' && rule.wasm) Object.assign(answer, rule.wasm(bytes));
    response.writeHead(answer.status, { 'Content-Type': answer.type, ...rule.headers });
    response.end(answer.body);
  });
  await new Promise((resolve) => server.listen(port, '127.0.0.1', resolve));
  base = `http://127.0.0.1:${port}`;
});
after(() => server?.close());

const page = (fault) => `${base}/${fault}/tests/e2e/fixtures/five.html`;

// The message every connected figure shows: [{ title, text }].
const messages = (p) => p.$$eval('metaballs-view', (elements) => elements.map((e) => {
  const $ = (id) => e.shadowRoot.getElementById(id);
  return { shown: !$('message').hidden, title: $('message-title').textContent, text: $('message-text').textContent };
}));

async function failsWith(fault, title, text) {
  const { page: p } = await open(page(fault));
  const started = Date.now();
  await p.waitForFunction(() => [...document.querySelectorAll('metaballs-view')].every(
    (e) => !e.shadowRoot.getElementById('message').hidden), null, { timeout: 30_000 });
  const shown = await messages(p);
  console.log(`${fault}: every figure says "${shown[0].title}" after ${Date.now() - started} ms: ${shown[0].text}`);
  assert.equal(shown.length, 5);
  for (const m of shown) {
    assert.match(m.title, title);
    assert.match(m.text, text);
  }
}

test('a missing wasm (404) gives every figure a message naming the file and what to deploy', async () => {
  await failsWith('missing', /could not load/, /metaballs_bg\.wasm.*answered 404.*pkg\/ folder/);
});

test('a wasm cut short gives every figure a message saying it is damaged', async () => {
  await failsWith('cut', /could not load/, /cut short or damaged.*pkg\/ folder/);
});

test('a page whose Content-Security-Policy forbids WebAssembly says what the policy needs', async () => {
  await failsWith('csp', /blocks WebAssembly/, /'wasm-unsafe-eval'.*script-src 'self' 'wasm-unsafe-eval'/);
});

test('a wasm served with the wrong type still draws, with a notice to serve it as application/wasm', async () => {
  const { page: p, errors } = await open(page('mime'));
  await p.waitForFunction(() => document.getElementById('a').stats?.triangles > 0, null, { timeout: 60_000 });
  assert.match(await p.$eval('#a', (e) => e.shadowRoot.getElementById('notice').textContent), /"text\/plain".*application\/wasm/);
  assert.deepEqual(errors, []);
});

test("the policy the README gives (script-src 'self' 'wasm-unsafe-eval') draws", async () => {
  const { page: p, errors } = await open(page('cspok'));
  await p.waitForFunction(() => ['a', 'b'].every((id) => document.getElementById(id).stats?.triangles > 0), null, { timeout: 60_000 });
  assert.equal((await messages(p)).some((m) => m.shown), false);
  assert.deepEqual(errors, []);
});
