// The canvas's size in pixels: its CSS size times the pixel ratio, which follows the screen up to a cap
// and stays at 1 or less on software adapters (they shade every pixel on the CPU), and at half that
// there while the exact surface is ray cast (every pixel marches through the field).

/** Device pixels per CSS pixel drawing the exact surface on a software adapter. */
export const SOFTWARE_EXACT_RATIO = 0.5;

/** True when the settings `s` ray cast the exact surface. */
export const drawsExact = (s) => s.display === 'exact' || (s.compare ?? 'none') !== 'none';

/** Device pixels per CSS pixel for a figure whose cap is `cap`. */
export function pixelRatio(cap, software, exact = false) {
  return Math.min(devicePixelRatio, cap, software ? (exact ? SOFTWARE_EXACT_RATIO : 1) : Infinity);
}

/** [width, height] in pixels for `canvas` at `ratio`, from a ResizeObserver `entry` when there is one. */
export function canvasPixels(canvas, ratio, entry = null) {
  const box = entry?.devicePixelContentBoxSize?.[0];
  let width;
  let height;
  if (box) {
    width = (box.inlineSize * ratio) / devicePixelRatio;
    height = (box.blockSize * ratio) / devicePixelRatio;
  } else {
    const rect = canvas.getBoundingClientRect();
    width = rect.width * ratio;
    height = rect.height * ratio;
  }
  return [Math.max(1, Math.round(width)), Math.max(1, Math.round(height))];
}
