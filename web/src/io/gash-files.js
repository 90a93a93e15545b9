// One measured topography per gash, from one CSV file per gash (pure, with Node tests): each file
// read as a measured grid is (io/measured-import.js: the page's export, decimal commas, a BOM),
// in gash order by file name (gash-2 before gash-10), each of the grid's shape. Throws an Error
// naming the file.
import { checkShape, readMeasured } from './measured-import.js';

// files: [{name, text}]; grid: {r: [mm], x: [mm]} -> {names, grids} in gash order.
export function readGashTopographies(files, grid) {
  if (files.length < 2) throw new Error(`Choose one CSV file per gash, at least 2; got ${files.length}.`);
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
