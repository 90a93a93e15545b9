// The correction's verdict; under it what the pass will leave and its bound (µm rms at the probe
// points, units from the module's description of its fields). A stop (the measured face within
// the probe noise) is set apart, led by "Stop:", and predicts nothing: there is no pass to run.
import { predictionText, verdictText } from '../words.js';
import { fieldMeaning, fieldUnit } from '../result-fields.js';
import { escapeHtml } from '../format.js';

const $ = (selector) => document.querySelector(selector);

function renderVerdict(r) {
  const v = $('#verdict'), p = $('#prediction');
  const c = r.correction;
  const stop = Boolean(c) && c.stop === true;
  v.classList.toggle('stop', stop);
  if (stop) v.dataset.stop = 'true';
  else delete v.dataset.stop;
  const line = c ? predictionText(c, fieldUnit) : null;
  p.hidden = !line;
  p.textContent = line || '';
  p.title = line ? `${fieldMeaning('correction.predictedRms')}. At most: ${fieldMeaning('correction.predictedRmsHigh')}.` : '';
  if (!c) { v.textContent = ''; delete v.dataset.sseBefore; delete v.dataset.sseAfter; return; }
  v.dataset.sseBefore = c.sseBefore;
  v.dataset.sseAfter = c.sseAfter;
  const text = verdictText(c);
  if (stop && text.startsWith('Stop:')) v.innerHTML = `<strong>Stop:</strong>${escapeHtml(text.slice(5))}`;
  else v.textContent = text;
}

export function mountVerdict(store) {
  store.on('result', ({ result }) => renderVerdict(result));
}
