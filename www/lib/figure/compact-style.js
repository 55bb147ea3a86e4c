// The styles of a small figure (features/sheets.js): its boxes as one sheet at a time, opened from a row
// of tabs, below the picture (`:state(sheet)`) or over its lower part (`:state(over)`). And controls a
// finger can hit (WCAG 2.2, 2.5.8): buttons, lists, summaries and sliders at least 24 CSS px high at
// every size; on a small figure, checkboxes and colour wells too, and every control 24 px wide. The
// tabs start where the reader's lines start (the left, or the right in RTL).

// The boxes that become the sheet.
const BOXES = '#panel, #hud, #levels-box, #inspector, #march, #sphere-box';
// What covers the picture, and what sits on its lower edge.
const LAYERS = '#view, #poster, #print-frame, #critical-marks, #edit-overlay, #message';
const LOWER = '#play, #tabs';
// The picture's height while the sheet is below it: the figure's width at 16:9 (the sheet goes below
// only where the figure's height followed its width; features/sheets.js).
const PICTURE = 'calc(100cqw * 9 / 16)';

export const COMPACT_STYLE = `
button, select, summary, input[type="range"] { min-height: 24px; }
button { min-width: 24px; }
#tabs {
  position: absolute;
  inset-inline-start: 8px;
  bottom: 8px;
  display: none;
  flex-wrap: wrap;
  gap: 6px;
  max-width: calc(100% - 96px);
  z-index: 2;
}
:host(:state(compact)) #tabs:not([hidden]) { display: flex; }
#tabs button { flex: none; padding: 3px 10px; font-size: 12px; background: var(--panel-solid); border-radius: 14px; }
#tabs button:hover { background: var(--button-hover); }
#tabs button[aria-expanded="true"] { background: var(--accent); color: var(--on-accent); border-color: var(--accent); }
:host(:state(compact)) #play { padding: 3px 10px; font-size: 12px; border-radius: 14px; }
/* Notices over the picture's top, clear of the tabs; a question to confirm over everything. */
:host(:state(compact)) :is(#notice, #wheel-hint) { bottom: auto; top: 8px; z-index: 4; }
:host(:state(compact)) #confirm { z-index: 4; }
:host(:state(compact)) #tabs ~ :is(${BOXES}):not(.shown) { display: none; }
:host(:state(compact)) #tabs ~ :is(${BOXES}) > details > summary { display: none; }
:host(:state(compact)) #tabs ~ :is(${BOXES}).shown {
  inset-inline: 0;
  top: auto;
  bottom: 0;
  width: auto;
  max-width: none;
  margin: 0;
  padding: 6px 12px 10px;
  overflow-y: auto;
  background: var(--panel-solid);
  border-radius: 10px 10px 0 0;
  z-index: 3;
}
/* Over the picture: from 40 % of its height down to the tabs (the sheet's bottom is set above them). */
:host(:state(over)) #tabs ~ :is(${BOXES}).shown { top: 40%; inset-inline: 8px; max-height: none; border-radius: 10px; }
/* One row of tabs there, scrolled sideways when they do not fit, to leave the sheet its height. */
:host(:state(over)) #tabs:not([hidden]) { flex-wrap: nowrap; overflow-x: auto; scrollbar-width: none; }
/* Below the picture: the figure grows by the sheet. */
/* (Not stretched to a taller neighbour's height in a grid or flex row: its own height is its sheet's.) */
:host(:state(sheet)) { aspect-ratio: auto; height: auto; align-self: start; }
:host(:state(sheet))::before { content: ""; display: block; aspect-ratio: 16 / 9; }
:host(:state(sheet)) #tabs ~ :is(${BOXES}).shown {
  position: relative;
  max-height: min(60vh, 440px);
  border-radius: 0;
  border-top: 1px solid var(--border);
}
/* The step-through fills its sheet, and its table scrolls. */
:host(:state(sheet)) #tabs ~ #march.shown { height: min(60vh, 440px); overflow: hidden; }
:host(:state(sheet)) :is(${LAYERS}) { bottom: auto; height: ${PICTURE}; }
:host(:state(sheet)) :is(${LOWER}) { bottom: auto; top: calc(${PICTURE} - 8px); translate: 0 -100%; }
:host(:state(sheet)) #confirm { top: calc(${PICTURE} / 2); }
:host(:state(compact)) .control:not(.slice, .list) { grid-template-columns: minmax(64px, 38%) minmax(40px, 1fr) minmax(32px, 52px); }
:host(:state(compact)) :is(input[type="checkbox"], input[type="color"], input[type="number"]) { min-height: 24px; }
:host(:state(compact)) input[type="checkbox"] { width: 24px; height: 24px; }
`;
