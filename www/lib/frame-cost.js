// How long a frame would take at a resolution and sphere count, on this adapter, from what has been
// measured so far: so that no link or slider can ask for a frame that freezes the browser without the
// person agreeing first.
//
// Work per frame grows with the blocks bounded (n³/64 per sphere) and with the surface (about n² per
// sphere); the time per unit of work comes from frames measured here, or before the first measurement
// from a cautious guess for the kind of adapter.

/** Frames estimated longer than this need the person's confirmation. */
export const CONFIRM_ABOVE_MS = 1000;

// Guessed time of a 128³ × 16 frame before any is measured: software adapters and WebGL2 (CPU meshing
// and a software rasteriser, often) take about a tenth of a second; hardware a few milliseconds.
const GUESS_MS = { software: 100, hardware: 4 };
const REFERENCE = { resolution: 128, spheres: 16 };

/** Relative work of one frame at `resolution` cells per axis with `spheres` spheres. */
export function frameWork({ resolution, spheres }) {
  return spheres * (resolution ** 3 / 64 + 4 * resolution ** 2);
}

export class FrameCost {
  /** `software`: a software adapter (or WebGL2), for the guess before any frame is measured. */
  constructor(software) {
    this.msPerWork = (software ? GUESS_MS.software : GUESS_MS.hardware) / frameWork(REFERENCE);
    this.measured = false;
  }

  /** Takes in a measured frame time for `settings` (a moving average, so one slow frame does not rule). */
  observe(settings, ms) {
    if (!(ms > 0) || !Number.isFinite(ms)) return;
    const rate = ms / frameWork(settings);
    this.msPerWork = this.measured ? 0.7 * this.msPerWork + 0.3 * rate : rate;
    this.measured = true;
  }

  /** Estimated milliseconds per frame for `settings`. */
  estimate(settings) {
    return this.msPerWork * frameWork(settings);
  }
}

/** "about 5 s" / "about 1.4 s" for a time in milliseconds. */
export function describeMs(ms) {
  return ms >= 10_000 ? `about ${Math.round(ms / 1000)} s` : `about ${(ms / 1000).toFixed(1)} s`;
}
