// The rule every kind of GPU loss follows (a lost WebGPU device, a lost WebGL2 context): each loss is
// recorded; the wait before starting again doubles with each loss in the last minute; and after three
// in a minute the figures stop trying and offer "Try again".

/** Losses closer together than this count as one run. */
export const LOSS_WINDOW_MS = 60_000;
/** This many losses in a run and the figures stop trying. */
export const MAX_LOSSES = 3;

export class LossCount {
  #times = [];

  /** Records a loss at `now` (ms); returns the losses within the window, this one included. */
  record(now = performance.now()) {
    this.#times = this.#times.filter((t) => now - t < LOSS_WINDOW_MS);
    this.#times.push(now);
    return this.#times.length;
  }

  /** Losses in the current run. */
  get count() { return this.#times.length; }

  /** True once the run holds `MAX_LOSSES`: no more attempts until a person asks for one. */
  get exhausted() { return this.#times.length >= MAX_LOSSES; }

  /** Milliseconds to wait before attempt `attempt` (0 first) after the latest loss. */
  backoff(attempt = 0) {
    return 250 * 2 ** (Math.max(0, this.#times.length - 1) + attempt);
  }

  /** Forgets the run ("Try again"). */
  clear() { this.#times = []; }
}
