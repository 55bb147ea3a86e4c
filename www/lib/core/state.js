// A figure's settings as the parameter table defines them, by canonical name: the values in effect,
// the ones the renderer holds, the ones changed since the last frame, and which the author gave.
// Attributes are read through the table's reader (`parser`, handed in by the element: read.js, and the
// wasm's parser for the kinds with grammars of their own) and written back, under the spelling the
// author used, without being taken in again.

export class FigureState {
  /** The values in effect. */
  state;
  /** The values the renderer holds. */
  applied;
  /** Names changed since the renderer last took them. */
  changed = new Set();
  /** Names the author or the person set (the others follow the adapter's defaults). */
  given = new Set();
  #element;
  #parser;
  #reflecting = false;

  /**
   * `rows`: the figure's table (a Rows); `parser(spelling, text)` reads a value or throws an Error
   * saying what is accepted.
   */
  constructor(element, rows, parser) {
    this.#element = element;
    this.rows = rows;
    this.#parser = parser;
    this.state = rows.defaults();
    this.applied = { ...this.state };
  }

  /** True while a value is being written back to its attribute (its callback must not take it in). */
  get reflecting() { return this.#reflecting; }

  /**
   * Reads an attribute's text given under `spelling` (a name or an alias): `{ value }`, or
   * `{ message, said }`: the English message saying what is wrong and what is kept, and what it is
   * made of (for `FigureState.refused`).
   */
  parse(name, text, spelling = name) {
    try {
      return { value: this.read(spelling, text) };
    } catch (error) {
      const kept = this.format(name);
      return { message: `${spelling}="${text}": ${error.message}; keeping ${kept}`, said: { spelling, text, error, kept } };
    }
  }

  /** The message of a refused attribute (`said`, from `parse`) in the reader's language (`words`). */
  static refused(words, { spelling, text, error, kept }) {
    return words.t('refused.keeping', { spelling, text, message: words.refusal(error), kept });
  }

  /** Reads `text` given under `spelling`: the value, or throws an Error saying what is accepted. */
  read(spelling, text) {
    return this.#parser(spelling, text);
  }

  /** The value in effect, as an attribute would show it. */
  format(name) {
    const value = this.state[name];
    return typeof value === 'string' ? `"${value}"` : String(value);
  }

  /** The spellings of `name` the element carries as attributes now. */
  present(name) {
    return this.rows.spellingsOf(name).filter((spelling) => this.#element.hasAttribute(spelling));
  }

  /**
   * Writes a value to its attribute without taking it in again: under each spelling the element
   * carries, or the canonical name where it carries none.
   */
  reflect(name, value = this.state[name]) {
    this.#reflecting = true;
    try {
      const spellings = this.present(name);
      for (const spelling of spellings.length ? spellings : [name]) this.#element.setAttribute(spelling, String(value));
    } finally {
      this.#reflecting = false;
    }
  }
}
