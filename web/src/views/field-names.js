// The names on screen of the case's fields, read from the form's labels (and the legends of its
// groups), for refusals worded as the user sees the form (field-words.js).
import { wordedError } from '../field-words.js';
import { escapeHtml } from '../format.js';

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
