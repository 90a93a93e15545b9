// The grinding passes plotted: per pass, measured (solid) and predicted (dashed), the rms (µm, with
// the prediction's bound as a bar above it and the probe noise's floor, sigma, as a dotted line
// over a shaded band: a measured rms in the band is noise, and another pass would only move it), the sum of
// squares (µm²), the largest |deviation| (µm) and the thickness error (µm), side by side; the rms
// and the sum of squares on a log scale while every value is positive. series: historySeries() of
// web/src/pass-history.js, which leaves out every value that is not finite. units: the module's
// units of the figures (result-fields.js), where it gives them.
const PANELS = [
  { q: 'rms', title: 'RMS', unit: 'µm', log: true },
  { q: 'sse', title: 'Sum of squares', unit: 'µm²', log: true },
  { q: 'max', title: 'Largest |deviation|', unit: 'µm' },
  { q: 'thickness', title: 'Thickness error', unit: 'µm' },
];
const COLOURS = { measured: '#2b6cb0', predicted: '#dd6b20', floor: '#718096' };
const figure = (v) => String(Number(v.toPrecision(3)));

// The floor as a step line over the passes, from the plot's left edge to its right.
function floorLine(floor, passCount) {
  if (!floor.x.length) return null;
  return { x: [0.5, ...floor.x, passCount + 0.5], y: [floor.y[0], ...floor.y, floor.y[floor.y.length - 1]] };
}

export function drawPassHistory(Plotly, el, series, passCount, units = {}) {
  const traces = [], layout = {
    height: 300, margin: { t: 60, r: 20, b: 50, l: 60 }, annotations: [], hovermode: 'closest',
    legend: { orientation: 'h', x: 0, xanchor: 'left', y: 1.2, yanchor: 'bottom' },
  };
  const ticks = Array.from({ length: Math.max(1, passCount) }, (_, i) => i + 1);
  const n = PANELS.length, gap = 0.035;
  PANELS.forEach(({ q, title, unit: fallback, log: logWhenPositive }, i) => {
    const unit = units[q] || fallback;
    const axis = i === 0 ? '' : String(i + 1);
    const domain = [i / n + (i ? gap : 0), (i + 1) / n - (i < n - 1 ? gap : 0)];
    const s = series[q];
    const floor = q === 'rms' ? floorLine(series.floor || { x: [], y: [] }, passCount) : null;
    const high = q === 'rms' && s.predicted.high ? s.predicted.high : [];
    const values = [...s.measured.y, ...s.predicted.y, ...high.filter((v) => v !== null), ...(floor ? floor.y : [])];
    const log = Boolean(logWhenPositive) && values.length > 0 && values.every((v) => v > 0);
    layout[`xaxis${axis}`] = { domain, anchor: `y${axis}`, title: { text: 'pass' }, tickvals: ticks, range: [0.5, passCount + 0.5] };
    layout[`yaxis${axis}`] = { anchor: `x${axis}`, type: log ? 'log' : 'linear', exponentformat: 'power', zeroline: q === 'thickness' };
    layout.annotations.push({ text: `${title} (${unit})`, xref: 'paper', yref: 'paper', x: (domain[0] + domain[1]) / 2, y: 1.02,
      xanchor: 'center', yanchor: 'bottom', showarrow: false, font: { size: 13 } });
    if (floor) {
      const sigmas = [...new Set(series.floor.y)];
      traces.push({
        type: 'scatter', mode: 'lines', x: floor.x, y: floor.y, xaxis: `x${axis}`, yaxis: `y${axis}`,
        name: sigmas.length === 1 ? `probe noise σ ${figure(sigmas[0])} ${unit}` : 'probe noise σ',
        line: { color: COLOURS.floor, dash: 'dot', width: 2, shape: 'hvh' }, fill: 'tozeroy', fillcolor: 'rgba(113, 128, 150, 0.18)',
        hovertemplate: `probe noise σ %{y:.3g} ${unit}: below it the face is noise<extra></extra>`,
      });
    }
    for (const set of ['measured', 'predicted']) {
      const trace = {
        type: 'scatter', mode: 'lines+markers', x: s[set].x, y: s[set].y,
        xaxis: `x${axis}`, yaxis: `y${axis}`, name: set, legendgroup: set, showlegend: i === 0,
        line: { color: COLOURS[set], dash: set === 'predicted' ? 'dash' : 'solid' },
        marker: { size: 8, symbol: set === 'predicted' ? 'circle-open' : 'circle' },
        hovertemplate: `pass %{x}, ${set}: %{y:.4g} ${unit}<extra></extra>`,
      };
      // The prediction's bound: a bar from the predicted rms up to it.
      if (set === 'predicted' && high.length) {
        const up = s.predicted.y.map((y, k) => (high[k] !== null && high[k] >= y ? high[k] - y : 0));
        trace.error_y = { type: 'data', symmetric: false, array: up, arrayminus: up.map(() => 0), color: COLOURS.predicted, thickness: 1.5, width: 6 };
        trace.customdata = high.map((h) => (h === null ? '' : `, at most ${figure(h)} ${unit}`));
        trace.hovertemplate = `pass %{x}, predicted: %{y:.4g} ${unit}%{customdata}<extra></extra>`;
      }
      traces.push(trace);
    }
  });
  return Plotly.react(el, traces, layout, { responsive: true, displaylogo: false });
}
