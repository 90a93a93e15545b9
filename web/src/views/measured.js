// Measured data and correction: the CSV box (paste, upload, use, clear) with its message, the
// grid's shape, and the correction's verdict. A grid given here is measured: the correction assumes
// the probe's noise (web/src/probe-noise.js).
import { predictionText, verdictText } from '../words.js';
import { fieldMeaning, fieldUnit } from '../result-fields.js';
import { MAX_MEASURED_BYTES, measuredText, tooLargeMessage } from '../io/csv.js';
import { ORIENT_OPTIONS, checkGridValueCount, checkShape, orient, readMeasured } from '../io/measured-import.js';
import { looksLikePoints, readPoints } from '../io/points-import.js';
import { escapeHtml, fixed } from '../format.js';
import { chosenFileText } from '../io/files.js';
import { tuningFor } from '../probe-noise.js';
import { OPTION_FIELD } from '../correction-options.js';
import { mountX3p } from './x3p.js';

const $ = (selector) => document.querySelector(selector);
// The grid's and the locks' refusals; the correction's options show theirs at their inputs.
const isMeasuredField = (field) => /^(measured|correction)/.test(field || '') && !OPTION_FIELD.test(field);

// The verdict; under it what the pass will leave and its bound (µm rms at the probe points, units
// from the module's description of its fields). A stop (the measured face within the probe noise)
// is set apart, led by "Stop:", and predicts nothing: there is no pass to run.
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

// The preview's warnings (grid or points): what looks wrong in what was read, then the problem
// that stops its use. A warning the ticked option answers is not repeated: the preview says what
// the option does. The preview's table shows only without a problem; returns whether it does.
function showWarnings(read, problem, ticked) {
  const warnings = [...(read ? read.warnings.filter((w) => !ticked[w.kind]).map((w) => w.text) : []), ...(problem ? [problem] : [])];
  $('#measured-warning').hidden = !warnings.length;
  $('#measured-warning').textContent = warnings.join(' ');
  $('#measured-preview-table').hidden = Boolean(problem);
  return !problem;
}

// Why a grid's text is refused before it goes into the box (too many values: a textarea of a
// million lines takes the browser 20 s to lay out), or '' (a points file has limits of its own).
function tooManyValues(text) {
  if (looksLikePoints(text)) return '';
  try {
    checkGridValueCount(text);
    return '';
  } catch (e) {
    return e.message;
  }
}

// Text pasted or dropped into the box counts against the same limits as an uploaded file; over
// them, nothing is inserted (a 100 MB paste would freeze the page, and so would a million lines).
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

export function mountMeasured(store) {
  const box = $('#measured-csv');
  const message = $('#measured-error');
  const show = (text) => { message.textContent = text; message.hidden = false; };
  const refuse = (text) => store.refuse({ field: 'measured', message: text });

  const options = () => Object.fromEntries(ORIENT_OPTIONS.map((o) => [o, $(`[data-orient="${o}"]`).checked]));
  // The grid the text gives with the options ticked, checked against the grid now; throws.
  const gridOf = (text, t) => {
    const read = readMeasured(text, t);
    const g = orient(read.values, options());
    checkShape(g, t.r.length, t.x.length);
    return { read, grid: g };
  };
  // The preview: what was read and recognised, what looks wrong, the grid as it would be used.
  let previews = 0;
  const preview = () => {
    const r = store.state.result, text = box.value;
    $('#measured-preview').dataset.previews = String(++previews);  // for the tests: a preview was made
    $('#measured-preview').hidden = !r || text.trim() === '';
    if ($('#measured-preview').hidden) return;
    const t = r.topography;
    const points = looksLikePoints(text);
    for (const o of ['transpose', 'flipRadial', 'flipAxial']) $(`[data-orient="${o}"]`).disabled = points;
    if (points) { previewPoints(text); return; }
    let read = null, g = null, problem = '';
    try {
      read = readMeasured(text, t);
      g = orient(read.values, options());
      checkShape(g, t.r.length, t.x.length);
    } catch (e) {
      problem = e.message;
    }
    const ticked = options();
    const size = g ? `${g.length} × ${(g[0] || []).length} values` : '';
    $('#measured-read').textContent = read
      ? `Read ${size}${read.notes.length ? `, with ${read.notes.join(', ')}` : ''}.${problem ? '' : ` Preview (µm, as it would be used${
        ticked.mm ? ', the values in mm multiplied by 1000' : ''}):`}`
      : '';
    if (!showWarnings(read, problem, ticked)) return;
    const shown = (n) => Math.min(n, 12);
    const head = `<tr><th>r \\ x (mm)</th>${t.x.slice(0, shown(t.x.length)).map((x) => `<th>${fixed(x, 1)}</th>`).join('')}${t.x.length > 12 ? '<th>…</th>' : ''}</tr>`;
    const body = g.slice(0, shown(g.length)).map((row, i) => `<tr><th>${fixed(t.r[i], 2)}</th>${row.slice(0, shown(row.length))
      .map((v) => `<td>${escapeHtml(fixed(v, 3))}</td>`).join('')}${row.length > 12 ? '<td>…</td>' : ''}</tr>`).join('');
    $('#measured-preview-table').innerHTML = `<thead>${head}</thead><tbody>${body}${g.length > 12 ? '<tr><th>…</th></tr>' : ''}</tbody>`;
  };
  // The preview of a points CSV (docs/measured-points.md): what was read, what looks wrong, the
  // first points as they would be used (only "change sign" and "values in mm" apply to points).
  const previewPoints = (text) => {
    let read = null, problem = '';
    try {
      read = readPoints(text);
    } catch (e) {
      problem = e.message;
    }
    const ticked = options();
    const used = read ? pointsOriented(read.points) : [];
    $('#measured-read').textContent = read
      ? `Read a points file: ${read.notes.join(', ')}. Preview (r and x in mm, deviation in µm, as it would be used${
        ticked.mm ? ', the deviations in mm multiplied by 1000' : ''}):`
      : '';
    if (!showWarnings(read, problem, ticked)) return;
    const body = used.slice(0, 12).map((p, k) => `<tr><th>${k + 1}</th>${p.map((v) => `<td>${escapeHtml(fixed(v, 3))}</td>`).join('')}</tr>`).join('');
    $('#measured-preview-table').innerHTML = `<thead><tr><th>point</th><th>r (mm)</th><th>x (mm)</th><th>deviation (µm)</th></tr></thead>` +
      `<tbody>${body}${used.length > 12 ? `<tr><th>…</th><td colspan="3">${used.length - 12} more</td></tr>` : ''}</tbody>`;
  };
  // The points with the ticked options that apply to them: change sign, mm to µm.
  const pointsOriented = (list) => {
    const o = options();
    const scale = (o.negate ? -1 : 1) * (o.mm ? 1000 : 1);
    return list.map(([r, x, d]) => [r, x, scale === 1 || d === 0 ? d : d * scale]);
  };
  let pending = null;
  const previewSoon = () => { clearTimeout(pending); pending = setTimeout(preview, 150); };
  box.addEventListener('input', previewSoon);
  $('#measured-preview').addEventListener('change', preview);
  store.on('result', () => { if (!$('#measured-preview').hidden || box.value.trim() !== '') preview(); });

  // The inputs before a points file was used: put back if the calculator refuses the points, so
  // that nothing on screen is lost.
  let beforePoints = null;
  const withoutPoints = (extra) => {
    const { measuredPoints, ...rest } = extra || {};
    return rest;
  };
  const use = (text) => {
    const r = store.state.result;
    if (!r) { refuse('Compute a setup first, so that the grid is known.'); return; }
    try {
      if (looksLikePoints(text)) {
        const measuredPoints = pointsOriented(readPoints(text).points);
        message.hidden = true;
        beforePoints = { measured: store.state.measured, extra: structuredClone(store.state.extra), tuning: store.state.tuning };
        store.setInputs({ measured: null, extra: { ...store.state.extra, measuredPoints }, tuning: tuningFor(store.state.tuning, false) },
          { source: 'measured', force: true });
        store.emit('commit');
        return;
      }
      const measured = gridOf(text, r.topography).grid;
      message.hidden = true;
      store.setInputs({ measured, extra: withoutPoints(store.state.extra), tuning: tuningFor(store.state.tuning, false) },
        { source: 'measured', force: true });
      store.emit('commit');
    } catch (e) {
      refuse(e.message);
    }
  };
  let keepMessage = false;
  store.on('refusal', ({ error, caseObject }) => {
    if (!beforePoints || !caseObject || !caseObject.measuredPoints || !/^measuredPoints/.test(error.field || '')) return;
    const back = beforePoints;
    beforePoints = null;
    keepMessage = true;  // the refusal stays in view while the inputs before are computed again
    store.setInputs(back, { source: 'measured', force: true });
  });

  guardSize(box, refuse);
  // An X3P file (views/x3p.js) goes into the box as CSV and is used as an uploaded CSV is.
  mountX3p(store, { take: (text) => { box.value = text; preview(); use(text); }, refuse });
  $('#use-measured').addEventListener('click', () => use(box.value));
  $('#clear-measured').addEventListener('click', () => {
    box.value = '';
    message.hidden = true;
    preview();
    store.setInputs({ measured: null, extra: withoutPoints(store.state.extra) }, { source: 'measured', force: true });
    store.emit('commit');
  });
  $('#measured-file').addEventListener('change', async (e) => {
    let file;
    try {
      file = await chosenFileText(e.target, MAX_MEASURED_BYTES, tooLargeMessage);
    } catch (err) {
      refuse(err.message);
      return;
    }
    if (!file) return;
    const many = tooManyValues(file.text);
    if (many) { refuse(`${file.name}: ${many}`); return; }
    box.value = file.text;
    preview();
    use(file.text);
  });

  store.on('refusal', ({ error }) => { if (isMeasuredField(error.field)) show(error.message); });
  // An undo step puts its grid into the box, if it has another grid than the one used now.
  let used = null;
  store.on('inputs', (_, state) => { used = state.measured; });
  store.on('restore', (_, state) => {
    if (JSON.stringify(state.measured) !== JSON.stringify(used)) {
      box.value = state.measured ? measuredText(state.measured) : '';
      message.hidden = true;
    }
    used = state.measured;
  });
  store.on('result', ({ result, caseObject }) => {
    if (caseObject.measuredPoints) beforePoints = null;
    if ((caseObject.measured || caseObject.measuredPoints) && !keepMessage) message.hidden = true;
    keepMessage = false;
    $('#grid-shape').textContent = `${result.topography.r.length} rows × ${result.topography.x.length} values`;
    renderVerdict(result);
  });
  return {
    // The text of a measured grid that came with a loaded case (set aside or used).
    setText(text) { box.value = text; message.hidden = true; previewSoon(); },
  };
}
