// The bound on what the proposed pass leaves (correction.predictedRmsHigh, µm rms on the probe
// grid), or null where no pass is proposed: a stop (the face is within the probe noise), a run
// kept (no change proposed), a proposal that is not to be used, or no finite bound. Shared by the
// page's sentences and files and the CLI's X3P (pure, with Node tests).
export function passBound(c) {
  if (!c || c.stop === true || c.runKept === true || c.usable === false) return null;
  return Number.isFinite(c.predictedRmsHigh) ? c.predictedRmsHigh : null;
}
