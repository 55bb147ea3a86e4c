// The figures' own English messages, by key, one module per part of the figure (the parameter
// tables' labels, nouns, groups and words are made from the tables in www/lib/i18n/words.js). English
// is the source: every other catalogue (www/lib/i18n/) has the same keys, and tests/e2e/words.test.js
// holds them to it.
import core from './core.js';
import figure from './figure.js';
import teaching from './teaching.js';
import plane from './plane.js';
import scene from './scene.js';

export default { ...core, ...figure, ...teaching, ...plane, ...scene };
