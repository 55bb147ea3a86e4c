// Arabic (العربية): every word the figures show, by key, in the parts English has (www/lib/i18n/en/)
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
  'iso level': 'مستوى التساوي',
  'marching cubes': 'المكعبات الزاحفة',
  'marching squares': 'المربعات الزاحفة',
  'surface nets': 'شبكات السطح',
  'genus': 'جنس',
  'saddle': 'سرج',
  'blob': 'كتل',
  'critical point': 'حرج',
};

export default { ...table, ...core, ...figure, ...teaching, ...scene, ...plane };
