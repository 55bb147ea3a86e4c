// End-to-end tests of the step-through of the 3D march in headless Chromium: a link opens it at a cell;
// stepping on WebGPU (the GPU's passes) and on WebGL2 (the CPU's mesher) draws exactly the triangles of
// the cells reached (the sum of each cell's own, as the inspector reports them) and ends with the whole
// mesh, with the lit row of the 256 always the cell's case; "next crossed", the panel's button, the link
// and the close button do what they say. (Every step of every cell, on both paths, against the oracle:
// tests/suite/march.rs.)

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useServerAndBrowser, openClosedAfterEach, frameDrawn, screenshot, differingFraction } from './helpers.js';

useServerAndBrowser();

const open = openClosedAfterEach();
const NO_WEBGPU = () => { delete Navigator.prototype.gpu; };
const BALLS = '-0.3,0,0,0.45;0.35,0.1,0.1,0.4';

// What the figure shows for the step: the march, the inspected cell's case and triangles, the lit row,
// the step's account, and the triangles of the mesh drawn.
async function shown(page) {
  await frameDrawn(page);
  return page.$eval('metaballs-view', async (e) => {
    const box = e.shadowRoot.getElementById('march');
    const [, triangles] = await e.withView((v) => v.mesh_triangles());
    return {
      march: e.getAttribute('march'),
      hidden: box.hidden,
      cell: e.inspected?.cell ?? null,
      case: e.inspected?.case ?? null,
      own: e.inspected?.triangles.length ?? null,
      lit: [...box.querySelectorAll('tr.current')].map((r) => Number(r.dataset.case)),
      said: box.querySelector('.where')?.textContent ?? '',
      drawn: triangles.length / 3,
    };
  });
}

// Walks the march: one cell forward at a time through the first row, then from crossed cell to crossed
// cell `crossings` times, checking at each step the lit row and that the mesh drawn is the triangles of
// the cells reached; then to the last cell, where it must be the whole mesh. Returns that mesh's size.
async function walk(page, n, crossings) {
  const click = (what) => page.locator('metaballs-view').locator(`#march button[data-do="${what}"]`).click();
  let sum = 0;
  const check = async (k, s) => {
    const cell = [k % n, Math.floor(k / n) % n, Math.floor(k / (n * n))];
    assert.equal(s.march, cell.join(','), `step ${k}`);
    assert.deepEqual(s.cell, cell, `step ${k}: the inspected cell`);
    assert.deepEqual(s.lit, [s.case], `step ${k}: the lit row is the cell's case`);
    assert.match(s.said, new RegExp(`^Step ${k + 1} of ${n ** 3}: cell \\(${cell.join(', ')}\\)case ${s.case} = `));
    sum += s.own;
    assert.equal(s.drawn, sum, `step ${k}: the mesh drawn is the triangles of the cells reached`);
  };
  for (let k = 0; k < n; k += 1) {
    if (k > 0) await click('forward');
    await check(k, await shown(page));
  }
  for (let i = 0; i < crossings; i += 1) {
    await click('next');
    const s = await shown(page);
    assert.ok(s.own > 0, `${s.march}: next crossed stops at a cell with triangles`);
    const [x, y, z] = s.cell;
    await check(x + n * (y + n * z), s);
  }
  await page.$eval('metaballs-view', (e, last) => e.setAttribute('march', last), `${n - 1},${n - 1},${n - 1}`);
  const end = await shown(page);
  await page.$eval('metaballs-view', (e) => e.setAttribute('march', 'off'));
  const off = await shown(page);
  assert.equal(off.hidden, true);
  assert.equal(off.cell, null, 'the inspector lets go of the cell');
  assert.equal(end.drawn, off.drawn, 'at the last cell the whole mesh is drawn');
  assert.ok(off.drawn > sum, `${off.drawn} triangles in all, ${sum} in the cells walked`);
  return off.drawn;
}

test('a link opens the step-through, and on WebGPU the mesh grows by the triangles of each cell reached', async () => {
  // mesher=gpu: the compute passes, which a software adapter would leave to the CPU's mesher.
  const { page, errors } = await open(`?balls=${BALLS}&res=8&paused=1&aa=0&mesher=gpu&march=0,0,0`);
  await page.waitForFunction(() => document.querySelector('metaballs-view')?.inspected, null, { timeout: 60000 });
  assert.match(await page.$eval('metaballs-view', (e) => e.stats.mesher ?? ''), /gpu/i);
  const first = await shown(page);
  assert.equal(first.hidden, false);
  assert.equal(first.drawn, 0, 'nothing is drawn before the first crossed cell');
  assert.ok(await walk(page, 8, 24) > 100);
  assert.deepEqual(errors, []);
});

test('on WebGPU with the CPU mesher, and on WebGL2, the march is drawn cell by cell too', async () => {
  const cpu = await open(`?balls=${BALLS}&res=8&paused=1&aa=0&mesher=cpu&march=0,0,0`);
  await cpu.page.waitForFunction(() => document.querySelector('metaballs-view')?.inspected, null, { timeout: 60000 });
  assert.match(await cpu.page.$eval('metaballs-view', (e) => e.stats.mesher ?? ''), /cpu/i);
  assert.ok(await walk(cpu.page, 8, 12) > 100);
  assert.deepEqual(cpu.errors, []);
  const { page, errors } = await open(`?balls=${BALLS}&res=8&paused=1&march=0,0,0`, { initScript: [NO_WEBGPU] });
  await page.waitForFunction(() => document.querySelector('metaballs-view')?.inspected, null, { timeout: 60000 });
  assert.ok(await walk(page, 8, 24) > 100);
  assert.deepEqual(errors, []);
});

test('the panel opens it at the inspected cell, next crossed skips empty cells, the link carries it and × closes it', async () => {
  const { page, errors } = await open(`?balls=${BALLS}&res=16&paused=1&aa=0&controls=all`);
  await page.waitForFunction(() => document.querySelector('metaballs-view')?.framesDrawn > 0, null, { timeout: 60000 });
  await frameDrawn(page);
  const whole = await screenshot(page, 'march-whole');
  await page.click('text=Teaching');
  await page.click('#step-through');
  let s = await shown(page);
  assert.equal(s.march, '0,0,0');
  assert.equal(s.drawn, 0);
  const stepped = await screenshot(page, 'march-start');
  assert.ok(await differingFraction(page, whole, stepped) > 0.02, 'the mesh is gone at the first cell, the box shows');
  await page.locator('metaballs-view').locator('#march button[data-do="next"]').click();
  s = await shown(page);
  assert.ok(s.case !== 0 && s.case !== 255 && s.own > 0, JSON.stringify(s));
  assert.equal(s.drawn, s.own, 'the first crossed cell draws its own triangles only');
  await page.waitForURL(new RegExp(`march=${s.march.replace(/,/g, '(,|%2C)')}`), { timeout: 5000 });
  await screenshot(page, 'march-first-crossed');
  // A cell picked with the inspector: the step-through opens there.
  await page.locator('metaballs-view').locator('#march button[data-do="close"]').click();
  s = await shown(page);
  assert.equal(s.hidden, true);
  assert.equal(s.march, 'off');
  await page.$eval('metaballs-view', (e) => e.inspectCell(8, 8, 8));
  await page.click('#step-through');
  s = await shown(page);
  assert.equal(s.march, '8,8,8');
  // A bad cell gets the notice and the figure keeps its step.
  await page.$eval('metaballs-view', (e) => e.setAttribute('march', '1,2'));
  await frameDrawn(page);
  assert.match(await page.textContent('#notice'), /march.*x,y,z/);
  assert.equal((await shown(page)).cell.join(','), '8,8,8');
  assert.deepEqual(errors, []);
});
