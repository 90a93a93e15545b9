// The case form (Tab. 1 and the grid): reads and writes the case, and shows the gash fields that
// apply. Typing changes the inputs at once; a finished change (the field left, Enter, a choice)
// is an undo step. A refused field's message: views/field-errors.js.
import { CASE_FORMAT, DEGREE, GRID } from './limits.js';

const $ = (selector) => document.querySelector(selector);
const $$ = (selector) => Array.from(document.querySelectorAll(selector));

function setPath(object, path, value) {
  const keys = path.split('.');
  let o = object;
  for (const k of keys.slice(0, -1)) o = o[k] = o[k] || {};
  o[keys[keys.length - 1]] = value;
}
function getPath(object, path) {
  return path.split('.').reduce((o, k) => (o == null || typeof o !== 'object' ? undefined : o[k]), object);
}

// The limits the core sets, on the inputs they bound.
function applyLimits() {
  const degree = $('[data-field="degree"]');
  Object.assign(degree, { min: DEGREE.min, max: DEGREE.max, placeholder: DEGREE.default });
  $('[data-limit="degree"]').textContent = `${DEGREE.min} to ${DEGREE.max}`;
  for (const [field, placeholder] of [['grid.radial', GRID.radial], ['grid.axial', GRID.axial]]) {
    Object.assign($(`[data-field="${field}"]`), { min: GRID.min, max: GRID.max, placeholder });
  }
}

export function readForm() {
  const c = { format: CASE_FORMAT, hob: {}, wheel: {}, setup: {}, machine: {} };
  for (const el of $$('#inputs [data-field]')) {
    const field = el.dataset.field;
    if (el.tagName === 'SELECT') { setPath(c, field, el.value); continue; }
    if (el.dataset.text !== undefined) {  // the job's texts, as typed; blank for none
      if (el.value.trim() !== '') setPath(c, field, el.value);
      continue;
    }
    if (el.value.trim() === '') {
      if (el.validity && el.validity.badInput) setPath(c, field, el.value); // lets the module name it
      continue;
    }
    setPath(c, field, Number(el.value));
  }
  if (c.hob.gash === 'straight') { delete c.hob.gashLead; delete c.hob.gashHelixAngle; delete c.hob.hand; }
  else if ($('#gash-by').value === 'lead') delete c.hob.gashHelixAngle;
  else delete c.hob.gashLead;
  return c;
}

export function writeForm(c) {
  for (const el of $$('#inputs [data-field]')) {
    const v = getPath(c, el.dataset.field);
    if (el.tagName === 'SELECT') el.value = v === undefined ? el.options[0].value : v;
    else el.value = v === undefined || v === null ? '' : String(v);
  }
  // The job's fields open when the case names a job.
  if (c.job && Object.keys(c.job).length) $('#job-details').open = true;
  $('#gash-by').value = c.hob && c.hob.gashLead === undefined && c.hob.gashHelixAngle !== undefined ? 'angle' : 'lead';
  showGashFields();
}

function showGashFields() {
  const helical = $('[data-field="hob.gash"]').value !== 'straight';
  const byLead = $('#gash-by').value === 'lead';
  for (const el of $$('.helical-only')) el.hidden = !helical;
  for (const el of $$('.by-lead')) el.hidden = !helical || !byLead;
  for (const el of $$('.by-angle')) el.hidden = !helical || byLead;
}

export function mountForm(store) {
  store.on('limits', applyLimits);  // the module's, once the calculator is ready
  const changed = (event) => {
    if (event.target.matches('[data-field="hob.gash"], #gash-by')) showGashFields();
    store.setInputs({ form: readForm() }, { source: 'form', at: event.timeStamp });
    if (event.type === 'change') store.emit('commit');
  };
  $('#inputs').addEventListener('input', changed);
  $('#inputs').addEventListener('change', changed);
  store.on('restore', (_, state) => writeForm(state.form));
  return {
    // Puts a case into the form; the caller sets the rest of the inputs with it.
    write(c) { writeForm(c); return readForm(); },
  };
}
