// The rake-face inspection as the page shows it (pure, with Node tests): the class verdict in a
// sentence, and per check its value with its unit, its grade and the class tolerances of the
// module band, measured and predicted after the correction (README, "Rake-face inspection").
import { fixed } from './format.js';

export const CHECK_WORDS = {
  cuttingFaceForm: { label: 'cutting-face form', unit: 'µm' },
  radialAlignment: { label: 'radial alignment', unit: 'µm' },
  gashLead: { label: 'gash lead', unit: 'µm per 100 mm' },
  adjacentSpacing: { label: 'adjacent spacing', unit: 'µm' },
  cumulativeSpacing: { label: 'cumulative spacing', unit: 'µm' },
};

const num = (v) => (typeof v === 'number' && Number.isFinite(v) ? v : null);

// "Rake face: class A (limited by the adjacent spacing), over 6.3 to 10 mm; predicted after the
// correction: class AA." A class that is not graded says why.
export function verdictSentence(inspection) {
  if (!inspection) return '';
  const klass = (c, limiting) => (c === 'not graded'
    ? 'not graded (the tolerance table has no value for this module on any check computed)'
    : `class ${c}${limiting ? ` (limited by the ${(CHECK_WORDS[limiting] || { label: limiting }).label})` : ''}`);
  const source = { gashTopographies: 'the worst of the gash topographies', measuredPoints: 'measured points' }[inspection.source] || `${inspection.source} face`;
  let text = `Rake face (DIN 3968, module band ${inspection.moduleBand}, ${source}): ${klass(inspection.class, inspection.limitingCheck)}`;
  if (inspection.after && inspection.after.class) text += `; predicted after the correction: ${klass(inspection.after.class, inspection.after.limitingCheck)}`;
  return `${text}.`;
}

// One row per check computed: {check, label, unit, value, grade, tolerances, after: {value, grade} | null}.
export function inspectionRows(inspection) {
  if (!inspection || !inspection.checks) return [];
  return Object.keys(CHECK_WORDS).filter((k) => inspection.checks[k]).map((k) => {
    const c = inspection.checks[k], a = inspection.after || {};
    const afterChecks = a.checks || {};
    return {
      check: k, ...CHECK_WORDS[k], value: num(c.value), grade: c.grade,
      tolerances: (c.classes || []).map((name, i) => `${name} ${fixed(c.tolerances[i], 1)}`).join(' · ') || 'none in the table',
      after: k in a || afterChecks[k] ? { value: num(a[k]), grade: afterChecks[k] ? afterChecks[k].grade : '' } : null,
    };
  });
}
