// The preview of the measured data's box (state.measuredText): what was read and recognised, the
// record its file carried, what looks wrong, and the grid or the points as they would be used with
// the options ticked under it (state.measuredOptions). Beside a refused file, a text that is the
// measurement in use is said to be ("In use, a.csv: ").
import { ORIENT_OPTIONS, checkShape, orient, readMeasured } from '../../../wasm/lib/measured-grid.js';
import { looksLikePoints, orientPoints, readPoints } from '../../../wasm/lib/points-csv.js';
import { metaText } from '../../../wasm/lib/preamble.js';
import { escapeHtml, fixed } from '../format.js';
import { boxText, isInUseText } from '../measurement.js';

const $ = (selector) => document.querySelector(selector);

// The record the file carried above its table, and what was skipped (wasm/lib/preamble.js).
const recordOf = (read) => [metaText(read.meta), read.skippedText].filter(Boolean).map((t) => ` ${t}`).join('');

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

// A grid's preview at the grid of topography t: its size, the first 12 rows and columns.
function previewGrid(text, t, ticked, lead) {
  let read = null, g = null, problem = '';
  try {
    read = readMeasured(text, t);
    g = orient(read.values, ticked);
    checkShape(g, t.r.length, t.x.length);
  } catch (e) {
    problem = e.message;
  }
  const size = g ? `${g.length} × ${(g[0] || []).length} values` : '';
  $('#measured-read').textContent = read
    ? `${lead}Read ${size}${read.notes.length ? `, with ${read.notes.join(', ')}` : ''}.${recordOf(read)}${problem ? '' : ` Preview (µm, as it would be used${
      ticked.mm ? ', the values in mm multiplied by 1000' : ''}):`}`
    : '';
  if (!showWarnings(read, problem, ticked)) return;
  const shown = (n) => Math.min(n, 12);
  const head = `<tr><th>r \\ x (mm)</th>${t.x.slice(0, shown(t.x.length)).map((x) => `<th>${fixed(x, 1)}</th>`).join('')}${t.x.length > 12 ? '<th>…</th>' : ''}</tr>`;
  const body = g.slice(0, shown(g.length)).map((row, i) => `<tr><th>${fixed(t.r[i], 2)}</th>${row.slice(0, shown(row.length))
    .map((v) => `<td>${escapeHtml(fixed(v, 3))}</td>`).join('')}${row.length > 12 ? '<td>…</td>' : ''}</tr>`).join('');
  $('#measured-preview-table').innerHTML = `<thead>${head}</thead><tbody>${body}${g.length > 12 ? '<tr><th>…</th></tr>' : ''}</tbody>`;
}

// A points CSV's preview (docs/measured-points.md): the first points as they would be used (only
// "change sign" and "values in mm" apply to points).
function previewPoints(text, ticked, lead) {
  let read = null, problem = '';
  try {
    read = readPoints(text);
  } catch (e) {
    problem = e.message;
  }
  const used = read ? orientPoints(read.points, ticked) : [];
  $('#measured-read').textContent = read
    ? `${lead}Read a points file: ${read.notes.join(', ')}.${recordOf(read)} Preview (r and x in mm, deviation in µm, as it would be used${
      ticked.mm ? ', the deviations in mm multiplied by 1000' : ''}):`
    : '';
  if (!showWarnings(read, problem, ticked)) return;
  const body = used.slice(0, 12).map((p, k) => `<tr><th>${k + 1}</th>${p.map((v) => `<td>${escapeHtml(fixed(v, 3))}</td>`).join('')}</tr>`).join('');
  $('#measured-preview-table').innerHTML = `<thead><tr><th>point</th><th>r (mm)</th><th>x (mm)</th><th>deviation (µm)</th></tr></thead>` +
    `<tbody>${body}${used.length > 12 ? `<tr><th>…</th><td colspan="3">${used.length - 12} more</td></tr>` : ''}</tbody>`;
}

export function mountMeasuredPreview(store) {
  const section = $('#measured-preview');
  const ticks = () => Object.fromEntries(ORIENT_OPTIONS.map((o) => [o, $(`[data-orient="${o}"]`).checked]));
  const preview = () => {
    const state = store.state, r = state.result, text = boxText(state.measuredText);
    section.dataset.previews = String(Number(section.dataset.previews || 0) + 1);  // for the tests: a preview was made
    section.hidden = !r || text.trim() === '';
    if (section.hidden) return;
    const points = looksLikePoints(text);
    for (const o of ['transpose', 'flipRadial', 'flipAxial']) $(`[data-orient="${o}"]`).disabled = points;
    const lead = isInUseText(state, text) ? `In use, ${state.measuredSource.name}: ` : '';
    if (points) previewPoints(text, state.measuredOptions, lead);
    else previewGrid(text, r.topography, state.measuredOptions, lead);
  };
  // Typing or a text given waits for a pause; a file's text shows at once; an undo step's
  // shows with its result.
  let pending = null;
  const previewSoon = () => { clearTimeout(pending); pending = setTimeout(preview, 150); };
  store.on('measured-text', ({ source }) => {
    if (source === 'box' || source === 'case') previewSoon();
    else if (source === 'file') preview();
  });
  // The options ticked (as the page opened, and as changed) are the state's.
  store.setMeasurement({ measuredOptions: ticks() });
  section.addEventListener('change', () => { store.setMeasurement({ measuredOptions: ticks() }); preview(); });
  store.on('result', () => { if (!section.hidden || store.state.measuredText.trim() !== '') preview(); });
}
