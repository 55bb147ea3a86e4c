// The element's shadow DOM: its markup, and its own styles adopted by every shadow root (one stylesheet
// per page, made when the first figure is; nothing here runs at import, so a server-side build can
// import the module). Shadow DOM keeps the host page's rules out and these in; pages restyle the figure
// through the custom properties and ::part() names below (README, custom-elements.json).

import { inEnglish, say } from '../engine/asset-errors.js';
import { COMPACT_STYLE } from './compact-style.js';
import { DARK, LIGHT } from './palette.js';

const STYLE = `
:host {
  ${DARK}
  display: block;
  position: relative;
  width: 100%;
  aspect-ratio: 16 / 9;
  overflow: hidden;
  background: var(--metaballs-poster-color, #0b0d12);
  color: var(--text);
  font: 13px/1.4 system-ui, -apple-system, "Segoe UI", Roboto, sans-serif;
  color-scheme: dark;
  contain: layout paint;
  container-type: inline-size;
  border-radius: 6px;
}
:host([theme="light"]) { ${LIGHT} }
@media (prefers-color-scheme: light) {
  :host([theme="auto"]) { ${LIGHT} }
}
:host([hidden]) { display: none; }
/* Right to left (the reader's language, or the page's dir): the boxes mirror; the picture, what is
   drawn over it in its coordinates, and the drawings and plots do not. */
/* The figure runs its own language's way, whatever way the page around it runs. */
:host { direction: ltr; }
:host(:state(rtl)) { direction: rtl; }
canvas, #poster, #print-frame, #edit-overlay, #critical-marks, #hud-quality-bars, svg, .legend .ends { direction: ltr; }

/* Before the first frame: the poster (or the poster colour). In print: the latest frame as a picture,
   else the poster; the controls are left out. */
#poster, #print-frame {
  position: absolute;
  inset: 0;
  width: 100%;
  height: 100%;
  object-fit: cover;
  pointer-events: none;
}
#poster[hidden], #print-frame { display: none; }
.visually-hidden {
  position: absolute;
  width: 1px;
  height: 1px;
  overflow: hidden;
  clip-path: inset(50%);
  white-space: nowrap;
}
@media print {
  :host { box-shadow: none !important; break-inside: avoid; }
  canvas, #panel, #hud, #play, #notice, #wheel-hint, #confirm, #inspector, #march, #sphere-box, #edit-overlay,
  #critical-marks, #levels-box, #message, #tabs { display: none !important; }
  #poster[src] { display: block; }
  #print-frame[src] { display: block; }
}
* { box-sizing: border-box; }

canvas {
  position: absolute;
  inset: 0;
  display: block;
  width: 100%;
  height: 100%;
  margin: 0;
  padding: 0;
  border: 0;
  cursor: grab;
  outline: none;
}
canvas:active { cursor: grabbing; }
canvas:focus-visible { outline: 2px solid var(--accent); outline-offset: -2px; }
:host(:focus-within) { box-shadow: 0 0 0 2px var(--accent); }

/* The panel and the inspector: boxes over the figure that scroll when it is short. */
#panel, #inspector {
  position: absolute;
  max-height: calc(100% - 16px);
  overflow-y: auto;
  background: var(--panel);
  border-radius: 8px;
}
#panel {
  top: 8px;
  inset-inline-start: 8px;
  width: min(280px, 33%);
}
#panel[hidden] { display: none; }
summary { padding: 6px 10px; cursor: pointer; color: var(--muted); user-select: none; }
summary:focus-visible { outline: 2px solid var(--accent); outline-offset: -2px; }
.controls { padding: 0 10px 10px; }
.control {
  display: grid;
  grid-template-columns: minmax(48px, 106px) minmax(40px, 1fr) minmax(32px, 52px);
  align-items: center;
  gap: 6px;
  margin: 4px 0;
}
.control label { min-width: 0; color: var(--muted); overflow-wrap: anywhere; hyphens: auto; }
.control output { min-width: 0; text-align: end; font-variant-numeric: tabular-nums; overflow-wrap: anywhere; }
/* A colour's hex code is one word: smaller rather than broken. */
input[type="color"] + output { overflow-wrap: normal; font-size: 11px; }
input { margin: 0; font: inherit; }
input[type="range"] { width: 100%; accent-color: var(--accent); }
input[type="color"] { width: 100%; height: 22px; border: none; background: none; padding: 0; }
input[type="checkbox"] { accent-color: var(--accent); justify-self: start; }
.buttons { display: flex; gap: 6px; margin: 8px 0 4px; flex-wrap: wrap; }
button, select {
  color: var(--text);
  background: var(--button);
  border: 1px solid var(--border);
  font: inherit;
}
button {
  flex: 1;
  padding: 5px 8px;
  border-radius: 6px;
  cursor: pointer;
}
/* A button in a row is never narrower than its longest word (a longer language's words wrap between them). */
.buttons > button { min-width: min-content; overflow-wrap: break-word; }
button:hover { background: var(--button-hover); }
button[aria-pressed="true"] { background: var(--accent); color: var(--on-accent); border-color: var(--accent); }
button:focus-visible, input:focus-visible { outline: 2px solid var(--accent); outline-offset: 2px; }
.seed, .hint { margin: 4px 0; color: var(--muted); font-size: 12px; }
::slotted(*) { color: var(--muted); font-size: 12px; }

#hud {
  position: absolute;
  top: 8px;
  inset-inline-end: 8px;
  max-width: 50%;
  padding: 4px 10px 6px;
  background: var(--panel);
  border-radius: 8px;
  font-variant-numeric: tabular-nums;
  font-size: 12px;
}
#hud[hidden] { display: none; }
#hud summary { padding: 0 0 2px; font-size: 11.5px; }
#hud details:not([open]) summary { padding: 0; }
#hud div { overflow-wrap: anywhere; }
#hud #hud-lod ol { list-style: none; margin: 0; padding: 0; }
#hud #hud-lod li i { display: inline-block; width: 8px; height: 8px; margin-inline-end: 4px; border-radius: 2px; }
figure.error-plot { margin: 6px 0 0; font-size: 11px; }
figure.error-plot svg { display: block; width: 100%; height: auto; }
figure.error-plot text { fill: currentColor; font-size: 9px; }
figure.error-plot line.grid { stroke: currentColor; opacity: 0.2; }
div.levels svg { display: block; width: 100%; height: auto; margin-top: 4px; touch-action: none; }
div.levels text { fill: currentColor; font-size: 9px; }
div.levels line.grid { stroke: currentColor; opacity: 0.2; }
div.levels rect.walls { fill: currentColor; opacity: 0.08; }
div.levels .cursor-line { stroke: var(--accent); stroke-width: 1.5; }
div.levels .cursor-grip { fill: var(--accent); cursor: ew-resize; }
div.levels .hit { fill: transparent; }
div.levels .branch { stroke: currentColor; fill: none; opacity: 0.7; }
div.levels .join { cursor: pointer; }
div.levels .join:focus-visible circle:not(.hit), div.levels .cursor:focus-visible rect:not(.hit) { stroke: var(--accent); stroke-width: 2; }
div.levels ol.critical-levels { margin: 4px 0 0; padding-inline-start: 18px; font-size: 11px; max-height: 8em; overflow: auto; }
#hud #hud-field-warning { color: var(--warn); max-width: 28em; white-space: normal; overflow: visible; text-overflow: clip; }
#critical-marks { position: absolute; inset: 0; pointer-events: none; overflow: hidden; }
/* Each mark on a dark chip, so that it reads over any part of the picture. */
#critical-marks span { position: absolute; left: 0; top: 0; margin: calc(-0.6em - 1px) 0 0 calc(-0.45em - 3px);
  padding: 1px 3px; border-radius: 3px; background: rgba(11, 13, 18, 0.85); font: 11px/1 system-ui, sans-serif; white-space: nowrap; }
#hud #hud-quality-bars { display: inline-flex; align-items: flex-end; gap: 1px; height: 14px; vertical-align: middle; }
#hud #hud-quality-bars i { display: inline-block; width: 6px; background: currentColor; opacity: 0.8; }
#hud .key { display: inline-block; min-width: 56px; color: var(--muted); }
#overflow { color: var(--warn); white-space: normal !important; }
/* Small figures keep the statistics to frames per second and triangles. */
@container (max-width: 480px) { #hud .wide { display: none; } }

#play {
  position: absolute;
  inset-inline-end: 8px;
  bottom: 8px;
  flex: none;
  padding: 6px 12px;
  background: var(--panel);
}
#play[hidden] { display: none; }

#notice, #wheel-hint {
  position: absolute;
  left: 50%;
  bottom: 8px;
  transform: translateX(-50%);
  max-width: calc(100% - 16px);
  padding: 6px 10px;
  border-radius: 6px;
  font-size: 12.5px;
}
#notice { background: #3b2f12; border: 1px solid #8a6a1f; color: #ffe2a3; }
#wheel-hint { background: var(--panel); color: var(--text); pointer-events: none; }
#notice[hidden], #wheel-hint[hidden] { display: none; }
#confirm {
  position: absolute;
  left: 50%;
  top: 50%;
  transform: translate(-50%, -50%);
  max-width: min(440px, calc(100% - 16px));
  padding: 10px 12px;
  border-radius: 8px;
  background: #3b2f12;
  border: 1px solid #8a6a1f;
  color: #ffe2a3;
  font-size: 13px;
}
#confirm p { margin: 0 0 8px; }
#confirm .buttons { display: flex; gap: 8px; flex-wrap: wrap; }
#confirm[hidden] { display: none; }
.unavailable { opacity: 0.5; cursor: not-allowed; }

select {
  width: 100%;
  min-width: 0;
  padding: 2px 4px;
  border-radius: 4px;
}
select:focus-visible { outline: 2px solid var(--accent); outline-offset: 1px; }
details.group { border-top: 1px solid #2a3042; }
details.group > summary { padding: 5px 0; font-weight: 600; color: var(--text); }
.control.slice { grid-template-columns: minmax(48px, 106px) 58px minmax(40px, 1fr) 32px; }
.control.list { grid-template-columns: minmax(48px, 106px) 1fr; align-items: start; }
.control .label { color: var(--muted); }
.checks { display: flex; flex-wrap: wrap; gap: 2px 10px; }
.checks label { white-space: nowrap; color: var(--text); }
.legend { margin: 2px 0 6px; font-size: 11px; color: var(--muted); }
.legend .ramp { display: block; height: 8px; border-radius: 2px; }
.legend .ends { display: flex; justify-content: space-between; }
.legend.classes { display: flex; flex-wrap: wrap; gap: 2px 8px; }
.legend.classes i { display: inline-block; width: 9px; height: 9px; margin-inline-end: 3px; border-radius: 2px; }
.gallery { display: grid; grid-template-columns: repeat(auto-fill, minmax(76px, 1fr)); gap: 6px; }
.gallery figure { margin: 0; padding: 3px; border: 1px solid transparent; border-radius: 6px; text-align: center; }
.gallery figure.current { border-color: var(--accent); background: #2c2220; }
.gallery figcaption { font-size: 10.5px; color: var(--muted); line-height: 1.25; }
svg .edge { stroke: #6b7488; stroke-width: 1; }
svg .triangle { stroke: #11141b; stroke-width: 0.6; fill-opacity: 0.85; }
svg .inside { fill: #ff8c1a; stroke: #11141b; }
svg .outside { fill: #11141b; stroke: #4d8dff; stroke-width: 1.2; }
svg .corner-number { fill: var(--muted); font-size: 9px; }
#inspector {
  inset-inline-end: 8px;
  bottom: 8px;
  width: min(330px, 45%);
  padding: 6px 10px 8px;
  font-size: 12px;
  font-variant-numeric: tabular-nums;
  z-index: 1;
}
#inspector[hidden] { display: none; }
/* The step-through of the march: the column at the start (the left, or the right in RTL), over the panel. */
#march { position: absolute; inset-inline-start: 8px; top: 8px; bottom: 8px; width: min(300px, 40%); z-index: 1; }
/* Along the iso level: the column at the start, opaque over the panel (which is inert behind it). */
#levels-box { position: absolute; inset-inline-start: 8px; top: 8px; bottom: 8px; width: min(300px, 45%); overflow-y: auto;
  padding: 4px 10px 8px; background: var(--panel-solid); border-radius: 8px; font-size: 12px; z-index: 1; }
#levels-box[hidden] { display: none; }
#levels-box h3 { margin: 2px 0; font-size: 12px; font-weight: 600; }
#levels-box button.close { float: inline-end; }
#play:not([hidden]) ~ #levels-box { bottom: 48px; }
#march[hidden] { display: none; }
#play:not([hidden]) ~ #march { bottom: 48px; }
/* Above the play button when both show. */
#play:not([hidden]) ~ #inspector { bottom: 48px; max-height: calc(100% - 56px); }
#inspector header { display: flex; justify-content: space-between; align-items: center; }
#inspector h3 { margin: 0; font-size: 13px; }
#inspector .close { flex: none; padding: 0 8px; }
#inspector p { margin: 4px 0; }
#inspector table { border-collapse: collapse; font-size: 11.5px; }
#inspector td, #inspector th { padding: 0; padding-inline-end: 6px; text-align: start; font-weight: normal; color: var(--text); }
#inspector th { color: var(--muted); }
#inspector .inspector-body { display: flex; gap: 8px; align-items: flex-start; }
#inspector .drawing { display: flex; flex-wrap: wrap; gap: 4px; }
#inspector canvas.interpolant { position: static; width: 96px; height: 96px; cursor: default; }
#inspector .in { color: var(--in); }
#inspector .out { color: var(--out); }
#inspector .faces { margin: 2px 0; padding-inline-start: 16px; }
#inspector .faces .disagrees { color: var(--bad); }

/* Edit mode: rings around the hovered and the selected sphere, and the selected sphere's box. */
canvas.editing { cursor: crosshair; }
#edit-overlay { position: absolute; inset: 0; width: 100%; height: 100%; pointer-events: none; overflow: visible; }
#edit-overlay circle { fill: none; stroke-width: 2; }
#edit-overlay circle[hidden] { display: none; }
#hover-ring { stroke: rgba(255, 255, 255, 0.7); stroke-dasharray: 5 4; }
#selected-ring { stroke: var(--accent); }
#sphere-box {
  position: absolute;
  inset-inline-end: 8px;
  bottom: 8px;
  width: min(280px, 45%);
  padding: 6px 10px 8px;
  background: var(--panel);
  border-radius: 8px;
  font-size: 12px;
  z-index: 1;
}
#sphere-box[hidden] { display: none; }
#play:not([hidden]) ~ #sphere-box { bottom: 48px; }
#sphere-box header { display: flex; justify-content: space-between; align-items: center; }
#sphere-box h3 { margin: 0; font-size: 13px; }
#sphere-box .close { flex: none; padding: 0 8px; }
#sphere-box p { margin: 4px 0; }
:host(.dropping) { box-shadow: 0 0 0 3px var(--accent); }

#message {
  position: absolute;
  inset: 0;
  display: flex;
  flex-direction: column;
  align-items: center;
  justify-content: center;
  padding: 16px;
  text-align: center;
  background: var(--panel);
  overflow: auto;
}
#message[hidden] { display: none; }
#message h2 { margin: 0 0 6px; font-size: 16px; }
#message p { margin: 0 0 8px; max-width: 620px; color: var(--muted); white-space: pre-line; }
#message button { flex: none; }
`;

let sheet = null;
/** The stylesheet every figure's shadow root adopts (made once, by the first figure). */
export function elementStyle() {
  if (!sheet) {
    sheet = new CSSStyleSheet();
    sheet.replaceSync(STYLE + COMPACT_STYLE);
  }
  return sheet;
}

/**
 * The markup of every figure's shadow root. Its words are marked by key (`data-t`, `data-t-label`,
 * `data-t-title`) and worded in the reader's language when the figure connects (core/context.js).
 */
export const TEMPLATE = `
  <img id="poster" part="poster" alt="" hidden>
  <img id="print-frame" alt="">
  <canvas id="view" tabindex="0" part="canvas" role="img" aria-describedby="how"></canvas>
  <span id="how" class="visually-hidden" data-t="figure.how"></span>
  <div id="announce" class="visually-hidden" role="status" aria-live="polite"></div>
  <div id="tabs" role="group" data-t-label="sheet.tabs" hidden></div>
  <aside id="panel" part="panel" data-t-label="panel.controls" hidden></aside>
  <section id="hud" part="hud" data-t-label="hud.statistics" aria-live="off" hidden>
    <details open><summary data-t="hud.statistics"></summary>
    <div><span class="key" data-t="hud.fps"></span> <span id="fps">–</span></div>
    <div class="wide"><span class="key" data-t="hud.frame"></span> <span id="frame-time">–</span></div>
    <div><span class="key" data-t="hud.triangles"></span> <span id="triangles">–</span></div>
    <div class="wide"><span class="key" data-t="hud.adapter"></span> <span id="adapter">–</span></div>
    <div class="wide" data-t-title="hud.scale-title"><span class="key" data-t="hud.scale"></span> <span id="hud-scale">–</span></div>
    <div id="hud-error" hidden><span class="key" data-t="hud.error"></span> <span id="hud-error-text"></span></div>
    <div id="hud-topology" hidden><span class="key" data-t="hud.topology"></span> <span id="hud-topology-text"></span></div>
    <div id="hud-field" hidden data-t-title="hud.field-title"><span class="key" data-t="hud.field"></span> <span id="hud-field-text"></span></div>
    <div id="hud-field-warning" class="warning" role="status" hidden></div>
    <div id="hud-quality" hidden><span class="key" data-t="hud.quality"></span> <span id="hud-quality-bars" role="img"></span></div>
    <div id="hud-lod-cell" hidden data-t-title="hud.lod-cell-title"><span class="key" data-t="hud.lod-cell"></span> <span id="hud-lod-cell-text"></span></div>
    <div id="hud-lod" hidden><span class="key" data-t="hud.lod"></span> <span id="hud-lod-summary"></span><ol id="hud-lod-levels"></ol></div>
    <div id="overflow" role="alert" hidden data-t="hud.overflow"></div>
    </details>
  </section>
  <button id="play" type="button" hidden data-t="play.button"></button>
  <section id="levels-box" data-t-label="setting.levels" hidden></section>
  <section id="inspector" data-t-label="action.inspector" hidden></section>
  <section id="march" data-t-label="action.step-through" hidden></section>
  <svg id="edit-overlay" aria-hidden="true"><circle id="hover-ring" hidden></circle><circle id="selected-ring" hidden></circle></svg>
  <section id="sphere-box" data-t-label="figure.sphere-box" hidden></section>
  <input type="file" id="scene-file" accept=".json,application/json" hidden>
  <div id="wheel-hint" hidden></div>
  <div id="notice" part="notice" role="status" hidden></div>
  <div id="confirm" role="alertdialog" aria-labelledby="confirm-text" hidden>
    <p id="confirm-text"></p>
    <div class="buttons"><button type="button" id="confirm-apply" data-t="guard.apply"></button><button type="button" id="confirm-keep"></button></div>
  </div>
  <div id="message" role="alert" hidden>
    <h2 id="message-title"></h2>
    <p id="message-text"></p>
    <button id="retry" type="button" hidden data-t="figure.retry"></button>
  </div>`;

/**
 * The figure's message box (`#message` in `root`): a title, a text and perhaps "Try again". Each is a
 * saying (engine/asset-errors.js) worded with `words()`, the figure's words now, and again on `reword`.
 */
export function messageBox(root, words) {
  const $ = (id) => root.getElementById(id);
  let shown = { title: '', text: '' };
  const write = (w) => {
    $('message-title').textContent = say(w, shown.title);
    $('message-text').textContent = say(w, shown.text);
  };
  return {
    show(title, text, retry = false) {
      shown = { title, text };
      write(words());
      $('retry').hidden = !retry;
      $('message').hidden = false;
    },
    hide() { $('message').hidden = true; },
    /** Words the message again (the figure's language changed). */
    reword(w) { write(w); },
    /** The text shown, in English (what a promise the figure could not keep rejects with). */
    get text() { return inEnglish(shown.text); },
  };
}
