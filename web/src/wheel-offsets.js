// The wheel's offsets along the profile normal as Fig. 4 shows them on its secondary scale (pure,
// with Node tests): the offset the wheel was dressed with (wheelProfile.offset), the offset the
// correction proposes to dress in addition (the spline through correction.wheelProfileOffset), and
// the two together (correction.dresserPath.offset), each as {name, R (mm), offset (µm)} at the
// profile's points, the proposal with its spline points as `knots`; an empty list for the conjugate
// wheel without a proposal.
export function wheelOffsetCurves(r) {
  const p = r.wheelProfile;
  const proposed = r.correction && r.correction.wheelProfileOffset;
  const after = r.correction && r.correction.dresserPath && r.correction.dresserPath.offset;
  const curves = [];
  if (p.offset) curves.push({ name: 'offset as dressed', R: p.R, offset: p.offset });
  if (proposed && proposed.R.length && after) {
    // The core evaluates the spline at the profile's radii: the offset after the dressing less the current one.
    const current = p.offset || p.R.map(() => 0);
    curves.push({ name: 'proposed in addition', R: p.R, offset: after.map((v, i) => v - current[i]),
      knots: { R: proposed.R, offset: proposed.offset } });
    if (p.offset) curves.push({ name: 'dressed after the correction', R: p.R, offset: after });
  }
  return curves;
}

// The range of the secondary scale, µm: symmetric about 0, at least ±1 µm, so that a zero offset
// reads as a line at 0 and a small one is not blown up to fill the plot.
export function offsetRange(curves) {
  const largest = Math.max(1, ...curves.flatMap((c) => [...c.offset, ...(c.knots ? c.knots.offset : [])].map(Math.abs)));
  return [-1.15 * largest, 1.15 * largest];
}
