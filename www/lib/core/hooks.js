// The hooks a figure's features may implement, each documented once: the context (context.js) calls
// them by name on every feature that has the method (`each`, `collect`, `some`), and refuses a name
// that is not here, so a misspelt call fails at once instead of reaching no feature.
// `tests/e2e/hooks.test.js` holds the calls in the sources and the features' methods to this list.

/** Hook name → what it tells a feature, with its arguments. */
export const HOOKS = Object.freeze({
  // Settings.
  changed: '(name, value) a setting the feature owns (`static attributes`, "*" for all) was changed',
  refresh: '(state) any setting changed, was adopted or went back: redraw what shows them',
  veto: '(name, value) true holds a change back (the slow-frame guard asks first)',
  beforeSet: '(name, value) a change from inside (panel, gesture, method) is about to be made',
  madeInside: '(name, value, share) a change from inside took effect',
  spheresGiven: '(text) the sphere list was given as text (attribute, property, link)',
  spheresEdited: '() the spheres were moved, added or removed by hand',
  spheresReplaced: '() the spheres were replaced whole (a scene file, a reset)',
  // The element's life.
  connected: '() the element was put in a document',
  disconnected: '() the element was taken out of its document',
  firstStart: '() the WebAssembly is in, the first time the element was connected',
  loaded: '() the WebAssembly is in and the attributes given so far are read (each time it is connected)',
  deviceKnown: '() the adapter is known: what the panel offers can be decided',
  starting: '({ software, compute }) a renderer is being made on an adapter of this kind',
  started: '(view) a renderer was made',
  restored: '(view) a renderer was made again after a lost device',
  panelBuilt: '() the panel was built (again)',
  controls: '() the panel controls the feature builds itself: { name: (panel) => node }',
  // Frames.
  beforeFrame: '(now, view) an animation frame is about to be drawn: what changes the picture first',
  holds: '() true keeps the animation still (a drag, a search pause-on waits for, a sync leader)',
  beforeDraw: '(now, frame) the frame is about to be drawn',
  drawn: '(now, frame) the frame was drawn (shown or not); the 2D figure\'s frame is { changing }',
  frameDrawn: '(now, frame) a frame someone sees was drawn',
  idle: '(now, view) no frame was due on this animation frame',
  afterTick: '(now, view, { animating }) every animation frame the figure is on screen',
  timed: '({ since, frameMs, tickMs, animating }) the frame times of the last half second',
  scaled: '(scale, width, height) the canvas took a new size or render scale',
  statsOf: '(view, frame) true once the statistics of frame `frame` are read',
  shape: '(shape) the mesh\'s shape was found (blobs, genus, closed, manifold)',
  announce: '(text) a sentence for screen readers',
  // Words.
  language: '(words) the figure\'s language, its direction or a catalogue changed: reword what it shows',
});

/** True for a hook's name. */
export const isHook = (name) => Object.hasOwn(HOOKS, name);

/** Throws, saying which hooks there are, for a name that is none. */
export function checkHook(name) {
  if (!isHook(name)) throw new Error(`"${name}" is not a feature hook (see www/lib/core/hooks.js)`);
}
