// Figures with the same `sync` name share their spheres, their animation time and their camera. The
// first of them on the page leads: it animates, and the others take its spheres before each of their
// frames (all run on the page's one device). A camera change in any of them is made in all.

/** The settings a camera change carries to the other figures of a group. */
export const CAMERA = ['yaw', 'pitch', 'distance'];

// Every figure on the page that can sync, in the order they joined: { name(), frames, camera(name,
// value) }.
const members = new Set();

/**
 * A figure as a member of its group: `name()` reads its `sync` setting, `camera(name, value)` makes a
 * camera change another member shared; `frames` (its FigureFrames) is set once they exist.
 */
export const syncMember = (name, camera) => ({ name, camera, frames: null });

/** Adds a figure; `name()` reads its current `sync` setting (empty: none). */
export function joinSync(member) {
  members.add(member);
}

export function leaveSync(member) {
  members.delete(member);
}

const peersOf = (member) => {
  const name = member.name();
  return name ? [...members].filter((m) => m.name() === name) : [];
};

/** The figure whose spheres and time `member` follows, or null when it leads or syncs with none. */
export function leaderOf(member) {
  const leader = peersOf(member)[0];
  return leader && leader !== member ? leader : null;
}

/** Makes the camera change `name` = `value` of `member` in the other figures of its group. */
export function shareCamera(member, name, value) {
  for (const peer of peersOf(member)) {
    if (peer !== member) peer.camera(name, value);
  }
}
