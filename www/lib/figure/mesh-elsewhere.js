// A figure's frames whose mesh the page's mesher worker makes, pipelined: while frame N is drawn, the
// scene has already moved on to frame N + 1 and the worker is meshing it, so a figure draws on every
// animation frame whose mesh is back, one step behind the scene at most, and the page's thread only
// uploads and draws. Each step moves the spheres on by the time that passed since the last one (what
// passed while the worker was busy included). A still figure (paused, a step asked for, a setting
// changed) meshes exactly its state and draws it once back. A figure whose meshes come from compute
// passes, whose scene another figure or a gesture drives, or on a page without the worker, draws at
// once.

import { meshWorker } from '../engine/meshers.js';
import { within } from '../engine/wasm.js';

// The longest step the animation takes at once, in seconds (as a slow frame's).
const MAX_STEP = 0.1;

const sameJob = (a, b) => a != null && b != null && a.length === b.length && a.every((x, i) => x === b[i]);

export class MeshElsewhere {
  #element;
  #request = null;
  // Time that passed since the scene last moved, taken in its next step.
  #owed = 0;
  // The worker failed this figure once: it meshes on the page's thread from then on.
  #failed = false;
  // The frame being drawn has a mesh from the worker: the next one is meshed there too.
  #given = false;
  // The spheres of the frame on screen while the scene is a step ahead of it (else null).
  #shown = null;
  // The job of the mesh from the worker that the renderer holds: a still frame of the same job (the
  // camera turned, a view changed) draws it again at once, without meshing.
  #held = null;
  #requestFrame;

  /** `requestFrame()` asks the page for a frame once a mesh is back. */
  constructor(element, requestFrame) {
    this.#element = element;
    this.#requestFrame = requestFrame;
  }

  /** True while a mesh is being made, or is back and not drawn yet: the figure has a frame to draw. */
  get pending() {
    return this.#request !== null;
  }

  /** The spheres of the frame on screen (packed as `View.spheres`): the view's, unless it is a step ahead. */
  shownSpheres(view) {
    return this.#shown ?? view.spheres();
  }

  /**
   * Before a frame: the step (in seconds) to draw `view`'s frame with, `dt` having passed, or null
   * while its mesh is being made elsewhere (the frame is drawn on a later animation frame). A mesh
   * back from the worker is drawn as it is (step 0) and the time is owed to `ahead`. `here`: the
   * scene is driven from outside (a sync leader's spheres, a drag), so the frame meshes on the page's
   * thread. `longest`: the most time one step moves the spheres on, however much was owed.
   */
  step(view, dt, here = false, longest = MAX_STEP) {
    const request = this.#request;
    this.#owed = Math.min(this.#owed + dt, longest);
    this.#given = false;
    if (request?.busy) return null;
    this.#shown = null;
    if (request) {
      this.#request = null;
      const job = within(this.#element, () => view.cpu_job(false));
      if (request.mesh && sameJob(job, request.job)) {
        within(this.#element, () => view.give_mesh(request.job, ...request.mesh));
        this.#given = true;
        this.#held = request.job;
        return 0;
      }
      // The job changed while it was meshed (a setting, spheres placed): this frame meshes here.
      here = true;
    }
    const step = this.#owed;
    this.#owed = 0;
    // Every frame waits for the worker to start, the page's first too: it is handed the page's compiled
    // wasm, so it starts within tens of milliseconds, while a first mesh takes the page's thread for as
    // long on a small machine.
    const worker = this.#failed || here ? null : meshWorker(true);
    if (!worker) {
      this.#held = null;
      return step;
    }
    within(this.#element, () => view.advance(step));
    const job = within(this.#element, () => view.cpu_job(false));
    if (sameJob(job, this.#held)) return 0;
    return this.#send(worker, job) ? null : 0;
  }

  /**
   * After a frame of an animating figure is drawn: the scene takes its next step (the time owed, at
   * most `longest`) and the worker meshes it while this frame shows. Only after a frame whose mesh
   * came from the worker: one meshed on the page's thread or on the GPU takes its steps as it draws.
   */
  ahead(view, longest = MAX_STEP) {
    if (!this.#given || this.#request || this.#failed) return;
    this.#given = false;
    const worker = meshWorker(false);
    if (!worker) return;
    const step = Math.min(this.#owed, longest);
    this.#owed = 0;
    this.#shown = within(this.#element, () => view.spheres());
    within(this.#element, () => view.advance(step));
    this.#send(worker, within(this.#element, () => view.cpu_job(false)));
  }

  // Sends the view's job (`cpu_job`) to the worker; false when the view meshes on the GPU (no job).
  #send(worker, job) {
    if (!job) return false;
    const made = { job, busy: true, mesh: null };
    this.#request = made;
    worker.mesh(job).then((mesh) => { made.mesh = mesh; }, (error) => {
      this.#failed = true;
      console.warn(`<metaballs-view> meshes on the page's thread: ${error.message}`);
    }).finally(() => {
      made.busy = false;
      this.#requestFrame();
    });
    return true;
  }

  /** The view is gone (released, lost): a mesh being made for it is dropped. */
  forget() {
    this.#request = null;
    this.#given = false;
    this.#shown = null;
    this.#held = null;
    this.#owed = 0;
  }
}
