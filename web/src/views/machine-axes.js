// The axes to run in the units the control takes (web/src/machine-axes.js): with a correction its
// proposal as the NC program carries it (correction.roundedAxes), with the face predicted with it
// and the pass's floor, else the axes run; the coefficients per power of the hob rotation in
// degrees to the digits the program carries, a copy button, and the axis positions over the
// motion range as CSV at the step the user chooses.
import { AXES, CORRECTION } from '../limits.js';
import { unitText } from '../result-fields.js';
import { download } from '../io/files.js';
import { axisPositions, coefficientsText, machineUnit, positionsCsv, programNote, programmed, roundedFiguresText } from '../machine-axes.js';
import { axesToRun, machineCoefficients, programFor } from '../../../wasm/lib/axes-to-run.js';

const $ = (selector) => document.querySelector(selector);

// The axes shown, and in words which they are (axesToRun: the CLI's NC program takes the same).
function axesOf(state) {
  const { axes, words } = axesToRun(state.result, state.resultCase && state.resultCase.axes);
  return { axes, source: `(${words})` };
}
const programOf = (state) => programFor(state.result, state.resultCase, $('#nc-dialect').value, { digits: CORRECTION.coefficientDigits });

export function mountMachineAxes(store) {
  const helical = () => store.state.result.setup.motionUnit === 'rad';
  function render(state) {
    const { axes, source } = axesOf(state);
    const h = helical();
    const m = machineCoefficients(axes, h);
    const degree = axes.X.length - 1;
    $('#machine-axes-source').textContent = source;
    $('#machine-axes-figures').textContent = roundedFiguresText(state.result.correction, unitText);
    $('#positions-step-unit').textContent = h ? 'deg' : 'mm';
    $('#machine-coefficients thead').innerHTML = `<tr><th>axis</th>${Array.from({ length: degree + 1 }, (_, k) => `<th>a${k}</th>`).join('')}</tr>`;
    $('#machine-coefficients tbody').innerHTML = AXES.map((a) => `<tr data-axis="${a}"><th>${a}</th>${m[a].map((c, k) =>
      `<td class="num" title="${machineUnit(a, k, h)}">${programmed(c, CORRECTION.coefficientDigits)} <span class="unit">${machineUnit(a, k, h)}</span></td>`).join('')}</tr>`).join('');
    noteProgram(state);
  }
  // The NC program's blocks and deviation beside its buttons, for the control chosen.
  // The printed report's "Program this" prints the same program ('ncProgram').
  function noteProgram(state) {
    const note = $('#nc-note');
    try {
      const program = programOf(state);
      note.textContent = programNote(program);
      const select = $('#nc-dialect');
      store.emit('ncProgram', { program: { name: select.options[select.selectedIndex].textContent, text: program.text } });
    } catch (e) {
      note.textContent = e.message;
      store.emit('ncProgram', { program: null });
    }
  }
  $('#nc-dialect').addEventListener('change', () => { if (store.state.result) noteProgram(store.state); });
  $('#copy-nc').addEventListener('click', async () => {
    if (!store.state.result) return;
    let program;
    try {
      program = programOf(store.state);
    } catch (e) {
      $('#nc-note').textContent = e.message;
      return;
    }
    try {
      await navigator.clipboard.writeText(program.text);
      store.setStatus(`The NC program (${program.fileName}) is on the clipboard.`, 'ok');
    } catch (e) {
      store.setStatus('The clipboard is not available here: download the NC program instead.', 'error');
    }
  });
  $('#download-nc').addEventListener('click', () => {
    if (!store.state.result) return;
    try {
      const program = programOf(store.state);
      download(program.fileName, program.text, 'text/plain;charset=us-ascii');
    } catch (e) {
      $('#nc-note').textContent = e.message;
    }
  });
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
      download('hobsharp-axis-positions.csv', positionsCsv(rows, helical(), { decimalComma: $('#csv-style').value === 'semicolon' }), 'text/csv;charset=utf-8');
    } catch (e) {
      note.textContent = e.message;
    }
  });
}
