// What both figure elements do with their table: a property per setting, and an attribute's text read
// into the figure's context (checked by the table's reader, refused with a notice and an event).

/**
 * Gives `Class` a property per row of `rows` (and the property spellings of earlier versions): reading
 * gives the value in effect (`stateOf(element)[name]`), writing goes through the attribute's checks.
 */
export function defineSettingProperties(Class, rows, stateOf) {
  const properties = [...rows.names.map((name) => [rows.propertyName(name), name]), ...rows.oldProperties];
  for (const [property, name] of properties) {
    if (Object.hasOwn(Class.prototype, property)) continue;
    Object.defineProperty(Class.prototype, property, {
      get() { return stateOf(this)[name]; },
      set(value) { this.setAttribute(name, String(value)); },
    });
  }
}

/**
 * Takes attribute `spelling`'s new text into figure context `ctx` (of element `tag`): a removed
 * attribute gives way to another spelling still given, else to the default; a refused value keeps the
 * one in effect, and the notice, the console and a `metaballs-error` event say why.
 */
export function takeAttribute(ctx, tag, spelling, text) {
  const settings = ctx.settings;
  if (settings.reflecting) return;
  const name = settings.rows.canonical(spelling);
  if (text === null) {
    const [other] = settings.present(name);
    if (other) {
      takeAttribute(ctx, tag, other, ctx.element.getAttribute(other));
      return;
    }
    settings.given.delete(name);
    ctx.accept(name, settings.rows.rowOf(name).value);
    return;
  }
  const { value, message, said } = settings.parse(name, text, spelling);
  if (message) {
    console.warn(`<${tag}> ${message}`);
    ctx.notice(settings.constructor.refused(ctx.words, said));
    ctx.emit('metaballs-error', { message, attribute: spelling });
    return;
  }
  settings.given.add(name);
  ctx.accept(name, value);
}

/** A function showing `text` in the box with id `id` in `root` for `ms` milliseconds (a later call replaces it). */
export function flasher(root) {
  const timers = {};
  return (id, text, ms) => {
    const box = root.getElementById(id);
    box.textContent = text;
    box.hidden = false;
    clearTimeout(timers[id]);
    timers[id] = setTimeout(() => { box.hidden = true; }, ms);
  };
}

/**
 * The element's custom states (ElementInternals, styled as `:state(name)`): `set(name, on)`, `has(name)`
 * and `supported`. Where the browser lacks them (or takes only `--` names, as before Chromium 125), they
 * are not set and the figure keeps its layout for every size.
 */
export function customStates(element) {
  let states = null;
  try {
    states = element.attachInternals?.().states ?? null;
    states?.add('probe');
    states?.delete('probe');
  } catch {
    states = null;
  }
  return {
    supported: Boolean(states),
    has: (name) => Boolean(states?.has(name)),
    set(name, on) {
      if (!states) return;
      if (on) states.add(name);
      else states.delete(name);
    },
  };
}
