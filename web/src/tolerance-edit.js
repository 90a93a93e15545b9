// The inspection's inputs as the page edits them (pure, with Node tests): the tolerance table
// (the case's inspection.tolerances, docs/case-format.md; the default table until a cell is
// edited) in the hob's module band, the gash deviations at the pitch radius, and the
// measurement's uncertainty U95 (inspection.uncertainty). All live in state.extra.inspection, so
// the case, the link and the undo steps keep them. A cell left blank has no tolerance (null); a
// text that is not a number is kept as text, so that the calculator names the cell. A cell typed
// is the engineer's: where the table marks its cells' confidence, that cell becomes "entered".
const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);
const EDITED = 'edited on the page';

export function tableInUse(extra, defaults) {
  const t = extra && isObject(extra.inspection) && extra.inspection.tolerances;
  return structuredClone(isObject(t) ? t : defaults);
}

export const isEdited = (extra) => Boolean(extra && isObject(extra.inspection) && extra.inspection.tolerances !== undefined);

// The band's cells as the inputs show them: {check: {class: text}}, '' where there is none.
export function cellTexts(table, band, checks, classes) {
  const out = {};
  for (const check of checks) {
    out[check] = {};
    for (const k of classes) {
      const row = table.checks && table.checks[check] && table.checks[check][k];
      const v = Array.isArray(row) ? row[band] : undefined;
      out[check][k] = v === undefined || v === null ? '' : String(v);
    }
  }
  return out;
}

const withInspection = (extra, change) => {
  const next = structuredClone(extra || {});
  const inspection = isObject(next.inspection) ? next.inspection : {};
  change(inspection);
  if (Object.keys(inspection).length) next.inspection = inspection; else delete next.inspection;
  return next;
};

// The default table's marks spelled out: a cell it does not mark "series" is printed in the source
// its row names (docs/inspection.md), while a case's table leaves unmarked cells "entered". So a
// copy of the default table keeps every cell's mark.
function withDefaultMarks(table) {
  for (const entry of Object.values(table.checks || {})) {
    if (!isObject(entry)) continue;
    for (const [klass, row] of Object.entries(entry)) {
      if (!Array.isArray(row) || ['source', 'seriesSource', 'confidence'].includes(klass)) continue;
      const marks = entry.confidence = isObject(entry.confidence) ? entry.confidence : {};
      const given = Array.isArray(marks[klass]) ? marks[klass] : [];
      marks[klass] = row.map((_, b) => (typeof given[b] === 'string' ? given[b] : 'printed'));
    }
  }
  return table;
}

// extra with the band's cell of (check, class) set from the text typed.
export function withCell(extra, defaults, { band, check, klass, text }) {
  const table = isEdited(extra) ? tableInUse(extra, defaults) : withDefaultMarks(tableInUse(extra, defaults));
  const bands = table.moduleBands.length - 1;
  table.checks = table.checks || {};
  const entry = table.checks[check] = table.checks[check] || {};
  const row = Array.isArray(entry[klass]) ? entry[klass] : Array(bands).fill(null);
  while (row.length < bands) row.push(null);
  const t = text.trim().replace(',', '.');
  row[band] = t === '' ? null : Number.isFinite(Number(t)) ? Number(t) : text;
  entry[klass] = row;
  const marks = isObject(entry.confidence) && entry.confidence[klass];
  if (Array.isArray(marks) && band < marks.length) marks[band] = 'entered';
  if (!String(entry.source || '').endsWith(EDITED)) entry.source = entry.source ? `${entry.source}; ${EDITED}` : EDITED;
  return withInspection(extra, (i) => { i.tolerances = table; });
}

// extra with the default table again (the case then carries none).
export const withDefaultTable = (extra) => withInspection(extra, (i) => { delete i.tolerances; });

// The gash deviations typed: numbers separated by commas, semicolons or blanks (with semicolons,
// decimal commas); blank removes them. Throws an Error naming the value that is not a number.
export function parseGashDeviations(text) {
  const t = text.trim();
  if (t === '') return null;
  const semicolon = t.includes(';');
  const cells = (semicolon ? t.split(';').map((c) => c.trim().replace(',', '.')) : t.split(/[\s,]+/)).filter((c) => c !== '');
  return cells.map((c, i) => {
    const v = Number(c.replace(/^\u2212/, '-'));
    if (!Number.isFinite(v) || !/\d/.test(c)) throw new Error(`Gash deviation ${i + 1}: "${c.slice(0, 20)}" is not a number (µm).`);
    return v;
  });
}

// The gashes as deviations or as one topography per gash: either replaces the other.
export const withGashDeviations = (extra, list) => withInspection(extra, (i) => {
  delete i.gashTopographies;
  if (list) i.gashDeviations = list; else delete i.gashDeviations;
});

export const withGashTopographies = (extra, grids) => withInspection(extra, (i) => {
  delete i.gashDeviations;
  if (grids) i.gashTopographies = grids; else delete i.gashTopographies;
});

export const gashTopographyCount = (extra) => {
  const g = extra && isObject(extra.inspection) && extra.inspection.gashTopographies;
  return Array.isArray(g) ? g.length : 0;
};

export const gashText = (extra) => {
  const list = extra && isObject(extra.inspection) && extra.inspection.gashDeviations;
  return Array.isArray(list) ? list.join(', ') : '';
};

// The cell's confidence as the table marks it ("printed", "series", "entered"); a cell the table
// does not mark is "entered" in a case's table, "printed" in the default one (docs/inspection.md).
export function cellConfidence(table, { band, check, klass, edited }) {
  const entry = table && table.checks && table.checks[check];
  const marks = entry && isObject(entry.confidence) && entry.confidence[klass];
  const word = Array.isArray(marks) ? marks[band] : undefined;
  return typeof word === 'string' ? word : edited ? 'entered' : 'printed';
}

// A cell's confidence in the table in use for the hob's band, (check, klass) => word, as the
// inspection's rows take it (inspection-table.js, confidenceOf); null without a table or a band.
export function cellConfidenceOf(extra, defaults, band) {
  if (!defaults || !(band >= 0)) return null;
  const table = tableInUse(extra, defaults), edited = isEdited(extra);
  return (check, klass) => cellConfidence(table, { band, check, klass, edited });
}

// The measurement's uncertainty U95 typed (µm): blank is the calculator's default, so the case
// leaves it out; a text that is not a number is kept, for the calculator to name the field.
export const withUncertainty = (extra, text) => withInspection(extra, (i) => {
  const t = String(text).trim().replace(',', '.').replace(/^\u2212/, '-');
  if (t === '') delete i.uncertainty;
  else i.uncertainty = Number.isFinite(Number(t)) ? Number(t) : String(text).trim();
});

export const uncertaintyText = (extra) => {
  const u = extra && isObject(extra.inspection) ? extra.inspection.uncertainty : undefined;
  return u === undefined || u === null ? '' : String(u);
};
