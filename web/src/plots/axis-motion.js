// The five axis motions over the motion range. With a correction, what it changes: corrected
// minus nominal, X, Y, Z in µm and A, B in arc-seconds (the page's display units for a change:
// µm-level changes vanish in a plot of the motions themselves); without one, the nominal motions
// in the axes' own units as the module states them (limits().axes: mm and rad).
import { AXES, AXIS_UNIT, isRotary } from '../limits.js';
import { motionSymbol, motionUnit } from '../format.js';
import { polynomialAt } from '../../../wasm/lib/polynomial.js';
import { reactPlot } from './config.js';

const ARCSEC_PER_RAD = (180 / Math.PI) * 3600;

export function drawAxisMotion(Plotly, el, r) {
  const n = 121, lo = r.motion.min, hi = r.motion.max;
  const t = Array.from({ length: n }, (_, i) => lo + ((hi - lo) * i) / (n - 1));
  const corrected = r.correction && r.correction.axes;
  const traces = AXES.map((a) => {
    const scale = corrected ? (isRotary(a) ? ARCSEC_PER_RAD : 1000) : 1;
    const unit = corrected ? (isRotary(a) ? '″' : 'µm') : AXIS_UNIT[a];
    const y = t.map((v) => scale * (corrected ? polynomialAt(corrected[a], v) - polynomialAt(r.axes[a], v) : polynomialAt(r.axes[a], v)));
    return {
      x: t, y, name: corrected ? `Δ${a}` : a, mode: 'lines', yaxis: isRotary(a) ? 'y2' : 'y',
      line: { dash: isRotary(a) ? 'dot' : 'solid' },
      hovertemplate: `${corrected ? 'Δ' : ''}${a} = %{y:.4g} ${unit}<extra></extra>`,
    };
  });
  const title = corrected
    ? 'Correction of the axis motions (corrected − nominal)'
    : 'Axis motions over the motion range (nominal)';
  return reactPlot(Plotly, el, traces, {
    title: { text: title, font: { size: 14 }, y: 0.97 }, height: 340, margin: { t: 64, r: 70, b: 50, l: 70 },
    hovermode: 'x unified',
    xaxis: { title: { text: `motion parameter ${motionSymbol(r)} (${motionUnit(r)})` } },
    yaxis: { title: { text: corrected ? 'ΔX, ΔY, ΔZ (µm)' : `X, Y, Z (${AXIS_UNIT.X})` } },
    yaxis2: { title: { text: corrected ? 'ΔA, ΔB (arc-seconds)' : `A, B (${AXIS_UNIT.A})` }, overlaying: 'y', side: 'right', showgrid: false },
    // Above the plot, under its title: clear of the axis titles and of the curves.
    legend: { orientation: 'h', x: 0, xanchor: 'left', y: 1.02, yanchor: 'bottom' },
  });
}
