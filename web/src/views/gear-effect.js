// The effect of the rake face on the gear (docs/gear-effect.md): per flank the
// profile slope deviation fHα with its pressure-angle error, the profile form deviation ffα and
// their scatter along the hob; a plot of the gear's profile deviation over the active profile
// (one line per tooth of the gash) and one of fHα along the hob. Without the hob's relief the
// calculator's sentence says what is missing.
import { escapeHtml, fixed, withUnit } from '../format.js';
import { FLANKS, gearEffectRows, hasGearEffect } from '../gear-effect-figures.js';
import { unitText } from '../result-fields.js';
import { reactPlot } from '../plots/config.js';

const $ = (selector) => document.querySelector(selector);
// A field's unit as the module gives it (result-fields.js).
const unit = (path) => unitText(`gearEffect.${path}`);

function show(result) {
  const g = result.gearEffect;
  const on = hasGearEffect(g);
  $('#gear-effect').hidden = !on;
  $('#gear-effect-reason').hidden = on;
  $('#gear-effect-reason').textContent = g ? g.reason : '';
  $('[data-derived="sideReliefAngle"]').textContent = on ? `at d_p: ${withUnit(fixed(g.sideReliefAngle, 3), unit('sideReliefAngle'))}, k = ${withUnit(fixed(g.reliefPerRadian, 3), unit('reliefPerRadian'))}` : '';
  if (!on) return;
  $('#gear-effect-note').textContent = `From the ${g.source === 'simulated' ? 'simulated' : 'measured'} rake face; active profile on the hob `
    + `r = ${fixed(g.activeFrom, 2)} to ${withUnit(fixed(g.activeTo, 2), unit('activeTo'))}; ${g.alongHob.x.length} teeth of the gash along the hob. `
    + 'fHα plus: more material toward the gear\'s tip (a smaller pressure angle).';
  $('#gear-effect-table thead').innerHTML = `<tr><th>figure</th>${FLANKS.map(([, l]) => `<th>${escapeHtml(l)}</th>`).join('')}</tr>`;
  $('#gear-effect-table tbody').innerHTML = gearEffectRows(g).map(([label, unit, l, r]) => `<tr><th>${escapeHtml(label)}</th>
    <td class="num">${fixed(l, 3)} ${unit}</td><td class="num">${fixed(r, 3)} ${unit}</td></tr>`).join('');
}

const COLOURS = { left: '#1f77b4', right: '#d62728' };

function drawProfiles(Plotly, g) {
  const traces = [];
  const x = unit('alongHob.x'), height = unit('profile.height'), deviation = unit('profile.left');
  for (const [flank, label] of FLANKS) {
    Array.from(g.profile[flank]).forEach((row, t) => traces.push({
      x: row, y: g.profile.height, mode: 'lines', name: `${flank}, x = ${fixed(g.alongHob.x[t], 1)} ${x}`,
      legendgroup: flank, line: { color: COLOURS[flank], dash: flank === 'left' ? 'solid' : 'dash', width: 1.5 },
      hovertemplate: `${label}<br>height %{y:.2f} ${height}<br>deviation %{x:.4f} ${deviation}<extra>x = ${fixed(g.alongHob.x[t], 1)} ${x}</extra>`,
    }));
  }
  return reactPlot(Plotly, 'plot-gear-profile', traces, {
    title: { text: 'Gear profile deviation over the active profile' }, height: 360, margin: { t: 40, r: 20, b: 50, l: 60 },
    xaxis: { title: { text: `profile deviation on the gear (${deviation}, + = more material)` }, zeroline: true },
    yaxis: { title: { text: `height on the gear tooth (${height}, tip up)` } },
    showlegend: false,
  });
}

// A y range at least `least` µm wide about the values' middle, or none (Plotly's own) for a wider
// spread: fHα that does not change along the hob (scatter 0) is drawn flat, not its rounding
// noise (1e-9 µm) magnified to fill the plot with nine-digit tick labels.
function leastRange(values, least = 0.1) {
  let lo = Infinity, hi = -Infinity;  // a loop: no list is spread into a call
  for (const v of values) { lo = Math.min(lo, v); hi = Math.max(hi, v); }
  if (!(hi - lo < least)) return null;
  const mid = (lo + hi) / 2;
  return [mid - least / 2, mid + least / 2];
}

function drawAlong(Plotly, g) {
  const x = unit('alongHob.x'), slope = unit('alongHob.left.profileSlope');
  const traces = FLANKS.map(([flank, label]) => ({
    x: g.alongHob.x, y: g.alongHob[flank].profileSlope, mode: 'lines+markers', name: label,
    line: { color: COLOURS[flank], dash: flank === 'left' ? 'solid' : 'dash' },
    text: Array.from(g.alongHob[flank].pressureAngleError, (a) => `pressure-angle error ${withUnit(fixed(a, 3), unit(`alongHob.${flank}.pressureAngleError`))}`),
    hovertemplate: `x = %{x:.1f} ${x}<br>fHα = %{y:.4f} ${slope}<br>%{text}<extra></extra>`,
  }));
  const range = leastRange(FLANKS.flatMap(([flank]) => Array.from(g.alongHob[flank].profileSlope)));
  const yRange = range ? { range, autorange: false } : { autorange: true };
  return reactPlot(Plotly, 'plot-gear-along', traces, {
    title: { text: 'fHα along the hob' }, height: 360, margin: { t: 40, r: 20, b: 50, l: 60 },
    xaxis: { title: { text: `tooth position along the hob axis x (${x})` } },
    yaxis: { title: { text: `fHα (${slope})` }, zeroline: true, ...yRange },
    legend: { orientation: 'h', y: -0.25 },
  });
}

export function mountGearEffect(store, plots) {
  store.on('result', ({ result }) => show(result));
  plots.add(async ({ Plotly, result }) => {
    const g = result.gearEffect;
    if (!hasGearEffect(g)) return;
    await drawProfiles(Plotly, g);
    await drawAlong(Plotly, g);
  });
}
