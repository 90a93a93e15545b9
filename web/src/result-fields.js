// The result's fields as the module describes them (Module.resultFields(): [{path, kind, unit,
// meaning, when}], docs/api.md's table of result fields): the page takes a figure's unit and its
// meaning from here, not from words of its own. Filled once the worker is ready, with the limits
// (main.js); until then, and for a path the module does not describe, there is none.
const FIELDS = new Map();

// fields: what Module.resultFields() returns. Refuses a shape it cannot use.
export function setResultFields(fields) {
  if (!Array.isArray(fields) || !fields.every((f) => f && typeof f.path === 'string')) {
    throw new Error('The calculator gave no description of its results the page can use.');
  }
  FIELDS.clear();
  for (const f of fields) FIELDS.set(f.path, { unit: String(f.unit || ''), meaning: String(f.meaning || ''), kind: f.kind });
}

// A field's unit ('µm', 'µm²', '' for none) or null when the module does not describe it.
export function fieldUnit(path) {
  const f = FIELDS.get(path);
  return f ? f.unit : null;
}

// What a field means, in the module's words ('' when it does not describe it).
export function fieldMeaning(path) {
  const f = FIELDS.get(path);
  return f ? f.meaning : '';
}
