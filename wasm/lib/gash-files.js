// One measured topography per gash, from one CSV file per gash (pure, with Node tests): each file
// read as a measured grid is (measured-grid.js: the page's export, decimal commas, a BOM),
// in gash order by file name (gash-2 before gash-10), each of the grid's shape. Throws an Error
// naming the file.
import { checkShape, readMeasured } from './measured-grid.js';
import { INSPECTION } from './limits.js';

// Throws when n files cannot be one per gash: fewer than 2, or more than the calculator's most
// gashes (limits().inspection.maxGashes), checked before any file is read.
export function checkGashFileCount(n) {
  if (n < 2) throw new Error(`Choose one CSV file per gash, at least 2; got ${n}.`);
  if (INSPECTION.maxGashes && n > INSPECTION.maxGashes) throw new Error(`${n} files chosen, one per gash; a hob has at most ${INSPECTION.maxGashes} gashes.`);
}

// files: [{name, text}]; grid: {r: [mm], x: [mm]} -> {names, grids} in gash order.
export function readGashTopographies(files, grid) {
  checkGashFileCount(files.length);
  const sorted = [...files].sort((a, b) => a.name.localeCompare(b.name, 'en', { numeric: true }));
  const grids = sorted.map(({ name, text }) => {
    try {
      const { values, warnings } = readMeasured(text, grid);
      checkShape(values, grid.r.length, grid.x.length);
      const mm = warnings.find((w) => w.kind === 'mm');
      if (mm) throw new Error(mm.text.replace(/ Tick .*$/, ' Give them in µm.'));
      return values;
    } catch (e) {
      throw new Error(`${name}: ${e.message}`);
    }
  });
  return { names: sorted.map((f) => f.name), grids };
}
