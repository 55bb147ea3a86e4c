// TypeScript declarations of <metaballs-2d>, written by `metaballs manifest --out www` from the
// 2D figure's rows and src/manifest/plane.rs. Do not edit: change those and run the command.

export interface Metaballs2dCircle {
  x: number;
  y: number;
  r: number;
  /** 1 adds the circle's term, -1 subtracts it. */
  charge?: 1 | -1;
}

/** The figure as it is now, written to paste (`shareText()`). */
export interface Metaballs2dShareText {
  /** The module's script tag and the element with its attributes. */
  html: string;
  /** The iframe page's URL. */
  url: string;
  /** An iframe of that page at the size the figure was seen at. */
  iframe: string;
  /** The notebook widget's call. */
  python: string;
  /** MyST's {anywidget} directive. */
  myst: string;
  /** The full page's link. */
  link: string;
}

/** What `record()` makes (every field optional). */
export interface Metaballs2dRecordOptions {
  /** Seconds of animation (default 4). */
  seconds?: number;
  /** 24, 30 or 60 (default 30). */
  fps?: 24 | 30 | 60;
  /** Pixels (default the figure's size, even). */
  width?: number;
  height?: number;
  /** 'webm-vp9', 'webm-vp8', 'mp4-h264' or 'gif' (default the first the browser writes). */
  format?: string;
  /** Called after each frame. */
  onProgress?: (done: number, count: number) => void;
  /** Aborting it stops the recording: the promise rejects with an AbortError. */
  signal?: AbortSignal;
}

/** A message: a text with `{field}` placeholders, or plural forms chosen by its `count` field. */
export type MetaballsMessage =
  | string
  | { zero?: string; one?: string; two?: string; few?: string; many?: string; other: string };

/** Adds a language (a tag such as 'nl'), or overrides words of one, for every figure on the page. */
export declare function registerTranslation(lang: string, messages: Record<string, MetaballsMessage>): void;

/** Every English message by its key: what a translation gives. */
export declare const englishWords: Readonly<Record<string, MetaballsMessage>>;

export declare class Metaballs2d extends HTMLElement {
  /** Iso level: 0.05 to 20. Attribute `iso`; default 1. */
  iso: number;
  /** Interpolation: linear, midpoint. Attribute `interpolation`; default "linear". */
  interpolation: 'linear' | 'midpoint';
  /** Saddle: table, center, decider. Attribute `saddle`; default "table". */
  saddle: 'table' | 'center' | 'decider';
  /** Kernel: inverse_square, blinn, wyvill. Attribute `kernel`; default "inverse_square". */
  kernel: 'inverse_square' | 'blinn' | 'wyvill';
  /** Blobbiness: 0.25 to 8. Attribute `blobbiness`; default 2. */
  blobbiness: number;
  /** Sphere count: 1 to 64. Attribute `spheres`; default 5. */
  spheres: number;
  /** Layout seed: 0 to 4294967295. Attribute `seed`; default 1. */
  seed: number;
  /** Animation speed: 0 to 3. Attribute `speed`; default 1. */
  speed: number;
  /** Paused: a boolean attribute. Attribute `paused`; default false. */
  paused: boolean;
  /** Theme: dark, light, auto. Attribute `theme`; default "dark". */
  theme: 'dark' | 'light' | 'auto';
  /** The figure's accessible name (without it, one is made from what it shows). Attribute `alt`; default "". */
  alt: string;
  /** Resolution (squares per axis): 8 to 1024. Attribute `resolution`; default 16. */
  resolution: number;
  /** The circles, x,y,r per circle joined by ; (a negative r subtracts); without it, `spheres` circles from `seed`. Attribute `circles`; default "". */
  circles: string;
  /** Iso levels: a comma list of numbers from 0.05 to 20. Attribute `iso-levels`; default "". */
  isoLevels: string;
  /** Show: all, none, or a comma list of grid, values, corners, cases, crossings, contour, saddles, bands, circles. Attribute `show`; default "grid,values,corners,cases,crossings,contour,saddles,bands". */
  show: string;
  /** The step-through of the march, open at a square i,j or a step (off: closed). Attribute `march`; default "". */
  march: string;
  /** The id of a <metaballs-view> with a slice: its slice plane is drawn instead of circles. Attribute `slice-of`; default "". */
  sliceOf: string;
  /** Controls: all, none, or a comma list of iso, resolution, interpolation, saddle, kernel, blobbiness, iso-levels, show, paused, speed, spheres, seed, theme, step-through, circles, scene, share. Attribute `controls`; default "none". */
  controls: string;
  /** The circles as placed; set to such a list to place them. */
  circleList: Metaballs2dCircle[];
  /** The step-through's step (square j · resolution + i), or null when it is off. */
  readonly stepIndex: number | null;
  /** The <metaballs-view> whose slice plane it follows (slice-of), or null. */
  readonly following: HTMLElement | null;
  /** The last frame's time to sample, march and paint, in ms. */
  readonly frameMs: number;
  /** The contour at the iso level as data: rings, saddles, crossings and cases. */
  contours(): object;
  /** The picture as an SVG document (vector). */
  toSVG(size?: number): string;
  /** The samples drawn, row by row from the lower left. */
  samples(): { cells: number; values: number[] };
  /** Sets the circles moving. */
  play(): void;
  /** Holds the circles still. */
  pause(): void;
  /** Opens the step-through at step k, or moves it there. */
  stepTo(k: number): void;
  /** One square forward. */
  stepForward(): void;
  /** One square back. */
  stepBack(): void;
  /** The next square the contour crosses. */
  nextCrossed(): void;
  /** The circles and every setting of the picture as a scene document (JSON). */
  saveScene(): string;
  /** Loads a scene document; throws with what is wrong, changing nothing. */
  loadScene(text: string): void;
  /** Downloads the scene document. */
  downloadScene(): void;
  /** The figure as it is now, written to paste: its HTML, the iframe page's URL and an iframe, the Python widget's call, a MyST directive and the full page's link. */
  shareText(): Metaballs2dShareText;
  /** A PNG of the picture at the figure's size times `scale`. */
  makePoster(scale?: number): Promise<Blob>;
  /** A clip of the circles moving, its frames 1/fps of animation apart: WebM, MP4 or GIF. */
  record(options?: Metaballs2dRecordOptions): Promise<Blob>;
  /** Opens the share box. */
  openShare(): void;
  /** Shows a short message inside the figure. */
  showNotice(text: string, ms?: number): void;
}

export interface Metaballs2dEventMap {
  /** A setting changed (from an attribute, a property, a control or a gesture). */
  'metaballs-change': CustomEvent<{ property: string; attribute: string; value: number | boolean | string }>;
  /** The figure could not draw, or refused an attribute's value (it shows why). */
  'metaballs-error': CustomEvent<{ message: string; attribute?: string }>;
  /** A circle is being dragged. */
  'metaballs-2d-drag': CustomEvent<{ circles: Metaballs2dCircle[] }>;
}

declare global {
  interface HTMLElementTagNameMap {
    'metaballs-2d': Metaballs2d;
  }
  interface HTMLElementEventMap extends Metaballs2dEventMap {}
}
