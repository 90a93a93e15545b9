// The wheel's offsets along the profile normal as Fig. 4 shows them on its secondary scale (pure,
// with Node tests): the offset the wheel was dressed with (wheelProfile.offset), the offset the
// correction proposes to dress in addition (correction.wheelProfileOffset), and the two together,
// each as {name, R (mm), offset (µm)}; an empty list for the conjugate wheel without a proposal.
export function wheelOffsetCurves(r) {
  const p = r.wheelProfile;
  const proposed = r.correction && r.correction.wheelProfileOffset;
  const curves = [];
  if (p.offset) curves.push({ name: 'offset as dressed', R: p.R, offset: p.offset });
  if (proposed && proposed.R.length) {
    curves.push({ name: 'proposed in addition', R: proposed.R, offset: proposed.offset });
    // The sum where both are known at the same radii (the proposal at the profile points).
    const current = p.offset || p.R.map(() => 0);
    const same = proposed.R.length === p.R.length && proposed.R.every((v, i) => Math.abs(v - p.R[i]) < 1e-9);
    if (same && p.offset) curves.push({ name: 'dressed after the correction', R: p.R, offset: current.map((v, i) => v + proposed.offset[i]) });
  }
  return curves;
}

// The range of the secondary scale, µm: symmetric about 0, at least ±1 µm, so that a zero offset
// reads as a line at 0 and a small one is not blown up to fill the plot.
export function offsetRange(curves) {
  const largest = Math.max(1, ...curves.flatMap((c) => c.offset.map(Math.abs)));
  return [-1.15 * largest, 1.15 * largest];
}
