// One figure's context: what its features share instead of handing each other closures. It holds
// the element, its shadow root and canvas, its settings, the renderer's frames (set by the element),
// the actions keys and buttons run, and the features; it takes every change of a setting and tells
// the features that own it.
//
// A feature is an object made with the context. It names the settings it owns (`static attributes`,
// '*' for all) and implements the hooks it needs, each optional: the hooks are declared, each with
// what it tells a feature, in hooks.js, and the context calls no other name.

import { checkHook } from './hooks.js';
import { relabel, Words } from '../i18n/words.js';
import { languageOf } from './language.js';

export class FigureContext {
  /** The renderer's frames (a FigureFrames), set by the element. */
  frames = null;
  /** What keys and buttons do, by name; features add theirs. */
  actions = {};
  /** Shows a message in one of the shadow root's boxes for a while: flash(id, text, ms). */
  flash = () => {};
  #words = null;
  #features = [];

  /** `settings`: the figure's FigureState; `states`: the element's custom states (core/element.js). */
  constructor(element, root, settings, states = null) {
    this.element = element;
    this.states = states;
    this.root = root;
    this.canvas = root.getElementById('view');
    this.settings = settings;
    this.state = settings.state;
  }

  /** An element of the shadow root by id. */
  $(id) { return this.root.getElementById(id); }

  /** The wasm view, while a renderer is alive. */
  get view() { return this.frames?.view ?? null; }

  /** Makes feature `Feature` with this context, adds it and returns it. */
  use(Feature) {
    const feature = new Feature(this);
    this.#features.push(feature);
    return feature;
  }

  /** The feature made from class `Feature`. */
  get(Feature) { return this.#features.find((f) => f instanceof Feature); }

  /** Calls `hook(...args)` on every feature that has it. */
  each(hook, ...args) {
    checkHook(hook);
    for (const feature of this.#features) feature[hook]?.(...args);
  }

  /** The results of `hook(...args)` of every feature that has it. */
  collect(hook, ...args) {
    checkHook(hook);
    return this.#features.filter((feature) => feature[hook]).map((feature) => feature[hook](...args));
  }

  /** True when any feature's `hook(...args)` returns true. */
  some(hook, ...args) {
    checkHook(hook);
    return this.#features.some((feature) => feature[hook]?.(...args) === true);
  }

  /** Draws at least `frames` more frames, even while still. */
  redraw(frames) { this.frames?.redraw(frames); }

  /**
   * The words the figure shows, in its reader's language (a Words of i18n/words.js): until the page's
   * watch gives them (on connect), those of the language the page gives it now (an attribute refused
   * while the element upgrades is worded in it).
   */
  get words() {
    if (!this.#words) {
      const { lang, dir } = languageOf(this.element);
      this.#words = new Words(lang, dir);
    }
    return this.#words;
  }

  /** Message `key` in the reader's language, worded with `fields` (see i18n/words.js). */
  t(key, fields) { return this.words.t(key, fields); }

  /**
   * Speaks `words` from now on: the marked words of the shadow root (`data-t`, `data-t-label`,
   * `data-t-title`) are set again, the boxes run the language's way (the `rtl` state; the canvas does
   * not mirror), and every feature rewords what it shows.
   */
  speak(words) {
    this.#words = words;
    relabel(this.root, words);
    this.states?.set('rtl', words.rtl);
    this.each('language', words);
    this.redraw(1);
  }

  /** Shows a short message inside the figure. */
  notice(text, ms = 8000) { this.flash('notice', text, ms); }

  emit(type, detail) {
    this.element.dispatchEvent(new CustomEvent(type, { detail, bubbles: true, composed: true }));
  }

  /** Takes a valid value: records it, applies it to the renderer on the next frame, tells the features. */
  accept(name, value) {
    if (this.state[name] === value) return;
    if (this.some('veto', name, value)) {
      this.settings.reflect(name);
      this.each('refresh', this.state);
      return;
    }
    this.state[name] = value;
    this.settings.changed.add(name);
    for (const feature of this.#features) {
      const owned = feature.constructor.attributes ?? [];
      if (owned === '*' || owned.includes(name)) feature.changed?.(name, value);
    }
    this.#changed(name, value);
    this.redraw(0);
  }

  /** A change from inside (gestures, panel, methods): reflected to the attribute, then accepted. */
  set(name, value, share = true) {
    this.each('beforeSet', name, value);
    this.settings.reflect(name, value);
    this.settings.given.add(name);
    const before = this.state[name];
    this.accept(name, value);
    if (this.state[name] !== before) this.each('madeInside', name, this.state[name], share);
  }

  /** Takes a value that already holds in the renderer (the spheres after an edit): no setter runs. */
  adopt(name, value) {
    if (this.state[name] === value) return;
    this.state[name] = value;
    this.settings.applied[name] = value;
    this.settings.reflect(name);
    this.#changed(name, value);
  }

  /** A value the renderer refused goes back to the one it holds. */
  revert(name) {
    this.state[name] = this.settings.applied[name];
    this.settings.reflect(name);
    this.each('refresh', this.state);
  }

  #changed(name, value) {
    this.each('refresh', this.state);
    this.emit('metaballs-change', { property: this.settings.rows.propertyName(name), attribute: name, value });
  }
}
