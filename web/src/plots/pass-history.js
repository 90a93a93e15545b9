// The grinding passes plotted: per pass, measured (solid) and predicted (dashed), the rms (µm; the
// predicted point at the prediction's bound, a bar down to the identified machine's figure; the probe noise's floor, sigma, as a dotted line
// over a shaded band: a measured rms in the band is noise, and another pass would only move it), the sum of
// squares (µm²), the largest |deviation| (µm) and the thickness error (µm), side by side. The rms
// on a log scale that stops at a scale that means something (rmsAxisFloor: a tenth of the smallest
// probe noise, at least 0.01 µm): a figure below it is drawn on the axis's floor as a downward
// triangle, its value in the hover, so that a solver's 1e-20 does not stretch the scale over
// eighteen decades; the others linear. series: historySeries() of
// web/src/pass-history.js, which leaves out every value that is not finite. units: the module's
// units of the figures (result-fields.js), {rms, sse, max, thickness}.
import { reactPlot } from './config.js';

const PANELS = [
  { q: 'rms', title: 'RMS', log: true },
  { q: 'sse', title: 'Sum of squares' },
  { q: 'max', title: 'Largest |deviation|' },
  { q: 'thickness', title: 'Thickness error' },
];
const COLOURS = { measured: '#2b6cb0', predicted: '#dd6b20', floor: '#718096' };
const figure = (v) => String(Number(v.toPrecision(3)));

// The floor as a step line over the passes, from the plot's left edge to its right.
function floorLine(floor, passCount) {
  if (!floor.x.length) return null;
  return { x: [0.5, ...floor.x, passCount + 0.5], y: [floor.y[0], ...floor.y, floor.y[floor.y.length - 1]] };
}

// The rms axis's floor, µm: a tenth of the smallest probe noise, and never below 0.01 µm (what a
// rake-face measurement can tell apart at all).
export const LEAST_RMS_SHOWN = 0.01;
export function rmsAxisFloor(floorValues = []) {
  const sigmas = floorValues.filter((v) => Number.isFinite(v) && v > 0);
  return Math.max(LEAST_RMS_SHOWN, sigmas.length ? Math.min(...sigmas) / 10 : 0);
}

// Side by side, or, in a plot narrower than NARROW px (a phone), two by two, so that the panels'
// titles do not run into each other.
const NARROW = 640;

export function drawPassHistory(Plotly, el, series, passCount, units = {}) {
  const columns = ((el && el.clientWidth) || 1000) < NARROW ? 2 : PANELS.length;
  const rows = Math.ceil(PANELS.length / columns);
  const traces = [], layout = {
    height: rows > 1 ? 580 : 300, margin: { t: 60, r: 20, b: 50, l: 60 }, annotations: [], hovermode: 'closest',
    legend: { orientation: 'h', x: 0, xanchor: 'left', y: rows > 1 ? 1.1 : 1.2, yanchor: 'bottom' },
  };
  const ticks = Array.from({ length: Math.max(1, passCount) }, (_, i) => i + 1);
  const n = columns, gap = columns < PANELS.length ? 0.1 : 0.035, rowGap = 0.2;
  PANELS.forEach(({ q, title, log: logWhenPositive }, k) => {
    const unit = units[q] || '';
    const axis = k === 0 ? '' : String(k + 1);
    const i = k % columns, row = Math.floor(k / columns);
    const domain = [i / n + (i ? gap : 0), (i + 1) / n - (i < n - 1 ? gap : 0)];
    const yDomain = [1 - (row + 1) / rows + (row < rows - 1 ? rowGap : 0), 1 - row / rows];
    const s = series[q];
    const floor = q === 'rms' ? floorLine(series.floor || { x: [], y: [] }, passCount) : null;
    const high = q === 'rms' && s.predicted.high ? s.predicted.high : [];
    const values = [...s.measured.y, ...s.predicted.y, ...high.filter((v) => v !== null), ...(floor ? floor.y : [])];
    const log = Boolean(logWhenPositive);
    const bottom = log ? rmsAxisFloor(series.floor ? series.floor.y : []) : null;
    const shown = (v) => (log ? Math.max(v, bottom) : v);
    layout[`xaxis${axis}`] = { domain, anchor: `y${axis}`, title: { text: 'pass' }, tickvals: ticks, range: [0.5, passCount + 0.5] };
    layout[`yaxis${axis}`] = { domain: yDomain, anchor: `x${axis}`, type: log ? 'log' : 'linear', exponentformat: 'power', zeroline: q === 'thickness' };
    if (log) {
      const top = Math.max(bottom * 10, ...values.filter((v) => Number.isFinite(v)));
      layout[`yaxis${axis}`].range = [Math.log10(bottom), Math.log10(top) + 0.15];
    }
    layout.annotations.push({ text: `${title} (${unit})`, xref: 'paper', yref: 'paper', x: (domain[0] + domain[1]) / 2, y: yDomain[1] + (rows > 1 ? 0.01 : 0.02),
      xanchor: 'center', yanchor: 'bottom', showarrow: false, font: { size: 13 } });
    if (floor) {
      const sigmas = [...new Set(series.floor.y)];
      traces.push({
        type: 'scatter', mode: 'lines', x: floor.x, y: floor.y, xaxis: `x${axis}`, yaxis: `y${axis}`,
        name: sigmas.length === 1 ? `probe noise σ ${figure(sigmas[0])} ${unit}` : 'probe noise σ',
        line: { color: COLOURS.floor, dash: 'dot', width: 2, shape: 'hvh' }, fill: 'tozeroy', fillcolor: 'rgba(113, 128, 150, 0.18)',
        hovertemplate: `probe noise σ %{y:.3g} ${unit}: what noise alone measures, rms (the stop allows 3 of its standard deviations more)<extra></extra>`,
      });
    }
    // The rms predicted is drawn at its bound (what the pass leaves), a bar down to the identified
    // machine's figure; where there is no bound (the first pass's simulated face), at that figure.
    const bounded = (k) => high[k] !== null && high[k] !== undefined && high[k] >= s.predicted.y[k];
    const drawnAt = { measured: s.measured.y, predicted: s.predicted.y.map((y, k) => (bounded(k) ? high[k] : y)) };
    for (const set of ['measured', 'predicted']) {
      const below = drawnAt[set].map((y) => log && y < bottom);
      const symbol = set === 'predicted' ? 'circle-open' : 'circle';
      const trace = {
        type: 'scatter', mode: 'lines+markers', x: s[set].x, y: drawnAt[set].map(shown),
        xaxis: `x${axis}`, yaxis: `y${axis}`, name: set, legendgroup: set, showlegend: k === 0,
        line: { color: COLOURS[set], dash: set === 'predicted' ? 'dash' : 'solid' },
        marker: { size: 8, symbol: below.some(Boolean) ? below.map((b) => (b ? 'triangle-down' : symbol)) : symbol },
        customdata: drawnAt[set].map((y, k) => `${set === 'predicted' && bounded(k) ? 'at most ' : ''}${Number(y.toPrecision(4))} ${unit}${below[k] ? `, below the axis's ${figure(bottom)} ${unit}` : ''}`),
        hovertemplate: `pass %{x}, ${set}: %{customdata}<extra></extra>`,
      };
      // Below the bound, the identified machine's figure: a bar from the point (as drawn) down to it.
      if (set === 'predicted' && high.length) {
        const down = trace.y.map((y, k) => (bounded(k) ? Math.max(0, y - shown(s.predicted.y[k])) : 0));
        trace.error_y = { type: 'data', symmetric: false, array: down.map(() => 0), arrayminus: down, color: COLOURS.predicted, thickness: 1.5, width: 6 };
        trace.customdata = trace.customdata.map((text, k) => (bounded(k) ? `${text}; ${Number(s.predicted.y[k].toPrecision(4))} ${unit} on the identified machine` : text));
      }
      traces.push(trace);
    }
  });
  return reactPlot(Plotly, el, traces, layout);
}
