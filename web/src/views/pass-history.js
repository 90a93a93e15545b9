// The grinding passes: "Use as next run" (the pass under way kept, the proposed axes into the
// run), the history as a table and a plot, per pass measured and predicted (web/src/pass-history.js
// says which figures). A kept pass's figures come from the calculator: its case (the form, its
// axes and grid) is evaluated once and the figures kept; a pass the calculator refuses (the grid
// changed since) shows why in its row.
import { escapeHtml, faceFigure, fixed, signed } from '../format.js';
import { STOP_WHY, historyRows, historySeries, nextRunInputs, passCase, predictedRmsText, resultFigures } from '../pass-history.js';
import { drawPassHistory } from '../plots/pass-history.js';
import { loadPlotly } from '../plots/passes.js';
import { fieldMeaning, fieldUnit, unitText } from '../result-fields.js';

const $ = (selector) => document.querySelector(selector);

// The figures' units as the module gives them (the measured ones; the predicted have the same).
const units = () => Object.fromEntries(['rms', 'sse', 'max', 'thickness'].map((q) => [q, unitText(`correction.${q}Before`)]));

// The figures on the scale a probe reads (issue 22): an rms below 0.001 µm and a sum of squares
// below 1e-6 µm² are "below" that, not the solver's 3e-11.
const LEAST_SSE = 1e-6;

const cells = (f, set) => (f
  ? `<td class="num" data-${set}="rms">${predictedRmsText(f)}</td><td class="num" data-${set}="sse">${faceFigure(f.sse, LEAST_SSE, 6)}</td>` +
    `<td class="num" data-${set}="max">${fixed(f.max, 3)}</td><td class="num" data-${set}="thickness">${signed(f.thickness, 3)}</td>`
  : '<td class="num">—</td><td class="num">—</td><td class="num">—</td><td class="num">—</td>');

// The predicted rms is correction.predictedRms, the face without the probe's noise (the other
// predicted figures keep the measurement's residual, noise and all), with its bound.
function renderTable(rows) {
  const u = units();
  const rest = `<th>sum of squares (${escapeHtml(u.sse)})</th>` +
    `<th>largest |deviation| (${escapeHtml(u.max)})</th><th>thickness error (${escapeHtml(u.thickness)})</th>`;
  const predictedRms = `<th title="${escapeHtml(fieldMeaning('correction.predictedRms'))}">rms, probe noise taken out (${escapeHtml(fieldUnit('correction.predictedRms') || u.rms)})</th>`;
  $('#pass-table thead').innerHTML = '<tr><th rowspan="2">pass</th><th colspan="4">measured</th>' +
    `<th colspan="4">predicted</th><th rowspan="2">note</th></tr><tr><th>rms (${escapeHtml(u.rms)})</th>${rest}${predictedRms}${rest}</tr>`;
  $('#pass-table tbody').innerHTML = rows.map((r) => `<tr data-pass="${r.pass}">
    <th>${escapeHtml(r.label)}</th>${cells(r.measured, 'measured')}${cells(r.predicted, 'predicted')}
    <td class="pass-note">${escapeHtml(r.note)}</td></tr>`).join('');
}

export function mountPassHistory(store, calculator, measuredView) {
  const section = $('#passes-section');
  const figures = new Map();  // a kept pass's case (JSON) -> its figures, {error}, or null while computed
  let filling = false;

  const keys = (state) => state.passes.map((p) => JSON.stringify(passCase(state, p)));

  function render() {
    const state = store.state;
    const next = nextRunInputs(state);
    $('#next-run').disabled = !next.inputs;
    $('#next-run-why').textContent = next.why || '';
    $('#next-run-why').classList.toggle('stop', next.why === STOP_WHY);
    $('#clear-passes').hidden = !state.passes.length;
    const shown = Boolean(state.result) && (state.passes.length > 0 || Boolean(state.result.correction));
    $('#pass-history').hidden = !shown;
    if (!shown) return;
    const kept = keys(state).map((k) => (figures.has(k) ? figures.get(k) : null));
    const rows = historyRows(kept, resultFigures(state.result));
    renderTable(rows);
    const count = rows.length ? rows[rows.length - 1].pass : 1;
    loadPlotly().then((Plotly) => drawPassHistory(Plotly, $('#plot-passes'), historySeries(rows), count, units()))
      .then(() => { section.dataset.drawn = String(rows.length); }, () => {});
  }

  // Evaluates the kept passes not yet known, one at a time, showing each as it arrives.
  async function fill() {
    if (filling) return;
    filling = true;
    try {
      for (;;) {
        const state = store.state;
        const i = keys(state).findIndex((k) => !figures.has(k));
        if (i < 0) break;
        const c = passCase(state, state.passes[i]), key = JSON.stringify(c);
        figures.set(key, null);
        try {
          const { result } = await calculator.evaluate(c);
          figures.set(key, resultFigures(result));
        } catch (e) {
          figures.set(key, { error: `not computed: ${e.message}` });
        }
        render();
      }
    } finally {
      filling = false;
    }
  }

  const update = () => { if (figures.size > 500) figures.clear(); render(); fill(); };
  for (const event of ['result', 'restore', 'inputs']) store.on(event, update);
  store.on('width', render);  // the window made wider or narrower: the panels laid out again

  $('#next-run').addEventListener('click', () => {
    const { inputs, why } = nextRunInputs(store.state);
    if (!inputs) { store.setStatus(why, 'error'); return; }
    measuredView.setText('');
    store.setInputs(inputs, { source: 'passes', force: true });
    store.emit('commit');
  });
  $('#clear-passes').addEventListener('click', () => {
    if (!window.confirm('Clear the history of grinding passes? Undo brings it back.')) return;
    store.setInputs({ passes: [] }, { source: 'passes', force: true });
    store.emit('commit');
  });
}
