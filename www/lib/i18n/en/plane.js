// English: the 2D figure's own words (its panel's labels and words are the table's keys). Fields:
// `count`, `cells`, `step`, `steps`, `i`, `j`, `corner`, `bit`, `case`, `rate` (numbers); `iso` and
// `value` (numbers written as the figure writes them, in the language's digits); `from`, `to`, `first`,
// `second` (edge and segment names); `name` (a file's name), `reason` (what is wrong); `sum` (the bits
// added up, HTML). The refusals (`refused.plane-…`, worded by i18n/words.js's `refusal` as the table's
// are) name what the figure reads: `part`, `text`, `x`, `y`, `radius`, `version` are echoed as given.
export default {
  // What the figure shows, for screen readers (unless the author gave `alt`).
  'plane.label': {
    one: 'Marching squares: {count} circle on {cells} × {cells} squares, contour at iso {iso}',
    other: 'Marching squares: {count} circles on {cells} × {cells} squares, contour at iso {iso}',
  },
  // The picture: how a saddle square's inside corners go where the table decides it.
  'plane.picture.joined': 'joined',
  'plane.picture.apart': 'apart',
  // The panel.
  'plane.circles-hint': 'Double-click to add a circle or remove one; drag to move it.',
  'plane.scene': 'Scene',
  'plane.levels-example': 'e.g. 0.6,1.6',
  'plane.last-circle': 'circles: the last circle stays (the figure needs one)',
  'plane.scene-refused': '{name}: {reason}; the scene is unchanged',
  // The step-through's panel (also the 3D figure's: its buttons and rates).
  'plane.stepper.back': 'One step back',
  'plane.stepper.forward': 'One step forward',
  'plane.stepper.play': 'Play the march',
  'plane.stepper.pause': 'Pause the march',
  'plane.stepper.pause-button': 'pause',
  'plane.stepper.next': 'next crossed',
  'plane.stepper.next-title': 'The next one the surface crosses',
  'plane.stepper.rate-label': 'Steps per second',
  'plane.stepper.rate': '{rate}/s',
  'plane.stepper.close': 'Close the step-through',
  // The table of the 16 cases.
  'plane.cases.name': 'The 16 cases of marching squares',
  'plane.cases.case': 'case',
  'plane.cases.bits': 'bits 3210',
  'plane.cases.segments': 'segments',
  'plane.cases.edges': '{from}–{to}',
  'plane.cases.pair': '{first}, {second}',
  // HTML: a saddle's two ways.
  'plane.cases.either': '{first} <i>or</i> {second}',
  'plane.edge.bottom': 'bottom',
  'plane.edge.right': 'right',
  'plane.edge.top': 'top',
  'plane.edge.left': 'left',
  // The account of a step.
  'plane.step.done': 'Step {step} of {steps}: the march is done.',
  'plane.step.square': 'Step {step} of {steps}: square ({i}, {j})',
  'plane.step.corner-in': 'corner {corner}: {value} > {iso} → {bit}',
  'plane.step.corner-out': 'corner {corner}: {value} ≤ {iso} → {bit}',
  'plane.step.case': 'case {case} = {sum}',
  'plane.step.saddle-table': 'Saddle: the table cuts the inside corners apart',
  'plane.step.saddle-joined': 'Saddle: {value} > {iso}, the inside corners joined',
  'plane.step.saddle-apart': 'Saddle: {value} ≤ {iso}, the inside corners cut apart',
  // What the figure refuses: circles and steps given, and scene documents.
  'refused.plane-circle': 'circles: "{part}" is not x,y,r (three numbers, r not 0)',
  'refused.plane-circle-number': 'circles: "{part}" is not a number',
  'refused.plane-circle-outside': 'circles: ({x}, {y}) is outside the box [-1, 1]²',
  'refused.plane-no-circles': 'circles: give at least one circle as x,y,r',
  'refused.plane-march': 'march: "{text}" is not a square i,j, a step number, off or none',
  'refused.plane-march-square': 'march: "{text}" is not a square i,j of the {cells} × {cells} grid, nor a step from 0 to {steps}',
  'refused.plane-scene-long': 'the file is too long for a scene document',
  'refused.plane-scene-json': 'the file is not JSON ({detail})',
  'refused.plane-scene-format': 'format must be "{format}", got {got}',
  'refused.plane-scene-version': 'version {version} is not one this figure reads ({reads})',
  'refused.plane-scene-circles': 'circles must be a list of at least one circle',
  'refused.plane-scene-circle': '{field} must have a center [x, y] and a radius, as numbers',
  'refused.plane-scene-outside': '{field}.center ({x}, {y}) is outside the box [-1, 1]²',
  'refused.plane-scene-radius': '{field}.radius must be above 0, got {radius}',
  'refused.plane-scene-setting': 'settings.{spelling}: not a setting a scene holds ({names})',
  'refused.plane-scene-settings': 'settings.{reason}',
  'refused.plane-scene-value': '{name}: {reason}',
};
