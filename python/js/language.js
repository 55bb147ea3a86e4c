// The language a notebook figure speaks: the widget's `lang` trait (a tag such as `ja`) as the element's
// `lang` attribute, or, where the trait is empty, none (the figure follows the notebook's page).

import { quietly } from './quietly.js';

/** Keeps `figure`'s `lang` equal to `model`'s; returns a function that stops. */
export function followLanguage(model, figure) {
  const write = () => {
    const lang = model.get('lang');
    if (lang) figure.setAttribute('lang', lang);
    else figure.removeAttribute('lang');
  };
  write();
  model.on('change:lang', write);
  return () => quietly(() => model.off('change:lang', write));
}
