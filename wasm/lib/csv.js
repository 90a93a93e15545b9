// Measured grids as CSV text: rows root to tip, values along the gash, µm. Reading one, with what
// real files hold: measured-grid.js.
import { GRID } from './limits.js';
import { fixed } from './number-text.js';
import { MAX_CASE_DEPTH, nestingDepth } from './nesting.js';

// The largest measured text the page takes, pasted or uploaded: a grid of at most 201 x 201
// values is a few hundred kB.
export const MAX_MEASURED_BYTES = 2 * 1024 * 1024;
// The most values a measured text may hold, read before it is parsed as a grid: a grid of at most
// 201 x 201 values is 40,804 with its positions, and a measuring machine's lines above it add a
// few. 2 MB of one-digit lines hold 1,000,000 (which froze the page 16 s).
export const MAX_GRID_VALUES = 50000;

export function tooLargeMessage(what, bytes) {
  return `${what} is ${(bytes / 1048576).toFixed(1)} MB; a measured grid of at most ${GRID.max} × ${GRID.max} values ` +
    `is a few hundred kB (the limit is ${MAX_MEASURED_BYTES / 1048576} MB). Is this the right data?`;
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
