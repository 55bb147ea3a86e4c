// The stepper's panel, for the march in 2D and in 3D: play, pause, one step back and forward, the next
// crossed square or cell, the speed; an account of the square or cell at this step (its corner values
// and the case built bit by bit); and the case table (16 rows in 2D, the 256 in 3D grouped into their
// classes) with the row of this step's case lit. Only the table scrolls.

import { SEGMENTS } from './squares.js';
import { caseBits } from './stepper.js';

const EDGE_NAMES = ['bottom', 'right', 'top', 'left'];
const STYLE = `
.stepper { font: 12.5px/1.4 system-ui, sans-serif; color: var(--metaballs-text, #d7dbe4);
  background: var(--metaballs-panel-background, #1b1f2a); border-radius: 6px; padding: 8px; height: 100%;
  box-sizing: border-box; display: flex; flex-direction: column; }
.stepper .rows { flex: 1; min-height: 0; overflow: auto; }
.stepper .rows:focus-visible { outline: 2px solid currentColor; outline-offset: -2px; }
.stepper .steps { display: flex; flex-wrap: wrap; gap: 4px; margin-bottom: 6px; padding: 0; }
.stepper button, .stepper select { font: inherit; padding: 2px 8px; flex: none; width: auto; }
.stepper table { border-collapse: collapse; width: 100%; }
.stepper td, .stepper th { padding: 1px 4px; text-align: left; font-variant-numeric: tabular-nums; }
.stepper th.group { padding-top: 6px; font-weight: 600; color: var(--metaballs-muted, #a9b1c2); }
.stepper tr.current { background: var(--metaballs-accent, #b7791f); color: #11141b; }
.stepper .in { color: #ff8c1a; font-weight: 600; }
.stepper .where { min-height: 7.5em; }`;

/** Describes a segment of a case by the edges it joins. */
const joins = (segments) => segments.map(([a, b]) => `${EDGE_NAMES[a]}–${EDGE_NAMES[b]}`).join(', ') || '—';

/** The 16 cases of marching squares as the panel's table: case, bits, the segments each draws. */
export const SQUARE_TABLE = {
  name: 'The 16 cases of marching squares',
  head: ['case', 'bits 3210', 'segments'],
  groups: [{
    rows: SEGMENTS.apart.map((segments, c) => [c, c.toString(2).padStart(4, '0'),
      `${joins(segments)}${c === 5 || c === 10 ? ` <i>or</i> ${joins(SEGMENTS.joined[c])}` : ''}`]),
  }],
};

/** The account of marching squares' step `step` of `steps` at `square` (march's `square(i, j)`, or null at the end). */
export function squareAccount(step, steps, square, iso) {
  if (!square) return `Step ${step} of ${steps}: the march is done.`;
  const { terms, sum } = caseSum(square.corners, iso);
  const { saddle } = square;
  const decided = saddle && (saddle.value === null ? 'the table cuts the inside corners apart'
    : `${saddle.value.toFixed(3)} ${saddle.joined ? '&gt;' : '≤'} ${iso}, the inside corners ${saddle.joined ? 'joined' : 'cut apart'}`);
  return `Step ${step + 1} of ${steps}: square (${square.square.join(', ')})<br>${terms.join('<br>')}<br>${sum}${decided ? `<br>Saddle: ${decided}` : ''}`;
}

/**
 * The case of corner values `corners` at `iso` built bit by bit, as HTML: `terms`, each corner's value,
 * whether it is inside and the bit it adds; `sum`, the case as the sum of the bits; and the case.
 */
export function caseSum(corners, iso, digits = 3) {
  const { bits, case: sum } = caseBits(corners, iso);
  const shown = (v) => (Math.abs(v) >= 1000 ? v.toExponential(2) : v.toFixed(digits));
  return {
    terms: bits.map((b) => `<span class="${b.inside ? 'in' : ''}">corner ${b.corner}: ${shown(b.value)} ${b.inside ? '&gt;' : '≤'} ${iso} → ${b.bit}</span>`),
    sum: `case <b class="case">${sum}</b> = ${bits.map((b) => (b.inside ? `<span class="in">${b.bit}</span>` : b.bit)).join(' + ')}`,
    case: sum,
  };
}

/**
 * Builds the panel into `host`; `actions` are the figure's: back, forward, next (crossed), play
 * (toggle), speed(steps per second), and close (optional: a × button). `table` is
 * `{ name, head, groups: [{ title?, rows: [[case, ...cells]] }] }`. Returns `update(state)`, where
 * state is `{ playing, account (HTML), lit (the case whose row is lit, or null) }`.
 */
export function stepperPanel(host, actions, table) {
  const groups = table.groups.map((g) => (g.title ? `<tr><th class="group" colspan="${table.head.length}">${g.title}</th></tr>` : '')
    + g.rows.map(([c, ...cells]) => `<tr data-case="${c}"><td>${c}</td>${cells.map((t) => `<td>${t}</td>`).join('')}</tr>`).join(''));
  host.innerHTML = `<style>${STYLE}</style>
    <div class="stepper" part="stepper">
      <div class="steps">
        <button type="button" data-do="back" aria-label="One step back">◀</button>
        <button type="button" data-do="play" class="play" aria-label="Play the march">▶</button>
        <button type="button" data-do="forward" aria-label="One step forward">▶|</button>
        <button type="button" data-do="next" title="The next one the surface crosses">next crossed</button>
        <select aria-label="Steps per second">${[1, 4, 16, 64].map((s) => `<option value="${s}"${s === 4 ? ' selected' : ''}>${s}/s</option>`).join('')}</select>
        ${actions.close ? '<button type="button" data-do="close" aria-label="Close the step-through">×</button>' : ''}
      </div>
      <div class="where" aria-live="polite"></div>
      <div class="rows" tabindex="0" role="region" aria-label="${table.name}"><table class="cases">
        <thead><tr>${table.head.map((h) => `<th>${h}</th>`).join('')}</tr></thead><tbody>${groups.join('')}</tbody></table></div>
    </div>`;
  host.querySelector('.steps').addEventListener('click', (e) => {
    const what = e.target.closest('button')?.dataset.do;
    if (what) actions[what]();
  });
  host.querySelector('select').addEventListener('change', (e) => actions.speed(Number(e.target.value)));
  const where = host.querySelector('.where');
  const rows = new Map([...host.querySelectorAll('tbody tr[data-case]')].map((r) => [Number(r.dataset.case), r]));
  const scroller = host.querySelector('.rows');
  const play = host.querySelector('.play');
  let lit = null;
  return ({ playing, account, lit: wanted }) => {
    play.textContent = playing ? 'pause' : '▶';
    play.setAttribute('aria-label', playing ? 'Pause the march' : 'Play the march');
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
}
