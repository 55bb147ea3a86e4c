// One figure's rows of the parameter table, by every spelling: the canonical names, the short names of
// links and the older spellings still accepted (aliases), each row's property, default and kind. Both
// elements read their tables (lib/attributes.js, written from Rust by `metaballs manifest`) through it;
// nothing here names a setting.

const camel = (text) => text.replace(/[-_]([a-z])/g, (_, c) => c.toUpperCase());

// Each spelling of a parameter: its name, its short name in links and its older spellings.
const spellings = (row) => [...new Set([row.name, row.url, ...(row.aliases ?? [])])];

export class Rows {
  /** `rows`: a table of lib/attributes.js. */
  constructor(rows) {
    this.rows = rows;
    /** Canonical attribute names, in the table's order. */
    this.names = rows.map((row) => row.name);
    this.#bySpelling = new Map();
    for (const row of rows) {
      for (const spelling of spellings(row)) this.#bySpelling.set(spelling, row);
    }
    /** Every spelling an attribute may be given under. */
    this.spellings = [...this.#bySpelling.keys()];
    /** Attributes of plain text (a description, a URL): taken as written. */
    this.textNames = new Set(rows.filter((p) => p.kind === 'text').map((p) => p.name));
    // Property spellings kept from earlier versions (`color_by`, `balls`): each spelling of a row and
    // its Python name read as a property, where it differs from the row's own property. Not the short
    // names of links (`res`, `aa`): they were never properties.
    this.oldProperties = new Map();
    for (const row of rows) {
      for (const spelling of [row.name, ...(row.aliases ?? []), row.python]) {
        const property = spelling.replace(/-([a-z])/g, (_, c) => c.toUpperCase());
        if (property !== row.property) this.oldProperties.set(property, row.name);
      }
    }
    for (const row of rows) this.oldProperties.delete(row.property);
  }

  #bySpelling;

  /** The row for a name or any of its spellings, or undefined. */
  rowOf(spelling) { return this.#bySpelling.get(spelling); }

  /** The canonical name of a spelling (itself when unknown). */
  canonical(spelling) { return this.#bySpelling.get(spelling)?.name ?? spelling; }

  /** The spellings of one parameter: its name first, then its short name and older spellings. */
  spellingsOf(name) {
    const row = this.#bySpelling.get(name);
    return row ? spellings(row) : [name];
  }

  /** The element's property for a parameter (`max-pixel-ratio` → `maxPixelRatio`). */
  propertyName(spelling) { return this.#bySpelling.get(spelling)?.property ?? camel(spelling); }

  /**
   * The id of a parameter's control in the panel: the name it had in earlier versions (its Python name
   * where that is an older spelling or its short name, else its first older spelling, else its name),
   * so that styles and scripts written against earlier panels still find it.
   */
  controlId(name) {
    const row = this.#bySpelling.get(name);
    if (!row) return name;
    const aliases = row.aliases ?? [];
    if (aliases.includes(row.python)) return row.python;
    if (aliases.length) return aliases[0];
    return row.url === row.python ? row.python : row.name;
  }

  /** The default values of every parameter, typed. */
  defaults() { return Object.fromEntries(this.rows.map((p) => [p.name, p.value])); }
}
