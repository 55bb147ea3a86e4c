// What a figure on a phone must be, measured in the page (each function runs there, by page.evaluate):
// nothing of a figure drawn past its box, the picture mostly uncovered, controls a finger can hit, and
// the contrast of every text against what is behind it.

/**
 * For figure `host`: `{ past, uncovered, small, figure }`. `past` lists the shadow root's elements seen
 * outside the figure's box (each clipped by its scrolling ancestors first); `uncovered` is the share
 * of the picture's points where the canvas is what a finger or the eye meets (sampled on a 24 × 16
 * grid); `small` lists the controls shown smaller than 24 × 24 CSS px.
 */
export function figureLayout(host) {
  const root = host.shadowRoot;
  const box = host.getBoundingClientRect();
  const shown = (element) => {
    for (let e = element; e && e !== host; e = e.parentElement ?? e.getRootNode().host) {
      const style = getComputedStyle(e);
      if (style.display === 'none' || style.visibility === 'hidden') return false;
    }
    return true;
  };
  // The part of `element` its ancestors up to the host let show (they clip where they scroll or hide).
  const visible = (element) => {
    let { left, top, right, bottom } = element.getBoundingClientRect();
    for (let e = element.parentElement ?? element.getRootNode().host; e && e !== host; e = e.parentElement ?? e.getRootNode().host) {
      const style = getComputedStyle(e);
      if (style.overflowX !== 'visible' || style.overflowY !== 'visible') {
        const r = e.getBoundingClientRect();
        left = Math.max(left, r.left);
        top = Math.max(top, r.top);
        right = Math.min(right, r.right);
        bottom = Math.min(bottom, r.bottom);
      }
    }
    return { left, top, right, bottom, width: right - left, height: bottom - top };
  };
  const name = (e) => `${e.tagName.toLowerCase()}${e.id ? `#${e.id}` : ''}${typeof e.className === 'string' && e.className ? `.${e.className.split(' ').join('.')}` : ''}`;
  const past = [];
  const small = [];
  for (const element of root.querySelectorAll('*')) {
    if (['STYLE', 'SCRIPT'].includes(element.tagName) || !shown(element)) continue;
    const r = visible(element);
    if (r.width <= 0.5 || r.height <= 0.5) continue;
    if (r.left < box.left - 0.5 || r.top < box.top - 0.5 || r.right > box.right + 0.5 || r.bottom > box.bottom + 0.5) {
      past.push(`${name(element)} at ${Math.round(r.left - box.left)},${Math.round(r.top - box.top)} `
        + `${Math.round(r.width)}×${Math.round(r.height)} in ${Math.round(box.width)}×${Math.round(box.height)}`);
    }
    const control = element.matches('button, select, summary, input:not([type=hidden]):not([type=file]), [tabindex]:not(canvas):not(section):not(div)');
    if (control && r.width > 0 && r.height > 0) {
      const whole = element.getBoundingClientRect();
      if (whole.width < 23.5 || whole.height < 23.5) small.push(`${name(element)} ${Math.round(whole.width)}×${Math.round(whole.height)} "${(element.textContent ?? '').trim().slice(0, 20)}"`);
    }
  }
  const canvas = root.querySelector('canvas');
  const c = canvas.getBoundingClientRect();
  let seen = 0;
  let points = 0;
  for (let j = 0; j < 16; j += 1) {
    for (let i = 0; i < 24; i += 1) {
      const x = c.left + ((i + 0.5) * c.width) / 24;
      const y = c.top + ((j + 0.5) * c.height) / 16;
      if (y < 0 || y >= innerHeight) continue;
      points += 1;
      if (root.elementFromPoint(x, y) === canvas) seen += 1;
    }
  }
  return { past, small, uncovered: points ? seen / points : 1, points, figure: `${Math.round(box.width)}×${Math.round(box.height)}` };
}

/**
 * Every text the shadow root of `host` shows, with its contrast against what is behind it: the
 * backgrounds of its ancestors laid over each other (each with the opacity of it and its ancestors),
 * and where they let the picture through, the worst of every grey behind them (the picture can be
 * anything). SVG text is drawn in its fill. Returns the texts below 4.5:1 (3:1 when large).
 */
export function figureContrast(host) {
  const parse = (text) => {
    const m = text.match(/rgba?\(([^)]+)\)/);
    if (!m) return [0, 0, 0, 0];
    const parts = m[1].split(/[\s,/]+/).filter(Boolean).map(Number);
    return [parts[0], parts[1], parts[2], parts.length > 3 ? parts[3] : 1];
  };
  const over = (top, under) => {
    const a = top[3];
    return [0, 1, 2].map((k) => top[k] * a + under[k] * (1 - a)).concat(1);
  };
  const luminance = ([r, g, b]) => {
    const l = (v) => { const s = v / 255; return s <= 0.04045 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4; };
    return 0.2126 * l(r) + 0.7152 * l(g) + 0.0722 * l(b);
  };
  const ratio = (a, b) => {
    const [x, y] = [luminance(a), luminance(b)].sort((p, q) => q - p);
    return (x + 0.05) / (y + 0.05);
  };
  const root = host.shadowRoot;
  const failing = [];
  let texts = 0;
  for (const element of root.querySelectorAll('*')) {
    const own = [...element.childNodes].some((n) => n.nodeType === 3 && n.textContent.trim());
    if (!own || ['STYLE', 'SCRIPT', 'OPTION'].includes(element.tagName)) continue;
    const style = getComputedStyle(element);
    if (style.display === 'none' || style.visibility === 'hidden' || element.closest('[hidden]')) continue;
    if (element.getClientRects().length === 0 || element.closest('.visually-hidden, [aria-hidden="true"]')) continue;
    texts += 1;
    // The backgrounds from the text out to the host, innermost first, and the opacity of them all.
    // (The host's own background is under the picture, so it is not one of them.)
    const layers = [];
    for (let e = element; e && e !== host; e = e.parentElement ?? e.getRootNode().host) {
      const s = getComputedStyle(e);
      layers.push({ background: parse(s.backgroundColor), opacity: Number(s.opacity) });
    }
    // A layer shows through its own opacity and every enclosing layer's; the text through them all.
    let through = 1;
    const visible = [];
    for (let k = layers.length - 1; k >= 0; k -= 1) {
      through *= layers[k].opacity;
      const [r, g, b, a] = layers[k].background;
      visible.unshift([r, g, b, a * through]);
    }
    const opacity = through;
    const color = parse(element instanceof SVGElement ? style.fill : style.color);
    color[3] *= opacity;
    let worst = Infinity;
    for (let grey = 0; grey <= 255; grey += 15) {
      const ground = visible.filter((bg) => bg[3] > 0).reduceRight((under, top) => over(top, under), [grey, grey, grey, 1]);
      worst = Math.min(worst, ratio(over(color, ground), ground));
    }
    const size = parseFloat(style.fontSize);
    const large = size >= 24 || (size >= 18.66 && Number(style.fontWeight) >= 700);
    if (worst < (large ? 3 : 4.5) - 0.005) {
      failing.push(`${element.tagName.toLowerCase()}${element.id ? `#${element.id}` : ''} "${element.textContent.trim().slice(0, 30)}" ${style.color}: ${worst.toFixed(2)}`);
    }
  }
  return { failing, texts };
}
