// Camera gestures scoped to one element: drag to orbit (mouse, pen, touch), pinch or wheel to zoom,
// keys while it has focus, double-click to reset, click (a press that does not move) to pick. The
// wheel zooms only while the figure has focus or with Ctrl held; otherwise it scrolls the page and a
// one-line hint says how to zoom. Where `actions.grab` takes a press (a sphere under it, in edit
// mode), the drag moves what it grabbed instead of the camera; on touch, a long press grabs (or, on
// empty space, holds: the editor adds a sphere there). The camera keeps its settings within their
// ranges (the parameter table's).

/**
 * Wires gestures on `surface` (the canvas) and keys on `host`. `camera` has get() → {yaw, pitch,
 * distance} and set(partial), which keeps each within its range; `actions` has togglePause, reseed, resetView, step, hint(key) (a message's key),
 * pick(x, y, event) (CSS pixels from the canvas's top left) and deselect, and for editing grab(x, y)
 * → a drag {move(x, y), end()} or null, hold(x, y) (a long touch on empty space) → true when it did
 * something, hover(x, y), leave(), wheel(deltaY) → true when it used the wheel, remove(), freeze() and charge().
 */
export function wireCameraInput(host, surface, camera, actions) {
  const focused = () => host.matches(':focus-within');
  const orbit = (dYaw, dPitch) => {
    const { yaw, pitch } = camera.get();
    camera.set({
      yaw: ((((yaw + dYaw + 180) % 360) + 360) % 360) - 180,
      pitch: pitch + dPitch,
    });
  };
  const zoom = (factor) => {
    const { distance } = camera.get();
    camera.set({ distance: distance * factor });
  };

  // One-finger vertical swipes scroll the page unless the figure has focus.
  const touchAction = () => { surface.style.touchAction = focused() ? 'none' : 'pan-y'; };
  host.addEventListener('focusin', touchAction);
  host.addEventListener('focusout', touchAction);
  touchAction();

  const pointers = new Map();
  let pinchSpan = 0;
  // A press that stays within a few pixels and ends soon is a click, not a drag.
  let press = null;
  // What a press grabbed (a sphere), and the long-press timer that grabs on touch.
  let drag = null;
  let longPress = 0;
  const LONG_PRESS_MS = 450;
  const span = () => {
    const [a, b] = [...pointers.values()];
    return Math.hypot(a.x - b.x, a.y - b.y);
  };
  surface.addEventListener('pointerdown', (e) => {
    try {
      surface.setPointerCapture?.(e.pointerId);
    } catch { /* a pointer the browser no longer tracks */ }
    pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
    if (pointers.size === 2) pinchSpan = span();
    press = pointers.size === 1 && e.button === 0
      ? { x: e.clientX, y: e.clientY, offsetX: e.offsetX, offsetY: e.offsetY, time: e.timeStamp } : null;
    clearTimeout(longPress);
    drag = null;
    if (press && actions.grab) {
      if (e.pointerType === 'touch') {
        const { offsetX, offsetY } = e;
        longPress = setTimeout(() => {
          if (pointers.size === 1 && press) {
            // On a sphere: grab it. On empty space: add one there (if editing), and drag that.
            drag = actions.grab(offsetX, offsetY);
            const added = !drag && actions.hold?.(offsetX, offsetY);
            if (added) drag = actions.grab(offsetX, offsetY);
            if (drag || added) press = null;
          }
        }, LONG_PRESS_MS);
      } else if (!e.shiftKey) {
        drag = actions.grab(e.offsetX, e.offsetY);
      }
    }
  });
  surface.addEventListener('pointermove', (e) => {
    const p = pointers.get(e.pointerId);
    if (!p) {
      if (e.pointerType !== 'touch') actions.hover?.(e.offsetX, e.offsetY);
      return;
    }
    if (drag && pointers.size === 1) {
      drag.move(e.offsetX, e.offsetY);
      return;
    }
    if (press && Math.hypot(e.clientX - press.x, e.clientY - press.y) >= 4) clearTimeout(longPress);
    const dx = e.clientX - p.x;
    const dy = e.clientY - p.y;
    p.x = e.clientX;
    p.y = e.clientY;
    if (pointers.size === 1) {
      orbit(-dx * 0.3, dy * 0.3);
    } else if (pointers.size === 2) {
      const now = span();
      if (pinchSpan > 0 && now > 0) zoom(pinchSpan / now);
      pinchSpan = now;
    }
  });
  const release = (e) => {
    clearTimeout(longPress);
    const dragged = drag && Math.hypot(e.clientX - (press?.x ?? -1e9), e.clientY - (press?.y ?? -1e9)) >= 4;
    if (drag) {
      drag.end();
      drag = null;
    }
    if (press && !dragged && e.type === 'pointerup' && pointers.size === 1
      && Math.hypot(e.clientX - press.x, e.clientY - press.y) < 4 && e.timeStamp - press.time < 500) {
      actions.pick(press.offsetX, press.offsetY, e);
    }
    press = null;
    pointers.delete(e.pointerId);
    pinchSpan = pointers.size === 2 ? span() : 0;
  };
  surface.addEventListener('pointerup', release);
  surface.addEventListener('pointercancel', release);
  surface.addEventListener('pointerleave', () => actions.leave?.());
  surface.addEventListener('wheel', (e) => {
    if (!focused() && !e.ctrlKey) {
      actions.hint('figure.wheel-hint');
      return;
    }
    e.preventDefault();
    const deltaY = e.deltaY * (e.deltaMode === 1 ? 33 : 1);
    if (actions.wheel?.(deltaY)) return;
    zoom(Math.exp(deltaY * 0.0015));
  }, { passive: false });
  surface.addEventListener('dblclick', () => actions.resetView());

  host.addEventListener('keydown', (e) => {
    // Keys go to the panel's controls while one of them has focus.
    const target = e.composedPath()[0];
    if (target instanceof HTMLInputElement || target instanceof HTMLButtonElement
      || target instanceof HTMLSelectElement || target?.tagName === 'SUMMARY') return;
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    const step = e.shiftKey ? 15 : 5;
    const keys = {
      ArrowLeft: () => orbit(-step, 0), a: () => orbit(-step, 0),
      ArrowRight: () => orbit(step, 0), d: () => orbit(step, 0),
      ArrowUp: () => orbit(0, step), w: () => orbit(0, step),
      ArrowDown: () => orbit(0, -step), s: () => orbit(0, -step),
      '+': () => zoom(0.9), '=': () => zoom(0.9),
      '-': () => zoom(1 / 0.9), _: () => zoom(1 / 0.9),
      p: actions.togglePause, ' ': actions.togglePause,
      n: actions.reseed, r: actions.resetView, '.': actions.step, Escape: actions.deselect,
      ...(actions.remove ? { Delete: actions.remove, Backspace: actions.remove, f: actions.freeze, n: actions.charge } : {}),
    };
    const action = keys[e.key.length === 1 ? e.key.toLowerCase() : e.key];
    if (action) {
      e.preventDefault();
      action();
    }
  });
}
