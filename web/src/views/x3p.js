// The topography as an ISO 5436-2 X3P file (wasm/lib/x3p.js), beside the measured grid's CSV box:
// "Upload X3P…" reads a measured topography, checks its positions against the grid, and puts it
// into the box as CSV with its positions, so that the preview and "Use this grid" take it as
// they take a CSV; "Export topography (X3P)" writes the measured, the predicted (after the
// correction) or the simulated topography of the result on screen. A refused file leaves the box
// and the results as they were. The file is read off the page's thread (x3p-reader.js).
import { MAX_X3P_BYTES, writeX3p, x3pFileName, x3pGridCsv, x3pTopographies } from '../../../wasm/lib/x3p.js';
import { readX3pOffPage } from '../x3p-reader.js';
import { download } from '../io/files.js';
import { unitText } from '../result-fields.js';

const $ = (selector) => document.querySelector(selector);

// The chosen file's bytes (null when none was chosen); throws when it is empty or too large.
async function chosenFileBytes(input) {
  const file = input.files[0];
  input.value = '';
  if (!file) return null;
  if (file.size === 0) throw new Error(`${file.name} is empty.`);
  if (file.size > MAX_X3P_BYTES) {
    throw new Error(`${file.name} is ${(file.size / 1048576).toFixed(1)} MB; an X3P topography of at most 201 × 201 points is a few hundred kB (the limit is ${MAX_X3P_BYTES / 1048576} MB).`);
  }
  return { name: file.name, bytes: new Uint8Array(await file.arrayBuffer()) };
}

// take(text, name): puts text into the box, previews and uses it as the file `name` (the CSV
// upload's path); refuse(message): the measured grid's refusal; refuseFile(name, reason): a file's refusal,
// which says what stays in use (measurement.js), as a CSV file's does.
export function mountX3p(store, { take, refuse, refuseFile }) {
  const kind = $('#x3p-kind');
  const exportButton = $('#export-x3p');
  let offered = [];

  $('#measured-x3p-file').addEventListener('change', async (e) => {
    let file = null;
    try {
      file = await chosenFileBytes(e.target);
      if (!file) return;
      const r = store.state.result;
      if (!r) throw new Error('Compute a setup first, so that the grid is known.');
      const t = r.topography;
      store.setStatus(`Reading ${file.name}…`, 'busy');
      const { notes, values } = await readX3pOffPage(file.bytes, t);  // off the page's thread
      $('#x3p-read').textContent = `Read ${file.name}: ${notes.join(', ')}; its lines are the grid's.`;
      take(x3pGridCsv({ r: t.r, x: t.x, values }), file.name);
    } catch (err) {
      if (file) refuseFile(file.name, err.message);
      else refuse(err.message);
    }
  });

  store.on('result', ({ result, caseObject }) => {
    offered = x3pTopographies(result, caseObject, unitText);
    const was = kind.value;
    kind.innerHTML = offered.map((o) => `<option value="${o.kind}">${o.label}</option>`).join('');
    if (offered.some((o) => o.kind === was)) kind.value = was;
    exportButton.disabled = offered.length === 0;
  });
  exportButton.addEventListener('click', () => {
    const r = store.state.result;
    const chosen = offered.find((o) => o.kind === kind.value);
    if (!r || !chosen) return;
    const date = new Date();
    download(x3pFileName(chosen.kind, date), writeX3p({ r: r.topography.r, x: r.topography.x, values: chosen.values, kind: chosen.kind, date, note: chosen.note }), 'application/octet-stream');
  });
}
