// The stepper's panel, for the march in 2D and in 3D: play, pause, one step back and forward, the next
// crossed square or cell, the speed; an account of the square or cell at this step (its corner values
// and the case built bit by bit); and the case table (16 rows in 2D, the 256 in 3D grouped into their
// classes) with the row of this step's case lit. Only the table scrolls.

import { relabel } from '../i18n/words.js';
import { ENGLISH, numeral } from './picture.js';
import { SEGMENTS } from './squares.js';
import { caseBits } from './stepper.js';

// The edges of a square, in order (their names: messages `plane.edge.<name>`).
const EDGE_NAMES = ['bottom', 'right', 'top', 'left'];
const STYLE = `
.stepper { font: 12.5px/1.4 system-ui, sans-serif; color: var(--metaballs-text, #d7dbe4);
  background: var(--metaballs-panel-background, #1b1f2a); border-radius: 6px; padding: 8px; height: 100%;
  box-sizing: border-box; display: flex; flex-direction: column; }
.stepper .rows { flex: 1; min-height: 0; overflow: auto; }
.stepper .rows:focus-visible { outline: 2px solid currentColor; outline-offset: -2px; }
.stepper .steps { display: flex; flex-wrap: wrap; gap: 4px; margin-bottom: 6px; padding: 0; }
/* The play controls keep their order in any direction, as the picture they walk does. */
.stepper .steps { direction: ltr; }
.stepper button, .stepper select { font: inherit; padding: 2px 8px; flex: none; width: auto; }
.stepper table { border-collapse: collapse; width: 100%; }
.stepper td, .stepper th { padding: 1px 4px; text-align: start; font-variant-numeric: tabular-nums; }
.stepper th.group { padding-top: 6px; font-weight: 600; color: var(--metaballs-muted, #a9b1c2); }
.stepper tr.current { background: var(--metaballs-accent, #b7791f); color: #11141b; }
.stepper .in { color: #ff8c1a; font-weight: 600; }
.stepper .where { min-height: 7.5em; }`;

const escape = (text) => String(text).replace(/[&<>"]/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;' })[c]);

/** Describes the segments of a case by the edges they join, in `words`' language, as HTML. */
function joins(words, segments) {
  const names = segments.map(([a, b]) => words.t('plane.cases.edges', {
    from: words.t(`plane.edge.${EDGE_NAMES[a]}`), to: words.t(`plane.edge.${EDGE_NAMES[b]}`),
  }));
  if (names.length === 0) return '—';
  return escape(names.length === 1 ? names[0] : words.t('plane.cases.pair', { first: names[0], second: names[1] }));
}

/**
 * The 16 cases of marching squares as the panel's table, in `words`' language: case, bits, the
 * segments each draws (a saddle's both ways).
 */
export function squareTable(words = ENGLISH) {
  return {
    name: escape(words.t('plane.cases.name')),
    head: ['plane.cases.case', 'plane.cases.bits', 'plane.cases.segments'].map((key) => escape(words.t(key))),
    groups: [{
      rows: SEGMENTS.apart.map((segments, c) => [c, c.toString(2).padStart(4, '0'), c === 5 || c === 10
        // The message is HTML (its `or` in italics); its fields are escaped.
        ? words.t('plane.cases.either', { first: joins(words, segments), second: joins(words, SEGMENTS.joined[c]) })
        : joins(words, segments)]),
    }],
  };
}

/**
 * The account of marching squares' step `step` of `steps` at `square` (march's `square(i, j)`, or null
 * at the end), in `words`' language, as HTML.
 */
export function squareAccount(step, steps, square, iso, words = ENGLISH) {
  const line = (key, fields) => escape(words.t(key, fields));
  if (!square) return line('plane.step.done', { step, steps });
  const { terms, sum } = caseSum(square.corners, iso, 3, words);
  const [i, j] = square.square;
  const lines = [line('plane.step.square', { step: step + 1, steps, i, j }), ...terms, sum];
  const { saddle } = square;
  if (saddle) {
    const level = numeral(words, String(iso));
    if (saddle.value === null) lines.push(line('plane.step.saddle-table'));
    else lines.push(line(saddle.joined ? 'plane.step.saddle-joined' : 'plane.step.saddle-apart', { value: numeral(words, saddle.value.toFixed(3)), iso: level }));
  }
  return lines.join('<br>');
}

/**
 * The case of corner values `corners` at `iso` built bit by bit, as HTML in `words`' language: `terms`,
 * each corner's value, whether it is inside and the bit it adds; `sum`, the case as the sum of the bits;
 * and the case.
 */
export function caseSum(corners, iso, digits = 3, words = ENGLISH) {
  const { bits, case: sum } = caseBits(corners, iso);
  const shown = (v) => numeral(words, Math.abs(v) >= 1000 ? v.toExponential(2) : v.toFixed(digits));
  const level = numeral(words, String(iso));
  const n = (x) => words.number(x);
  // The sentence's fields stand in for the HTML of the case and its sum, put in once it is escaped.
  const sentence = escape(words.t('plane.step.case', { case: '\u0001', sum: '\u0002' }));
  const parts = bits.map((b) => (b.inside ? `<span class="in">${n(b.bit)}</span>` : n(b.bit))).join(' + ');
  return {
    terms: bits.map((b) => `<span class="${b.inside ? 'in' : ''}">${escape(words.t(b.inside ? 'plane.step.corner-in' : 'plane.step.corner-out', {
      corner: b.corner, value: shown(b.value), iso: level, bit: b.bit,
    }))}</span>`),
    sum: sentence.replace('\u0001', () => `<b class="case">${n(sum)}</b>`).replace('\u0002', () => parts),
    case: sum,
  };
}

/**
 * Builds the panel into `host`; `actions` are the figure's: back, forward, next (crossed), play
 * (toggle), speed(steps per second), and close (optional: a × button). `table` is
 * `{ name, head, groups: [{ title?, rows: [[case, ...cells]] }] }` (HTML), or a function of the words
 * giving it. `words`: the language it speaks (English if not given). Returns `update(state)`, where
 * state is `{ playing, account (HTML), lit (the case whose row is lit, or null) }`; `update.language(words)`
 * words the panel again in another language (its marked words are also `relabel`'s).
 */
export function stepperPanel(host, actions, table, words = ENGLISH) {
  const tableOf = (w) => (typeof table === 'function' ? table(w) : table);
  host.innerHTML = `<style>${STYLE}</style>
    <div class="stepper" part="stepper">
      <div class="steps">
        <button type="button" data-do="back" data-t-label="plane.stepper.back">◀</button>
        <button type="button" data-do="play" class="play">▶</button>
        <button type="button" data-do="forward" data-t-label="plane.stepper.forward">▶|</button>
        <button type="button" data-do="next" data-t="plane.stepper.next" data-t-title="plane.stepper.next-title"></button>
        <select data-t-label="plane.stepper.rate-label">${[1, 4, 16, 64].map((s) => `<option value="${s}"${s === 4 ? ' selected' : ''}></option>`).join('')}</select>
        ${actions.close ? '<button type="button" data-do="close" data-t-label="plane.stepper.close">×</button>' : ''}
      </div>
      <div class="where" aria-live="polite"></div>
      <div class="rows" tabindex="0" role="region"><table class="cases"></table></div>
    </div>`;
  host.querySelector('.steps').addEventListener('click', (e) => {
    const what = e.target.closest('button')?.dataset.do;
    if (what) actions[what]();
  });
  host.querySelector('select').addEventListener('change', (e) => actions.speed(Number(e.target.value)));
  const where = host.querySelector('.where');
  const scroller = host.querySelector('.rows');
  const cases = host.querySelector('.cases');
  const play = host.querySelector('.play');
  let rows = new Map();
  let lit = null;
  let playing = false;
  let spoken = words;
  const showPlay = () => {
    play.textContent = playing ? spoken.t('plane.stepper.pause-button') : '▶';
    play.setAttribute('aria-label', spoken.t(playing ? 'plane.stepper.pause' : 'plane.stepper.play'));
  };
  // Everything the panel says, in `w`'s language: its buttons, rates and table.
  const language = (w) => {
    spoken = w;
    relabel(host, w);
    for (const option of host.querySelectorAll('select option')) option.textContent = w.t('plane.stepper.rate', { rate: Number(option.value) });
    const { name, head, groups } = tableOf(w);
    // The name as text (HTML's entities read).
    const named = document.createElement('div');
    named.innerHTML = name;
    scroller.setAttribute('aria-label', named.textContent);
    cases.innerHTML = `<thead><tr>${head.map((h) => `<th>${h}</th>`).join('')}</tr></thead><tbody>${groups.map((g) => (g.title
      ? `<tr><th class="group" colspan="${head.length}">${g.title}</th></tr>` : '')
      + g.rows.map(([c, ...cells]) => `<tr data-case="${c}"><td>${numeral(w, c)}</td>${cells.map((t) => `<td>${t}</td>`).join('')}</tr>`).join('')).join('')}</tbody>`;
    rows = new Map([...cases.querySelectorAll('tbody tr[data-case]')].map((r) => [Number(r.dataset.case), r]));
    rows.get(lit)?.classList.add('current');
    showPlay();
  };
  language(words);
  const update = ({ playing: now, account, lit: wanted }) => {
    playing = now;
    showPlay();
    // Read out step by step, not while it plays (a step every few frames would drown everything else).
    where.setAttribute('aria-live', playing ? 'off' : 'polite');
    if (where.innerHTML !== account) where.innerHTML = account;
    if (wanted === lit) return;
    rows.get(lit)?.classList.remove('current');
    lit = wanted;
    const row = rows.get(lit);
    if (!row) return;
    row.classList.add('current');
    // The lit row kept in view within the panel (not by scrolling the page).
    const [r, h] = [row.getBoundingClientRect(), scroller.getBoundingClientRect()];
    if (r.top < h.top || r.bottom > h.bottom) scroller.scrollTop += r.top - h.top - h.height / 2;
  };
  update.language = language;
  return update;
}
