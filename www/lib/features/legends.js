// Colour keys for the teaching views, drawn with the colours shaders/draw/views/ uses: the ramp (area,
// shape, field slice), the 15 case classes and the levels of detail.

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

function levels() {
  const list = document.createElement('div');
  list.className = 'legend classes';
  for (let k = 0; k < 9; k += 1) {
    const item = document.createElement('span');
    item.title = k ? `level ${k}: cells ${2 ** k}× the finest` : 'level 0: the finest cells';
    item.innerHTML = `<i style="background: ${levelColor(k)}"></i>${k}`;
    list.append(item);
  }
  const note = document.createElement('span');
  note.textContent = 'finest first · paler: transition cells';
  list.append(note);
  return list;
}

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

function classes(names) {
  const list = document.createElement('div');
  list.className = 'legend classes';
  names.forEach((name, k) => {
    const item = document.createElement('span');
    item.title = `class ${k}: ${name}`;
    item.innerHTML = `<i style="background: ${classColor(k)}"></i>${k}`;
    list.append(item);
  });
  return list;
}

/** The key for the view `state` shows, or null: triangle colouring first, then the cells' classes. */
export function colorKey(state, classNames) {
  switch (state['color-by']) {
    case 'area': return ramp('0', '½ cell face');
    case 'quality': return ramp('sliver', 'equilateral');
    case 'case': return classes(classNames);
    case 'level': return levels();
    // The views colour the square root of the error's share of half a cell: the middle is ⅛ cell.
    case 'error': return ramp('on the surface', '½ cell away (middle: ⅛)');
    default: return state.grid === 'cells' ? classes(classNames) : null;
  }
}

/** The key for the field slice: log-scaled, iso in the middle. */
export function sliceKey() {
  return ramp('f = iso ÷ 16', 'iso × 16');
}
