//! The author's API of `<metaballs-view>` beyond its attributes, declared once: its methods, read-only
//! properties, events, parts and CSS custom properties, from which the manifest and the TypeScript
//! declarations are written (`tests/e2e/api.test.js` holds the element to them).

/// The element's methods: name, TypeScript signature after the name, what it does.
pub const METHODS: &[(&str, &str, &str)] = &[
    ("play", "(): void", "Starts the animation."),
    ("pause", "(): void", "Stops the animation."),
    ("step", "(): void", "Draws one frame of animation (1/60 s) and stays paused."),
    ("resetView", "(): void", "Back to the default camera."),
    (
        "ready",
        "(): Promise<void>",
        "Resolves once the renderer has started (or rejects with why it could not).",
    ),
    (
        "nextFrame",
        "(): Promise<MetaballsStats>",
        "Resolves with the statistics of a frame drawn after the call, drawing one even off screen or paused.",
    ),
    (
        "inspectCell",
        "(x: number, y: number, z: number): MetaballsCellReport | null",
        "Selects a cell for the inspector and returns its report (null outside the grid).",
    ),
    ("deselect", "(): void", "Lets go of the inspected cell or the selected sphere."),
    (
        "criticalPoints",
        "(): Promise<MetaballsCriticalPoints>",
        "The field's critical points for the spheres now (found with proof), the merge tree and the counts between critical levels.",
    ),
    ("saveScene", "(): string", "The scene (spheres and every setting of the picture) as a JSON document."),
    (
        "loadScene",
        "(text: string): void",
        "Loads a scene document; throws with what is wrong, keeping the scene.",
    ),
    ("downloadScene", "(): void", "Saves the scene document as a file."),
    (
        "exportMesh",
        "(format?: 'stl' | 'obj' | 'ply'): Promise<Uint8Array>",
        "The mesh of the current settings as file bytes (a frame is drawn first, even off screen).",
    ),
    (
        "downloadMesh",
        "(format?: 'stl' | 'obj' | 'ply'): Promise<void>",
        "Saves the mesh of the current settings as a file.",
    ),
    ("picture", "(scale?: number): Promise<Blob>", "A PNG of the view at the canvas size times `scale`."),
    ("downloadPicture", "(scale?: number): Promise<void>", "Saves a PNG of the view."),
    (
        "shareText",
        "(): MetaballsShareText",
        "The figure as it is now, written to paste: its HTML, the iframe page's URL and an iframe, the Python widget's call, a MyST directive and the full page's link.",
    ),
    (
        "makePoster",
        "(scale?: number): Promise<Blob>",
        "A PNG of the view at the figure's size (CSS pixels) times `scale`, the picture `poster` expects.",
    ),
    (
        "downloadPoster",
        "(scale?: number): Promise<void>",
        "Saves the poster PNG and names it in the share box's HTML.",
    ),
    (
        "record",
        "(options?: MetaballsRecordOptions): Promise<Blob>",
        "A clip of the animation, its frames 1/fps of animation apart: WebM, MP4 or GIF.",
    ),
    ("openShare", "(): void", "Opens the share box."),
    ("showNotice", "(text: string, ms?: number): void", "Shows a short message inside the figure."),
    (
        "sphereOnScreen",
        "(index: number): { x: number; y: number; radius: number } | null",
        "Where sphere `index` is drawn: its centre and radius in CSS pixels from the figure's top left, or null.",
    ),
    (
        "printable",
        "(): Promise<void>",
        "Resolves once the figure has a picture for print (its poster, or one of a drawn frame).",
    ),
    (
        "topology",
        "(): Promise<MetaballsTopology>",
        "The surface's shape now: its components, genus, closedness and manifoldness.",
    ),
    (
        "withView",
        "<T>(f: (view: unknown) => T): Promise<T>",
        "Runs `f` with the wasm view while the element's own frames are held.",
    ),
];

/// Read-only properties beyond the attributes: name, TypeScript type, meaning.
pub const READ_ONLY: &[(&str, &str, &str)] = &[
    ("stats", "MetaballsStats", "Figures of the newest frames."),
    ("framesDrawn", "number", "Frames this element has drawn (none while off screen)."),
    ("inspected", "MetaballsCellReport | null", "What marching cubes decided in the inspected cell."),
    ("selectedSphere", "number", "The selected sphere's index in edit mode, or -1."),
    ("pendingChange", "Record<string, unknown> | null", "A costly change waiting for confirmation."),
    (
        "renderScale",
        "number",
        "The fraction of its pixel ratio the figure draws at now (below 1 while an animating figure's frames are slow).",
    ),
    ("gpuBytes", "number", "GPU memory this figure's renderer holds, in bytes (0 while it has none)."),
];

/// Events (they bubble and cross the shadow boundary): name, TypeScript type of `detail`, when.
pub const EVENTS: &[(&str, &str, &str)] = &[
    (
        "metaballs-change",
        "{ property: string; attribute: string; value: number | boolean | string }",
        "A setting changed (from an attribute, a property, a control or a gesture).",
    ),
    ("metaballs-inspect", "{ cell: MetaballsCellReport | null }", "A cell was selected or let go."),
    (
        "metaballs-edit",
        "{ spheres: MetaballsSphere[] }",
        "A sphere was added, moved, resized or removed by hand.",
    ),
    ("metaballs-scene", "{ spheres: MetaballsSphere[] }", "A scene document was loaded."),
    ("metaballs-export", "{ format: string; bytes: number; ms: number }", "A mesh was exported."),
    (
        "metaballs-record",
        "{ format: string; width: number; height: number; fps: number; frames: number; bytes: number; ms: number }",
        "A clip was recorded.",
    ),
    (
        "metaballs-error",
        "{ message: string; attribute?: string }",
        "The figure could not draw, or refused an attribute's value (it shows why).",
    ),
];

/// `<metaballs-view>`'s custom states (`:state(name)`), set by the figure from its own width.
pub const STATES: &[(&str, &str)] = &[
    (
        "compact",
        "Narrower than 440 CSS px: the boxes open one at a time, from a row of tabs over the picture.",
    ),
    ("sheet", "A box is open as a sheet below the picture; the figure is taller by it."),
    ("over", "A box is open as a sheet over the picture's lower part (the page fixes the figure's size)."),
];

/// `::part()` names: name, what it is.
pub const PARTS: &[(&str, &str)] = &[
    ("canvas", "The drawing."),
    ("poster", "The picture shown before the first frame, and in print."),
    ("panel", "The controls."),
    ("hud", "The statistics."),
    ("notice", "Short messages."),
];

/// CSS custom properties: name, default, meaning.
pub const CSS_PROPERTIES: &[(&str, &str, &str)] = &[
    ("--metaballs-background-top", "theme", "Top colour of the drawn background (#rrggbb)."),
    ("--metaballs-background-bottom", "theme", "Bottom colour of the drawn background (#rrggbb)."),
    ("--metaballs-accent", "#e77661", "Focus rings, pressed buttons, sliders."),
    ("--metaballs-panel-background", "theme", "Background of the panel, statistics and inspector."),
    ("--metaballs-text", "theme", "Text colour of the panel."),
    ("--metaballs-muted", "theme", "Secondary text colour of the panel."),
    ("--metaballs-poster-color", "theme", "Background of the box before the first frame."),
];
