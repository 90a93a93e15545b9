// The measured data's buttons: "Upload CSV…" reads a file into the box and uses it, "Use this
// grid" uses the box's text, "Clear" ends the measurement; "Upload X3P…" (views/x3p.js) puts its
// topography into the box as CSV and uses it as an uploaded CSV is. A file refused (empty, too
// large, too many values, or by the calculator) leaves what is in use (web/src/measurement.js).
import { MAX_MEASURED_BYTES, tooLargeMessage } from '../../../wasm/lib/csv.js';
import { chosenFileText } from '../io/files.js';
import { clearMeasurement, refuseFile, tooManyValues, useFile, useMeasurement } from '../measurement.js';
import { mountX3p } from './x3p.js';

const $ = (selector) => document.querySelector(selector);

export function mountMeasuredFiles(store) {
  const refuse = (message) => store.refuse({ field: 'measured', message });
  mountX3p(store, {
    take: (text, name) => useFile(store, text, name),
    refuse,
    refuseFile: (name, reason) => refuseFile(store, name, reason),
  });
  $('#use-measured').addEventListener('click', () => useMeasurement(store, store.state.measuredText));
  $('#clear-measured').addEventListener('click', () => clearMeasurement(store));
  $('#measured-file').addEventListener('change', async (e) => {
    const chosen = e.target.files[0];
    let file;
    try {
      file = await chosenFileText(e.target, MAX_MEASURED_BYTES, tooLargeMessage);
    } catch (err) {
      // Empty or too large: refused as a file (never an earlier file's note); "The file is empty."
      const name = chosen.name;
      refuseFile(store, name, err.message.startsWith(`${name} `) ? `The file ${err.message.slice(name.length + 1)}` : err.message);
      return;
    }
    if (!file) return;
    // Too many values: refused as a file, before the text goes into the box (issue 22, item 4).
    const many = tooManyValues(file.text);
    if (many) { refuseFile(store, file.name, many); return; }
    useFile(store, file.text, file.name);
  });
}
