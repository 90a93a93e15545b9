// The bound on what the proposed pass leaves (correction.predictedRmsHigh, µm rms on the probe
// grid), or null where no pass is proposed (keepsAxesRun: a stop, or no change proposed), a
// proposal that is not to be used, faces that moved against the change of the axes since the last
// pass (correction.signReversed: no figure stands until the measuring machine's sign is checked),
// or no finite bound. Shared by the
// page's sentences and files and the CLI's X3P (pure, with Node tests).
export function passBound(c) {
  if (!c || keepsAxesRun(c) || c.usable === false || c.signReversed === true) return null;
  return Number.isFinite(c.predictedRmsHigh) ? c.predictedRmsHigh : null;
}

// True where the correction proposes no change of the axes run: a run kept (the correction found
// would leave more), every axis locked, or no axis direction above the probe noise (every
// correction.change 0; the verdict then starts "No change proposed:"). A stop also keeps the axes,
// and says so in its own words.
export function changesNothing(c) {
  if (!c) return false;
  return c.runKept === true || (Array.isArray(c.change) && c.change.every((v) => v === 0));
}

// True where the axes run stay: a stop (the face is within the probe noise) or no change proposed.
// (The core's Correction::keepsRun() is a stop or a run kept.)
export function keepsAxesRun(c) {
  return Boolean(c) && (c.stop === true || changesNothing(c));
}

// The pass's floor (correction.resolutionFloor, µm rms on the probe grid: what quantising each axis
// position to its step does to the face) where it lies above the bound, or null: the bound is of
// the exact axes, and no pass goes below the floor (docs/conventions.md, Machine resolution).
export function floorAboveBound(c) {
  const high = passBound(c);
  if (high === null || !c || !Number.isFinite(c.resolutionFloor)) return null;
  return c.resolutionFloor > high ? c.resolutionFloor : null;
}
