// A figure's frames whose mesh the page's mesher worker makes: before such a frame the scene advances
// and the view's mesh job goes to the worker; the frame is drawn, without a further step, once the mesh
// is back. Meanwhile the page's thread is free, and the time that passes is owed to the next step. A
// figure whose meshes come from compute passes, whose scene another figure or a gesture drives, or on a
// page without the worker, draws at once.

import { meshWorker } from '../engine/meshers.js';
import { within } from '../engine/wasm.js';

// The longest step the animation takes at once, in seconds (as a slow frame's).
const MAX_STEP = 0.1;

const sameJob = (a, b) => a !== undefined && b !== undefined && a.length === b.length && a.every((x, i) => x === b[i]);

export class MeshElsewhere {
  #element;
  #request = null;
  // Time that passed while a mesh was made, taken in the next step.
  #owed = 0;
  // The worker failed this figure once: it meshes on the page's thread from then on.
  #failed = false;
  #requestFrame;

  /** `requestFrame()` asks the page for a frame once a mesh is back. */
  constructor(element, requestFrame) {
    this.#element = element;
    this.#requestFrame = requestFrame;
  }

  /**
   * The step (in seconds) to draw `view`'s next frame with after advancing it by `dt`, or null while
   * its mesh is being made elsewhere (the frame is drawn on a later animation frame). `here`: the scene
   * is driven from outside (a sync leader's spheres, a drag), so the frame meshes on the page's thread.
   * `longest`: the most time one step moves the spheres on, however much was owed while the worker was busy.
   */
  step(view, dt, here = false, longest = MAX_STEP) {
    const request = this.#request;
    if (request?.busy) {
      this.#owed = Math.min(this.#owed + dt, longest);
      return null;
    }
    if (request) {
      this.#request = null;
      const job = within(this.#element, () => view.cpu_job(false));
      if (request.mesh && sameJob(job, request.job)) {
        within(this.#element, () => view.give_mesh(request.job, ...request.mesh));
        return 0;
      }
      // The job changed while it was meshed (a setting, spheres placed): this frame meshes here.
      here = true;
    }
    const step = Math.min(this.#owed + dt, longest);
    this.#owed = 0;
    // Every frame waits for the worker to start, the page's first too: it is handed the page's compiled
    // wasm, so it starts within tens of milliseconds, while a first mesh takes the page's thread for as
    // long on a small machine.
    const worker = this.#failed || here ? null : meshWorker(true);
    if (!worker) return step;
    within(this.#element, () => view.advance(step));
    const job = within(this.#element, () => view.cpu_job(false));
    if (!job) return 0;
    const made = { job, busy: true, mesh: null };
    this.#request = made;
    worker.mesh(job).then((mesh) => { made.mesh = mesh; }, (error) => {
      this.#failed = true;
      console.warn(`<metaballs-view> meshes on the page's thread: ${error.message}`);
    }).finally(() => {
      made.busy = false;
      this.#requestFrame();
    });
    return null;
  }

  /** The view is gone (released, lost): a mesh being made for it is dropped. */
  forget() {
    this.#request = null;
    this.#owed = 0;
  }
}
