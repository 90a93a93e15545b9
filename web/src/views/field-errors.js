// A refused input's message, at the field, in the words of its label: red, at the input it is
// about (or at its group of fields, or under the form), with the calculator's own message, which
// names the case's JSON path, as a tooltip. Cleared by the next result.
import { worded } from './field-names.js';

const $ = (selector) => document.querySelector(selector);
const $$ = (selector) => Array.from(document.querySelectorAll(selector));

function clear() {
  for (const el of $$('#inputs .invalid')) { el.classList.remove('invalid'); el.removeAttribute('aria-invalid'); }
  for (const el of $$('#inputs .field-message')) el.remove();
  $('#form-error').hidden = true;
}

function message(error, tag) {
  const note = document.createElement(tag);
  note.className = 'field-message';
  note.innerHTML = worded(error).html;
  note.title = error.message;
  return note;
}

function show(error) {
  const field = error.field || '';
  if (/^(measured|correction)/.test(field)) return;  // the measured view shows those
  if (/^wheel\.(profileOffset|measuredProfile)/.test(field)) return;  // the wheel's own view does (views/wheel-input.js)
  if (/^inspection\b/.test(field)) return;  // and the inspection's (views/tolerance-table.js)
  const input = field && $(`#inputs [data-field="${field}"]`);
  const group = field && $(`#inputs fieldset[data-group="${field}"]`);
  if (input && input.closest('label') && !input.closest('label').hidden) {
    input.classList.add('invalid');
    input.setAttribute('aria-invalid', 'true');
    input.closest('label').append(message(error, 'span'));
  } else if (group) {
    group.append(message(error, 'p'));
  } else {
    const box = $('#form-error');
    box.innerHTML = worded(error).html;
    box.title = error.message;
    box.hidden = false;
  }
}

export function mountFieldErrors(store) {
  store.on('result', clear);
  store.on('refusal', ({ error, caseObject }) => {
    if (!caseObject) return;  // refused by the page before it reached the calculator
    clear();
    show(error);
  });
}
