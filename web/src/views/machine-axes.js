// The axes to run in the units the control takes (web/src/machine-axes.js): with a correction its
// proposal as the NC program carries it (correction.roundedAxes), with the face predicted with it
// and the pass's floor, else the axes run; the coefficients per power of the hob rotation in
// degrees to the digits the program carries, a copy button, and the axis positions over the
// motion range as CSV at the step the user chooses.
import { AXES, CORRECTION } from '../limits.js';
import { fieldUnit } from '../result-fields.js';
import { download } from '../io/files.js';
import { axisPositions, coefficientsText, machineCoefficients, machineUnit, positionsCsv, programmed, roundedFiguresText } from '../machine-axes.js';

const $ = (selector) => document.querySelector(selector);

// The axes shown, and in words which they are. When the correction says stop (the face measured
// is within the probe noise) the axes run stay: those are shown, not a proposal.
function axesOf(state) {
  const r = state.result, c = r.correction;
  if (c && c.stop === true) {
    return { axes: r.runAxes || (state.resultCase && state.resultCase.axes) || r.axes,
      source: '(the axes run: keep them; the face measured is within the probe noise)' };
  }
  if (c && c.roundedAxes) return { axes: c.roundedAxes, source: '(the corrected proposal, as the NC program carries it)' };
  if (state.resultCase && state.resultCase.axes) return { axes: state.resultCase.axes, source: '(the axes run; no correction)' };
  return { axes: r.axes, source: '(nominal; no correction)' };
}

export function mountMachineAxes(store) {
  const helical = () => store.state.result.setup.motionUnit === 'rad';
  function render(state) {
    const { axes, source } = axesOf(state);
    const h = helical();
    const m = machineCoefficients(axes, h);
    const degree = axes.X.length - 1;
    $('#machine-axes-source').textContent = source;
    $('#machine-axes-figures').textContent = roundedFiguresText(state.result.correction, (path) => fieldUnit(path) || '');
    $('#positions-step-unit').textContent = h ? 'deg' : 'mm';
    $('#machine-coefficients thead').innerHTML = `<tr><th>axis</th>${Array.from({ length: degree + 1 }, (_, k) => `<th>a${k}</th>`).join('')}</tr>`;
    $('#machine-coefficients tbody').innerHTML = AXES.map((a) => `<tr data-axis="${a}"><th>${a}</th>${m[a].map((c, k) =>
      `<td class="num" title="${machineUnit(a, k, h)}">${programmed(c, CORRECTION.coefficientDigits)} <span class="unit">${machineUnit(a, k, h)}</span></td>`).join('')}</tr>`).join('');
  }
  store.on('result', (_, state) => render(state));
  $('#copy-axes').addEventListener('click', async () => {
    if (!store.state.result) return;
    const text = coefficientsText(machineCoefficients(axesOf(store.state).axes, helical()), helical(), CORRECTION.coefficientDigits);
    try {
      await navigator.clipboard.writeText(text);
      store.setStatus('The coefficients are on the clipboard.', 'ok');
    } catch (e) {
      store.setStatus('The clipboard is not available here: select the table and copy it.', 'error');
    }
  });
  $('#download-positions').addEventListener('click', () => {
    const r = store.state.result;
    if (!r) return;
    const note = $('#positions-note');
    try {
      const rows = axisPositions(axesOf(store.state).axes, r.motion.min, r.motion.max, Number($('#positions-step').value), helical());
      note.textContent = `${rows.length} positions.`;
      download('hobsharp-axis-positions.csv', positionsCsv(rows, helical()), 'text/csv;charset=utf-8');
    } catch (e) {
      note.textContent = e.message;
    }
  });
}
