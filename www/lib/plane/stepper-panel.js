// The stepper's panel beside the 2D figure: play, pause, one step back and forward, the next crossed
// square, the speed; the square at this step with its corner values and the case built bit by bit; and
// the 16 cases' table with the square's row lit.

import { SEGMENTS } from './squares.js';
import { caseBits } from './stepper.js';

const EDGE_NAMES = ['bottom', 'right', 'top', 'left'];
const STYLE = `
.stepper { font: 12.5px/1.4 system-ui, sans-serif; color: var(--metaballs-text, #d7dbe4);
  background: var(--metaballs-panel-background, #1b1f2a); border-radius: 6px; padding: 8px; height: 100%;
  box-sizing: border-box; display: flex; flex-direction: column; }
.stepper .rows { flex: 1; min-height: 0; overflow: auto; }
.stepper .rows:focus-visible { outline: 2px solid currentColor; outline-offset: -2px; }
.stepper .controls { display: flex; flex-wrap: wrap; gap: 4px; margin-bottom: 6px; }
.stepper button, .stepper select { font: inherit; padding: 2px 6px; }
.stepper table { border-collapse: collapse; width: 100%; }
.stepper td, .stepper th { padding: 1px 4px; text-align: left; font-variant-numeric: tabular-nums; }
.stepper tr.current { background: var(--metaballs-accent, #b7791f); color: #11141b; }
.stepper .in { color: #ff8c1a; font-weight: 600; }
.stepper .where { min-height: 7.5em; }`;

/** Describes a segment of a case by the edges it joins. */
const joins = (segments) => segments.map(([a, b]) => `${EDGE_NAMES[a]}–${EDGE_NAMES[b]}`).join(', ') || '—';

/**
 * Builds the panel into `host` (a shadow root's element); `actions` are the figure's: back, forward,
 * next (crossed), play (toggle), speed(steps per second). Returns `update(state)`, where state is
 * `{ step, steps, square: march's square(i, j) or null, iso, playing }`.
 */
export function stepperPanel(host, actions) {
  host.innerHTML = `<style>${STYLE}</style>
    <div class="stepper" part="stepper">
      <div class="controls">
        <button type="button" data-do="back" aria-label="One square back">◀</button>
        <button type="button" data-do="play" class="play" aria-label="Play the march">▶</button>
        <button type="button" data-do="forward" aria-label="One square forward">▶|</button>
        <button type="button" data-do="next" title="The next square the contour crosses">next crossed</button>
        <select aria-label="Steps per second">${[1, 4, 16, 64].map((s) => `<option value="${s}"${s === 4 ? ' selected' : ''}>${s}/s</option>`).join('')}</select>
      </div>
      <div class="where" aria-live="polite"></div>
      <div class="rows" tabindex="0" role="region" aria-label="The 16 cases of marching squares"><table class="cases"><thead><tr><th>case</th><th>bits 3210</th><th>segments</th></tr></thead><tbody>
        ${SEGMENTS.apart.map((segments, c) => `<tr data-case="${c}"><td>${c}</td><td>${c.toString(2).padStart(4, '0')}</td><td>${joins(segments)}${c === 5 || c === 10 ? ` <i>or</i> ${joins(SEGMENTS.joined[c])}` : ''}</td></tr>`).join('')}
      </tbody></table></div>
    </div>`;
  host.querySelector('.controls').addEventListener('click', (e) => {
    const what = e.target.closest('button')?.dataset.do;
    if (what) actions[what]();
  });
  host.querySelector('select').addEventListener('change', (e) => actions.speed(Number(e.target.value)));
  const where = host.querySelector('.where');
  const rows = [...host.querySelectorAll('tbody tr')];
  // Only the table scrolls: the controls and the square's account stay in view.
  const scroller = host.querySelector('.rows');
  const play = host.querySelector('.play');
  return ({ step, steps, square, iso, playing }) => {
    play.textContent = playing ? 'pause' : '▶';
    play.setAttribute('aria-label', playing ? 'Pause the march' : 'Play the march');
    for (const row of rows) row.classList.toggle('current', square !== null && Number(row.dataset.case) === square.case);
    // The lit row kept in view within the panel (not by scrolling the page).
    const lit = square && rows[square.case];
    if (lit) {
      const [r, h] = [lit.getBoundingClientRect(), scroller.getBoundingClientRect()];
      if (r.top < h.top || r.bottom > h.bottom) scroller.scrollTop += r.top - h.top - h.height / 2;
    }
    if (!square) {
      where.textContent = `Step ${step} of ${steps}: the march is done.`;
      return;
    }
    const { bits, case: c } = caseBits(square.corners, iso);
    const terms = bits.map((b) => `<span class="${b.inside ? 'in' : ''}">corner ${b.corner}: ${b.value.toFixed(3)} ${b.inside ? '&gt;' : '≤'} ${iso} → ${b.bit}</span>`).join('<br>');
    const saddle = square.saddle
      ? `<br>Saddle: ${square.saddle.value === null ? 'the table cuts the inside corners apart' : `${square.saddle.value.toFixed(3)} ${square.saddle.joined ? '&gt;' : '≤'} ${iso}, the inside corners ${square.saddle.joined ? 'joined' : 'cut apart'}`}`
      : '';
    where.innerHTML = `Step ${step + 1} of ${steps}: square (${square.square.join(', ')})<br>${terms}<br>`
      + `case <b class="case">${c}</b> = ${bits.map((b) => b.bit).join(' + ')}${saddle}`;
  };
}
