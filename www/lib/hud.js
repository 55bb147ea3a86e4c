// The figure's statistics: frames per second, frame time, triangles, adapter, and a warning when the
// triangle budget stays full. Figures update twice a second from the GPU's asynchronous reports.

const numberFormat = new Intl.NumberFormat('en');

export class Hud {
  /** Writes into the readouts of `root` (the element's shadow root). */
  constructor(root) {
    this.root = root;
    this.frames = 0;
    this.since = 0;
    this.overflows = 0;
    this.stats = { triangles: 0, fps: 0, frameTime: 0, adapter: '', overflowed: false };
  }

  setAdapter(label) {
    this.stats.adapter = label;
    this.root.getElementById('adapter').textContent = label;
  }

  /** Counts a frame drawn. */
  countFrame() {
    this.frames += 1;
  }

  /** Called every animation frame; refreshes the figures every half second from `view`'s stats. */
  update(now, view) {
    if (!this.since) this.since = now;
    const elapsed = now - this.since;
    if (elapsed < 500) return;
    const $ = (id) => this.root.getElementById(id);
    this.stats.fps = (this.frames * 1000) / elapsed;
    this.stats.frameTime = this.frames ? elapsed / this.frames : 0;
    $('fps').textContent = this.frames ? this.stats.fps.toFixed(1) : '–';
    $('frame-time').textContent = this.frames ? `${this.stats.frameTime.toFixed(1)} ms` : 'idle';
    this.frames = 0;
    this.since = now;
    const stats = view.stats();
    if (!stats) return;
    this.stats.triangles = stats.triangles;
    $('triangles').textContent = numberFormat.format(stats.triangles);
    $('triangles').title = `budget ${numberFormat.format(stats.max_triangles)} triangles`;
    // The buffers grow a frame after an overflow; warn only when it lasts (they hit the device's limit).
    this.overflows = stats.overflowed ? this.overflows + 1 : 0;
    this.stats.overflowed = this.overflows >= 2;
    $('overflow').hidden = !this.stats.overflowed;
    stats.free();
  }
}
