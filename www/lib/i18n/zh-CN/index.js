// Simplified Chinese (简体中文): every word the figures show, by key, in the parts English has (www/lib/i18n/en/)
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
  'iso level': '等值',
  'marching cubes': '移动立方体',
  'marching squares': '移动正方形',
  'surface nets': 'Surface Nets',
  'genus': '亏格',
  'saddle': '鞍点',
  'blob': '团块',
  'critical point': '临界点',
};

export default { ...table, ...core, ...figure, ...teaching, ...scene, ...plane };
