// A figure's scene in and out: the spheres after an edit by hand (into the count and the `balls` link
// form), scene documents saved and loaded (from text, a picked file or a dropped one), the mesh as a
// file and pictures. The element keeps its state; this works through the hooks it passes.

import { wasmModule } from './engine.js';
import { download, meshBlob, pngOf, readSceneFile } from './scene-files.js';

export class SceneIO {
  #hooks;

  /**
   * `hooks`: view() → the wasm view or null; state() → the element's values; set(name, value) (a
   * change, applied on the next frame); adopt(name, value) (a value the renderer already holds);
   * apply() (push pending changes into the renderer now); restoreLater(packed) (spheres for a view not
   * started yet); changed() (redraw); editor (the SphereEditor); canvas; ready() (resolves after a frame of the current state is drawn);
   * notice(text, ms); emit(type, detail).
   */
  constructor(hooks) {
    this.#hooks = hooks;
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
    this.#hooks.adopt('balls', wasmModule().spheres_text(packed));
  }

  /** Hand-placed spheres from the `balls` attribute replace the seeded layout. */
  applyBalls(text) {
    if (!text) return;
    const view = this.#hooks.view();
    try {
      view.set_spheres(wasmModule().parse_spheres_text(text));
      this.#hooks.adopt('spheres', view.spheres().length / 7);
      this.#hooks.editor.reset();
    } catch (error) {
      this.#hooks.notice(`balls: ${error.message}`);
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
    this.#hooks.editor.reset();
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
      this.#hooks.notice(`Loaded ${file.name}: ${this.#hooks.state().spheres} spheres`, 4000);
    } catch (error) {
      this.#hooks.notice(`${file.name} was not loaded: ${error.message}. The scene is unchanged.`);
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
    this.#hooks.notice(`Exported ${format.toUpperCase()}: ${(bytes.length / 1e6).toFixed(2)} MB`, 3000);
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
