// The measured data's box (state.measuredText): what the user types goes into the state, and
// what others give (a file, a loaded case, an undo step) into the box. Text pasted or dropped
// counts against the same limits as an uploaded file; over them, nothing is inserted (a 100 MB
// paste would freeze the page, and so would a million lines). Above it, the grid's shape.
import { MAX_MEASURED_BYTES, tooLargeMessage } from '../../../wasm/lib/csv.js';
import { tooManyValues, typed } from '../measurement.js';

const $ = (selector) => document.querySelector(selector);

function guardSize(box, refuse) {
  const guard = (event, text, what) => {
    const kept = box.value.length - (box.selectionEnd - box.selectionStart);
    const many = kept + text.length <= MAX_MEASURED_BYTES ? tooManyValues(text) : '';
    if (kept + text.length <= MAX_MEASURED_BYTES && !many) return;
    event.preventDefault();
    refuse(many ? `${what}: ${many}` : tooLargeMessage(what, text.length));
  };
  box.addEventListener('paste', (e) => guard(e, e.clipboardData ? e.clipboardData.getData('text/plain') : '', 'The pasted text'));
  box.addEventListener('drop', (e) => guard(e, e.dataTransfer ? e.dataTransfer.getData('text/plain') : '', 'The dropped text'));
}

export function mountMeasuredBox(store) {
  const box = $('#measured-csv');
  box.addEventListener('input', () => typed(store, box.value));
  store.on('measured-text', ({ source }, state) => {
    if (source !== 'box') box.value = state.measuredText;
  });
  guardSize(box, (message) => store.refuse({ field: 'measured', message }));
  store.on('result', ({ result }) => {
    $('#grid-shape').textContent = `${result.topography.r.length} rows × ${result.topography.x.length} values`;
  });
}
