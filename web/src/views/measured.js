// Measured data and correction: the CSV box (paste, upload, use, clear) with its message, the
// grid's shape, and the correction's verdict. A grid given here is measured: the correction assumes
// the probe's noise (web/src/probe-noise.js).
import { predictionText, verdictText } from '../words.js';
import { fieldMeaning, fieldUnit } from '../result-fields.js';
import { MAX_MEASURED_BYTES, measuredText, tooLargeMessage } from '../../../wasm/lib/csv.js';
import { ORIENT_OPTIONS, checkGridValueCount, checkShape, orient, readMeasured } from '../../../wasm/lib/measured-grid.js';
import { looksLikePoints, readPoints } from '../../../wasm/lib/points-csv.js';
import { escapeHtml, fixed } from '../format.js';
import { chosenFileText } from '../io/files.js';
import { tuningFor } from '../probe-noise.js';
import { OPTION_FIELD } from '../correction-options.js';
import { mountX3p } from './x3p.js';
import { metaText } from '../../../wasm/lib/preamble.js';

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

  // What is in use (issue 22): the measurement the results are from, {name, what, meta, text}, or
  // null; kept as store.state.measuredSource for the record (the report: its name and the metadata
  // its file carried, wasm/lib/preamble.js). attempt: a measurement sent, in use once its result comes.
  let inUse = null, attempt = null;
  // A file refused: {note (the message beside the box), status (the status line's, once the
  // measurement in use is computed again)}; the preview then says its text is the one in use.
  let refusal = null;
  const setInUse = (m) => { inUse = m; store.state.measuredSource = m && { name: m.name, what: m.what, meta: m.meta || {} }; };
  const inUseAfter = (caseObject) => {
    if (!caseObject.measured && !caseObject.measuredPoints) setInUse(null);
    else if (attempt) setInUse(attempt);
    else if (!inUse) {
      setInUse(caseObject.measured
        ? { name: 'the measured grid', what: `${caseObject.measured.length} × ${(caseObject.measured[0] || []).length} values`, text: box.value }
        : { name: 'the measured points', what: `${caseObject.measuredPoints.length} points`, text: box.value });
    }
    attempt = null;
  };
  const inUseText = () => (inUse ? `In use: ${inUse.name} (${inUse.what}).` : 'In use: no measurement (the face simulated for the axes run).');
  // A file the page or the calculator refused: the box gets back what it held before (the preview
  // then shows what is in use), the message and the status say what was refused, why, and what is in use.
  const refusedFile = (name, reason, boxBefore) => {
    const lead = name.replace(/^the /, 'The ');  // a file's name as it is; "The grid in the box"
    const note = `${lead} is refused: ${reason} ${inUseText()}`;
    refusal = { note, status: `${lead} is refused (${inUse ? `${inUse.name} stays in use` : 'no measurement in use'}): ${reason}` };
    if (boxBefore !== undefined && box.value !== boxBefore) {
      box.value = boxBefore;
      preview();
    }
  };
  // The preview's lead when its text is the measurement in use beside a refusal ("In use, a.csv: ").
  const lf = (text) => String(text).replace(/\r\n?/g, '\n');  // as the box keeps it
  const inUseLabel = (text) => (refusal && inUse && lf(inUse.text) === lf(text) ? `In use, ${inUse.name}: ` : '');
  // The record the file carried above its table, and what was skipped (wasm/lib/preamble.js).
  const recordOf = (read) => [metaText(read.meta), read.skippedText].filter(Boolean).map((t) => ` ${t}`).join('');

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
      ? `${inUseLabel(text)}Read ${size}${read.notes.length ? `, with ${read.notes.join(', ')}` : ''}.${recordOf(read)}${problem ? '' : ` Preview (µm, as it would be used${
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
      ? `${inUseLabel(text)}Read a points file: ${read.notes.join(', ')}.${recordOf(read)} Preview (r and x in mm, deviation in µm, as it would be used${
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
  box.addEventListener('input', () => { refusal = null; previewSoon(); });
  $('#measured-preview').addEventListener('change', preview);
  store.on('result', () => { if (!$('#measured-preview').hidden || box.value.trim() !== '') preview(); });

  // The inputs before a measurement (points or grid) was used: put back if the calculator refuses
  // it, so that the measurement in use stays in use and nothing on screen is lost.
  let before = null;
  const withoutPoints = (extra) => {
    const { measuredPoints, ...rest } = extra || {};
    return rest;
  };
  const inputsBefore = (boxBefore) => ({ measured: store.state.measured, extra: structuredClone(store.state.extra), tuning: store.state.tuning, box: boxBefore });
  // name: the file's, or undefined for the box's text; boxBefore: what the box held before the
  // file, put back if the file is refused (the preview then shows what is in use).
  const use = (text, name, boxBefore) => {
    const r = store.state.result;
    if (!r) { refuse('Compute a setup first, so that the grid is known.'); return; }
    refusal = null;
    try {
      if (looksLikePoints(text)) {
        const read = readPoints(text);
        const measuredPoints = pointsOriented(read.points);
        message.hidden = true;
        attempt = { name: name || 'the points in the box', what: `${measuredPoints.length} points`, meta: read.meta, text };
        before = inputsBefore(boxBefore);
        store.setInputs({ measured: null, extra: { ...store.state.extra, measuredPoints }, tuning: tuningFor(store.state.tuning, false) },
          { source: 'measured', force: true });
        store.emit('commit');
        return;
      }
      const { read, grid: measured } = gridOf(text, r.topography);
      message.hidden = true;
      attempt = { name: name || 'the grid in the box', what: `${measured.length} × ${(measured[0] || []).length} values`, meta: read.meta, text };
      before = inputsBefore(boxBefore);
      store.setInputs({ measured, extra: withoutPoints(store.state.extra), tuning: tuningFor(store.state.tuning, false) },
        { source: 'measured', force: true });
      store.emit('commit');
    } catch (e) {
      if (name === undefined) { refuse(e.message); return; }
      refuseNow(name, e.message, boxBefore);
    }
  };
  // A file refused before anything is computed: the message and the status say so at once.
  const refuseNow = (name, reason, boxBefore) => {
    refusedFile(name, reason, boxBefore);
    refuse(refusal.note);
    store.setStatus(refusal.status, 'error');
    refusal.status = null;
  };
  let keepMessage = false;
  // The calculator refused the measurement just sent (its points, or its grid: say, a value beyond
  // 10 mm): the inputs before are computed again (recompute.js then sets no grid aside).
  store.on('refusal', ({ error, caseObject }) => {
    if (!before || !caseObject) return;
    const field = error.field || '';
    const points = Boolean(caseObject.measuredPoints) && /^measuredPoints/.test(field);
    const grid = Boolean(caseObject.measured) && /^measured(\[|$)/.test(field);
    if (!points && !grid) return;
    const { box: boxBefore, ...back } = before;
    before = null;
    keepMessage = true;  // the refusal stays in view while the inputs before are computed again
    refusedFile(attempt ? attempt.name : points ? 'the points in the box' : 'the grid in the box', error.message, boxBefore);
    refusal.error = error;
    attempt = null;
    store.setInputs(back, { source: 'measured', force: true });
  });

  guardSize(box, refuse);
  // An X3P file (views/x3p.js) goes into the box as CSV and is used as an uploaded CSV is.
  mountX3p(store, { take: (text) => { box.value = text; preview(); use(text); }, refuse });
  $('#use-measured').addEventListener('click', () => use(box.value));
  $('#clear-measured').addEventListener('click', () => {
    refusal = null;
    box.value = '';
    message.hidden = true;
    preview();
    store.setInputs({ measured: null, extra: withoutPoints(store.state.extra) }, { source: 'measured', force: true });
    store.emit('commit');
  });
  $('#measured-file').addEventListener('change', async (e) => {
    const chosen = e.target.files[0];
    let file;
    try {
      file = await chosenFileText(e.target, MAX_MEASURED_BYTES, tooLargeMessage);
    } catch (err) {
      // Empty or too large: refused as a file (never an earlier file's note); "The file is empty."
      const name = chosen.name;
      refuseNow(name, err.message.startsWith(`${name} `) ? `The file ${err.message.slice(name.length + 1)}` : err.message);
      return;
    }
    if (!file) return;
    // Too many values: refused as a file, before the text goes into the box (issue 22, item 4).
    const many = tooManyValues(file.text);
    if (many) { refuseNow(file.name, many); return; }
    const boxBefore = box.value;
    box.value = file.text;
    preview();
    use(file.text, file.name, boxBefore);
  });

  // A refused file's note where the refusal is that file's (the calculator's, or the note itself);
  // any other refusal as it comes, never an earlier file's note.
  store.on('refusal', ({ error }) => {
    if (!isMeasuredField(error.field)) return;
    show(refusal && (refusal.error === error || refusal.note === error.message) ? refusal.note : error.message);
  });
  // An undo step puts its grid into the box, if it has another grid than the one used now.
  let used = null;
  store.on('inputs', (_, state) => { used = state.measured; });
  store.on('restore', (_, state) => {
    if (JSON.stringify(state.measured) !== JSON.stringify(used)) {
      setInUse(null);  // named again by the result (inUseAfter)
      box.value = state.measured ? measuredText(state.measured) : '';
      message.hidden = true;
    }
    used = state.measured;
  });
  store.on('result', ({ result, caseObject }) => {
    if (caseObject.measured || caseObject.measuredPoints) before = null;
    if ((caseObject.measured || caseObject.measuredPoints) && !keepMessage) { message.hidden = true; refusal = null; }
    keepMessage = false;
    inUseAfter(caseObject);
    // A refused file: the status says so over the "Updated" of the measurement in use computed again.
    if (refusal && refusal.status) { store.setStatus(refusal.status, 'error'); refusal.status = null; }
    $('#grid-shape').textContent = `${result.topography.r.length} rows × ${result.topography.x.length} values`;
    renderVerdict(result);
  });
  return {
    // The text of a measured grid that came with a loaded case (set aside or used).
    setText(text) { box.value = text; message.hidden = true; previewSoon(); },
  };
}
