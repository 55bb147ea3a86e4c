// English: the 3D figure's shell. Its boxes and their labels (`hud.`, `panel.`, `play.`, `sheet.`,
// `legend.`), what it says when it cannot draw or starts again (`figure.`), its short notices
// (`notice.`) and the question before a slow frame (`guard.`). The panel's controls are labelled from
// the table's keys (`setting.`, `group.`, `word.`, `action.`). Fields: numbers as the reader writes
// them, already formatted where the figure writes them itself (a message that counts also has `count`,
// a number, for its plural form); `reason`, `detail`, `message`: a cause as the browser, the GPU or a
// parser gave it; `table`, `name`, `value`, `spelling`: as written in the page's attributes.
export default {
  // The figure and its boxes.
  'figure.how': 'Drag to orbit, click then wheel to zoom; P pauses.',
  'figure.sphere-box': 'Selected sphere',
  'figure.wheel-hint': 'Click the figure (or hold Ctrl) to zoom with the wheel',
  // Its accessible name (`what`: the parts below, as a list) and what a control just did.
  'figure.name': 'Merging spheres: {what}',
  'figure.name-spheres': { one: '{count} sphere', other: '{count} spheres' },
  'figure.name-iso': 'iso {iso}',
  'figure.name-cells': '{resolution}³ cells',
  'figure.name-paused': 'paused',
  'figure.announce-paused': 'paused',
  'figure.announce-playing': 'playing',
  'figure.announce-on': '{setting} on',
  'figure.announce-off': '{setting} off',
  'figure.announce-value': '{setting} {value}',

  // The message box: a title, then what happened and what to do.
  'figure.retry': 'Try again',
  'figure.paused': 'Paused',
  'figure.webgl-wait': {
    one: 'This browser has no WebGPU, so the figures draw with WebGL2, which allows a page only a few drawing '
      + 'contexts: {count} figure is drawing already. This one starts when it is removed.',
    other: 'This browser has no WebGPU, so the figures draw with WebGL2, which allows a page only a few drawing '
      + 'contexts: {count} figures are drawing already. This one starts when one of them is removed.',
  },
  'figure.could-not-start': 'The figure could not start',
  'figure.could-not-load': 'The figure could not load',
  'figure.renderer-stopped': 'The renderer stopped',
  'figure.gpu-error': 'The GPU reported an error',
  'figure.gpu-lost': 'The GPU was lost ({reason}); starting again…',
  'figure.gpu-failing': 'The GPU keeps failing',
  'figure.gpu-failing-text': {
    one: 'The GPU was lost {count} time within a minute ({reason}), so the figures stopped trying.',
    other: 'The GPU was lost {count} times within a minute ({reason}), so the figures stopped trying.',
  },
  'figure.gpu-gone': 'The GPU is gone',
  'figure.gpu-gone-text': 'The GPU was lost ({reason}) and no new device could be had.',
  'figure.context-lost': 'The drawing context was lost; starting again…',
  'figure.context-failing': 'The drawing context keeps failing',
  'figure.context-failing-text': {
    one: 'The WebGL2 context was lost {count} time within a minute, so the figure stopped trying.',
    other: 'The WebGL2 context was lost {count} times within a minute, so the figure stopped trying.',
  },
  'figure.no-gpu': 'Neither WebGPU nor WebGL2 is available',
  'figure.webgpu-failed': 'WebGPU could not start',
  'figure.webgl-failed': 'WebGL2 could not start',
  'figure.webgpu-help': 'This figure draws with WebGPU or, without it, WebGL2; this browser offers neither. '
    + 'Use a current Chrome or Edge (113 or later), Safari 26, or Firefox 141 or later. '
    + 'On Linux, Chrome needs WebGPU switched on at chrome://flags/#enable-unsafe-webgpu; '
    + 'the page must also be served over https or from localhost.',
  // Two paragraphs: why it could not start (`detail`, the browser's words), then `figure.webgpu-help`.
  'figure.gpu-start-failed': '{detail}\n\n{help}',
  // The WebAssembly could not be had (`url`: where from; `deploy`: `figure.deploy`).
  'figure.deploy': "Make sure the site holds the package's pkg/ folder beside its www/ folder, as published, then reload the page.",
  'figure.fetch-failed': 'Its WebAssembly ({url}) could not be fetched ({detail}). Check the connection and reload '
    + 'the page; a page on another site must be allowed to fetch from where the element is served.',
  'figure.server-answered': 'Its WebAssembly ({url}) could not be fetched: the server answered {status}. {deploy}',
  'figure.wasm-damaged': 'Its WebAssembly ({url}) is cut short or damaged, so the browser cannot compile it ({detail}). {deploy}',
  'figure.code-unfetched': 'Its code could not be fetched ({detail}). {deploy}',
  'figure.wasm-blocked': 'This page blocks WebAssembly',
  'figure.csp': "The page's Content-Security-Policy does not allow compiling WebAssembly, which the figure needs. "
    + "Its script-src must include 'wasm-unsafe-eval', as in {csp}.",

  // Notices.
  'notice.wasm-type': 'The server sends the figures\' WebAssembly as "{type}" rather than application/wasm, so they '
    + 'start more slowly. Serve .wasm files as application/wasm.',
  'notice.no-type': 'no type',
  'notice.setting-refused': '{name} {value}: {message}',
  'notice.resolution-refused': 'resolution {resolution}: {message}',
  'notice.exact-software': 'The exact surface is drawn at {ratio}× pixel ratio on this software renderer.',
  // A new case table: the cells it changed, and the blobs before and after.
  'notice.table': 'table={table}',
  'notice.table-blobs': 'table={table}: blobs {before} → {after}',
  'notice.table-kept-lod': 'table={table}: level of detail keeps the classic table; the mesh is unchanged',
  'notice.table-kept-nets': 'table={table}: surface nets keeps the classic table; the mesh is unchanged',
  'notice.table-kept-dual': 'table={table}: dual contouring has no case table; the mesh is unchanged',
  'notice.table-kept-tetra': 'table={table}: marching tetrahedra has no ambiguous case and no case table; the mesh is unchanged',
  'notice.table-none-face': 'table={table}: no cell here has a face the asymptotic decider joins; both tables give this mesh',
  'notice.table-none-tunnel': 'table={table}: no cell here has a tunnel MC33 draws; both tables give this mesh',
  'notice.table-none-both': 'table={table}: no cell here has a face the asymptotic decider joins or a tunnel MC33 '
    + 'draws; both tables give this mesh',
  // `cells`: the cells changed, as (x, y, z), or `notice.cells-more`.
  'notice.table-changed-face': {
    one: 'table={table}: {count} cell changed, each with a face the decider joins and the classic table cuts: {cells}',
    other: 'table={table}: {count} cells changed, each with a face the decider joins and the classic table cuts: {cells}',
  },
  'notice.table-changed-tunnel': {
    one: 'table={table}: {count} cell changed, each with a tunnel through its inside that MC33 draws: {cells}',
    other: 'table={table}: {count} cells changed, each with a tunnel through its inside that MC33 draws: {cells}',
  },
  'notice.table-changed-both': {
    one: 'table={table}: {count} cell changed, each with a face the decider joins and the classic table cuts, '
      + 'or a tunnel MC33 draws: {cells}',
    other: 'table={table}: {count} cells changed, each with a face the decider joins and the classic table cuts, '
      + 'or a tunnel MC33 draws: {cells}',
  },
  'notice.cells-more': '{cells} and {count} more',
  // `notice`: one of the notices above.
  'notice.with-blobs': '{notice}; blobs {before} → {after}',

  // The statistics.
  'hud.statistics': 'Statistics',
  'hud.fps': 'FPS',
  'hud.frame': 'Frame',
  'hud.triangles': 'Triangles',
  'hud.adapter': 'Adapter',
  'hud.scale': 'Scale',
  'hud.scale-title': 'The fraction of the pixel ratio drawn: lower while frames are slow',
  'hud.error': 'Error',
  'hud.topology': 'Topology',
  'hud.field': 'Field',
  'hud.field-title': "The surface's shape from the field's critical points, exact at any resolution",
  'hud.quality': 'Quality',
  'hud.lod-cell': 'LOD cell',
  'hud.lod-cell-title': 'The largest a cell looks on screen: larger while frames are slow, from lod-pixels up to max-lod-pixels',
  'hud.lod': 'LOD',
  'hud.overflow': 'Triangle budget full: part of the surface is not drawn. Lower the resolution or raise the iso level.',
  // `adapter`: the GPU's name; `mesher`: GPU, CPU, LOD-GPU or LOD-CPU.
  'hud.adapter-meshing': '{adapter} · {mesher} meshing',
  'hud.scale-value': '{scale}× · {width}×{height}',
  'hud.frame-ms': '{ms} ms',
  'hud.idle': 'idle',
  'hud.budget': { one: 'budget {triangles} triangle', other: 'budget {triangles} triangles' },
  'hud.topology-manifold': { one: '{count} blob · genus {genus} · closed manifold', other: '{count} blobs · genus {genus} · closed manifold' },
  'hud.topology-closed': { one: '{count} blob · genus {genus} · closed, not manifold', other: '{count} blobs · genus {genus} · closed, not manifold' },
  'hud.topology-open': { one: '{count} blob · genus {genus} · open', other: '{count} blobs · genus {genus} · open' },
  'hud.error-value': 'RMS {rms} · max {max} cells',
  'hud.error-title': {
    one: 'distance of {vertices} vertex to the exact surface, in cell sizes',
    other: 'distance of {vertices} vertices to the exact surface, in cell sizes',
  },
  'hud.shape-bar': { one: 'shape {from}–{to}: {triangles} triangle', other: 'shape {from}–{to}: {triangles} triangles' },
  'hud.shapes-label': 'triangle shapes from sliver to equilateral; {percent} % below {limit}',
  'hud.lod-cell-value': '≤ {cell} px ({least}–{most})',
  'hud.lod-cell-held': '≤ {cell} px, held there so that touching blocks differ by one level ({least}–{most} asked)',
  'hud.lod-summary': { one: '{resolution}³ effective · {count} level', other: '{resolution}³ effective · {count} levels' },
  // One level of detail: its number, its blocks and its triangles (△).
  'hud.lod-level': '{level}: {blocks} blocks · {triangles} △',

  // Playing, pausing, the camera.
  'play.button': '▶ Play',
  'play.play': 'Play',
  'play.pause': 'Pause',
  'play.pause-title': 'Pause or play (P)',
  'play.step-title': 'One frame forward, paused (.)',
  'play.reset-title': 'Reset the camera (R or double-click)',

  // The question before a slow frame (`settings`: `guard.settings`; `time`: `guard.about-seconds`).
  'guard.question': '{settings}: {time} per frame on this adapter, during which the page would not respond.',
  'guard.apply': 'Apply anyway',
  'guard.keep': 'Keep {settings}',
  'guard.about-seconds': 'about {seconds} s',
  'guard.settings': { one: '{resolution}³ × {count} sphere', other: '{resolution}³ × {count} spheres' },
  'guard.settings-lod': { one: '{resolution}³ with LOD × {count} sphere', other: '{resolution}³ with LOD × {count} spheres' },

  // The panel.
  'panel.controls': 'Controls',
  'panel.more': 'More',
  'panel.hint': 'Drag to orbit · click, then wheel to zoom · arrows to turn · double-click to reset',
  'panel.needs-webgpu': 'Needs WebGPU (compute shaders); this browser draws with WebGL2 and meshes on the CPU',
  'panel.on': 'on',
  'panel.off': 'off',
  'panel.antialiasing-on': '4×',
  'panel.slice-axis': 'Slice axis',
  'panel.slice-position': 'Slice position',
  'panel.slice-off': 'off',

  // The colour keys.
  'legend.level': 'level {level}: cells {factor}× the finest',
  'legend.level-0': 'level {level}: the finest cells',
  'legend.levels-note': 'finest first · paler: transition cells',
  // `name`: the class's name, as the case gallery gives it.
  'legend.class': 'class {class}: {name}',
  'legend.area-high': '½ cell face',
  'legend.sliver': 'sliver',
  'legend.equilateral': 'equilateral',
  'legend.error-low': 'on the surface',
  'legend.error-high': '½ cell away (middle: ⅛)',
  'legend.rank-1': 'rank 1: a face (the planes agree)',
  'legend.rank-2': 'rank 2: an edge (two families of planes)',
  'legend.rank-3': 'rank 3: a corner',
  'legend.rank-note': 'darker: minimiser outside its cell',
  'legend.slice-low': 'f = iso ÷ 16',
  'legend.slice-high': 'iso × 16',

  // A small figure's tabs, one per box.
  'sheet.tabs': "The figure's panels",
  'sheet.inspector': 'Cell',
  'sheet.march': 'Steps',
  'sheet.levels-box': 'Levels',
  'sheet.sphere-box': 'Sphere',
  'sheet.hud': 'Statistics',
  'sheet.hud-warned': 'Statistics ⚠',
  'sheet.warning': 'The statistics have a warning',
  'sheet.panel': 'Controls',
};
