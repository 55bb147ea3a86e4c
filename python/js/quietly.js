// Hosts differ in what their anywidget model offers: MyST's static pages throw from `off`,
// `save_changes` and `send`. Both widgets make those calls through `quietly`.

/** Runs a model call the host may not offer; says whether it ran. */
export function quietly(call) {
  try {
    call();
    return true;
  } catch {
    return false;
  }
}
