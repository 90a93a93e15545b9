// The result's fields as the module describes them (Module.resultFields(): [{path, kind, unit,
// meaning, when, label}], docs/api.md's table of result fields): the page takes a figure's unit,
// its label and its meaning from here, not from words of its own (tests/js/page-units.test.mjs). Filled once the worker is ready, with the limits
// (main.js); until then, and for a path the module does not describe, there is none.
import { splitName } from './field-words.js';

const FIELDS = new Map();

// fields: what Module.resultFields() returns. Refuses a shape it cannot use.
export function setResultFields(fields) {
  if (!Array.isArray(fields) || !fields.every((f) => f && typeof f.path === 'string')) {
    throw new Error('The calculator gave no description of its results the page can use.');
  }
  FIELDS.clear();
  for (const f of fields) {
    FIELDS.set(f.path, { unit: String(f.unit || ''), meaning: String(f.meaning || ''), label: String(f.label || ''), kind: f.kind });
  }
}

// A field's unit ('µm', 'µm²', '' for none) or null when the module does not describe it.
export function fieldUnit(path) {
  const f = FIELDS.get(path);
  return f ? f.unit : null;
}

// A result path inside a meaning ("re-simulated with correction.axes"): a top-level member of the
// result with a dot and more.
const RESULT_PATH = /\b(?:nominal|correction|inspection|gearEffect|face|wheel|setup|machine|measured|passes|job|hob|grid)(?:\.[A-Za-z]\w*)+/g;

// A field's unit as text: '' where it has none or the module does not describe it.
export const unitText = (path) => fieldUnit(path) || '';

// What a field means, in the module's words ('' when it does not describe it), for the page: a
// path it names is said in words, by that field's label or its last name ("the correction's
// axes" for correction.axes) - the page shows no path (docs/api.md's table keeps them).
export function fieldMeaning(path) {
  const f = FIELDS.get(path);
  if (!f) return '';
  return f.meaning.replace(RESULT_PATH, (p) => {
    const named = FIELDS.get(p);
    if (named && named.label) return named.label;
    const parts = p.split('.');
    const last = splitName(parts[parts.length - 1]);
    return parts.length > 2 ? `${splitName(parts[parts.length - 2])} ${last}` : `the ${splitName(parts[0])}'s ${last}`;
  });
}

// A figure's short name as the page shows it ('rms', 'sum of squares'; '' when it has none).
export function fieldLabel(path) {
  const f = FIELDS.get(path);
  return f ? f.label : '';
}

// Whether the result holds the field: the module describes it and the result has a value at its
// path (an optional field is there only as its description's `when` says).
export function fieldPresent(result, path) {
  if (!FIELDS.has(path)) return false;
  let node = result;
  for (const key of path.split('.')) {
    if (node === null || typeof node !== 'object' || !(key in node)) return false;
    node = node[key];
  }
  return node !== undefined;
}
