// The names on screen of the case's fields, read from the form's labels (and the legends of its
// groups), for refusals worded as the user sees the form (field-words.js).
import { wordedError } from '../field-words.js';
import { escapeHtml } from '../format.js';
import { fieldUnit } from '../result-fields.js';

// A label's name as plain text, subscripts written with an underscore: "Pitch diameter d_p".
function plainText(el) {
  const copy = el.cloneNode(true);
  for (const sub of copy.querySelectorAll('sub')) sub.textContent = `_${sub.textContent}`;
  return copy.textContent.replace(/\s+/g, ' ').trim();
}

let names = null;
export function fieldNames() {
  if (names) return names;
  names = {
    axes: { text: 'Run axes', html: 'Run axes' },
    'axes.X': { text: 'Run axis X', html: 'Run axis X' }, 'axes.Y': { text: 'Run axis Y', html: 'Run axis Y' },
    'axes.Z': { text: 'Run axis Z', html: 'Run axis Z' }, 'axes.A': { text: 'Run axis A', html: 'Run axis A' },
    'axes.B': { text: 'Run axis B', html: 'Run axis B' },
  };
  // The correction's options and the inspection's inputs, as their labels say (outside the form).
  for (const [path, text] of Object.entries({
    'correction.locked': 'Locked coefficients', 'correction.lockedAxes': 'Locked axes', 'correction.method': 'Correction method', 'correction.probeNoise': 'Probe noise σ', 'correction.wheel': 'Wheel correction',
    'correction.resolution.X': 'Resolution of X', 'correction.resolution.Y': 'Resolution of Y', 'correction.resolution.Z': 'Resolution of Z',
    'correction.resolution.A': 'Resolution of A', 'correction.resolution.B': 'Resolution of B',
    'inspection.uncertainty': 'Measurement uncertainty U95', 'inspection.tolerances': 'Tolerance table',
    'wheel.profileOffset.R': 'Wheel offset: conjugate wheel radius R', 'wheel.profileOffset.offset': 'Wheel offset (+ = more wheel)',
    'wheel.measuredProfile.R': 'Measured wheel profile: radius R', 'wheel.measuredProfile.Z': 'Measured wheel profile: axial position Z',
  })) names[path] = { text, html: escapeHtml(text) };
  for (const fieldset of document.querySelectorAll('#inputs fieldset[data-group]')) {
    const legend = fieldset.querySelector('legend');
    const words = legend.textContent.replace(/^\([A-Z]\)\s*/, '').trim();
    names[fieldset.dataset.group] = { text: words, html: escapeHtml(words) };
  }
  for (const input of document.querySelectorAll('#inputs [data-field]')) {
    const name = input.closest('label') && input.closest('label').querySelector('.name');
    if (name) names[input.dataset.field] = { text: plainText(name), html: name.innerHTML.trim() };
  }
  return names;
}

// {text, html} of an error in the form's words, or the calculator's message as it is.
export function worded(error) {
  const w = wordedError({ field: error.field, message: error.calculatorMessage ?? error.message }, fieldNames());
  if (w) return w;
  const text = String(error.message || '');
  return { text, html: escapeHtml(text) };
}

// The unit the page shows beside each case field's input, by the field's path ('' where it has
// none, or words in the unit's place, data-words, such as the grid lines' "root to tip"): the
// form's fields, the probe noise and the machine resolution of the correction's options, and the
// measurement uncertainty (whose unit the result's schema gives).
export function fieldUnits() {
  const unitOf = (input) => {
    const unit = input.closest('label') && input.closest('label').querySelector('.unit:not([data-limit]):not([data-words])');
    return unit ? unit.textContent.trim() : '';
  };
  const units = {};
  for (const input of document.querySelectorAll('#inputs [data-field]')) units[input.dataset.field] = unitOf(input);
  for (const input of document.querySelectorAll('[data-resolution]')) units[`correction.resolution.${input.dataset.resolution}`] = unitOf(input);
  for (const [path, id] of [['correction.probeNoise', '#probe-noise'], ['inspection.uncertainty', '#inspection-uncertainty']]) {
    const input = document.querySelector(id);
    if (input) units[path] = unitOf(input);
  }
  // A wheel file's points (views/wheel-input.js), in the units of the result fields they become.
  for (const [path, resultPath] of [['wheel.profileOffset.R', 'wheelOffset.R'], ['wheel.profileOffset.offset', 'wheelOffset.offset'],
    ['wheel.measuredProfile.R', 'wheelProfile.dressedR'], ['wheel.measuredProfile.Z', 'wheelProfile.dressedZ']]) units[path] = fieldUnit(resultPath);
  return units;
}

// The names (plain text) and units of the case's fields by path, as the results CSV writes its
// inputs (io/results-csv.js).
export function inputWords() {
  return { names: Object.fromEntries(Object.entries(fieldNames()).map(([path, name]) => [path, name.text])), units: fieldUnits() };
}
