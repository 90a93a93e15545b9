// Runs inside the module factory (--pre-js). It gives the module its JS API, the same in the
// browser and in Node: Module.evaluate(case) takes a `hobsharp-case/1` object and returns plain
// JS data, or throws an Error whose message names the field (error.field holds its name).

// A flat row-major Float64Array as a list of rows.
function hobsharpRows(flat, rows, cols) {
  const out = [];
  for (let i = 0; i < rows; i++) out.push(Array.from(flat.subarray(i * cols, (i + 1) * cols)));
  return out;
}

function hobsharpAxes(a) {
  const out = {};
  for (const k of ['X', 'Y', 'Z', 'A', 'B']) out[k] = Array.from(a[k]);
  return out;
}

function hobsharpTopography(t) {
  return {
    r: Array.from(t.r), x: Array.from(t.x),
    normal: hobsharpRows(t.normal, t.rows, t.cols),
    circular: hobsharpRows(t.circular, t.rows, t.cols),
    thickness: t.thickness, sse: t.sse, max: t.max,
  };
}

Module['evaluate'] = function (caseObject) {
  if (caseObject === null || typeof caseObject !== 'object' || Array.isArray(caseObject)) {
    throw new TypeError('evaluate(case): the case must be a hobsharp-case/1 object');
  }
  let r;
  try {
    r = Module['evaluateJson'](JSON.stringify(caseObject));
  } catch (e) {
    // Nothing should get here (the bindings catch every C++ exception); never leak a bare number.
    throw new Error('The calculation failed inside the module: ' + (e && e.message ? e.message : String(e)));
  }
  if (!r.ok) {
    const error = new Error(r.message);
    error.field = r.field;
    throw error;
  }
  const s = r.sensitivities, cells = s.rows * s.cols;
  const out = {
    setup: r.setup,
    axes: hobsharpAxes(r.axes),
    runAxes: hobsharpAxes(r.runAxes),
    wheelProfile: { r: Array.from(r.wheelProfile.r), beta: Array.from(r.wheelProfile.beta),
                    R: Array.from(r.wheelProfile.R), Z: Array.from(r.wheelProfile.Z) },
    motion: r.motion,
    topography: hobsharpTopography(r.topography),
    sensitivities: {
      coefficients: r.sensitivities.coefficients,
      normal: s.coefficients.map((_, j) => hobsharpRows(s.normal.subarray(j * cells, (j + 1) * cells), s.rows, s.cols)),
      thickness: Array.from(s.thickness),
    },
  };
  if (r.correction) {
    const c = r.correction;
    const predicted = hobsharpTopography(c.predicted);
    out.correction = {
      axes: hobsharpAxes(c.axes),
      coefficients: c.coefficients,
      change: Array.from(c.change),
      residual: predicted.normal,
      residualCircular: predicted.circular,
      measuredCircular: hobsharpRows(c.measured.circular, c.measured.rows, c.measured.cols),
      sseBefore: c.sseBefore, sseAfter: c.sseAfter,
      maxBefore: c.measured.max, maxAfter: c.predicted.max,
      thicknessBefore: c.thicknessBefore, thicknessAfter: c.thicknessAfter,
      singularValues: Array.from(c.singularValues),
      rank: c.rank, amplifyingDropped: c.amplifyingDropped,
      unobservable: c.unobservable,
      uncorrectableShare: c.uncorrectableShare,
      verdict: c.verdict,
    };
  }
  return out;
};
