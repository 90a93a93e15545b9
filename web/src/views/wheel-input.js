// The wheel as dressed: the conjugate wheel of Eqs. 3-6, a dressed wheel's offset or a measured
// wheel's axial profile loaded from a CSV file (wasm/lib/wheel-csv.js), kept in the case as
// wheel.profileOffset or wheel.measuredProfile. A file the page cannot read changes nothing; a
// wheel the calculator refuses is named here and stays, so that it can be replaced or removed.
import { MAX_MEASURED_BYTES } from '../../../wasm/lib/csv.js';
import { chosenFileText } from '../io/files.js';
import { readWheelCsv, wheelSource, withWheelPoints } from '../../../wasm/lib/wheel-csv.js';

const $ = (selector) => document.querySelector(selector);
export const isWheelField = (field) => /^wheel\.(profileOffset|measuredProfile)/.test(field || '');

function show(state) {
  const source = wheelSource(state.extra);
  $('#wheel-source').textContent = source ? `Wheel: ${source.text}` : 'Wheel: the conjugate profile of the face (Eqs. 3-6).';
  $('#wheel-conjugate').disabled = !source;
}

// from: 'page' (a file it could not read) or 'calculator' (a wheel it refused, cleared by the next result).
function setError(text, from = 'page') {
  const box = $('#wheel-error');
  box.textContent = text || '';
  box.hidden = !text;
  box.dataset.from = text ? from : '';
}

export function mountWheelInput(store) {
  const file = $('#wheel-file');
  const change = (extra, note) => {
    store.setInputs({ extra }, { source: 'wheel' });
    store.emit('commit');
    show(store.state);
    $('#wheel-read').textContent = note;
  };
  file.addEventListener('change', async () => {
    // Only what the file holds is read here: a file refused changes nothing, so the words say so.
    let chosen = null, imported;
    try {
      chosen = await chosenFileText(file, MAX_MEASURED_BYTES,
        (name, bytes) => `${name} is ${(bytes / 1048576).toFixed(1)} MB; a wheel's points are a few kB. Is this the right file?`);
      if (!chosen) return;
      imported = readWheelCsv(chosen.text);
    } catch (e) {
      // An earlier file's "Read ..." note would seem to be this file's: gone (#wheel-source says what is in use).
      $('#wheel-read').textContent = '';
      setError(`${chosen ? `${chosen.name}: ` : ''}${e.message} The wheel in use is unchanged.`);
      return;
    }
    setError('');
    change(withWheelPoints(store.state.extra, imported), `Read ${chosen.name}: ${imported.points.R.length} points` +
      `${imported.notes.length ? ` (${imported.notes.join('; ')})` : ''}.`);
  });
  $('#wheel-conjugate').addEventListener('click', () => {
    setError('');
    change(withWheelPoints(store.state.extra, null), 'The conjugate wheel is in use.');
  });
  for (const event of ['restore', 'inputs', 'limits']) store.on(event, () => show(store.state));
  store.on('result', () => { if ($('#wheel-error').dataset.from === 'calculator') setError(''); });
  store.on('refusal', ({ error, caseObject }) => {
    if (caseObject && isWheelField(error.field)) setError(error.message, 'calculator');
  });
}
