// Brazilian Portuguese (português do Brasil): every word the figures show, by key, in the parts English has (www/lib/i18n/en/)
// and the parameter tables' (table.js); docs/embedding.md, "Languages". One module for the page: the
// parts are bundled into one chunk, loaded only where a reader needs it. The glossary holds the field's
// terms as every message of the language says them.
import table from './table.js';
import core from './core.js';
import figure from './figure.js';
import teaching from './teaching.js';
import scene from './scene.js';
import plane from './plane.js';

export const glossary = {
  'iso level': 'isovalor',
  'marching cubes': 'marching cubes',
  'marching squares': 'marching squares',
  'surface nets': 'surface nets',
  'genus': 'gênero',
  'saddle': 'sela',
  'blob': 'blob',
  'critical point': 'crítico',
};

export default { ...table, ...core, ...figure, ...teaching, ...scene, ...plane };
