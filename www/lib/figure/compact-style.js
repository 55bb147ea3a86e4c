// The styles of a small figure (features/sheets.js): its boxes as one sheet at a time, opened from a row
// of tabs, below the picture (`:state(sheet)`) or over its lower part (`:state(over)`); and controls a
// finger can hit, at least 24 × 24 CSS pixels (WCAG 2.2, 2.5.8), at every size.

// The boxes that become the sheet.
const BOXES = '#panel, #hud, #levels-box, #inspector, #march, #sphere-box';
// What covers the picture, and what sits on its lower edge.
const LAYERS = 'canvas, #poster, #print-frame, #critical-marks, #edit-overlay, #message';
const LOWER = '#play, #tabs, #notice, #wheel-hint';
// The picture's height while the sheet is below it: the figure's width at 16:9.
const PICTURE = 'calc(100cqw * 9 / 16)';

export const COMPACT_STYLE = `
button, select, summary, input[type="range"] { min-height: 24px; }
button { min-width: 24px; }
#tabs {
  position: absolute;
  left: 8px;
  bottom: 8px;
  display: none;
  flex-wrap: wrap;
  gap: 6px;
  max-width: calc(100% - 96px);
  z-index: 2;
}
:host(:state(compact)) #tabs:not([hidden]) { display: flex; }
#tabs button { flex: none; padding: 3px 10px; font-size: 12px; background: var(--panel-solid); border-radius: 14px; }
#tabs button[aria-expanded="true"] { background: var(--accent); color: var(--on-accent); border-color: var(--accent); }
:host(:state(compact)) #play { padding: 3px 10px; font-size: 12px; border-radius: 14px; }
:host(:state(compact)) #tabs ~ :is(${BOXES}):not(.shown) { display: none; }
:host(:state(compact)) #tabs ~ :is(${BOXES}) > details > summary { display: none; }
:host(:state(compact)) #tabs ~ :is(${BOXES}).shown {
  left: 0;
  right: 0;
  top: auto;
  bottom: 0;
  width: auto;
  max-width: none;
  max-height: calc(60% - 44px);
  margin: 0;
  padding: 6px 12px 10px;
  overflow-y: auto;
  background: var(--panel-solid);
  border-radius: 10px 10px 0 0;
  z-index: 3;
}
:host(:state(over)) #tabs ~ :is(${BOXES}).shown { bottom: 44px; border-radius: 10px; left: 8px; right: 8px; }
/* The sheet below the picture: the figure grows by it. */
:host(:state(sheet)) { aspect-ratio: auto; height: auto; }
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
:host(:state(compact)) .control { grid-template-columns: minmax(64px, 38%) minmax(40px, 1fr) minmax(32px, 52px); }
:host(:state(compact)) .control label { white-space: normal; }
:host(:state(compact)) #hud div { white-space: normal; }
:host(:state(compact)) :is(input[type="range"], input[type="checkbox"], input[type="color"], input[type="number"], select) { min-height: 24px; }
:host(:state(compact)) input[type="checkbox"] { width: 24px; height: 24px; }
`;
