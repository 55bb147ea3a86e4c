// What every figure on the page shares, made when the first one is connected (never at import): a
// pair of observers (one starts elements as they come near the viewport, the other tells whether each
// is on screen at all), and the page's visibility and colour-scheme listeners.

import { hub } from './engine.js';

let page = null;

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
