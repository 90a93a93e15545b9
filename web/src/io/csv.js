// Measured grids as CSV text: rows root to tip, values along the gash, µm; blank lines and lines
// starting with # are skipped; commas, semicolons, tabs or spaces separate the values.
import { GRID } from '../limits.js';
import { fixed } from '../format.js';
import { MAX_CASE_DEPTH, nestingDepth } from './nesting.js';

// The largest measured text the page takes, pasted or uploaded: a grid of at most 201 x 201
// values is a few hundred kB.
export const MAX_MEASURED_BYTES = 2 * 1024 * 1024;

export function tooLargeMessage(what, bytes) {
  return `${what} is ${(bytes / 1048576).toFixed(1)} MB; a measured grid of at most ${GRID.max} × ${GRID.max} values ` +
    `is a few hundred kB (the limit is ${MAX_MEASURED_BYTES / 1048576} MB). Is this the right data?`;
}

export function parseMeasuredCsv(text, rows, cols) {
  if (text.length > MAX_MEASURED_BYTES) throw new Error(tooLargeMessage('The text', text.length));
  const lines = text.split(/\r?\n/).map((l) => l.trim()).filter((l) => l !== '' && !l.startsWith('#'));
  if (lines.length === 0) throw new Error('The measured grid is empty.');
  const grid = lines.map((line, i) => {
    const cells = line.split(/[,;\t ]+/).filter((c) => c !== '');
    return cells.map((cell, j) => {
      const v = Number(cell);
      if (!Number.isFinite(v)) throw new Error(`Row ${i + 1}, column ${j + 1}: "${cell.slice(0, 20)}" is not a number (µm).`);
      return v;
    });
  });
  if (grid.length !== rows) {
    throw new Error(`The grid has ${rows} radial lines (root to tip), but the CSV has ${grid.length} rows.`);
  }
  grid.forEach((row, i) => {
    if (row.length !== cols) throw new Error(`Row ${i + 1} has ${row.length} values; the grid has ${cols} axial lines.`);
  });
  return grid;
}

// A grid as the CSV box shows it; `digits` rounds the values (for a generated grid), a value that
// rounds to zero to 0.0000, never -0.0000.
export function gridToCsv(grid, digits) {
  const cell = (v) => (digits === undefined ? String(v) : fixed(v, digits));
  return grid.map((row) => row.map(cell).join(', ')).join('\n');
}

// Whatever a case file held as `measured`, as text for the CSV box: a grid as CSV, anything else
// as JSON (cut at the text limit), so that the user sees what was set aside.
export function measuredText(measured) {
  const isGrid = Array.isArray(measured) && measured.every((row) => Array.isArray(row) && row.every((v) => typeof v === 'number'));
  if (isGrid) return gridToCsv(measured);
  if (nestingDepth(measured) > MAX_CASE_DEPTH) return `(lists nested more than ${MAX_CASE_DEPTH} deep)`;
  const text = JSON.stringify(measured);
  return text === undefined ? '' : text.slice(0, MAX_MEASURED_BYTES);
}
