// A measured grid read as a user's file comes (pure, with Node tests): the page's own export with
// its header row of x positions and its column of r positions, a spreadsheet's semicolons with
// decimal commas, values typed in mm by mistake, or a grid written along the other direction.
// readMeasured() says what it recognised and what looks wrong; orient() applies the options the
// user ticks on the preview (transpose, reverse rows or columns, change sign, mm to µm).
import { MAX_GRID_VALUES, MAX_MEASURED_BYTES, tooLargeMessage } from './csv.js';
import { GRID } from './limits.js';
import { skippedText, splitPreamble } from './preamble.js';

// The values a grid of measured deviations can plausibly hold, µm: below this largest |value|, the
// numbers look like mm (a probe resolves about 0.1 µm; 0.05 mm is a plausible deviation).
export const MM_SUSPECT_BELOW = 0.05;
// How far a header's x or a column's r may lie from the grid's line, mm.
const POSITION_TOLERANCE = 0.01;

export const ORIENT_OPTIONS = ['transpose', 'flipRadial', 'flipAxial', 'negate', 'mm'];

const toNumber = (cell) => {
  const t = cell.replace(/^\u2212/, '-').replace(/^\+/, '');
  if (t === '' || !/^-?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/.test(t)) return NaN;
  return Number(t);
};

// One line's cells, and whether its commas were decimal marks (semicolons or tabs separate).
function cellsOf(line) {
  if (/;/.test(line) || (/\t/.test(line) && /\d,\d/.test(line))) {
    const cells = line.split(/[;\t]/).map((c) => c.trim());
    while (cells.length && cells[cells.length - 1] === '') cells.pop();  // a trailing separator
    return { cells: cells.map((c) => c.replace(',', '.')), decimalComma: cells.some((c) => /\d,\d/.test(c)) };
  }
  // Commas separate when there are any (a header cell such as "r \ x" keeps its spaces), else blanks.
  const cells = /,/.test(line) ? line.split(',').map((c) => c.trim()) : line.split(/\s+/);
  return { cells: cells.filter((c) => c !== ''), decimalComma: false };
}

const count = (n) => n.toLocaleString('en-US');

// Throws naming the line where the text's values run past MAX_GRID_VALUES, before the values are
// read: a text of 1,000,000 values is refused at once, not parsed (nor put into the page's box,
// views/measured-box.js, where a million lines take the browser 20 s to lay out).
export function checkGridValueCount(text) {
  let values = 0, n = 0;
  for (let start = 0; start < text.length; n += 1) {
    const end = text.indexOf('\n', start);
    const line = text.slice(start, end < 0 ? text.length : end).trim();
    start = end < 0 ? text.length : end + 1;
    if (line === '' || line.startsWith('#')) continue;
    values += cellsOf(line).cells.length;
    if (values > MAX_GRID_VALUES) {
      const most = GRID.max ? `; a measured grid has at most ${GRID.max} × ${GRID.max}, ${count((GRID.max + 1) ** 2)} with its positions` : '';
      throw new Error(`Line ${count(n + 1)}: the text holds more than ${count(MAX_GRID_VALUES)} values${most}. Is this the right file?`);
    }
  }
}

const near = (a, b) => Math.abs(a - b) <= POSITION_TOLERANCE;
const fmtList = (list) => list.map((v) => String(Math.round(v * 1000) / 1000)).join(', ');

// text -> {values: rows of numbers as written, notes: [sentences], warnings: [{kind, text}] (kind:
// the option that would answer it, 'transpose' or 'mm'), suggest: {transpose, mm}, meta: {date?,
// part?, operator?} from the lines above the table, skipped: [{line, text}] those lines,
// skippedText: the sentence saying so, or ''}; throws an Error naming the line and column of what
// cannot be read.
// grid: {r: [mm], x: [mm]}, the lines of the face grid now, to recognise and check positions.
export function readMeasured(text, grid) {
  if (text.length > MAX_MEASURED_BYTES) throw new Error(tooLargeMessage('The text', text.length));
  checkGridValueCount(text);
  const notes = [], warnings = [], suggest = { transpose: false, mm: false };
  const lines = [];
  text.replace(/^\uFEFF/, '').split(/\r?\n/).forEach((raw, i) => {
    const l = raw.trim();
    if (l !== '' && !l.startsWith('#')) lines.push({ n: i + 1, text: l });
  });
  if (lines.length === 0) throw new Error('The measured grid is empty.');
  // The lines a measuring machine writes above the table (preamble.js): the table begins at a
  // line of two or more numbers, or at a header just above such a line (as many cells, or one more).
  const all = lines.map(({ n, text: l }) => ({ n, ...cellsOf(l) }));
  const numbers = (row) => row.cells.filter((c) => Number.isFinite(toNumber(c))).length;
  const isHeaderOf = (row, next) => Boolean(next) && row.cells.length >= 2 && numbers(next) >= 2 && numbers(next) === next.cells.length &&
    (row.cells.length === next.cells.length || row.cells.length === next.cells.length + 1);
  const startsTable = (i) => numbers(all[i]) >= 2 || (numbers(all[i]) === all[i].cells.length) || isHeaderOf(all[i], all[i + 1]);
  const { start, skipped, meta } = splitPreamble(lines, startsTable);
  let rows = start < 0 ? all : all.slice(start);
  const decimalComma = rows.some((row) => row.decimalComma);
  if (decimalComma) notes.push('semicolons or tabs with decimal commas');
  // A header: a first line whose first cell is not a number ("r \ x", "r_mm", or column names).
  let headerX = null;
  const headerLine = rows[0].n;
  if (rows.length > 1 && Number.isNaN(toNumber(rows[0].cells[0] || ''))) {
    const rest = rows[0].cells.slice(1).map(toNumber);
    if (rest.length && rest.every(Number.isFinite)) { headerX = rest; notes.push(`a header row of ${rest.length} x positions (mm)`); }
    else notes.push('a header row');
    rows = rows.slice(1);
  }
  const values = rows.map(({ n, cells }) => cells.map((cell, j) => {
    const v = toNumber(cell);
    if (!Number.isFinite(v)) throw new Error(`Line ${n}, column ${j + 1}: "${cell.slice(0, 20)}" is not a number (µm).`);
    return v;
  }));
  // A first column of r positions: the header says so (one x fewer than values per row), or
  // every row has one value more than the grid's columns and the first column is the grid's r.
  const cols = grid.x.length;
  const widths = new Set(values.map((r) => r.length));
  const oneMore = widths.size === 1 && values[0].length === (headerX ? headerX.length + 1 : cols + 1);
  const firstIsR = oneMore && (headerX !== null || (values.length === grid.r.length && values.every((r, i) => near(r[0], grid.r[i]))));
  let out = values;
  if (firstIsR) {
    const r = values.map((row) => row[0]);
    out = values.map((row) => row.slice(1));
    notes.push(`a first column of ${r.length} r positions (mm)`);
    if (r.length === grid.r.length) {
      const i = r.findIndex((v, k) => !near(v, grid.r[k]));
      if (i >= 0) throw new Error(`Line ${rows[i].n}: the row is at r = ${fmtList([r[i]])} mm, but the grid's radial line ${i + 1} is at r = ${fmtList([grid.r[i]])} mm. Set the grid lines (Polynomials and measuring grid) to the measured positions, or give the values without positions.`);
    }
  }
  if (headerX && headerX.length === grid.x.length) {
    const j = headerX.findIndex((v, k) => !near(v, grid.x[k]));
    if (j >= 0) throw new Error(`Line ${headerLine}, column ${j + 2}: the column is at x = ${fmtList([headerX[j]])} mm, but the grid's axial line ${j + 1} is at x = ${fmtList([grid.x[j]])} mm. Set the grid lines (Polynomials and measuring grid) to the measured positions, or give the values without positions.`);
  }
  if (out.length === grid.x.length && out.every((row) => row.length === grid.r.length) && grid.r.length !== grid.x.length) {
    suggest.transpose = true;
    warnings.push({ kind: 'transpose', text: `The text has ${out.length} rows of ${grid.r.length} values: the grid written along the other direction? Tick "transpose".` });
  }
  let largest = 0;  // a loop: a text's values are never spread into a call
  for (const row of out) for (const v of row) largest = Math.max(largest, Math.abs(v));
  if (largest > 0 && largest < MM_SUSPECT_BELOW) {
    suggest.mm = true;
    warnings.push({ kind: 'mm', text: `The largest |value| is ${Number(largest.toPrecision(3))} µm, below what a probe resolves: these look like mm. Tick "values in mm" to multiply them by 1000.` });
  }
  return { values: out, notes, warnings, suggest, meta, skipped: skipped.map(({ n, text: t }) => ({ line: n, text: t })), skippedText: skippedText(skipped) };
}

// The grid after the options ticked, in this order: transpose, reverse the rows (the text went
// tip to root), reverse the columns, change the sign (the text's plus is missing material), mm to µm.
export function orient(values, options = {}) {
  let g = values.map((row) => [...row]);
  if (options.transpose) g = (g[0] || []).map((_, j) => g.map((row) => row[j]));
  if (options.flipRadial) g.reverse();
  if (options.flipAxial) g = g.map((row) => row.reverse());
  const scale = (options.negate ? -1 : 1) * (options.mm ? 1000 : 1);
  if (scale !== 1) g = g.map((row) => row.map((v) => (v === 0 ? 0 : v * scale)));
  return g;
}

// Throws an Error naming what does not fit the grid of rows x cols.
export function checkShape(g, rows, cols) {
  if (g.length !== rows) throw new Error(`The grid has ${rows} radial lines (root to tip), but the CSV has ${g.length} rows.`);
  g.forEach((row, i) => {
    if (row.length !== cols) throw new Error(`Row ${i + 1} has ${row.length} values; the grid has ${cols} axial lines.`);
  });
}

// The grid of a text with no options: the values, in the grid's shape, or an Error.
export function parseMeasuredCsv(text, rows, cols) {
  const { values } = readMeasured(text, { r: Array(rows).fill(NaN), x: Array(cols).fill(NaN) });
  checkShape(values, rows, cols);
  return values;
}
