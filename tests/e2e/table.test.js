// Every row of both elements' parameter tables, walked through the ways a page gives a setting: a link
// (by its short name, its name and each older spelling), an attribute (by each spelling), the property,
// the panel's control, the saved scene and the change event. The rows are read from the elements'
// tables, so a new row is covered here without a new line (tests/suite/table.rs walks the same rows
// through the Rust side, and python/tests the notebook's traits). The table reader's vectors, written
// from the Rust parser (www/parameter-vectors.json), are given to both elements as attributes: each is
// taken with the same value or refused with the same message.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import path from 'node:path';
import { useServerAndBrowser, openClosedAfterEach, otherText, root, tableRows, waitForTriangles } from './helpers.js';

useServerAndBrowser();
const open = openClosedAfterEach();

// The elements' tables as they are shipped.
const TABLE = tableRows();
const PLANE = tableRows(undefined, 'PLANE_TABLE');
const VECTORS = JSON.parse(readFileSync(path.join(root, 'www/parameter-vectors.json'), 'utf8'));

// Settings whose value a link may not carry here: a poster and a sync group are URLs and names of
// the page, not of the figure's picture.
const PAGE_ONLY_TEXT = (row) => row.kind === 'text' && row.name !== 'alt';

// Settings the 3D panel gives a button of their own rather than a labelled control: the Play button.
const BUTTONS = ['paused'];

/** The property's value `text` gives, as the element holds it. */
function typed(row, text) {
  if (row.kind === 'integer' || row.kind === 'number') return Number(text);
  if (row.kind === 'boolean') return text === 'true';
  return text;
}

const spellings = (row) => [...new Set([row.name, row.url, ...row.aliases])];

/** What the element holds for each row: the property, and the sphere list as spheres. */
const readAll = (page) => page.$eval('metaballs-view', (e, rows) => Object.fromEntries(rows.map((r) => {
  const v = e[r.property];
  return [r.name, Array.isArray(v) ? v.map((s) => [...s.center, s.radius].map((x) => Number(x.toFixed(4))).join(',')).join(';') : v];
})), TABLE.map(({ name, property }) => ({ name, property })));

const expected = (row, text) => (row.kind === 'spheres' ? text : typed(row, text));

test('a link sets every row by its short name, its name and each older spelling', async () => {
  // Not the sphere count: the sphere list in the same link sets it.
  const rows = TABLE.filter((row) => !PAGE_ONLY_TEXT(row) && !['controls', 'hud', 'spheres'].includes(row.name));
  const ways = [(row) => row.url, (row) => row.name, (row) => row.aliases.at(-1) ?? row.name];
  for (const spelling of ways) {
    const query = rows.map((row) => `${encodeURIComponent(spelling(row))}=${encodeURIComponent(otherText(row))}`);
    const { page, errors } = await open(`?${query.join('&')}`);
    await waitForTriangles(page);
    const held = await readAll(page);
    for (const row of rows) {
      assert.deepEqual(held[row.name], expected(row, otherText(row)), `${spelling(row)}=${otherText(row)} in a link`);
    }
    // The scene a person saves holds each setting a scene holds, under its name.
    const saved = JSON.parse(await page.$eval('metaballs-view', (e) => e.saveScene())).settings;
    for (const row of rows.filter((r) => r.scene && r.kind !== 'spheres')) {
      assert.deepEqual(saved[row.name], typed(row, otherText(row)), `the saved scene's ${row.name}`);
    }
    assert.deepEqual(errors, []);
  }
});

test('an attribute by each spelling, and the property, set every row; the panel shows it', async () => {
  const { page, errors } = await open('?paused=1&resolution=16');
  await waitForTriangles(page);
  for (const row of TABLE.filter((r) => !PAGE_ONLY_TEXT(r) && r.name !== 'controls')) {
    const text = otherText(row);
    for (const spelling of spellings(row)) {
      const held = await page.$eval('metaballs-view', async (e, [name, attribute, value, property, initial]) => {
        e.setAttribute(attribute, value);
        await e.nextFrame();
        const now = e[property];
        e.removeAttribute(attribute);
        e.setAttribute(name, initial);
        return now;
      }, [row.name, spelling, text, row.property, row.default]);
      const shown = Array.isArray(held) ? held.map((s) => [...s.center, s.radius].map((x) => Number(x.toFixed(4))).join(',')).join(';') : held;
      assert.deepEqual(shown, expected(row, text), `${spelling}="${text}" read as the property ${row.property}`);
    }
    if (row.kind === 'spheres') continue;
    // The property sets it too, and the panel's control (found by its label) shows it.
    const shown = await page.$eval('metaballs-view', async (e, [property, value, label]) => {
      e[property] = value;
      await e.nextFrame();
      const labels = [...e.shadowRoot.querySelectorAll('label')].filter((l) => l.textContent === label && l.htmlFor);
      const input = labels.length ? e.shadowRoot.getElementById(labels[0].htmlFor) : null;
      return { held: e[property], control: input ? (input.type === 'checkbox' ? input.checked : input.value) : null };
    }, [row.property, typed(row, text), row.label]);
    assert.deepEqual(shown.held, typed(row, text), `the property ${row.property}`);
    // A number's control is a slider only where its row gives one (the seed is typed in).
    const controlled = row.group && ['number', 'integer', 'boolean', 'choice', 'color'].includes(row.kind)
      && (!['number', 'integer'].includes(row.kind) || row.sliderMax !== row.sliderMin);
    if (controlled && !BUTTONS.includes(row.name)) {
      const value = row.kind === 'boolean' ? typed(row, text) : text;
      assert.equal(shown.control, value, `the panel's ${row.label} shows ${row.name}`);
    }
    // Back to the default, as an attribute.
    await page.$eval('metaballs-view', (e, [name, value]) => e.setAttribute(name, value), [row.name, row.default]);
  }
  assert.deepEqual(errors, []);
});

// The 2D figure's rows a link, an attribute and the panel give (not the figure it follows, nor the
// panel's own list).
const PLANE_ROWS = PLANE.filter((row) => !['controls', 'slice-of'].includes(row.name));

test('the 2D figure: a link, an attribute by each spelling and the property set every row; the panel and the scene show it; the event is typed', async () => {
  for (const spelling of [(row) => row.url, (row) => row.name, (row) => row.aliases.at(-1) ?? row.name]) {
    const query = PLANE_ROWS.filter((row) => row.name !== 'march')
      .map((row) => `${encodeURIComponent(spelling(row))}=${encodeURIComponent(otherText(row))}`);
    const { page, errors } = await open(`squares.html?${query.join('&')}`);
    await page.waitForFunction(() => document.querySelector('metaballs-2d')?.frameMs > 0);
    const held = await page.$eval('metaballs-2d', (e, rows) => Object.fromEntries(rows.map((r) => [r.name, e[r.property]])), PLANE_ROWS);
    for (const row of PLANE_ROWS.filter((r) => r.name !== 'march')) {
      assert.deepEqual(held[row.name], typed(row, otherText(row)), `${spelling(row)}=${otherText(row)} in a 2D link`);
    }
    const saved = JSON.parse(await page.$eval('metaballs-2d', (e) => e.saveScene())).settings;
    for (const row of PLANE_ROWS.filter((r) => r.scene && r.name !== 'circles')) {
      const value = row.kind === 'levels' ? otherText(row).split(',').map(Number) : typed(row, otherText(row));
      assert.deepEqual(saved[row.name], value, `the saved 2D scene's ${row.name}`);
    }
    assert.deepEqual(errors, []);
  }
  const { page, errors } = await open('squares.html?paused=true');
  await page.waitForFunction(() => document.querySelector('metaballs-2d')?.frameMs > 0);
  await page.$eval('metaballs-2d', (e) => e.setAttribute('controls', 'all'));
  for (const row of PLANE_ROWS) {
    const text = otherText(row);
    for (const spelling of spellings(row)) {
      const { before, now, events } = await page.$eval('metaballs-2d', (e, [name, attribute, value, property]) => {
        const was = e[property];
        const seen = [];
        const listen = (event) => seen.push(event.detail);
        e.addEventListener('metaballs-change', listen);
        e.setAttribute(attribute, value);
        const held = e[property];
        e.removeAttribute(attribute);
        e.removeEventListener('metaballs-change', listen);
        return { before: was, now: held, events: seen };
      }, [row.name, spelling, text, row.property]);
      assert.deepEqual(now, typed(row, text), `${spelling}="${text}" read as the 2D property ${row.property}`);
      if (before !== now) assert.deepEqual(events[0], { property: row.property, attribute: row.name, value: now }, `the change event of ${spelling}`);
    }
    // The property sets it too, and the panel's control (found by its label) shows it.
    const shown = await page.$eval('metaballs-2d', (e, [property, value, label]) => {
      e[property] = value;
      const labels = [...e.shadowRoot.querySelectorAll('label')].filter((l) => l.textContent === label && l.htmlFor);
      const input = labels.length ? e.shadowRoot.getElementById(labels[0].htmlFor) : null;
      return { held: e[property], control: input ? (input.type === 'checkbox' ? input.checked : input.value) : null };
    }, [row.property, typed(row, text), row.label]);
    assert.deepEqual(shown.held, typed(row, text), `the 2D property ${row.property}`);
    const slider = !['number', 'integer'].includes(row.kind) || row.sliderMax !== row.sliderMin;
    if (row.group && ['number', 'integer', 'boolean', 'choice', 'levels'].includes(row.kind) && slider) {
      assert.equal(shown.control, row.kind === 'boolean' ? typed(row, text) : text, `the 2D panel's ${row.label} shows ${row.name}`);
    }
    await page.$eval('metaballs-2d', (e, name) => e.removeAttribute(name), row.name);
  }
  // pause() and play() are reflected, as on the 3D figure.
  const paused = await page.$eval('metaballs-2d', (e) => {
    e.play();
    const playing = [e.paused, e.getAttribute('paused')];
    e.pause();
    return [...playing, e.paused, e.getAttribute('paused')];
  });
  assert.deepEqual(paused, [false, 'false', true, 'true']);
  assert.deepEqual(errors, []);
});

// The vectors a figure's reader alone decides: not free text (a poster's URL, a sync group, a followed
// figure) nor the grammars the 2D figure adds (circles, the step-through's square).
const readsAlone = (v) => v.name === 'alt' || !['text', 'slice', 'cell', 'spheres'].includes(
  (v.table === 'plane' ? PLANE : TABLE).find((r) => r.name === v.name).kind);

/** Gives `vectors` to the figure `tag` as attributes: what it held after each, or the message it refused it with. */
function giveVectors(page, tag, vectors) {
  return page.$eval(tag, (e, [list, rows]) => {
    const out = [];
    let refused = null;
    e.addEventListener('metaballs-error', (event) => { refused = event.detail.message; });
    for (const v of list) {
      refused = null;
      const spelling = v.given ?? v.name;
      e.setAttribute(spelling, v.text);
      // A value the slow-frame guard holds back for the person's answer was read: it is the one asked.
      const pending = e.pendingChange;
      const held = pending && v.name in pending ? pending[v.name] : e[rows[v.name]];
      if (pending) e.shadowRoot.getElementById('confirm-keep').click();
      out.push(refused === null ? { value: held } : { message: refused });
      e.removeAttribute(spelling);
    }
    return out;
  }, [vectors, Object.fromEntries([...TABLE, ...PLANE].map((r) => [r.name, r.property]))]);
}

function sameAsRust(vectors, answers, tag) {
  let checked = 0;
  vectors.forEach((v, i) => {
    const got = answers[i];
    const what = `<${tag} ${v.given ?? v.name}="${v.text}">`;
    if ('value' in v) assert.ok(Object.is(got.value, v.value), `${what}: ${JSON.stringify(got)}, the Rust parser: ${JSON.stringify(v.value)}`);
    else assert.ok(got.message?.includes(`: ${v.message}; keeping `), `${what}: ${JSON.stringify(got)}, the Rust parser: ${v.message}`);
    checked += 1;
  });
  return checked;
}

test('the table reader\'s vectors read the same in both elements as in Rust: the value, or the same message', async () => {
  const { page, errors } = await open('?paused=1&resolution=16');
  await waitForTriangles(page);
  const view = VECTORS.filter((v) => v.table === 'view' && readsAlone(v));
  const viewChecked = sameAsRust(view, await giveVectors(page, 'metaballs-view', view), 'metaballs-view');
  const plane = await open('squares.html?paused=true');
  await plane.page.waitForFunction(() => document.querySelector('metaballs-2d')?.frameMs > 0);
  // The 2D figure's own rows, and the rows it shares with the 3D figure.
  const own = new Set(VECTORS.filter((v) => v.table === 'plane').map((v) => v.name));
  const names = new Set(PLANE.map((r) => r.name));
  const planeVectors = VECTORS.filter((v) => readsAlone(v) && (v.table === 'plane' || (names.has(v.name) && !own.has(v.name))));
  const planeChecked = sameAsRust(planeVectors, await giveVectors(plane.page, 'metaballs-2d', planeVectors), 'metaballs-2d');
  console.log(`${viewChecked} vectors on <metaballs-view>, ${planeChecked} on <metaballs-2d>`);
  assert.ok(viewChecked > 1000 && planeChecked > 500, `${viewChecked} and ${planeChecked} vectors checked`);
  assert.deepEqual(errors, []);
  assert.deepEqual(plane.errors, []);
});
