// A figure's scene in and out: the spheres placed by hand (from their attribute, and after an edit by
// hand into the count and the link form), scene documents saved and loaded (from text, a picked file
// or a dropped one), the mesh as a file and pictures, and the panel's buttons for them. File names,
// file formats' names and what the files hold are the same in every language; what the figure says of
// them is its reader's.

import { nameOfKind } from '../core/table.js';
import { PICTURE_FRAMES } from '../core/redraw.js';
import { wasmModule } from '../engine/wasm.js';
import { pngOf } from '../figure/look.js';
import { download } from '../core/download.js';
import { meshBlob, readSceneFile, wireDrop } from './files.js';
import { listedControls } from './panel.js';
import { mark } from '../i18n/words.js';

// The setting that holds spheres placed by hand, as text.
const SPHERES = nameOfKind('spheres');

/** The spheres (as `sphereList` gives them: center, radius, velocity, charge) as their attribute writes
 * them: a subtracting sphere (charge −1) with a negative radius. */
export function spheresText(list) {
  return list.map((s) => [...s.center, (s.charge ?? 1) < 0 ? -s.radius : s.radius, ...(s.velocity ?? [])].join(',')).join(';');
}

export class SceneFiles {
  static attributes = [SPHERES, 'spheres', 'seed'];
  #ctx;
  #hooks;

  constructor(ctx) {
    this.#ctx = ctx;
    this.#hooks = {
      view: () => ctx.view,
      state: () => ctx.state,
      set: (name, value) => ctx.set(name, value),
      adopt: (name, value) => ctx.adopt(name, value),
      apply: () => ctx.frames.apply(),
      restoreLater: (packed) => { ctx.frames.savedSpheres = packed; },
      changed: () => ctx.redraw(PICTURE_FRAMES),
      canvas: ctx.canvas,
      ready: () => ctx.frames.nextFrame(),
      notice: (text, ms) => ctx.notice(text, ms),
      emit: (type, detail) => ctx.emit(type, detail),
    };
    const run = (f) => Promise.resolve().then(f).catch((error) => ctx.notice(ctx.words.refusal(error)));
    Object.assign(ctx.actions, {
      reseed: () => ctx.set('seed', 1 + Math.floor(Math.random() * 1e6)),
      saveScene: () => run(() => this.downloadScene()),
      loadScene: () => ctx.$('scene-file').click(),
      exportMesh: (format) => run(() => this.downloadMesh(format)),
      picture: (scale) => run(() => this.downloadPicture(scale)),
    });
    const file = ctx.$('scene-file');
    file.addEventListener('change', () => {
      if (file.files[0]) this.loadFile(file.files[0]);
      file.value = '';
    });
    wireDrop(ctx.element, () => ctx.state.edit || listedControls(ctx.state.controls).includes('scene'),
      (dropped) => this.loadFile(dropped));
  }

  // Spheres kept from before the renderer was let go give way to spheres the attributes now set.
  changed() { this.#ctx.frames.savedSpheres = null; }

  // A new count or layout replaces hand-placed spheres with the seeded ones.
  beforeSet(name) {
    if ((name === 'spheres' || name === 'seed') && this.#ctx.state[SPHERES]) this.#ctx.adopt(SPHERES, '');
  }

  spheresGiven(text) { this.applyBalls(text); }

  spheresEdited() { this.edited(); }

  controls() {
    const ctx = this.#ctx;
    const { actions } = ctx;
    // A button worded by messages `key` (its text; null: a format's name, `text`) and `titleKey`.
    const button = (makeButton, id, key, titleKey, onClick, text = '') => mark(makeButton(id, text, '', onClick), { text: key, title: titleKey }, ctx.words);
    return {
      seed: ({ element, makeButton, updates }) => {
        // The seed is shown as written in the link (an identifier, not a quantity).
        const value = element('span', { id: 'seed-value' });
        const seed = element('p', { className: 'seed' }, mark(element('span'), { text: 'setting.seed' }, ctx.words), ' ', value);
        updates.push((s) => { value.textContent = String(s.seed); });
        return [button(makeButton, 'reseed', 'scene.reseed', 'scene.reseed-title', actions.reseed), seed];
      },
      scene: ({ element, makeButton }) => element('span', { className: 'buttons' },
        button(makeButton, 'save-scene', 'scene.save', 'scene.save-title', actions.saveScene),
        button(makeButton, 'load-scene', 'scene.load', 'scene.load-title', actions.loadScene)),
      export: ({ element, makeButton }) => element('span', { className: 'buttons' },
        ...['stl', 'obj', 'ply'].map((f) => button(makeButton, `export-${f}`, null, `export.${f}-title`,
          () => actions.exportMesh(f), f.toUpperCase())),
        button(makeButton, 'picture', null, 'export.picture-title', () => actions.picture(1), 'PNG'),
        button(makeButton, 'picture-2x', 'export.picture-2x', 'export.picture-2x-title', () => actions.picture(2))),
    };
  }

  /** After an edit by hand: the count and the link form follow the spheres in play. */
  edited() {
    const view = this.#hooks.view();
    if (!view) return;
    this.#adoptSpheres(view.spheres());
    this.#hooks.changed();
    this.#hooks.emit('metaballs-edit', { spheres: this.list() });
  }

  #adoptSpheres(packed) {
    this.#hooks.adopt('spheres', packed.length / 7);
    this.#hooks.adopt(SPHERES, wasmModule().spheres_text(packed));
  }

  /** Hand-placed spheres from their attribute replace the seeded layout. */
  applyBalls(text) {
    if (!text) return;
    const view = this.#hooks.view();
    try {
      view.set_spheres(wasmModule().parse_spheres_text(text));
      this.#hooks.adopt('spheres', view.spheres().length / 7);
      this.#ctx.each('spheresReplaced');
    } catch (error) {
      this.#hooks.notice(`${SPHERES}: ${this.#ctx.words.refusal(error)}`);
    }
  }

  /** The spheres in play (or kept for a view being rebuilt): [{ center, radius, velocity, charge }]. */
  list(saved = null) {
    const packed = this.#hooks.view()?.spheres() ?? saved ?? [];
    const out = [];
    for (let i = 0; i + 7 <= packed.length; i += 7) {
      const r = packed[i + 3];
      out.push({ center: [...packed.slice(i, i + 3)], radius: Math.abs(r), velocity: [...packed.slice(i + 4, i + 7)], charge: r < 0 ? -1 : 1 });
    }
    return out;
  }

  /** Where sphere `index` is drawn: { x, y, radius } in CSS pixels, or null. */
  onScreen(index) {
    const at = this.#hooks.view()?.sphere_on_screen(index);
    const canvas = this.#hooks.canvas;
    const scale = canvas.width / Math.max(1, canvas.clientWidth);
    return at ? { x: at[0] / scale, y: at[1] / scale, radius: at[2] / scale } : null;
  }

  save() {
    const view = this.#hooks.view();
    if (!view) throw new Error('the figure has not started yet');
    return wasmModule().save_scene(view.spheres(), JSON.stringify(this.#hooks.state()));
  }

  /** Loads a scene document; throws with what is wrong before anything changes. */
  load(text) {
    const scene = wasmModule().load_scene(text);
    const state = this.#hooks.state();
    for (const [name, value] of Object.entries(scene.settings)) {
      if (state[name] !== value) this.#hooks.set(name, value);
    }
    this.#adoptSpheres(scene.spheres);
    this.#ctx.each('spheresReplaced');
    const view = this.#hooks.view();
    if (view) {
      // Settings first: a new seed or resolution would otherwise replace the spheres after.
      this.#hooks.apply();
      view.set_spheres(scene.spheres);
      this.#hooks.changed();
    } else {
      this.#hooks.restoreLater(scene.spheres);
    }
    this.#hooks.emit('metaballs-scene', { spheres: this.list(scene.spheres) });
  }

  /** Loads a picked or dropped file, saying in the figure what came of it. */
  async loadFile(file) {
    try {
      this.load(await readSceneFile(file));
      this.#hooks.notice(this.#ctx.t('scene.loaded', { name: file.name, count: this.#hooks.state().spheres }), 4000);
    } catch (error) {
      // What is wrong with the file: the WebAssembly's refusal in the reader's words where it has a
      // code, else as the scene's reader says it (in English).
      this.#hooks.notice(this.#ctx.t('scene.not-loaded', { name: file.name, reason: this.#ctx.words.refusal(error) }));
      this.#hooks.emit('metaballs-error', { message: error.message });
    }
  }

  downloadScene() {
    download(new Blob([this.save()], { type: 'application/json' }), 'metaballs-scene.json');
  }

  async exportMesh(format) {
    await this.#hooks.ready();
    const started = performance.now();
    const bytes = await this.#hooks.view().export_mesh(format);
    const ms = performance.now() - started;
    this.#hooks.emit('metaballs-export', { format, bytes: bytes.length, ms });
    return bytes;
  }

  async downloadMesh(format) {
    const bytes = await this.exportMesh(format);
    download(meshBlob(bytes, format), `metaballs.${format}`);
    const size = this.#ctx.words.fixed(bytes.length / 1e6, 2);
    this.#hooks.notice(this.#ctx.t('export.done', { format: format.toUpperCase(), size }), 3000);
  }

  async picture(scale) {
    await this.#hooks.ready();
    const { canvas } = this.#hooks;
    const [width, height] = [canvas.width * scale, canvas.height * scale];
    return pngOf(await this.#hooks.view().render_pixels(width, height), width, height);
  }

  async downloadPicture(scale) {
    download(await this.picture(scale), scale === 1 ? 'metaballs.png' : `metaballs@${scale}x.png`);
  }
}
