// Which axes the control is to run, in words (pure, with Node tests): with a correction its
// proposal as the NC program carries it (correction.roundedAxes); when the correction says stop
// (the face measured is within the probe noise) the axes run, kept; without a correction the axes
// run, or the nominal ones. The page's "Axes to run" block and the printed report's "Program
// this" table show these (in the control's units, web/src/machine-axes.js).
export function axesToRun(state) {
  const r = state.result, c = r.correction;
  if (c && c.stop === true) {
    return { axes: r.runAxes || (state.resultCase && state.resultCase.axes) || r.axes,
      source: '(the axes run: keep them; the face measured is within the probe noise)' };
  }
  if (c && c.roundedAxes) return { axes: c.roundedAxes, source: '(the corrected proposal, as the NC program carries it)' };
  if (state.resultCase && state.resultCase.axes) return { axes: state.resultCase.axes, source: '(the axes run; no correction)' };
  return { axes: r.axes, source: '(nominal; no correction)' };
}
