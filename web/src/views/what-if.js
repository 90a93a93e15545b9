// The machine-error what-if ("Simulate a machine error..."): offsets the machine adds to each
// coefficient, ground into a face that is then taken as measured (the locks are in the
// correction's options: views/locks.js). Each finished change is an undo step; the offsets are
// saved with the case. The grid ground is noise-free, and the correction is told so (web/src/probe-noise.js).
import { AXES, coefficientUnit } from '../limits.js';
import { motionUnit } from '../format.js';
import { gridToCsv } from '../../../wasm/lib/csv.js';
import { tuningFor } from '../probe-noise.js';

const $ = (selector) => document.querySelector(selector);

function renderTable(r, state) {
  const degree = r.axes.X.length - 1;
  const per = motionUnit(r);
  const head = ['<tr><th>axis</th>'];
  for (let k = 0; k <= degree; k++) head.push(`<th>a${k}</th>`);
  $('#what-if thead').innerHTML = head.join('') + '</tr>';
  $('#what-if tbody').innerHTML = AXES.map((a) => {
    const offsets = state.offsets[a] || [];
    const cells = [];
    for (let k = 0; k <= degree; k++) {
      const name = `${a} a${k}`;
      const unit = coefficientUnit(a, k, per);
      cells.push(`<td><input type="number" step="any" data-offset="${a} ${k}" value="${offsets[k] || ''}" placeholder="0"
        title="offset of ${name}, ${unit}" aria-label="Offset of ${name} (${unit})"><span class="unit">${unit}</span></td>`);
    }
    return `<tr><th>${a}</th>${cells.join('')}</tr>`;
  }).join('');
}

export function mountWhatIf(store, calculator, measuredView) {
  // Drawn again only when what it shows changed, so that a tick keeps the keyboard's place.
  let drawn = '';
  const render = (force) => {
    const s = store.state;
    if (!s.result) return;
    const key = JSON.stringify([s.result.axes.X.length, motionUnit(s.result), s.offsets]);
    if (force || key !== drawn) { renderTable(s.result, s); drawn = key; }
  };
  store.on('result', () => render(false));
  store.on('restore', () => render(true));

  $('#what-if').addEventListener('change', (e) => {
    const t = e.target;
    const s = store.state;
    if (t.dataset.offset) {
      const [a, k] = t.dataset.offset.split(' ');
      (s.offsets[a] = s.offsets[a] || [])[Number(k)] = t.value === '' ? 0 : Number(t.value);
      store.emit('commit');
    }
  });
  $('#reset-error').addEventListener('click', () => { store.state.offsets = {}; render(true); store.emit('commit'); });
  $('#generate-error').addEventListener('click', async () => {
    const s = store.state;
    if (!s.result) return;
    // The machine adds the offsets to the axes it is given: the run axes of a second pass, if any.
    const given = s.result.runAxes || s.result.axes;
    const axes = {};
    for (const a of AXES) axes[a] = given[a].map((v, k) => v + ((s.offsets[a] || [])[k] || 0));
    store.setStatus('Grinding the face with the machine error…', 'busy');
    try {
      const { result } = await calculator.evaluate({ ...structuredClone(s.form), axes });
      const measured = result.topography.normal;
      measuredView.setText(gridToCsv(measured, 4));
      store.setInputs({ measured, tuning: tuningFor(s.tuning, true) }, { source: 'measured', force: true });
      store.emit('commit');
    } catch (e) {
      store.refuse({ field: 'measured', message: `The machine error cannot be ground: ${e.message}` });
    }
  });
}
