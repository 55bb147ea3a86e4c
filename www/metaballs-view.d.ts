// TypeScript declarations of <metaballs-view>, written by `metaballs manifest --out www` from the
// parameter table. Do not edit: change the table (or src/manifest/mod.rs) and run the command.

export interface MetaballsStats {
  triangles: number;
  fps: number;
  frameTime: number;
  adapter: string;
  mesher: string;
  overflowed: boolean;
  [name: string]: unknown;
}

export interface MetaballsSphere {
  center: [number, number, number];
  radius: number;
  velocity: [number, number, number];
  /** 1 adds the sphere's term, -1 subtracts it. */
  charge: 1 | -1;
}

/** The cell inspector's report (see docs/teaching.md). */
export type MetaballsCellReport = Record<string, unknown>;

/** A critical point of the field (see docs/teaching.md, "Along the iso level"). */
export interface MetaballsCriticalPoint {
  position: [number, number, number];
  value: number;
  index: 0 | 1 | 2 | 3;
  role: 'join' | 'loop' | 'hole' | 'cavity' | 'fill' | 'birth' | 'unresolved';
  eigenvalues: [number, number, number];
  ends: unknown[];
  inBox: boolean;
}

/** The surface's shape (`topology()`). */
export interface MetaballsTopology {
  components: number;
  genus: number;
  closed: boolean;
  manifold: boolean;
}

export interface MetaballsLevelCounts {
  blobs: number;
  cavities: number;
  genus: number;
  surfaces: number;
}

export interface MetaballsCriticalPoints {
  points: MetaballsCriticalPoint[];
  tree: { value: number | null; children: number[]; point: number | null; spheres: number[] }[];
  bands: (MetaballsLevelCounts & { above: number | null; below: number })[];
  complete: boolean;
  undecided: number;
  wallLevel: number;
  milliseconds: number;
  iso: number;
  counts: MetaballsLevelCounts | null;
}

/** The figure as it is now, written to paste (`shareText()`). */
export interface MetaballsShareText {
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
export interface MetaballsRecordOptions {
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

export declare class MetaballsView extends HTMLElement {
  /** Sphere count: 1 to 64. Attribute `spheres`; default 5. */
  spheres: number;
  /** Iso level: 0.05 to 20. Attribute `iso`; default 1. */
  iso: number;
  /** Resolution (cells per axis): 8 to 2048. Attribute `resolution`; default 64. */
  resolution: number;
  /** Lod: a boolean attribute. Attribute `lod`; default false. */
  lod: boolean;
  /** LOD cell size (pixels): 0.25 to 32. Attribute `lod-pixels`; default 2. */
  lodPixels: number;
  /** Lod-freeze: a boolean attribute. Attribute `lod-freeze`; default false. */
  lodFreeze: boolean;
  /** Mesh-on: auto, gpu, cpu. Attribute `mesh-on`; default "auto". */
  meshOn: 'auto' | 'gpu' | 'cpu';
  /** Method: marching_cubes, surface_nets, dual_contouring, marching_tetrahedra. Attribute `method`; default "marching_cubes". */
  method: 'marching_cubes' | 'surface_nets' | 'dual_contouring' | 'marching_tetrahedra';
  /** Split: six, five. Attribute `split`; default "six". */
  split: 'six' | 'five';
  /** Animation speed: 0 to 3. Attribute `speed`; default 1. */
  speed: number;
  /** Layout seed: 0 to 4294967295. Attribute `seed`; default 1. */
  seed: number;
  /** Paused: a boolean attribute. Attribute `paused`; default false. */
  paused: boolean;
  /** Pause-on: none, merge. Attribute `pause-on`; default "none". */
  pauseOn: 'none' | 'merge';
  /** Display: shaded, flat, wireframe, points, normals, exact. Attribute `display`; default "shaded". */
  display: 'shaded' | 'flat' | 'wireframe' | 'points' | 'normals' | 'exact';
  /** Compare: none, split, overlay. Attribute `compare`; default "none". */
  compare: 'none' | 'split' | 'overlay';
  /** Grid: none, lattice, cells, blocks. Attribute `grid`; default "none". */
  grid: 'none' | 'lattice' | 'cells' | 'blocks';
  /** Color-by: none, area, quality, case, level, error, rank. Attribute `color-by`; default "none". */
  colorBy: 'none' | 'area' | 'quality' | 'case' | 'level' | 'error' | 'rank';
  /** Ambiguous: a boolean attribute. Attribute `ambiguous`; default false. */
  ambiguous: boolean;
  /** Critical: a boolean attribute. Attribute `critical`; default false. */
  critical: boolean;
  /** Color: #rrggbb. Attribute `color`; default "#e77661". */
  color: string;
  /** Theme: dark, light, auto. Attribute `theme`; default "dark". */
  theme: 'dark' | 'light' | 'auto';
  /** Antialiasing: a boolean attribute. Attribute `antialiasing`; default true. */
  antialiasing: boolean;
  /** Slice: off, or an axis and a position in the box (z:0.25). Attribute `slice`; default "off". */
  slice: string;
  /** Interpolation: linear, midpoint. Attribute `interpolation`; default "linear". */
  interpolation: 'linear' | 'midpoint';
  /** Table: classic, decider, mc33. Attribute `table`; default "classic". */
  table: 'classic' | 'decider' | 'mc33';
  /** Blend: sum, max. Attribute `blend`; default "sum". */
  blend: 'sum' | 'max';
  /** Kernel: inverse_square, blinn, wyvill. Attribute `kernel`; default "inverse_square". */
  kernel: 'inverse_square' | 'blinn' | 'wyvill';
  /** Blobbiness: 0.25 to 8. Attribute `blobbiness`; default 2. */
  blobbiness: number;
  /** Saddle: table, center, decider. Attribute `saddle`; default "table". */
  saddle: 'table' | 'center' | 'decider';
  /** Levels: a boolean attribute. Attribute `levels`; default false. */
  levels: boolean;
  /** Light: all, none, or a comma list of point, directional, spot. Attribute `light`; default "point". */
  light: string;
  /** Spot cone angle (degrees): 2 to 80. Attribute `spot-angle`; default 15. */
  spotAngle: number;
  /** Spot softness: 0 to 1. Attribute `spot-softness`; default 0.3. */
  spotSoftness: number;
  /** Ambient strength: 0 to 1. Attribute `ambient`; default 0.15. */
  ambient: number;
  /** Diffuse strength: 0 to 2. Attribute `diffuse`; default 0.85. */
  diffuse: number;
  /** Specular strength: 0 to 2. Attribute `specular`; default 0.6. */
  specular: number;
  /** Shininess: 1 to 1024. Attribute `shininess`; default 64. */
  shininess: number;
  /** Projection: perspective, orthographic. Attribute `projection`; default "perspective". */
  projection: 'perspective' | 'orthographic';
  /** Field of view (degrees): 10 to 120. Attribute `fov`; default 45. */
  fov: number;
  /** Edit: a boolean attribute. Attribute `edit`; default false. */
  edit: boolean;
  /** Camera yaw (degrees): -360 to 360. Attribute `yaw`; default 30. */
  yaw: number;
  /** Camera pitch (degrees): -89 to 89. Attribute `pitch`; default 20. */
  pitch: number;
  /** Camera distance: 1.5 to 20. Attribute `distance`; default 4.3. */
  distance: number;
  /** March: off, or a cell of the grid x,y,z (3,4,5): the step-through of marching cubes there. Attribute `march`; default "off". */
  march: string;
  /** Divider position: 0.05 to 0.95. Attribute `divider`; default 0.5. */
  divider: number;
  /** Sphere-list: x,y,z,radius[,vx,vy,vz] per sphere joined by ; (a negative radius subtracts). Attribute `sphere-list`; default "". */
  get sphereList(): MetaballsSphere[];
  /** Sphere-list: x,y,z,radius[,vx,vy,vz] per sphere joined by ; (a negative radius subtracts). Attribute `sphere-list`; default "". */
  set sphereList(value: string | MetaballsSphere[]);
  /** Controls: all, none, or a comma list of spheres, iso, resolution, lod, lod-pixels, lod-freeze, mesh-on, method, split, speed, seed, paused, pause-on, step, view, display, compare, grid, color-by, ambiguous, critical, color, theme, antialiasing, slice, interpolation, table, blend, kernel, blobbiness, saddle, levels, inspector, step-through, error-plot, light, spot-angle, spot-softness, ambient, diffuse, specular, shininess, projection, fov, edit, scene, export, share. Attribute `controls`; default "none". */
  controls: string;
  /** Hud: on, off. Attribute `hud`; default "off". */
  hud: 'on' | 'off';
  /** Autoplay: visible, off. Attribute `autoplay`; default "visible". */
  autoplay: 'visible' | 'off';
  /** Max-pixel-ratio: 0.25 to 4. Attribute `max-pixel-ratio`; default 2. */
  maxPixelRatio: number;
  /** Min-render-scale: 0.25 to 1. Attribute `min-render-scale`; default 0.5. */
  minRenderScale: number;
  /** Largest LOD cell size (pixels): 0.25 to 64. Attribute `max-lod-pixels`; default 16. */
  maxLodPixels: number;
  /** The figure's accessible name (without it, one is made from what it shows). Attribute `alt`; default "". */
  alt: string;
  /** An image URL shown before the first frame and in print until a frame is drawn. Attribute `poster`; default "". */
  poster: string;
  /** A group name: the figures of a page with the same one share their spheres, animation time and camera (the first on the page leads). Attribute `sync`; default "". */
  sync: string;
  /** Figures of the newest frames. */
  readonly stats: MetaballsStats;
  /** Frames this element has drawn (none while off screen). */
  readonly framesDrawn: number;
  /** What marching cubes decided in the inspected cell. */
  readonly inspected: MetaballsCellReport | null;
  /** The selected sphere's index in edit mode, or -1. */
  readonly selectedSphere: number;
  /** A costly change waiting for confirmation. */
  readonly pendingChange: Record<string, unknown> | null;
  /** The fraction of its pixel ratio the figure draws at now (below 1 while an animating figure's frames are slow). */
  readonly renderScale: number;
  /** GPU memory this figure's renderer holds, in bytes (0 while it has none). */
  readonly gpuBytes: number;
  /** Starts the animation. */
  play(): void;
  /** Stops the animation. */
  pause(): void;
  /** Draws one frame of animation (1/60 s) and stays paused. */
  step(): void;
  /** Back to the default camera. */
  resetView(): void;
  /** Resolves once the renderer has started (or rejects with why it could not). */
  ready(): Promise<void>;
  /** Resolves with the statistics of a frame drawn after the call, drawing one even off screen or paused. */
  nextFrame(): Promise<MetaballsStats>;
  /** Selects a cell for the inspector and returns its report (null outside the grid). */
  inspectCell(x: number, y: number, z: number): MetaballsCellReport | null;
  /** Lets go of the inspected cell or the selected sphere. */
  deselect(): void;
  /** The field's critical points for the spheres now (found with proof), the merge tree and the counts between critical levels. */
  criticalPoints(): Promise<MetaballsCriticalPoints>;
  /** The scene (spheres and every setting of the picture) as a JSON document. */
  saveScene(): string;
  /** Loads a scene document; throws with what is wrong, keeping the scene. */
  loadScene(text: string): void;
  /** Saves the scene document as a file. */
  downloadScene(): void;
  /** The mesh of the current settings as file bytes (a frame is drawn first, even off screen). */
  exportMesh(format?: 'stl' | 'obj' | 'ply'): Promise<Uint8Array>;
  /** Saves the mesh of the current settings as a file. */
  downloadMesh(format?: 'stl' | 'obj' | 'ply'): Promise<void>;
  /** A PNG of the view at the canvas size times `scale`. */
  picture(scale?: number): Promise<Blob>;
  /** Saves a PNG of the view. */
  downloadPicture(scale?: number): Promise<void>;
  /** The figure as it is now, written to paste: its HTML, the iframe page's URL and an iframe, the Python widget's call, a MyST directive and the full page's link. */
  shareText(): MetaballsShareText;
  /** A PNG of the view at the figure's size (CSS pixels) times `scale`, the picture `poster` expects. */
  makePoster(scale?: number): Promise<Blob>;
  /** Saves the poster PNG and names it in the share box's HTML. */
  downloadPoster(scale?: number): Promise<void>;
  /** A clip of the animation, its frames 1/fps of animation apart: WebM, MP4 or GIF. */
  record(options?: MetaballsRecordOptions): Promise<Blob>;
  /** Opens the share box. */
  openShare(): void;
  /** Shows a short message inside the figure. */
  showNotice(text: string, ms?: number): void;
  /** Where sphere `index` is drawn: its centre and radius in CSS pixels from the figure's top left, or null. */
  sphereOnScreen(index: number): { x: number; y: number; radius: number } | null;
  /** Resolves once the figure has a picture for print (its poster, or one of a drawn frame). */
  printable(): Promise<void>;
  /** The surface's shape now: its components, genus, closedness and manifoldness. */
  topology(): Promise<MetaballsTopology>;
  /** Runs `f` with the wasm view while the element's own frames are held. */
  withView<T>(f: (view: unknown) => T): Promise<T>;
}

export interface MetaballsViewEventMap {
  /** A setting changed (from an attribute, a property, a control or a gesture). */
  'metaballs-change': CustomEvent<{ property: string; attribute: string; value: number | boolean | string }>;
  /** A cell was selected or let go. */
  'metaballs-inspect': CustomEvent<{ cell: MetaballsCellReport | null }>;
  /** A sphere was added, moved, resized or removed by hand. */
  'metaballs-edit': CustomEvent<{ spheres: MetaballsSphere[] }>;
  /** A scene document was loaded. */
  'metaballs-scene': CustomEvent<{ spheres: MetaballsSphere[] }>;
  /** A mesh was exported. */
  'metaballs-export': CustomEvent<{ format: string; bytes: number; ms: number }>;
  /** A clip was recorded. */
  'metaballs-record': CustomEvent<{ format: string; width: number; height: number; fps: number; frames: number; bytes: number; ms: number }>;
  /** The figure could not draw, or refused an attribute's value (it shows why). */
  'metaballs-error': CustomEvent<{ message: string; attribute?: string }>;
}

declare global {
  interface HTMLElementTagNameMap {
    'metaballs-view': MetaballsView;
  }
  interface HTMLElementEventMap extends MetaballsViewEventMap {}
}
