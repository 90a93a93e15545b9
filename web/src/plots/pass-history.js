// The grinding passes plotted: per pass, measured (solid) and predicted (dashed), the sum of
// squares (µm², on a log scale while every value is positive), the largest |deviation| (µm) and
// the thickness error (µm), side by side. series: historySeries() of web/src/pass-history.js,
// which leaves out every value that is not finite.
const PANELS = [
  { q: 'sse', title: 'Sum of squares (µm²)', unit: 'µm²' },
  { q: 'max', title: 'Largest |deviation| (µm)', unit: 'µm' },
  { q: 'thickness', title: 'Thickness error (µm)', unit: 'µm' },
];
const COLOURS = { measured: '#2b6cb0', predicted: '#dd6b20' };

export function drawPassHistory(Plotly, el, series, passCount) {
  const traces = [], layout = {
    height: 300, margin: { t: 60, r: 20, b: 50, l: 60 }, annotations: [], hovermode: 'closest',
    legend: { orientation: 'h', x: 0, xanchor: 'left', y: 1.2, yanchor: 'bottom' },
  };
  const ticks = Array.from({ length: Math.max(1, passCount) }, (_, i) => i + 1);
  PANELS.forEach(({ q, title, unit }, i) => {
    const n = i === 0 ? '' : String(i + 1);
    const domain = [i / 3 + (i ? 0.04 : 0), (i + 1) / 3 - (i < 2 ? 0.04 : 0)];
    const values = [...series[q].measured.y, ...series[q].predicted.y];
    const log = q === 'sse' && values.length > 0 && values.every((v) => v > 0);
    layout[`xaxis${n}`] = { domain, anchor: `y${n}`, title: { text: 'pass' }, tickvals: ticks, range: [0.5, passCount + 0.5] };
    layout[`yaxis${n}`] = { anchor: `x${n}`, type: log ? 'log' : 'linear', exponentformat: 'power', zeroline: q === 'thickness' };
    layout.annotations.push({ text: title, xref: 'paper', yref: 'paper', x: (domain[0] + domain[1]) / 2, y: 1.02,
      xanchor: 'center', yanchor: 'bottom', showarrow: false, font: { size: 13 } });
    for (const set of ['measured', 'predicted']) {
      traces.push({
        type: 'scatter', mode: 'lines+markers', x: series[q][set].x, y: series[q][set].y,
        xaxis: `x${n}`, yaxis: `y${n}`, name: set, legendgroup: set, showlegend: i === 0,
        line: { color: COLOURS[set], dash: set === 'predicted' ? 'dash' : 'solid' },
        marker: { size: 8, symbol: set === 'predicted' ? 'circle-open' : 'circle' },
        hovertemplate: `pass %{x}, ${set}: %{y:.4g} ${unit}<extra></extra>`,
      });
    }
  });
  return Plotly.react(el, traces, layout, { responsive: true, displaylogo: false });
}
