// The case's inputs as a job's record lists them (the results CSV, io/results-csv.js, and the
// printed report, views/report.js): every value the case gives, by its path ("hob.normalModule"),
// in the case's order. The measured data, the axes run, the passes and the page's own state are
// left out: each record writes them in a block of its own.
const OWN_BLOCKS = ['measured', 'measuredPoints', 'axes', 'passes', 'page'];

// [path, value] rows; a list stays a list, an object is opened into its values.
export function inputRows(c, prefix = '') {
  const rows = [];
  for (const [k, v] of Object.entries(c || {})) {
    const path = prefix ? `${prefix}.${k}` : k;
    if (OWN_BLOCKS.includes(path)) continue;
    if (v !== null && typeof v === 'object' && !Array.isArray(v)) rows.push(...inputRows(v, path));
    else rows.push([path, v]);
  }
  return rows;
}
