// English: the 3D figure's teaching features. The cell inspector and its gallery of the case classes
// (`inspector.`), the step-through of the march (`march.`), the "Along the iso level" box and its plot
// and merge tree (`levels.`), the critical points (`critical.`), the mesh's merges (`topology.`) and the
// error-vs-resolution plot (`error-plot.`). Numbers come as number fields or written for the language
// already; `{count}` picks the plural form.
export default {
  // The inspector's box.
  'inspector.hint': 'Click the surface to inspect a cell (Esc to let go).',
  'inspector.cases': 'The 15 cases and their 33 configurations',
  'inspector.cell': 'Cell ({x}, {y}, {z})',
  'inspector.close': 'Deselect the cell (Esc)',
  // {case}, {class} and {configuration} are the numbers in bold; {bits} the case's bits, {name} the class's name.
  'inspector.case': 'Case {case} = {bits} (bit c: corner c inside) · class {class}, {name} · configuration {configuration}',
  'inspector.drawn-subcase': '(the table in use draws {configuration})',
  'inspector.corner': 'corner',
  'inspector.above': 'f > {iso}?',
  'inspector.in': 'in',
  'inspector.out': 'out',
  'inspector.edge': 'edge',
  'inspector.vertex': 'vertex',
  // A point of the cell, its coordinates written for the language.
  'inspector.point': '({x}, {y}, {z})',
  'inspector.triangles': 'Triangles (edges): {triangles}',
  'inspector.none': 'none',
  'inspector.ambiguous': 'Ambiguous faces (inside corners on a diagonal):',
  // An ambiguous face: {plane} such as "x = 0", {saddle} one of the three below.
  'inspector.face-saddle-joins': 'saddle {value} > {iso}',
  'inspector.face-saddle-cuts': 'saddle {value} ≤ {iso}',
  'inspector.face-no-saddle': 'no saddle',
  'inspector.face-joins-joined': 'Face {plane}: {saddle}: the decider joins its inside corners; drawn joined',
  'inspector.face-joins-cut': 'Face {plane}: {saddle}: the decider joins its inside corners; drawn cut apart (against the decider)',
  'inspector.face-cuts-cut': 'Face {plane}: {saddle}: the decider cuts them apart; drawn cut apart',
  'inspector.face-cuts-joined': 'Face {plane}: {saddle}: the decider cuts them apart; drawn joined (against the decider)',
  'inspector.interior-tunnel': 'Inside the cell: the trilinear interpolant joins corners {corners} through a saddle; drawn as a tunnel (table=mc33)',
  'inspector.interior-apart': 'Inside the cell: the trilinear interpolant joins corners {corners} through a saddle; drawn apart (only table=mc33 draws the tunnel)',
  'inspector.drawing': 'case {case}: its triangles',
  'inspector.interpolant': 'case {case}: the trilinear interpolant of its corner values, ray cast',
  // The 15 classes of cases of marching cubes, by number.
  'inspector.class.0': 'empty',
  'inspector.class.1': 'one corner',
  'inspector.class.2': 'an edge',
  'inspector.class.3': 'two corners across a face',
  'inspector.class.4': 'two corners across the cube',
  'inspector.class.5': 'three corners of a face',
  'inspector.class.6': 'an edge and the far corner',
  'inspector.class.7': 'three separate corners',
  'inspector.class.8': 'a face',
  'inspector.class.9': 'a corner and its neighbours',
  'inspector.class.10': 'two opposite edges',
  'inspector.class.11': 'a twisted path',
  'inspector.class.12': 'three corners and a lone one',
  'inspector.class.13': 'every other corner',
  'inspector.class.14': 'a twisted path, mirrored',
  // The gallery: a class with one configuration, or one configuration of a class ({triangles}: how many, beside △).
  'inspector.gallery-class': {
    one: '{class} · {name} ({count} case, {triangles} △)',
    other: '{class} · {name} ({count} cases, {triangles} △)',
  },
  'inspector.gallery-configuration': '{configuration} · {how} ({triangles} △)',
  'inspector.gallery-class-title': 'Class {class}, {name} ({count} of the 256 cases)',
  'inspector.gallery-configuration-title': 'Class {class}, {name} ({count} of the 256 cases): configuration {configuration}, {how}',
  'inspector.gallery-class-label': 'class {class}: {name}',
  'inspector.gallery-configuration-label': 'configuration {configuration}: {name}, {how}',
  // What sets a configuration apart: short (the caption) and long (its title and label).
  'inspector.gallery-joined-short': '{joined}/{ambiguous} joined',
  'inspector.gallery-joined': {
    one: '{joined} of {count} ambiguous face joined',
    other: '{joined} of {count} ambiguous faces joined',
  },
  'inspector.gallery-tunnel-short': 'tunnel',
  'inspector.gallery-tunnel': 'a tunnel inside',
  'inspector.gallery-no-tunnel': 'no tunnel',

  // The step-through of the march.
  'march.step-through-title': 'Walk marching cubes one cell at a time (from the inspected cell, if any)',
  'march.whole-mesh': 'march: the step-through walks marching cubes on the uniform grid (lod off, method marching_cubes); the whole mesh is drawn',
  'march.table': 'The 256 cases of marching cubes, grouped into their 15 classes',
  'march.table-case': 'case',
  'march.table-bits': 'bits 76543210',
  'march.table-class': {
    one: 'Class {class} · {name} ({count} case)',
    other: 'Class {class} · {name} ({count} cases)',
  },
  'march.step': 'Step {step} of {steps}: cell ({x}, {y}, {z})',
  // {case} the case in bold, {sum} its bits added up.
  'march.case-sum': 'case {case} = {sum}',
  'march.class': {
    one: 'class {class}, {name}: {count} triangle (edges {edges})',
    other: 'class {class}, {name}: {count} triangles (edges {edges})',
  },

  // The "Along the iso level" box.
  'levels.close': 'Close along the iso level',
  'levels.close-title': 'Close (levels=false)',
  'levels.finding': 'Finding the critical points…',
  'levels.stopped': 'The search stopped: {reason}',
  'levels.unserved': 'Critical points and the merge tree are found, with proof, for the inverse-square kernel summed only; set kernel=inverse_square and blend=sum to see them.',
  'levels.points-proved': {
    one: '{count} critical point (all found, with proof, {ms} ms).',
    other: '{count} critical points (all found, with proof, {ms} ms).',
  },
  'levels.points-unproved': {
    one: '{count} critical point (the search may have missed some, {ms} ms).',
    other: '{count} critical points (the search may have missed some, {ms} ms).',
  },
  // {blobs} and {cavities} are the two counts below.
  'levels.at-iso': 'At iso {iso}: {blobs}, {cavities}, genus {genus}.',
  'levels.blobs': { one: '{count} blob', other: '{count} blobs' },
  'levels.cavities': { one: '{count} cavity', other: '{count} cavities' },
  'levels.counts-unknown': 'The counts along the level are not known here: {reason}.',
  // The plot's key, beside samples of its lines.
  'levels.key-surfaces': 'surfaces',
  'levels.key-genus': 'genus',
  'levels.key-area': 'area',
  'levels.key-volume': 'volume (scaled)',
  'levels.key-walls': 'shaded: the surface reaches the walls',
  'levels.axis': 'iso level (log)',
  'levels.cursor': 'iso {iso}',
  'levels.merge-tree': 'Merge tree of the blobs',
  'levels.tree-iso': 'iso',
  'levels.list': 'Critical levels, highest first',
  // The HUD's "Field" line, and where the mesh's shape differs from the field's.
  'levels.field': {
    one: '{count} surface · genus {genus}',
    other: '{count} surfaces · genus {genus}',
  },
  'levels.field-walls': {
    one: '{count} surface · genus {genus} · reaches the walls',
    other: '{count} surfaces · genus {genus} · reaches the walls',
  },
  'levels.more-pieces': {
    one: 'The mesh has {count} piece where the field has {surfaces}.',
    other: 'The mesh has {count} pieces where the field has {surfaces}.',
  },
  'levels.neck': 'The field joins spheres {spheres} here, f = {value} at the saddle; the neck is {width} cells wide at {n}³.',
  'levels.fewer-pieces': {
    one: 'The mesh joins what the field keeps apart ({count} surface, the mesh {pieces}): the grid is too coarse there.',
    other: 'The mesh joins what the field keeps apart ({count} surfaces, the mesh {pieces}): the grid is too coarse there.',
  },
  'levels.fewer-pieces-below': {
    one: 'The mesh joins what the field keeps apart ({count} surface, the mesh {pieces}); they join only below f = {value}: the grid is too coarse there.',
    other: 'The mesh joins what the field keeps apart ({count} surfaces, the mesh {pieces}); they join only below f = {value}: the grid is too coarse there.',
  },
  'levels.genus': "The mesh's genus is {mesh} where the field's is {field}: a tunnel the grid or the table (classic) does not resolve.",

  // The critical points: what each does as the iso level falls past it.
  'critical.role.join': 'two blobs join',
  'critical.role.loop': 'a blob meets itself: a tunnel opens',
  'critical.role.hole': 'a tunnel closes',
  'critical.role.cavity': 'a cavity closes off',
  'critical.role.fill': 'a cavity fills',
  'critical.role.birth': 'a blob appears',
  'critical.role.unresolved': 'not known (its flow was lost)',
  'critical.level': 'f = {value}: {what}',
  // {a} and {b}: the spheres of the two blobs.
  'critical.join': 'Spheres {a} and {b} join at f = {value}',
  'critical.join-title': 'Spheres {a} and {b} join at f = {value}: choose to set the iso level just below',
  'critical.join-chosen': 'spheres {a} and {b} meet: iso {iso}, just below {value}',
  'critical.merge-paused': {
    one: '{count} blob → {blobs}, paused',
    other: '{count} blobs → {blobs}, paused',
  },
  'critical.merge-paused-at': {
    one: '{count} blob → {blobs}, paused where the field joins them (f = {value} at the saddle)',
    other: '{count} blobs → {blobs}, paused where the field joins them (f = {value} at the saddle)',
  },

  // The mesh's blobs merging or splitting.
  'topology.merge': {
    one: '{count} blob → {blobs} in the mesh',
    other: '{count} blobs → {blobs} in the mesh',
  },

  // The error-vs-resolution plot.
  'error-plot.title': 'Mesh these spheres at 8³ to 64³ on the CPU and plot the distance to the exact surface',
  'error-plot.meshing-linear': 'Meshing {n}³ with linear placement ({step} of {steps})…',
  'error-plot.meshing-midpoint': 'Meshing {n}³ with midpoint placement ({step} of {steps})…',
  'error-plot.stopped': 'The plot stopped: {reason}',
  'error-plot.not-drawing': 'the figure is not drawing',
  // An axis tick: 10 to the power {exponent}.
  'error-plot.tick': '1e{exponent}',
  'error-plot.axis': 'cells per axis',
  'error-plot.slopes-linear': 'linear: RMS slope {rms}, max slope {max}',
  'error-plot.slopes-midpoint': 'midpoint: RMS slope {rms}, max slope {max}',
  'error-plot.no-slope': '—',
  // {slopes}: the two lines above, joined by "; ".
  'error-plot.description': 'Error against cells per axis, log-log. {slopes}; triangles grow with slope {slope}.',
  'error-plot.linear': 'linear',
  'error-plot.midpoint': 'midpoint',
  'error-plot.styles': 'solid RMS, dashed max',
  'error-plot.triangles': 'triangles ∝ n^{slope}',
};
