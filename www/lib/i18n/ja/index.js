// Japanese (日本語): every word the figures show, by key, in the parts English has (www/lib/i18n/en/)
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
  'iso level': '等値レベル',
  'marching cubes': 'マーチングキューブ',
  'marching squares': 'マーチングスクエア',
  'surface nets': 'サーフェスネット',
  'genus': '種数',
  'saddle': '鞍点',
  'blob': '塊',
  'critical point': '臨界点',
};

export default { ...table, ...core, ...figure, ...teaching, ...scene, ...plane };
