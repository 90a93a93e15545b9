// The lines a measuring machine writes above its table (a report head: "Datum;26.11.2026",
// "Part: hob 4711", "Operator;Meier", blank lines), as the grid and points readers find them
// (measured-grid.js, points-csv.js). Pure, with Node tests. The metadata recognised
// (the date, the part, the operator; English and German) is kept for the record; every other
// line above the table is skipped and said so.

// The names each piece of metadata goes by, as a key written without spaces, dots or dashes,
// lower case ("Teil-Nr." -> "teilnr").
const META_NAMES = {
  date: ['date', 'datum', 'messdatum', 'prüfdatum', 'pruefdatum', 'measuredon', 'measurementdate', 'dateofmeasurement'],
  part: ['part', 'teil', 'werkstück', 'werkstueck', 'workpiece', 'partno', 'partnumber', 'teilnr', 'teilenr', 'teilenummer', 'bauteil'],
  operator: ['operator', 'bediener', 'prüfer', 'pruefer', 'inspector', 'werker'],
};
export const META_LABELS = { date: 'date', part: 'part', operator: 'operator' };

// How many skipped lines a message quotes, and how much of each.
const QUOTED_LINES = 6;
const QUOTED_CHARS = 40;

const keyOf = (words) => words.toLowerCase().replace(/[^a-zäöüß]/g, '');

// A line "key: value" (or "key;value", "key = value", "key<tab>value", "key, value", "key value")
// -> {kind: 'date' | 'part' | 'operator', value} when the key is one recognised, else null.
export function metaOf(line) {
  const m = /^([^:;=\t,]+?)\s*[:;=\t,]\s*(.*)$/.exec(line.trim()) || /^(\S+)\s+(.*)$/.exec(line.trim());
  if (!m) return null;
  const key = keyOf(m[1]);
  const kind = Object.keys(META_NAMES).find((k) => META_NAMES[k].includes(key));
  if (!kind) return null;
  const value = m[2].replace(/[;\t,\s]+$/, '').replace(/\s*[;\t]\s*/g, ' ').trim();
  return value === '' ? null : { kind, value };
}

// lines: [{n (1-based line number), text}] without blanks and comments; startsTable(i): whether
// lines[i] begins the table. -> {start (index of the table's first line, or -1 when none does),
// skipped: [{n, text}] the lines above it, meta: {date?, part?, operator?}}.
export function splitPreamble(lines, startsTable) {
  let start = -1;
  for (let i = 0; i < lines.length; ++i) {
    if (metaOf(lines[i].text)) continue;  // a recognised key never begins a table
    if (startsTable(i)) { start = i; break; }
  }
  const skipped = start < 0 ? [] : lines.slice(0, start);
  const meta = {};
  for (const { text } of skipped) {
    const m = metaOf(text);
    if (m && meta[m.kind] === undefined) meta[m.kind] = m.value;
  }
  return { start, skipped, meta };
}

const quote = (text) => `"${text.length > QUOTED_CHARS ? `${text.slice(0, QUOTED_CHARS)}…` : text}"`;

// "Skipped 3 lines above the table: line 1 "Datum;26.11.2026", line 2 ..., and 2 more." or ''.
export function skippedText(skipped) {
  if (!skipped.length) return '';
  const quoted = skipped.slice(0, QUOTED_LINES).map(({ n, text }) => `line ${n} ${quote(text)}`);
  const more = skipped.length - quoted.length;
  return `Skipped ${skipped.length} line${skipped.length === 1 ? '' : 's'} above the table: ${quoted.join(', ')}` +
    `${more > 0 ? `, and ${more} more` : ''}.`;
}

// "Part hob 4711, date 26.11.2026, operator Meier." or '' (the record's words for the metadata).
export function metaText(meta) {
  const parts = ['part', 'date', 'operator'].filter((k) => meta && meta[k] !== undefined).map((k) => `${META_LABELS[k]} ${meta[k]}`);
  if (!parts.length) return '';
  const text = parts.join(', ');
  return `${text[0].toUpperCase()}${text.slice(1)}.`;
}
