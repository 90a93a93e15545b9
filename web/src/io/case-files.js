// The header's buttons: the paper example, a case saved and loaded as JSON, the link copied,
// and the results as CSV. The paper example asks before it replaces what the user gave beyond
// the form (a measured grid, run axes, offsets, locks); Undo brings it back as well.
import { savedCase, userData } from './case-state.js';
import { chosenFileText, download } from './files.js';
import { resultsCsv, resultsFileName } from './results-csv.js';
import { leftOutText } from './url.js';

const $ = (selector) => document.querySelector(selector);
const MAX_CASE_BYTES = 40 * 1024 * 1024;

// links: mountLink's (io/url.js), the link of the last good result; inputWords: the form's names
// and units of the case's fields for the results CSV (views/field-names.js, inputWords).
export function mountCaseFiles(store, loader, links, inputWords) {
  $('#preset-paper').addEventListener('click', () => {
    const losing = userData(store.state);
    if (losing.length && !window.confirm(`Load the paper example? It replaces ${losing.join(', ')}. ` +
      'Save the case first to keep them (Undo also brings them back).')) return;
    loader.paper();
  });
  $('#save-case').addEventListener('click', () => {
    download('hobsharp-case.json', JSON.stringify(savedCase(store.state), null, 2) + '\n', 'application/json');
  });
  $('#load-case').addEventListener('change', async (e) => {
    let file;
    try {
      file = await chosenFileText(e.target, MAX_CASE_BYTES,
        (name, bytes) => `${name} is ${(bytes / 1048576).toFixed(1)} MB: too large for a case file.`);
    } catch (err) {
      store.setNotice(`${err.message} Nothing was changed.`);
      return;
    }
    if (!file) return;
    let c;
    try {
      c = JSON.parse(file.text);
    } catch (err) {
      store.setNotice(`${file.name} is not a case file: ${err.message}. Nothing was changed.`);
      return;
    }
    loader.file(c, file.name);
  });
  // The link of the last good result (io/url.js), as it fits: what it leaves out is said, and a
  // job too large for any link is not handed out as one.
  $('#copy-link').addEventListener('click', async () => {
    const last = links.link();
    if (last.hash === null) { store.setStatus(leftOutText(last), 'error'); return; }
    const href = last.hash ? `${location.href.split('#')[0]}${last.hash}` : location.href;
    const note = last.hash ? leftOutText(last) : '';
    try {
      await navigator.clipboard.writeText(href);
      store.setStatus(`The link to this job is on the clipboard.${note ? ` ${note}` : ''}`, 'ok');
    } catch (e) {
      store.setStatus(`Copy this link: ${href}${note ? ` ${note}` : ''}`, 'ok');
    }
  });
  $('#download-results').addEventListener('click', () => {
    const { result, resultCase } = store.state;
    if (!result) return;
    const style = $('#csv-style').value;
    download(resultsFileName(resultCase), resultsCsv(result, { caseObject: resultCase, style, inputWords: inputWords() }), 'text/csv;charset=utf-8');
  });
}
