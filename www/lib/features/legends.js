// Colour keys for the teaching views, drawn with the colours shaders/draw/views/ uses: the ramp (area,
// shape, field slice), the 15 case classes and the levels of detail, worded with the figure's words
// (`words`, i18n/words.js). The ramps run left to right in every language, as the colours do.

/** The ramp's stops (sRGB), dark violet to yellow. */
const RAMP = ['#440154', '#3b528b', '#21918c', '#5ec962', '#fde725'];

/** The colour of case class `k` (0..14): hues 24° apart, saturation 0.65, value 0.95. */
export function classColor(k) {
  const h = (k / 15) * 6;
  const x = 1 - Math.abs((h % 2) - 1);
  const c = [[1, x, 0], [x, 1, 0], [0, 1, x], [0, x, 1], [x, 0, 1], [1, 0, x]][Math.min(5, Math.floor(h))];
  const [r, g, b] = c.map((v) => Math.round(255 * 0.95 * (0.35 + 0.65 * v)));
  return `rgb(${r}, ${g}, ${b})`;
}

/** The colour of level of detail `k` (0 the finest, blue): class hues 96° apart, as the views draw them. */
export function levelColor(k) {
  return classColor((9 + 4 * k) % 15);
}

// Numbered swatches, each `[number, colour, title]`, and a note after them.
function swatches(items, note, words) {
  const list = document.createElement('div');
  list.className = 'legend classes';
  for (const [number, color, title] of items) {
    const item = document.createElement('span');
    item.title = title;
    item.innerHTML = `<i style="background: ${color}"></i>`;
    item.append(words.number(number));
    list.append(item);
  }
  const after = document.createElement('span');
  after.textContent = note;
  list.append(after);
  return list;
}

function levels(words) {
  const items = Array.from({ length: 9 }, (_, k) => [k, levelColor(k),
    k ? words.t('legend.level', { level: k, factor: 2 ** k }) : words.t('legend.level-0', { level: 0 })]);
  return swatches(items, words.t('legend.levels-note'), words);
}

// The QEF's ranks with dual contouring: the first three levels' colours, as the views draw them.
function ranks(words) {
  const items = [1, 2, 3].map((rank) => [rank, levelColor(rank - 1), words.t(`legend.rank-${rank}`)]);
  return swatches(items, words.t('legend.rank-note'), words);
}

// A ramp with its ends' words.
function ramp(low, high) {
  const bar = document.createElement('div');
  bar.className = 'legend';
  bar.innerHTML = `<span class="ramp" style="background: linear-gradient(to right, ${RAMP.join(', ')})"></span>
    <span class="ends"><span></span><span></span></span>`;
  const [left, right] = bar.querySelectorAll('.ends span');
  left.textContent = low;
  right.textContent = high;
  return bar;
}

// The case classes (`names`: the gallery's, as the WebAssembly names them).
function classes(names, words) {
  const list = document.createElement('div');
  list.className = 'legend classes';
  names.forEach((name, k) => {
    const item = document.createElement('span');
    item.title = words.t('legend.class', { class: k, name });
    item.innerHTML = `<i style="background: ${classColor(k)}"></i>`;
    item.append(words.number(k));
    list.append(item);
  });
  return list;
}

/** The key for the view `state` shows, or null: triangle colouring first, then the cells' classes. */
export function colorKey(state, classNames, words) {
  switch (state['color-by']) {
    case 'area': return ramp(words.number(0), words.t('legend.area-high'));
    case 'quality': return ramp(words.t('legend.sliver'), words.t('legend.equilateral'));
    case 'case': return classes(classNames, words);
    case 'level': return levels(words);
    case 'rank': return state.method === 'dual_contouring' && !state.lod ? ranks(words) : null;
    // The views colour the square root of the error's share of half a cell: the middle is ⅛ cell.
    case 'error': return ramp(words.t('legend.error-low'), words.t('legend.error-high'));
    default: return state.grid === 'cells' ? classes(classNames, words) : null;
  }
}

/** The key for the field slice: log-scaled, iso in the middle. */
export function sliceKey(words) {
  return ramp(words.t('legend.slice-low'), words.t('legend.slice-high'));
}
