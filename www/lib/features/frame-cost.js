// How long a frame would take at a resolution and sphere count, on this adapter, from what has been
// measured so far: so that no link or slider can ask for a frame that freezes the browser without the
// person agreeing first.
//
// Work per frame grows with the blocks bounded (n³/64 per sphere) and with the surface (about n² per
// sphere); the time per unit of work comes from frames measured here, or before the first measurement
// from a cautious guess for the kind of adapter.

import { ENGLISH } from '../i18n/words.js';

/** Frames estimated longer than this need the person's confirmation. */
export const CONFIRM_ABOVE_MS = 1000;

// Guessed time of a 128³ × 16 frame before any is measured: software adapters and WebGL2 (CPU meshing
// and a software rasteriser, often) take about a tenth of a second; hardware a few milliseconds.
const GUESS_MS = { software: 100, hardware: 4 };
const REFERENCE = { resolution: 128, spheres: 16 };

/** Cells per axis a frame's work follows: the resolution, or with level of detail (whose cells follow
 * the screen) at most that of a 512³ grid, a cautious bound. */
const LOD_WORK_RESOLUTION = 512;

/** Relative work of one frame at `resolution` cells per axis with `spheres` spheres. */
export function frameWork({ resolution, spheres, lod = false }) {
  const n = lod ? Math.min(resolution, LOD_WORK_RESOLUTION) : resolution;
  return spheres * (n ** 3 / 64 + 4 * n ** 2);
}

/** A drawn frame that holds the page longer than this is measured even when the figure is still. */
const SLOW_FRAME_MS = 100;

/** Measurements the estimate takes the median of. */
const RECENT = 5;

/** A renderer's first frames build its pipelines and buffers (after a device loss, the device's
 * shaders too): their times say nothing about the settings. */
const WARM_FRAMES = 2;

export class FrameCost {
  // Milliseconds per unit of work of the newest measurements, oldest first.
  #rates = [];

  /** `software`: a software adapter (or WebGL2), for the guess before any frame is measured. */
  constructor(software) {
    this.msPerWork = (software ? GUESS_MS.software : GUESS_MS.hardware) / frameWork(REFERENCE);
    this.measured = false;
  }

  /**
   * Takes in a measured frame time for `settings`. The rate is the median of the newest few (the
   * higher middle one while they are even), so one slow frame, as when the page stalls, does not rule.
   */
  observe(settings, ms) {
    if (!(ms > 0) || !Number.isFinite(ms)) return;
    this.#rates.push(ms / frameWork(settings));
    if (this.#rates.length > RECENT) this.#rates.shift();
    const sorted = [...this.#rates].sort((a, b) => a - b);
    this.msPerWork = sorted[Math.floor(sorted.length / 2)];
    this.measured = true;
  }

  /** Estimated milliseconds per frame for `settings`. */
  estimate(settings) {
    return this.msPerWork * frameWork(settings);
  }
}

/** "about 5 s" / "about 1.4 s" for a time in milliseconds, in `words` (English by default). */
export function describeMs(ms, words = ENGLISH) {
  return words.t('guard.about-seconds', { seconds: ms >= 10_000 ? words.number(Math.round(ms / 1000), 0) : words.fixed(ms / 1000, 1) });
}

const describeSettings = (words, s) => words.t(s.lod ? 'guard.settings-lod' : 'guard.settings', {
  resolution: words.number(s.resolution, 0), count: s.spheres });

/**
 * A figure's guard against slow frames: holds its `FrameCost`, and the changes that wait for the
 * person's answer in the figure's confirmation box (`#confirm` in `root`). `apply(name, value)` makes a
 * confirmed change; `words()` gives the figure's words (English by default).
 */
export class CostGuard {
  // The settings the question shown is about: `{ current, next }`, or null.
  #asked = null;

  constructor(root, apply, words = () => ENGLISH) {
    this.root = root;
    this.apply = apply;
    this.words = words;
    this.cost = null;
    this.pending = null;
    this.confirmed = false;
    root.getElementById('confirm-apply').addEventListener('click', () => this.#resolve(true));
    root.getElementById('confirm-keep').addEventListener('click', () => this.#resolve(false));
  }

  /** Starts estimating, once the kind of adapter is known. */
  start(software) {
    this.cost ??= new FrameCost(software);
  }

  // Frames a new renderer draws before they are measured, and when the first measured one began.
  #warmFrames = 0;
  #measuredFrom = Infinity;
  // The last frame drawn, when it held the page long: its work and milliseconds.
  #lastSlow = null;

  /** A renderer started: its first frames are not measured. */
  rendererStarted() {
    this.#warmFrames = WARM_FRAMES;
    this.#measuredFrom = Infinity;
  }

  /**
   * A frame at `settings`, drawn at `now`, held the page for `blockedMs`. A long hold is measured when
   * the frame before, at the same settings, held it long too (the shorter of the two): a one-off, as
   * when a shader is built on first use or the tab stalls, is not.
   */
  frameDrawn(settings, now, blockedMs) {
    if (this.#warmFrames > 0) {
      this.#warmFrames -= 1;
      if (this.#warmFrames === 0) this.#measuredFrom = now;
      this.#lastSlow = null;
      return;
    }
    const slow = blockedMs > SLOW_FRAME_MS ? { work: frameWork(settings), ms: blockedMs } : null;
    const before = this.#lastSlow;
    this.#lastSlow = slow;
    if (slow && before?.work === slow.work) this.#observe(settings, Math.min(before.ms, slow.ms));
  }

  /** The mean time of the frames at `settings` since `since`: measured unless they include the first. */
  framesTimed(settings, since, ms) {
    if (since >= this.#measuredFrom) this.#observe(settings, ms);
  }

  // Level of detail's frames follow the screen, not the grid, so they do not teach the uniform grid's
  // rate.
  #observe({ resolution, spheres, lod }, ms) {
    if (!lod) this.cost?.observe({ resolution, spheres }, ms);
  }

  /** True when `next` would make frames slower than a second here, and slower than `current`. */
  tooSlow(current, next) {
    if (!this.cost || this.confirmed) return false;
    const estimate = this.cost.estimate(next);
    return estimate > CONFIRM_ABOVE_MS && estimate > this.cost.estimate(current);
  }

  /**
   * Before the first frame: where `state` asks for frames slower than a second, the costly parameters
   * go back to `defaults` (no higher than asked) and the person is asked. Returns the names changed.
   */
  startAffordably(state, defaults) {
    const asked = { resolution: state.resolution, spheres: state.spheres };
    const changed = [];
    for (const name of ['resolution', 'spheres']) {
      if (this.cost.estimate(state) <= CONFIRM_ABOVE_MS) break;
      if (defaults[name] >= state[name]) continue;
      state[name] = defaults[name];
      changed.push(name);
    }
    if (changed.length && this.cost.estimate(state) <= CONFIRM_ABOVE_MS) {
      this.ask(state, Object.fromEntries(changed.map((name) => [name, asked[name]])));
    }
    return changed;
  }

  /** Shows the confirmation for `changes` to `current`: their estimated frame time, and what is kept. */
  ask(current, changes) {
    this.pending = { ...(this.pending ?? {}), ...changes };
    this.#asked = { current: { ...current }, next: { ...current, ...this.pending } };
    this.reword(this.words());
    this.root.getElementById('confirm').hidden = false;
  }

  /** Words the question shown (if any) with `words`. */
  reword(words) {
    if (!this.#asked) return;
    const { current, next } = this.#asked;
    const $ = (id) => this.root.getElementById(id);
    $('confirm-text').textContent = words.t('guard.question', {
      settings: describeSettings(words, next), time: describeMs(this.cost.estimate(next), words) });
    $('confirm-keep').textContent = words.t('guard.keep', { settings: describeSettings(words, current) });
  }

  #resolve(apply) {
    const pending = this.pending;
    this.pending = null;
    this.#asked = null;
    this.root.getElementById('confirm').hidden = true;
    if (!apply || !pending) return;
    this.confirmed = true;
    try {
      for (const [name, value] of Object.entries(pending)) this.apply(name, value);
    } finally {
      this.confirmed = false;
    }
  }
}
