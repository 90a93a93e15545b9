// The rake-face inspection as the page shows it (pure, with Node tests; docs/inspection.md): the
// class with its ISO 14253-1 conformity and the proven class, the verdict in a sentence, a warning
// when the measurement's uncertainty is too coarse for a tolerance, the rake error, and per check
// its value, grade, conformity, proven grade and where its tolerance comes from, measured and
// predicted after the correction. Units are the result fields' own (unitOf: a field's path to its
// unit, result-fields.js); nothing here types one.
import { fixed, fmt, signed, withUnit } from './format.js';
import { unitText } from './result-fields.js';

// The checks DIN 3968 grades, in the order the table shows them.
// The spacing checks come from the gashes' deviations; the others from the face inspected.
export const CHECK_WORDS = {
  cuttingFaceForm: { label: 'cutting-face form' },
  radialAlignment: { label: 'radial alignment' },
  gashLead: { label: 'gash lead' },
  adjacentSpacing: { label: 'single pitch (adjacent spacing)', short: 'single pitch', spacing: true },
  pitchJump: { label: 'pitch jump', spacing: true },
};

// The face inspected is the one simulated for the axes run (inspection.source): nothing of it is
// measured, so no conformity (ISO 14253-1) is decided and no class proven on it.
export const onSimulatedFace = (inspection) => Boolean(inspection) && inspection.source === 'simulated';
export const SIMULATED_NOTE = 'the simulated face: nothing of it is measured, so no conformity is decided';

export const SERIES_NOTE = 'series value, not confirmed: enter the hob maker\'s table';
const num = (v) => (typeof v === 'number' && Number.isFinite(v) ? v : null);
const label = (check) => (CHECK_WORDS[check] || { label: check }).label;
const shortLabel = (check) => (CHECK_WORDS[check] || {}).short || label(check);
const minus = (text) => text.replace(/^-/, '\u2212');

// A figure with its unit as the schema states it (format.js).
export { withUnit };

// The tolerance the check's grade rests on (its class's; the loosest's when outside the table).
export function gradeTolerance(c) {
  if (!c || !c.tolerances || !c.tolerances.length) return null;
  const k = (c.classes || []).indexOf(c.grade);
  return k >= 0 ? c.tolerances[k] : c.tolerances[c.tolerances.length - 1];
}

// The class and its conformity, the lead of the inspection: {graded, simulated, same, klass,
// conformity, proven, classStar, provenStar, seriesNote, text, classText, provenText}. `text` is
// one line: "Class A — conforms (ISO 14253-1, U95 = 2 µm); proven class A". When the proven class
// differs, classText and provenText are the two halves the page shows side by side. On the
// simulated face the class alone, said to be the simulated face's, with no conformity and no
// proven class: "Class AA on the simulated face (nothing measured: no conformity is decided)".
// The class carries the * of a check it is that check's grade of, and the proven class that of a
// check's proven grade (the table's marks, as rows give them: inspectionRows); seriesNote says
// what the * means, and `text` carries it: "Class B* — conforms (...); proven class B* (* the
// class and the proven class rest on a series value, not confirmed: enter the hob maker's table)".
export function classLead(inspection, unitOf = unitText, rows = inspectionRows(inspection, { unitOf })) {
  if (!inspection) return null;
  const klass = inspection.class, proven = inspection.provenClass, conformity = inspection.conformity;
  if (klass === 'not graded') {
    return { graded: false, simulated: false, same: true, klass, conformity, proven, classStar: false, provenStar: false, seriesNote: '',
      text: 'Not graded', classText: 'Not graded', provenText: '' };
  }
  const simulated = onSimulatedFace(inspection);
  const classStar = rows.some((r) => r.grade === klass && r.series);
  const provenStar = !simulated && proven !== 'none' && rows.some((r) => r.decided && r.proven === proven && r.provenText.endsWith('*'));
  const rests = [classStar && 'class', provenStar && 'proven class'].filter(Boolean);
  const seriesNote = rests.length ? `* the ${rests.join(' and the ')} ${rests.length > 1 ? 'rest' : 'rests'} on a ${SERIES_NOTE}` : '';
  const noted = (text) => (seriesNote ? `${text} (${seriesNote})` : text);
  const star = (on) => (on ? '*' : '');
  if (simulated && conformity === 'does not conform') {
    // The face is not measured, but a measured gash spacing beyond the table plus U95 decides.
    const classText = `Class ${klass}${star(classStar)} — does not conform (ISO 14253-1: the gashes' spacing measured is beyond the tolerance plus U95; the face is not measured)`;
    return { graded: true, simulated: true, same: true, klass, conformity, proven, classStar, provenStar: false, seriesNote,
      text: noted(`${classText}; proven class: none`), classText, provenText: 'proven class: none' };
  }
  if (simulated) {
    // Gash deviations given are measured, the face is not: the class rests on both.
    const spacing = Object.keys(inspection.checks || {}).some((k) => (CHECK_WORDS[k] || {}).spacing);
    const classText = `Class ${klass}${star(classStar)} on the simulated face (${spacing ? 'the face is not measured' : 'nothing measured'}: no conformity is decided)`;
    return { graded: true, simulated: true, same: true, klass, conformity: 'not decided', proven: null, classStar, provenStar, seriesNote,
      text: noted(classText), classText, provenText: '' };
  }
  const u = withUnit(fmt(inspection.uncertainty, 3), unitOf('inspection.uncertainty'));
  const classText = `Class ${klass}${star(classStar)} — ${conformity} (ISO 14253-1, U95 = ${u})`;
  const provenText = proven === 'none' ? 'proven class: none' : `proven class ${proven}${star(provenStar)}`;
  return { graded: true, simulated: false, same: proven === klass, klass, conformity, proven, classStar, provenStar, seriesNote,
    text: noted(`${classText}; ${provenText}`), classText, provenText };
}

// "Rake face (DIN 3968, module band over 6.3 to 10 mm, measured face): class A (limited by the
// pitch jump); after the correction, if the identified error is all of the machine's: class AA." A class that is not graded says why.
export function verdictSentence(inspection) {
  if (!inspection) return '';
  // The face's checks left ungraded (inspection.faceNotGraded): measured points the axes' model of
  // the face does not explain; the table's gaps otherwise.
  const faceNot = Boolean(inspection.faceNotGraded);
  // "Outside B" where the limiting check's table stops at B: the other checks graded C or worse
  // are named, as the hob is no better than they are (an independent review: "outside B" by the
  // gash lead had hidden a radial alignment of class D).
  const worse = (checks, limiting, c) => (/^outside [^D]/.test(c) ? Object.entries(checks || {})
    .filter(([k, x]) => k !== limiting && /^(C|D|outside .+)$/.test(x.grade)).map(([k, x]) => `the ${label(k)} ${x.grade}`) : []);
  const klass = (c, limiting, checks) => {
    if (c === 'not graded') {
      return faceNot ? 'not graded (the axes\' model of the face does not explain the measured points: see the checks)'
        : 'not graded (the tolerance table has no value for this module on any check computed)';
    }
    const others = worse(checks, limiting, c);
    const limited = limiting ? ` (limited by the ${label(limiting)}${others.length ? `, whose table stops at ${c.slice(8)}; ${others.join(', ')}` : ''})` : '';
    return `class ${c}${limited}${faceNot ? ', the face\'s checks not graded (see the checks)' : ''}${
      inspection.notMeasured ? ', the gashes\' spacing not measured (see the checks)' : ''}`;
  };
  const source = { gashTopographies: 'the worst of the gash topographies', measuredPoints: 'measured points' }[inspection.source] || `${inspection.source} face`;
  let text = `Rake face (DIN 3968, module band ${inspection.moduleBand}, ${source}): ${klass(inspection.class, inspection.limitingCheck, inspection.checks)}`;
  if (inspection.after && inspection.after.class) text += `; after the correction, if the identified error is all of the machine's: ${klass(inspection.after.class, inspection.after.limitingCheck, inspection.after.checks)}`;
  return `${text}.`;
}

// The checks whose U95 exceeds a tenth of the tolerance they are graded by, in words; '' when none.
// "The measurement's uncertainty U95 exceeds a tenth of the tolerance for the radial alignment (U 3
// µm, tolerance AA 25 µm): its class rests on a measurement too coarse for it. Measure with a
// smaller uncertainty."
export function uncertaintyWarningText(inspection, unitOf = unitText) {
  const names = String((inspection && inspection.uncertaintyWarning) || '').split(',').map((s) => s.trim()).filter(Boolean);
  if (!names.length) return '';
  const parts = names.map((name) => {
    const c = inspection.checks && inspection.checks[name];
    const unit = unitOf(`inspection.checks.${name}.uncertainty`);
    const t = gradeTolerance(c);
    if (!c || t === null) return shortLabel(name);
    const klass = (c.classes || []).includes(c.grade) ? c.grade : c.classes[c.classes.length - 1];
    return `${shortLabel(name)} (U ${withUnit(fmt(c.uncertainty, 3), unit)}, tolerance ${klass} ${withUnit(fmt(t, 4), unitOf(`inspection.checks.${name}.tolerances`))})`;
  });
  const list = parts.length > 1 ? `${parts.slice(0, -1).join(', ')} and ${parts[parts.length - 1]}` : parts[0];
  return `The measurement's uncertainty U95 exceeds a tenth of the tolerance for the ${list}: ${
    parts.length > 1 ? 'their class rests' : 'its class rests'} on a measurement too coarse for it. Measure with a smaller uncertainty.`;
}

// The rake error in a line, with what it does to the gear when the case has the hob's relief:
// "Rake error: hook 2.1′ (0.050 mm into the tooth); the gear's pressure angle changes by −0.19′
// (−4.8′ per degree of hook)." Null when the result has no rake error.
export function rakeText(inspection, gearEffect, unitOf = unitText) {
  // Read off a face that does not stand for the measurement (inspection.faceNotGraded): not given.
  if (inspection && inspection.faceNotGraded) return 'Rake error: not read, as the face\'s checks are not graded (see the checks).';
  const angle = num(inspection && inspection.rakeAngle), offset = num(inspection && inspection.rakeOffset);
  if (angle === null || offset === null) return null;
  const angleUnit = unitOf('inspection.rakeAngle'), offsetUnit = unitOf('inspection.rakeOffset');
  const none = Number(fixed(Math.abs(angle), 1)) === 0 && Number(fixed(Math.abs(offset), 3)) === 0;
  const hook = angle > 0;
  let text = none ? `Rake error: none (${withUnit(fixed(0, 1), angleUnit)})`
    : `Rake error: ${hook ? 'hook' : 'drag'} ${withUnit(fixed(Math.abs(angle), 1), angleUnit)} (${withUnit(fixed(Math.abs(offset), 3), offsetUnit)} ${
      offset > 0 ? 'into the tooth' : offset < 0 ? 'out of the tooth' : 'across the face line'})`;
  const per = num(gearEffect && gearEffect.pressureAnglePerDegreeOfRake);
  const change = num(gearEffect && gearEffect.rakeErrorPressureAngle);
  const perText = per === null ? '' : withUnit(minus(fixed(per, 1)), unitOf('gearEffect.pressureAnglePerDegreeOfRake'));
  if (per !== null && change !== null && !none) {
    text += `; the gear's pressure angle changes by ${withUnit(minus(signed(change, 2)), unitOf('gearEffect.rakeErrorPressureAngle'))} (${perText} of hook).`;
  } else if (per !== null) {
    text += `; a hook would change the gear's pressure angle by ${perText} of hook.`;
  } else {
    text += '. Enter the hob\'s relief (gashes z and relief K, or the side relief angle) to see what it does to the gear\'s pressure angle.';
  }
  return text;
}

// "Cumulative spread of the cutting faces (largest minus smallest gash deviation; information, not
// graded): 10.000 µm; predicted after the correction 0.006 µm." Null without gash deviations.
export function cumulativeText(inspection, unitOf = unitText) {
  const v = num(inspection && inspection.cumulativeSpacing);
  if (v === null) return null;
  const unit = unitOf('inspection.cumulativeSpacing');
  const after = num(inspection.after && inspection.after.cumulativeSpacing);
  return `Cumulative spread of the cutting faces (largest minus smallest gash deviation; information, not graded): ${withUnit(fixed(v, 3), unit)}${
    after === null ? '' : `; predicted after the correction ${withUnit(fixed(after, 3), unitOf('inspection.after.cumulativeSpacing'))}`}.`;
}

// A check's value as the table shows it: 3 decimals, or as many more (up to 6, the grading's
// 1e-6 µm) as it takes not to read as a limit it is not: a tolerance, or a tolerance less or plus
// U (the conformity's limits). 25.0004 µm graded A against AA 25 µm reads "25.0004", not "25.000".
export function checkValueText(value, tolerances = [], uncertainty = 0) {
  if (value === null) return null;
  const u = uncertainty || 0;
  const limits = tolerances.filter((t) => typeof t === 'number').flatMap((t) => [t, t - u, t + u]);
  // As written: a limit such as 10 - 1.12 is 8.879999999999999 in binary, and 8.8804 must not read
  // as it. A value within 1e-9 of a limit is at it.
  const a = Math.abs(value);
  let digits = 3;
  while (digits < 6 && limits.some((t) => Math.abs(a - t) > 1e-9 && fixed(a, digits) === fixed(t, digits))) digits += 1;
  return fixed(value, digits);
}

// One row per check computed: {check, label, unit, value, valueText, grade, gradeText, conformity, proven,
// provenText, decided, confidence, series, source, uncertainty, tolerances, after: {value, grade,
// valueText} | null}; valueText: the value as the table shows it (checkValueText).
// decided: false for a check of the simulated face, whose conformity and proven grade are no decision.
// gradeText is the grade with a * when its tolerance is a series value, and provenText the proven
// class with a * when the tolerance it rests on is one (known from the table's cells, or the
// grade's own when it is the same class). With the table in use and the band
// (table, band, confidenceOf(check, klass) from tolerance-edit.js's cellConfidence), the class
// tolerances carry the * of their own cells.
export function inspectionRows(inspection, { unitOf = unitText, confidenceOf = null } = {}) {
  if (!inspection || !inspection.checks) return [];
  return Object.keys(CHECK_WORDS).filter((k) => inspection.checks[k]).map((k) => {
    const c = inspection.checks[k], a = inspection.after || {};
    const afterChecks = a.checks || {};
    const graded = c.grade !== 'not graded';
    const series = graded && c.confidence === 'series';
    const star = (klass) => (confidenceOf && confidenceOf(k, klass) === 'series' ? '*' : '');
    return {
      check: k, label: label(k), unit: unitOf(`inspection.${k}`), value: num(c.value), grade: c.grade,
      valueText: checkValueText(num(c.value), c.tolerances || [], graded ? num(c.uncertainty) : 0),
      gradeText: `${c.grade}${series ? '*' : ''}`,
      conformity: c.conformity, proven: graded ? c.provenGrade : '',
      decided: !(onSimulatedFace(inspection) && !CHECK_WORDS[k].spacing),
      provenText: !graded ? '' : `${c.provenGrade}${c.provenGrade === 'none' ? ''
        : confidenceOf ? star(c.provenGrade) : c.provenGrade === c.grade && series ? '*' : ''}`,
      confidence: c.confidence || '', series,
      source: c.source || '', uncertainty: num(c.uncertainty),
      tolerances: (c.classes || []).map((name, i) => `${name} ${fmt(c.tolerances[i], 4)}${star(name)}`).join(' · ') || 'none in the table',
      // After the correction: not where the face's checks rest on a model that does not explain the points.
      after: (k in a || afterChecks[k]) && !(inspection.faceNotGraded && !CHECK_WORDS[k].spacing)
        ? { value: num(a[k]), grade: afterChecks[k] ? afterChecks[k].grade : '',
          valueText: checkValueText(num(a[k]), c.tolerances || []) } : null,
    };
  });
}
