// End-to-end tests of <metaballs-view> as a course author embeds it: several figures sharing one GPU
// device, idle off screen, input scoped to the focused figure, attribute checks with inline notices,
// Shadow DOM isolation, device loss from JavaScript, the iframe page, and dist/ under a sub-path.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { spawn } from 'node:child_process';
import { cpSync, mkdtempSync, rmSync } from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import {
  useServerAndBrowser, openClosedAfterEach, root, freePort, waitForServer, pixelStats, differingFraction, frameDrawn,
  builtBy,
} from './helpers.js';

useServerAndBrowser();

const FIXTURES = 'tests/e2e/fixtures';

// Every page a test opens is closed after it, passed or failed, so that no figure keeps drawing.
const open = openClosedAfterEach({ viewport: { width: 840, height: 600 } });

const frames = (page, id) => page.$eval(`#${id}`, (e) => e.framesDrawn);
const waitForFrames = (page, id, count = 3) => page.waitForFunction(
  ([i, n]) => document.getElementById(i)?.framesDrawn >= n, [id, count], { timeout: 60_000 });
const waitForStats = (page, id) => page.waitForFunction(
  (i) => document.getElementById(i)?.stats?.triangles > 0, id, { timeout: 60_000 });

async function surfaceOf(page, selector) {
  const png = await page.locator(selector).screenshot();
  return { png, ...(await pixelStats(page, png)) };
}

test('five figures: one device, the visible ones draw, the ones below the fold stay idle', async () => {
  const { page, errors, close } = await open(`${FIXTURES}/five.html`);
  await waitForStats(page, 'a');
  await waitForStats(page, 'b');
  // Below the fold, each figure is drawn once while the page is idle, for its picture in print, and
  // lets go of its renderer again.
  await page.evaluate(() => Promise.all(['c', 'd', 'e'].map((id) => document.getElementById(id).printable())));
  // Two seconds of animation above: the figures below draw no frame meanwhile.
  await page.waitForTimeout(2000);
  for (const id of ['a', 'b']) {
    // A screenshot can fall between a change of render scale (the canvas resized, so cleared) and the
    // next frame on a busy machine: look again, a frame later, a few times.
    let { surface } = await surfaceOf(page, `#${id}`);
    for (let i = 0; i < 8 && surface <= 0.01; i++) {
      await frameDrawn(page, `#${id}`);
      ({ surface } = await surfaceOf(page, `#${id}`));
    }
    assert.ok(surface > 0.01, `figure ${id}: the surface covers only ${(surface * 100).toFixed(2)}%`);
  }
  const idle = await Promise.all(['c', 'd', 'e'].map((id) => frames(page, id)));
  console.log(`frames drawn by the off-screen figures: ${idle.join(', ')}`);
  assert.deepEqual(idle, [0, 0, 0], 'figures below the fold drew frames');
  const shared = await page.evaluate(() => {
    const V = customElements.get('metaballs-view');
    return { devices: V.devices, created: V.devicesCreated, renderers: V.liveRenderers, pipelines: V.pipelineSets };
  });
  console.log(`shared device: ${JSON.stringify(shared)}`);
  assert.deepEqual([shared.devices, shared.created], [1, 1], 'the page holds more than one device');
  assert.equal(shared.renderers, 2, 'only the two figures near the viewport have renderers');
  assert.ok(shared.pipelines <= 2, `${shared.pipelines} pipeline sets for two figures of one format`);

  // Scrolling one into view makes it draw; scrolling away stops it.
  await page.$eval('#d', (e) => e.scrollIntoView());
  await waitForFrames(page, 'd', 5);
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.waitForTimeout(500);
  const stopped = await frames(page, 'd');
  await page.waitForTimeout(1500);
  assert.equal(await frames(page, 'd'), stopped, 'a figure scrolled away kept drawing');
  assert.equal(await frames(page, 'e'), 0);
  assert.equal(await page.evaluate(() => customElements.get('metaballs-view').devicesCreated), 1);

  // Asked for a frame before it is on the page, then put far below the fold (a notebook's question can
  // come before its output is attached): it starts and answers all the same.
  const asked = await page.evaluate(async () => {
    const figure = document.createElement('metaballs-view');
    figure.setAttribute('resolution', '24');
    const answer = figure.nextFrame();
    await new Promise((r) => setTimeout(r, 100));
    document.body.append(figure);
    return (await answer).triangles;
  });
  assert.ok(asked > 0, `the figure asked before it was attached answered with ${asked} triangles`);
  assert.deepEqual(errors, []);
  await close();
});

test('removing a figure frees its buffers; putting it back draws again', async () => {
  const { page, errors, close } = await open(`${FIXTURES}/five.html`);
  await waitForStats(page, 'a');
  await waitForStats(page, 'b');
  await page.evaluate(() => Promise.all(['c', 'd', 'e'].map((id) => document.getElementById(id).printable())));
  const counts = () => page.evaluate(() => {
    const V = customElements.get('metaballs-view');
    return { renderers: V.liveRenderers, bytes: V.gpuBytes };
  });
  const before = await counts();
  await page.evaluate(() => { window.removed = document.getElementById('b'); window.removed.remove(); });
  const without = await counts();
  console.log(`GPU memory of the figures: ${before.bytes} bytes with two, ${without.bytes} after removing one`);
  assert.equal(without.renderers, before.renderers - 1);
  assert.ok(without.bytes < before.bytes, 'removing a figure freed no GPU memory');
  await page.evaluate(() => document.querySelector('.row').append(window.removed));
  await page.waitForFunction(() => window.removed.framesDrawn > 0 && window.removed.stats?.triangles > 0);
  const drawnBefore = await page.evaluate(() => window.removed.framesDrawn);
  await page.waitForFunction((n) => window.removed.framesDrawn > n + 3, drawnBefore);
  assert.equal((await counts()).renderers, before.renderers);
  assert.deepEqual(errors, []);
  await close();
});

test('reduced motion and autoplay="off" start figures paused with a play button', async () => {
  const { page, errors, close } = await open(`${FIXTURES}/five.html`, { reducedMotion: 'reduce' });
  await waitForStats(page, 'a');
  assert.equal(await page.$eval('#a', (e) => e.paused), true);
  assert.equal(await page.isVisible('#a >> #play'), true, 'no play button');
  await page.click('#a >> #play');
  assert.equal(await page.$eval('#a', (e) => e.paused), false);
  await close();

  const second = await open(`${FIXTURES}/five.html`);
  await second.page.evaluate(() => {
    const figure = document.createElement('metaballs-view');
    figure.id = 'late';
    figure.setAttribute('autoplay', 'off');
    document.querySelector('.row').append(figure);
  });
  await waitForStats(second.page, 'late');
  assert.equal(await second.page.$eval('#late', (e) => e.paused), true);
  assert.equal(await second.page.$eval('#a', (e) => e.paused), false);
  assert.deepEqual([...errors, ...second.errors], []);
  await second.close();
});

test('keys reach only the focused figure; the wheel over an unfocused one scrolls the page', async () => {
  const { page, errors, close } = await open(`${FIXTURES}/five.html`);
  await waitForStats(page, 'a');
  await waitForStats(page, 'b');
  const yaw = () => page.evaluate(() => ['a', 'b'].map((id) => document.getElementById(id).yaw));
  const [a0, b0] = await yaw();
  await page.focus('#a');
  await page.keyboard.press('ArrowLeft');
  await page.keyboard.press('ArrowLeft');
  const [a1, b1] = await yaw();
  assert.equal(a1, a0 - 10, 'the focused figure did not turn');
  assert.equal(b1, b0, 'a figure without focus turned');

  // Wheel over b, which has no focus: the page scrolls, b does not zoom, a hint says how.
  const box = await page.locator('#b').boundingBox();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  const distance = await page.$eval('#b', (e) => e.distance);
  await page.mouse.wheel(0, 300);
  await page.waitForFunction(() => window.scrollY > 0);
  assert.equal(await page.$eval('#b', (e) => e.distance), distance);
  assert.equal(await page.isVisible('#b >> #wheel-hint'), true);
  // With focus, the wheel zooms.
  await page.evaluate(() => window.scrollTo(0, 0));
  await page.focus('#b');
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.wheel(0, 300);
  await page.waitForFunction((d) => document.getElementById('b').distance > d, distance);
  assert.deepEqual(errors, []);
  await close();
});

test('every attribute: good values take effect, bad ones show a notice and keep the old value', async () => {
  const { page, errors, close } = await open(`${FIXTURES}/five.html`);
  await waitForStats(page, 'a');
  await page.$eval('#a', (e) => e.setAttribute('paused', ''));
  const good = {
    spheres: '7', iso: '0.7', resolution: '40', seed: '9', speed: '2', yaw: '-50', pitch: '35',
    distance: '6', shininess: '200', color: '#3366cc', antialiasing: 'on', controls: 'all', hud: 'off',
    autoplay: 'off', 'max-pixel-ratio': '1', edit: 'on', balls: '0,0.1,0,0.4;0.5,0,0,0.2,0.1,0,0',
  };
  const bad = ['NaN', '-500', '1e9', 'text', ''];
  for (const [name, value] of Object.entries(good)) {
    const property = name.replace(/-([a-z])/g, (_, c) => c.toUpperCase());
    await page.$eval('#a', (e, [n, v]) => e.setAttribute(n, v), [name, value]);
    const now = await page.$eval('#a', (e, p) => e[p], property);
    const expected = { spheres: 7, iso: 0.7, resolution: 40, seed: 9, speed: 2, yaw: -50, pitch: 35, distance: 6,
      shininess: 200, color: '#3366cc', antialiasing: true, controls: 'all', hud: 'off', autoplay: 'off',
      'max-pixel-ratio': 1, edit: true, balls: '0,0.1,0,0.4;0.5,0,0,0.2,0.1,0,0' }[name];
    assert.equal(now, expected, `${name}="${value}" gave ${now}`);
    for (const text of bad) {
      // An empty boolean attribute means true; empty balls mean the seeded layout.
      if (['antialiasing', 'edit', 'balls'].includes(name) && text === '') continue;
      await page.$eval('#a', (e, [n, v]) => e.setAttribute(n, v), [name, text]);
      const kept = await page.$eval('#a', (e, p) => e[p], property);
      assert.equal(kept, expected, `${name}="${text}" changed the value to ${kept}`);
      const notice = await page.textContent('#a >> #notice');
      assert.ok(notice.includes(`${name}="${text}"`), `notice for ${name}="${text}": ${notice}`);
    }
  }
  // Properties go through the same checks.
  await page.$eval('#a', (e) => { e.iso = 'abc'; });
  assert.equal(await page.$eval('#a', (e) => e.iso), 0.7);
  // After all that, the figure still draws.
  const drawn = await frames(page, 'a');
  await page.$eval('#a', (e) => e.step());
  await page.waitForFunction((n) => document.getElementById('a').framesDrawn > n, drawn);
  // Good values change the picture: a new colour.
  const blue = await surfaceOf(page, '#a');
  await page.$eval('#a', (e) => e.setAttribute('color', '#e77661'));
  await frameDrawn(page, '#a');
  const red = await surfaceOf(page, '#a');
  assert.ok(await differingFraction(page, blue.png, red.png) > 0.01, 'a new colour did not change the picture');
  assert.ok(red.surface > 0.01, 'the red surface is not visible');
  assert.deepEqual(errors.filter((e) => !e.includes('GPU error')), []);
  await close();
});

test('a host stylesheet that restyles canvas, div, button and input does not reach the figure', async () => {
  const shots = [];
  for (const query of ['', '?hostile']) {
    const { page, errors, close } = await open(`${FIXTURES}/styled.html${query}`);
    await page.waitForFunction(() => document.querySelector('metaballs-view')?.stats?.triangles > 0);
    await frameDrawn(page);
    await frameDrawn(page);
    shots.push({ page, close, png: await page.locator('metaballs-view').screenshot() });
    assert.deepEqual(errors, []);
  }
  const changed = await differingFraction(shots[1].page, shots[0].png, shots[1].png);
  console.log(`host stylesheet: ${(changed * 100).toFixed(3)}% of the figure's pixels differ`);
  assert.ok(changed < 0.01, `the host's CSS changed ${(changed * 100).toFixed(2)}% of the figure`);
  for (const s of shots) await s.close();
});

test('a destroyed device: every visible figure comes back with its settings', async () => {
  const { page, errors, close } = await open(`${FIXTURES}/five.html`);
  await waitForStats(page, 'a');
  await waitForStats(page, 'b');
  await page.$eval('#a', (e) => e.setAttribute('iso', '0.8'));
  await frameDrawn(page, '#a');
  const before = await page.evaluate(() => ['a', 'b'].map((id) => document.getElementById(id).framesDrawn));
  await page.evaluate(() => customElements.get('metaballs-view').destroyDevice());
  await page.waitForFunction(() => customElements.get('metaballs-view').devicesCreated === 2, null, { timeout: 20_000 });
  await page.waitForFunction((b) => ['a', 'b'].every((id, i) => document.getElementById(id).framesDrawn > b[i] + 5),
    before, { timeout: 20_000 });
  assert.equal(await page.$eval('#a', (e) => e.iso), 0.8);
  const { surface } = await surfaceOf(page, '#b');
  assert.ok(surface > 0.01, 'figure b is blank after the device came back');
  assert.equal(await page.isVisible('#a >> #message'), false);
  assert.deepEqual(errors.filter((e) => !/lost|destroy/i.test(e)), []);
  await close();
});

test('a device lost again and again: the figures stop, say so, and can be started again', async () => {
  const { page, errors, close } = await open(`${FIXTURES}/five.html`);
  await waitForStats(page, 'a');
  for (let loss = 1; loss <= 3; loss++) {
    await page.waitForFunction((n) => customElements.get('metaballs-view').devicesCreated === n, loss, { timeout: 20_000 });
    await page.evaluate(() => customElements.get('metaballs-view').destroyDevice());
    await page.waitForTimeout(200);
  }
  await page.waitForSelector('#a >> #message', { state: 'visible', timeout: 20_000 });
  assert.match(await page.textContent('#a >> #message-text'), /lost 3 times/);
  const created = await page.evaluate(() => customElements.get('metaballs-view').devicesCreated);
  await page.waitForTimeout(2000);
  assert.equal(await page.evaluate(() => customElements.get('metaballs-view').devicesCreated), created, 'it kept retrying');
  const drawn = await frames(page, 'a');
  await page.click('#a >> #retry');
  await page.waitForFunction((n) => document.getElementById('a').framesDrawn > n + 3, drawn, { timeout: 20_000 });
  assert.equal(await page.isVisible('#a >> #message'), false);
  assert.deepEqual(errors.filter((e) => !/lost|destroy/i.test(e)), []);
  await close();
});

test('embed.html shows no panel unless asked', async () => {
  const plain = await open('embed.html?spheres=2');
  await plain.page.waitForFunction(() => document.querySelector('metaballs-view')?.stats?.triangles > 0);
  assert.equal(await plain.page.isVisible('#panel'), false);
  assert.equal(await plain.page.isVisible('#hud'), false);
  assert.equal(await plain.page.$eval('metaballs-view', (e) => e.spheres), 2);
  await plain.close();
  const asked = await open('embed.html?controls=iso&hud=on');
  await asked.page.waitForFunction(() => document.querySelector('metaballs-view')?.stats?.triangles > 0);
  assert.equal(await asked.page.isVisible('#panel'), true);
  assert.equal(await asked.page.isVisible('#iso'), true);
  assert.equal(await asked.page.locator('#spheres').count(), 0);
  assert.equal(await asked.page.isVisible('#hud'), true);
  assert.deepEqual([...plain.errors, ...asked.errors], []);
  await asked.close();
});

test('dist/ (the bundled element) served under a sub-path draws the demo page and the lecture', async () => {
  await builtBy('www/dist.sh', 'dist/widget.js');
  const site = mkdtempSync(path.join(os.tmpdir(), 'metaballs-site-'));
  cpSync(path.join(root, 'dist'), path.join(site, 'course/figures'), { recursive: true });
  const port = await freePort();
  const server = spawn('python3', ['-m', 'http.server', '--bind', '127.0.0.1', String(port), '--directory', site],
    { stdio: 'ignore' });
  try {
    const url = `http://127.0.0.1:${port}/course/figures/www/examples/lecture.html`;
    await waitForServer(url);
    const { page, errors, close } = await open(url);
    await page.waitForFunction(() => document.querySelector('#merge metaballs-view')?.stats?.triangles > 0,
      null, { timeout: 60_000 });
    const { surface } = await surfaceOf(page, '#merge metaballs-view');
    assert.ok(surface > 0.005, `the first figure covers ${(surface * 100).toFixed(2)}%`);
    assert.equal(await page.$eval('#below metaballs-view', (e) => e.framesDrawn), 0);
    assert.deepEqual(errors, []);
    await close();
    // The demo page: the element and the page's script share one bundle (one wasm, one device).
    const demo = await open(`http://127.0.0.1:${port}/course/figures/index.html?spheres=7`);
    await demo.page.waitForFunction(() => document.querySelector('metaballs-view')?.stats?.triangles > 0,
      null, { timeout: 60_000 });
    assert.equal(await demo.page.$eval('metaballs-view', (e) => e.spheres), 7, 'the page did not apply its link');
    await demo.page.waitForFunction(() => /spheres=7/.test(document.getElementById('share').getAttribute('href')));
    assert.equal(await demo.page.evaluate(() => customElements.get('metaballs-view').devicesCreated), 1);
    // The bundled element finds its mesher worker (SwiftShader meshes on the CPU) and meshes there.
    await demo.page.waitForFunction(() => customElements.get('metaballs-view').meshingOffThread, null,
      { timeout: 30_000 });
    assert.ok(demo.page.workers().some((w) => w.url().endsWith('/course/figures/www/lib/engine/mesh-worker.js')),
      `workers: ${demo.page.workers().map((w) => w.url()).join(', ')}`);
    // The page's own scripts (the worker's starts once the first frame is drawn).
    const scripts = await demo.page.evaluate(() => performance.getEntriesByType('resource')
      .filter((r) => r.name.endsWith('.js') && !r.name.endsWith('/mesh-worker.js')).map((r) => r.name.split('/').pop()));
    assert.ok(scripts.length <= 4, `the page fetched ${scripts.length} scripts: ${scripts.join(', ')}`);
    assert.deepEqual(demo.errors, []);
    await demo.close();
  } finally {
    server.kill();
    rmSync(site, { recursive: true, force: true });
  }
});
