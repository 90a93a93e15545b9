// A measurement at the measuring machine's own points as CSV (docs/measured-points.md): a header
// with each column's name and unit, then one point per line, r (mm), x (mm), deviation (µm).
//   r (mm),x (mm),deviation (µm)
//   19.5,-70.2,1.25
// Pure, with Node tests; read by the page (web/src/measurement.js, views/measured-preview.js) and
// the CLI (wasm/cli.mjs --points).
// The header is required: the units it names are what makes the numbers safe to use.
//   - names: r (or radius), x (or axial), deviation (or dev); any case, in any column order;
//   - units: in parentheses or brackets after the name, "r (mm)" or "r [mm]"; mm for r and x,
//     µm (also written um or μm) or mm for the deviation (mm is multiplied by 1000, and noted);
//   - separators: commas with decimal points, or semicolons (or tabs) with decimal commas (or
//     points), as a German spreadsheet writes them; a UTF-8 BOM, blank lines and # comments are
//     skipped; a typographic minus is a minus.
// Anything else is refused with an Error naming the line (and the column).

// The largest text taken, as for a measured grid: 2 MB holds some 60,000 points.
export const MAX_POINTS_BYTES = 2 * 1024 * 1024;
// Below this largest |deviation| (µm) the numbers look like mm (as for a measured grid).
export const POINTS_MM_SUSPECT_BELOW = 0.05;
export const POINTS_HEADER = 'r (mm),x (mm),deviation (µm)';
import { skippedText, splitPreamble } from './preamble.js';

const COLUMNS = [
  { key: 'r', names: ['r', 'radius'], units: { mm: 1 }, unit: 'mm' },
  { key: 'x', names: ['x', 'axial'], units: { mm: 1 }, unit: 'mm' },
  { key: 'deviation', names: ['deviation', 'dev'], units: { 'µm': 1, 'μm': 1, um: 1, mm: 1000 }, unit: 'µm' },
];

const NUMBER = /^[-+\u2212]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/;
const toNumber = (cell) => {
  if (!NUMBER.test(cell)) return NaN;
  return Number(cell.charCodeAt(0) === 0x2212 ? `-${cell.slice(1)}` : cell);
};

// The separator a header line uses: ';', a tab, or ','.
const separatorOf = (line) => (line.includes(';') ? ';' : line.includes('\t') ? '\t' : ',');

// Whether a line names the r and deviation columns, as a points header does (right or not).
function looksLikeHeader(line) {
  const cells = line.split(separatorOf(line)).map((c) => c.trim().toLowerCase());
  return cells.some((c) => /^(deviation|dev)\b/.test(c)) && cells.some((c) => /^(r|radius)\b/.test(c));
}

// A header cell -> {column, scale, unit} or a reason it is not one.
function headerCell(cell) {
  const m = /^([A-Za-z_ ]+?)\s*(?:[([]\s*([^)\]]*?)\s*[)\]])?$/.exec(cell.trim());
  if (!m) return { reason: `"${cell.slice(0, 30)}" is not a column name with its unit, such as "r (mm)"` };
  const name = m[1].trim().toLowerCase();
  const column = COLUMNS.find((c) => c.names.includes(name));
  if (!column) return { reason: `"${cell.slice(0, 30)}" is not one of the columns r, x, deviation` };
  if (m[2] === undefined) return { reason: `the column "${name}" has no unit: write "${column.key} (${column.unit})"` };
  const unit = m[2].replace(/\u00b5|\u03bc/g, 'µ');
  const scale = column.units[unit] ?? column.units[unit.toLowerCase()];
  if (scale === undefined) {
    return { reason: `the column "${name}" is in "${m[2]}"; it must be in ${Object.keys(column.units).filter((u) => u !== 'μm').join(' or ')}` };
  }
  return { column, scale, unit };
}

// A line -> {sep, order: [{column, scale, unit}] per column} when it is the header, else {reason}:
// the sentence naming the line (and the column) of what is wrong.
function headerOf({ n, text }, what = 'the first line') {
  const sep = separatorOf(text);
  const cells = text.split(sep).map((c) => c.trim());
  while (cells.length > 3 && cells[cells.length - 1] === '') cells.pop();
  if (cells.length !== 3 || cells.some((c) => Number.isFinite(toNumber(c.replace(',', '.'))))) {
    return { reason: `Line ${n}: ${what} must be the header "${POINTS_HEADER}" (the names and units of the ` +
      `three columns); got ${cells.length} column${cells.length === 1 ? '' : 's'}: "${text.slice(0, 60)}".` };
  }
  const order = [];
  for (let j = 0; j < cells.length; ++j) {
    const h = headerCell(cells[j]);
    if (h.reason) return { reason: `Line ${n}, column ${j + 1}: ${h.reason}.` };
    if (order.some((o) => o.column === h.column)) return { reason: `Line ${n}, column ${j + 1}: the column "${h.column.key}" is given twice.` };
    order.push(h);
  }
  return { sep, order };
}

// text -> {points: [[r, x, deviation µm]...], notes: [sentences], warnings: [{kind, text}], meta:
// {date?, part?, operator?} from the lines above the header, skipped: [{line, text}] those lines,
// skippedText: the sentence saying so, or ''};
// throws an Error naming the line (and the column) of what cannot be read.
export function readPoints(text) {
  if (text.length > MAX_POINTS_BYTES) {
    throw new Error(`The points file is ${(text.length / 1048576).toFixed(1)} MB; the limit is ${MAX_POINTS_BYTES / 1048576} MB ` +
      '(some 60,000 points). Is this the right file?');
  }
  const lines = [];
  text.replace(/^\uFEFF/, '').split(/\r\n|\n|\r/).forEach((raw, i) => {
    const l = raw.trim();
    if (l !== '' && !l.startsWith('#')) lines.push({ n: i + 1, text: l });
  });
  if (lines.length === 0) throw new Error('The points file is empty.');
  // The table begins at the first line that is the header (preamble.js): a measuring machine's
  // lines above it are skipped, the metadata among them kept. Without one, the line that looks
  // most like it (else the first) says why it is not.
  const { start, skipped, meta } = splitPreamble(lines, (i) => !headerOf(lines[i]).reason);
  const head = start >= 0 ? lines[start] : (lines.find((l) => looksLikeHeader(l.text)) || lines[0]);
  const { sep, order, reason } = headerOf(head, head === lines[0] ? 'the first line' : 'the line above the points');
  if (reason) throw new Error(reason);
  const first = lines.indexOf(head) + 1;  // the first point's line
  const notes = [], warnings = [];
  const at = (key) => order.findIndex((o) => o.column.key === key);
  const ri = at('r'), xi = at('x'), di = at('deviation');
  if (ri !== 0 || xi !== 1 || di !== 2) notes.push(`the columns in the order ${order.map((o) => o.column.key).join(', ')}`);
  if (order[di].scale !== 1) notes.push('deviations in mm, multiplied by 1000');
  const decimalComma = sep !== ',';
  let commas = false;
  const points = [];
  for (let k = first; k < lines.length; ++k) {
    const { n, text: l } = lines[k];
    const row = l.split(sep).map((c) => c.trim());
    while (row.length > 3 && row[row.length - 1] === '') row.pop();  // a trailing separator
    if (row.length !== 3) {
      throw new Error(`Line ${n}: a point needs 3 values (${order.map((o) => o.column.key).join(', ')}); got ${row.length}: "${l.slice(0, 60)}".`);
    }
    const v = [0, 0, 0];
    for (let j = 0; j < 3; ++j) {
      let c = row[j];
      if (decimalComma && c.indexOf(',') >= 0 && c.indexOf(',') === c.lastIndexOf(',')) { c = c.replace(',', '.'); commas = true; }
      const x = toNumber(c);
      if (!Number.isFinite(x)) {
        throw new Error(`Line ${n}, column ${j + 1}: "${row[j].slice(0, 20)}" is not a number (${order[j].column.key}, ${order[j].unit}).`);
      }
      v[j] = order[j].scale === 1 ? x : x * order[j].scale;
    }
    points.push([v[ri], v[xi], v[di]]);
  }
  if (points.length === 0) throw new Error(`The points file has a header (line ${head.n}) but no points.`);
  notes.unshift(`${points.length} point${points.length === 1 ? '' : 's'}`);
  if (sep === ';' || sep === '\t') notes.push(commas ? `${sep === ';' ? 'semicolons' : 'tabs'} with decimal commas` : `${sep === ';' ? 'semicolons' : 'tabs'}`);
  let largest = 0;  // a loop, not Math.max(...): 60,000 arguments would overflow the stack
  for (const p of points) largest = Math.max(largest, Math.abs(p[2]));
  if (largest > 0 && largest < POINTS_MM_SUSPECT_BELOW && order[di].scale === 1) {
    warnings.push({ kind: 'mm', text: `The largest |deviation| is ${Number(largest.toPrecision(3))} µm, below what a probe resolves: these look like mm. Write the header's unit as "deviation (mm)".` });
  }
  return { points, notes, warnings, meta, skipped: skipped.map(({ n, text: t }) => ({ line: n, text: t })), skippedText: skippedText(skipped) };
}

// True when the text has a points header before its first line of numbers (after a BOM, blanks,
// comments and a measuring machine's lines above the table): the page reads it as points rather
// than as a grid.
export function looksLikePoints(text) {
  const lines = text.slice(0, 4096).replace(/^\uFEFF/, '').split(/\r\n|\n|\r/).map((l) => l.trim())
    .filter((l) => l !== '' && !l.startsWith('#'));
  // Above the first line of numbers: a measuring machine's lines, then the header.
  for (const l of lines) {
    if (looksLikeHeader(l)) return true;
    if (l.split(separatorOf(l)).filter((c) => Number.isFinite(toNumber(c.trim().replace(',', '.')))).length >= 2) return false;
  }
  return false;
}

// The points with the page's options ticked that apply to points (a grid's, orient() in
// measured-grid.js, also transposes and reverses): change the sign (the file's plus is missing
// material), the deviations in mm to µm. r and x stay as read; a zero stays +0.
export function orientPoints(points, options = {}) {
  const scale = (options.negate ? -1 : 1) * (options.mm ? 1000 : 1);
  return points.map(([r, x, d]) => [r, x, scale === 1 || d === 0 ? d : d * scale]);
}

// Points [[r, x, µm]...] as CSV with the header; `decimalComma` writes semicolons and decimal
// commas. What readPoints reads back unchanged (numbers written in full, shortest round trip).
export function pointsToCsv(points, { decimalComma = false } = {}) {
  const sep = decimalComma ? ';' : ',';
  const num = (v) => (decimalComma ? String(v).replace('.', ',') : String(v));
  const header = decimalComma ? POINTS_HEADER.replace(/,/g, ';') : POINTS_HEADER;
  return [header, ...points.map((p) => p.map(num).join(sep))].join('\n') + '\n';
}
