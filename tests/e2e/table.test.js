// Every row of the parameter table, walked through the ways a page gives a setting: a link (by its
// short name, its name and each older spelling), an attribute (by each spelling), the property, the
// panel's control and the saved scene. The rows are read from the element's table, so a new row is
// covered here without a new line (tests/suite/table.rs walks the same rows through the Rust side, and
// python/tests the notebook's traits).

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { useServerAndBrowser, openClosedAfterEach, tableRows, waitForTriangles } from './helpers.js';

useServerAndBrowser();
const open = openClosedAfterEach();

// The element's table as it is shipped.
const TABLE = tableRows();

// Settings whose value a link may not carry here: a poster and a sync group are URLs and names of
// the page, not of the figure's picture.
const PAGE_ONLY_TEXT = (row) => row.kind === 'text' && row.name !== 'alt';

/** A value of `row` other than its default, as text, that a software renderer draws quickly. */
function otherText(row) {
  switch (row.kind) {
    case 'integer':
    case 'number': {
      if (row.name === 'resolution') return '16';
      if (row.name === 'spheres') return '2';
      if (row.sliderMax === row.sliderMin) return String(row.value + 6);
      return String(row.sliderMin !== row.value ? row.sliderMin : row.sliderMax);
    }
    case 'boolean': return String(!row.value);
    case 'color': return '#123456';
    case 'choice': return row.words.find((w) => w !== row.value);
    case 'list': return row.words.find((w) => w !== row.value);
    case 'slice': return 'z:0.25';
    case 'cell': return '1,2,3';
    case 'spheres': return '0,0,0,0.3';
    default: return 'a figure';
  }
}

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
    const controlled = row.group && ['number', 'integer', 'boolean', 'choice', 'color'].includes(row.kind)
      && row.sliderMax !== row.sliderMin;
    if (controlled) {
      const value = row.kind === 'boolean' ? typed(row, text) : text;
      assert.equal(shown.control, value, `the panel's ${row.label} shows ${row.name}`);
    }
    // Back to the default, as an attribute.
    await page.$eval('metaballs-view', (e, [name, value]) => e.setAttribute(name, value), [row.name, row.default]);
  }
  assert.deepEqual(errors, []);
});
