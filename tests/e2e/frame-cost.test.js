// The guard's estimate of a frame's time (www/lib/features/frame-cost.js), in Node: it follows frames that are
// slow for a while, and is not ruled by one slow frame, by a stalled half second, or by the first frames
// of a renderer (which build its pipelines and buffers).

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { CostGuard, FrameCost, frameWork } from '../../www/lib/features/frame-cost.js';

// The parts of a figure's shadow root the guard writes to.
function fakeRoot() {
  const elements = {};
  return { getElementById: (id) => (elements[id] ??= { textContent: '', hidden: true, addEventListener() {} }) };
}

const SMALL = { resolution: 24, spheres: 2 };
const LARGE = { resolution: 48, spheres: 8 };
const msAt = (settings, msPerWork) => msPerWork * frameWork(settings);
const near = (actual, expected) => assert.ok(Math.abs(actual - expected) <= 1e-9 * expected, `${actual} is not ${expected}`);

// A guard on a software adapter whose renderer has started and drawn its first frames.
function startedGuard() {
  const guard = new CostGuard(fakeRoot(), () => {});
  guard.start(true);
  guard.rendererStarted();
  guard.frameDrawn(SMALL, 0, 900);
  guard.frameDrawn(SMALL, 10, 900);
  return guard;
}

test('the estimate is the median of the newest frames: one slow one does not rule, three do', () => {
  const cost = new FrameCost(true);
  const fast = 0.001;
  for (let i = 0; i < 4; i++) cost.observe(SMALL, msAt(SMALL, fast));
  cost.observe(SMALL, msAt(SMALL, 100 * fast));
  near(cost.msPerWork, fast);
  cost.observe(SMALL, msAt(SMALL, 100 * fast));
  near(cost.msPerWork, fast);
  cost.observe(SMALL, msAt(SMALL, 100 * fast));
  near(cost.msPerWork, 100 * fast);
  // Nothing measured: nothing taken in.
  cost.observe(SMALL, 0);
  cost.observe(SMALL, Number.NaN);
  near(cost.msPerWork, 100 * fast);
});

test("a new renderer's first frames are not measured, however slow", () => {
  const guard = startedGuard();
  assert.equal(guard.cost.measured, false);
  assert.equal(guard.tooSlow(SMALL, LARGE), false);
  // Nor is a window of frames that began before they were drawn.
  guard.framesTimed(SMALL, 5, 900);
  assert.equal(guard.cost.measured, false);
  guard.framesTimed(SMALL, 10, 20);
  assert.equal(guard.cost.measured, true);
});

test('one frame that holds the page long is not measured; two in a row at the same settings are', () => {
  const guard = startedGuard();
  guard.frameDrawn(SMALL, 20, 5);
  guard.frameDrawn(SMALL, 30, 400);
  guard.frameDrawn(SMALL, 40, 5);
  assert.equal(guard.cost.measured, false);
  assert.equal(guard.tooSlow(SMALL, LARGE), false, 'a still figure at 24³ × 2 spheres takes 48³ × 8 without asking');
  // Two slow frames at different settings are two one-offs.
  guard.frameDrawn(LARGE, 50, 400);
  guard.frameDrawn(SMALL, 60, 400);
  assert.equal(guard.cost.measured, false);
  // Slow for a while: the shorter of the two is taken, and 48³ × 8 is now worth asking about.
  guard.frameDrawn(SMALL, 70, 300);
  assert.equal(guard.cost.measured, true);
  near(guard.cost.estimate(SMALL), 300);
  assert.equal(guard.tooSlow(SMALL, LARGE), true);
});

test('a renderer started again after a device loss is measured afresh from its third frame', () => {
  const guard = startedGuard();
  guard.frameDrawn(SMALL, 20, 400);
  guard.rendererStarted();
  guard.frameDrawn(SMALL, 30, 400);
  guard.frameDrawn(SMALL, 40, 400);
  assert.equal(guard.cost.measured, false);
  guard.frameDrawn(SMALL, 50, 5);
  guard.framesTimed(SMALL, 45, 20);
  assert.equal(guard.cost.measured, true);
  near(guard.cost.estimate(SMALL), 20);
});
