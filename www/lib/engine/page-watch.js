// What every figure on the page shares, made when the first one is connected (never at import): a
// pair of observers (one starts elements as they come near the viewport, the other tells whether each
// is on screen at all), the page's visibility and colour-scheme listeners, how long a figure off
// screen keeps its GPU memory, and the time between frames the figures aim for.

import { hub } from './hub.js';

let page = null;

/** How long a figure stays off screen before it lets go of its GPU memory, in ms. */
export const RELEASE_AFTER_MS = 30_000;
let releaseAfter = RELEASE_AFTER_MS;
export const releaseDelay = () => releaseAfter;
export function setReleaseDelay(ms) {
  releaseAfter = Number.isFinite(ms) && ms >= 0 ? ms : RELEASE_AFTER_MS;
}

/** Time between the page's frames the figures aim for, in milliseconds (about 33 fps). */
export const FRAME_BUDGET_MS = 30;
let budget = FRAME_BUDGET_MS;

/** The page's frame budget now (tests force it slow or fast). */
export const frameBudget = () => budget;
export function setFrameBudget(ms) {
  budget = Number.isFinite(ms) && ms > 0 ? ms : FRAME_BUDGET_MS;
}

/** The page's shared observers and listeners (made on the first call). */
export function pageWatch() {
  if (page) return page;
  page = {
    near: new IntersectionObserver((entries) => {
      for (const entry of entries) if (entry.isIntersecting) entry.target.approach();
    }, { rootMargin: '200px' }),
    visible: new IntersectionObserver((entries) => {
      for (const entry of entries) entry.target.setOnScreen(entry.isIntersecting);
    }),
    reducedMotion: matchMedia('(prefers-reduced-motion: reduce)'),
  };
  document.addEventListener('visibilitychange', () => hub.requestFrame());
  matchMedia('(prefers-color-scheme: light)').addEventListener('change', () => {
    for (const element of hub.elements) element.schemeChanged();
  });
  return page;
}

/** Stops watching `element` (it left the page). */
export function unwatch(element) {
  page?.near.unobserve(element);
  page?.visible.unobserve(element);
}
