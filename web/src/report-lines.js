// The printed report's first page in words (pure, with Node tests; views/report.js puts it on the
// page): the verdict in one line, the job, and the inputs with their labels and units. Units of
// results come from the module (unitOf: a result field's path to its unit, result-fields.js);
// labels and units of the inputs from the caller (the form's own, views/field-names.js), so that
// nothing here types a unit or shows a case's field path.
import { classLead } from './inspection-table.js';
import { LEAST_RMS, faceFigure, fmt } from './format.js';
import { inputRows } from './io/input-rows.js';
import { floorNote } from './words.js';
import { changesNothing } from '../../wasm/lib/pass-bound.js';

const num = (v) => (typeof v === 'number' && Number.isFinite(v) ? v : null);
// An rms to 3 significant digits; below a nanometre, what no measurement tells apart from zero, as
// such ("below 0.001 µm"), not as a solver's 2e-11.
const figure = (v, unit) => faceFigure(v, LEAST_RMS) + (unit ? ` ${unit}` : '');

// The report's first line: the day, and what was measured (a grid, the machine's points, or nothing).
export function reportDateLine(caseObject, date = new Date()) {
  const points = caseObject.measuredPoints;
  const measured = caseObject.measured ? 'with a measured topography'
    : points ? `with a measured topography at ${points.length} probe points` : 'no measured topography';
  return `Printed ${date.toISOString().slice(0, 10)}; ${measured}.`;
}

// The inspection's line in the report's head: the class with its conformity and the proven class,
// "Rake face (DIN 3968): Class A — conforms (ISO 14253-1, U95 = 2 µm); proven class A." ('' without
// an inspection); on the simulated face its class with no decision (inspection-table.js, classLead).
// The verdict's sentence and the checks lead the topography's page.
// rows: the checks' rows with the table's series marks (inspectionRows), for the class's *.
export function reportInspectionLine(inspection, rows) {
  const lead = classLead(inspection, undefined, rows);
  if (!lead) return '';
  // On a measured face without the gashes' spacing, what the class rests on (on the simulated
  // face, nothing measured, the class decides nothing anyway).
  const spacing = lead.graded && !lead.simulated && inspection.notMeasured ? ' The gashes\' spacing is not measured: the class rests on the face\'s checks alone.' : '';
  return `Rake face (DIN 3968): ${lead.graded ? `${lead.text}.` : inspection.notGraded || 'Not graded.'}${spacing}`;
}

// The correction verdict's lead, before its first colon: "Correctable", "Uncertain", "Partly
// uncorrectable", "Correctable with the wheel", ... ('' for a verdict without one).
export function verdictWord(verdict) {
  const m = /^([^:.]{1,80}):/.exec(String(verdict || ''));
  return m ? m[1] : '';
}

// "Class A — conforms; Correctable: face 12.3 µm rms measured, at most 0.11 µm rms after the
// correction": the rake face's class with its conformity (ISO 14253-1), the verdict's lead word
// and the face's rms before and after, the bound with the verdict's condition and warning: "...;
// Uncertain: face 149 µm rms measured, at most 106 µm rms after the correction if the error the
// face cannot show is no larger than the one it shows; part of the face may stay unground.". Without a measurement the face is the one simulated for the axes run, and its
// class decides no conformity ("Class AA on the simulated face, no conformity decided"); when
// the correction says stop, the face is within the probe noise and the axes stay; with no change
// proposed (a run kept), the axes stay too.
export function verdictLine(result, unitOf, rows) {
  const lead = classLead(result && result.inspection, unitOf, rows);
  // A class on a series value carries its * and says so, as the inspection's table does.
  const klass = lead ? `Class ${lead.klass}${lead.classStar ? '*' : ''}` : '';
  const series = lead && lead.classStar ? ' (* on a series value, not confirmed)' : '';
  // What the class rests on: the gashes' spacing not measured (inspection.notMeasured) is said with it.
  const spacing = lead && lead.graded && result.inspection.notMeasured ? ', the gashes\' spacing not measured' : '';
  const head = !lead ? 'Rake face not inspected' : !lead.graded ? 'Rake face not graded'
    : lead.simulated && lead.conformity === 'does not conform' ? `${klass} — does not conform (a measured gash spacing; the face is not measured)${series}`
      : lead.simulated ? `${klass} on the simulated face, no conformity decided${series}` : `${klass} — ${lead.conformity}${spacing}${series}`;
  const c = result && result.correction;
  const before = num(c && c.rmsBefore);
  if (c && before !== null) {
    const unit = unitOf('correction.rmsBefore');
    const measured = `face ${figure(before, unit)} rms measured`;
    if (c.stop === true) return `${head}; ${measured}: within the probe noise, keep the axes run.`;
    if (changesNothing(c)) return `${head}; ${measured}: no change proposed, keep the axes run.`;
    // The faces measured moved against the change of the axes (correction.signReversed): no figure
    // after the correction stands until the measuring machine's sign is checked.
    if (c.signReversed === true) return `${head}; Check the sign: ${measured}, moved against the change of the axes since the last pass; no figure after the correction until the measuring machine's sign is checked.`;
    const verdict = String(c.verdict || '');
    const word = verdictWord(verdict);
    // Where some errors the face cannot show leave part of it unground (correction.mayStayUnground).
    const warning = c.mayStayUnground === true ? '; part of the face may stay unground' : '';
    // What the pass leaves by its bound alone (words.js, predictionText): the model's figure below
    // it is what the pass leaves only if the identified error is all of the machine's.
    const high = num(c.predictedRmsHigh);
    const lead = `${head}; ${word ? `${word}: ` : ''}${measured}`;
    if (high === null) return `${lead}${warning}.`;
    // What the bound assumes, in the verdict's words (correction.boundCondition).
    const condition = typeof c.boundCondition === 'string' && c.boundCondition ? ` ${c.boundCondition}` : '';
    return `${lead}, at most ${figure(Math.max(high, LEAST_RMS), unitOf('correction.predictedRmsHigh'))} rms after the correction${condition}${floorNote(c, unitOf)}${warning}.`;
  }
  const simulated = num(result && result.topography && result.topography.rms);
  const face = simulated === null ? '' : `; face ${figure(simulated, unitOf('topography.rms'))} rms simulated for the axes run`;
  return `${head}${face}; nothing measured, no correction.`;
}

// The job's record as [label, text] rows in the case's order, its labels the form's
// (names: a case field's path to its label); empty when the case names no job.
export const JOB_FIELDS = ['number', 'customer', 'hobSerial', 'operator', 'notes'];
export function jobRows(job, names) {
  if (!job || typeof job !== 'object') return [];
  return JOB_FIELDS.filter((k) => typeof job[k] === 'string' && job[k].trim() !== '')
    .map((k) => [names[`job.${k}`] || k, job[k].trim()]);
}

// The inputs as the report lists them: [{group, label, value, unit}] per value the case gives in
// the hob, wheel, setup, machine and grid groups and the degree (io/input-rows.js), then the setting
// angle and centre distance when derived. labels: a path to its label (the form's words; a path
// without one is left out, never shown as a path), units: a path to its unit ('' for none),
// groups: a group to its heading.
const GROUPS = ['hob', 'wheel', 'setup', 'machine', 'grid'];
const value = (v) => (typeof v === 'number' ? fmt(v, 8) : String(v));
export function reportInputRows(result, caseObject, { labels, units, groups }) {
  const rows = [];
  const given = inputRows(caseObject).filter(([path, v]) => v !== null && typeof v !== 'object' && !Array.isArray(v));
  const add = (path, v, derived = false) => {
    if (!labels[path]) return;
    const group = path.includes('.') ? path.split('.')[0] : 'grid';
    rows.push({ group: groups[group] || '', label: labels[path], value: value(v), unit: units[path] || '', derived });
  };
  for (const group of GROUPS) {
    for (const [path, v] of given) if (path.split('.')[0] === group && path.split('.').length === 2) add(path, v);
    if (group === 'setup' && result && result.setup) {
      for (const key of ['settingAngle', 'centerDistance']) {
        const given = caseObject.setup && caseObject.setup[key] !== undefined;
        if (!given && num(result.setup[key]) !== null) add(`setup.${key}`, result.setup[key], true);
      }
    }
    if (group === 'grid' && caseObject.degree !== undefined) add('degree', caseObject.degree);
  }
  return rows;
}

// The case link as a QR code holds at most this many bytes: version 40 at error correction level
// L in byte mode (ISO/IEC 18004, Table 7). A longer link gets a sentence instead of a code.
export const QR_MOST_BYTES = 2953;
export const linkBytes = (link) => new TextEncoder().encode(link).length;
export const LINK_TOO_LONG = (bytes) => `The case link (${bytes} bytes) is too long for a QR code (at most ${QR_MOST_BYTES} bytes): ` +
  'save the case file ("Save case") and keep it with this report.';
