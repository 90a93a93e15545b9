// The results as CSV, as a job's record needs them: the inputs, the verdict and the figures
// before and after, the effect on the gear, the axis polynomials (nominal, run, corrected, and
// the change to type in) with their units, the measured grid and the topography grids; and the
// wheel profile's points for a dresser. UTF-8 with a BOM, so that µ and ² survive spreadsheet programs; with a comma and
// a decimal point, or a semicolon and a decimal comma (style 'semicolon') as a German
// spreadsheet reads them. The figures' labels and units are the module's (result-fields.js).
import { AXES, coefficientUnit } from '../limits.js';
import { fmt, motionUnit } from '../format.js';
import { FACE_FIGURES } from '../figures.js';
import { FLANKS, gearEffectRows, hasGearEffect } from '../gear-effect-figures.js';
import { fieldLabel, fieldMeaning, fieldUnit, unitText } from '../result-fields.js';
import { POINTS_HEADER } from '../../../wasm/lib/points-csv.js';
import { passBound } from '../../../wasm/lib/pass-bound.js';
import { inputRows } from './input-rows.js';

const BOM = '\uFEFF';

// A name for the file from the job and the day: hobsharp-m8-helical-right-2026-11-23.csv. The
// module to 4 significant digits (m8.11, not a derived case's m8.11031724285288).
export function resultsFileName(caseObject, date = new Date()) {
  const h = (caseObject && caseObject.hob) || {};
  const m = h.normalModule;
  const job = [m === undefined ? '' : `m${typeof m === 'number' && Number.isFinite(m) ? fmt(m, 4) : m}`, h.gash || 'helical',
    (h.gash || 'helical') === 'straight' ? '' : h.hand || 'right'].filter(Boolean).join('-');
  return `hobsharp-${job}-${date.toISOString().slice(0, 10)}.csv`;
}

// inputWords: the page's names and units of the case's fields by path ({names: {path: text},
// units: {path: unit}}, views/field-names.js), so that each input is written as the form shows it,
// with its unit; a field without a name keeps its path as its name.
export function resultsCsv(r, { caseObject = null, style = 'comma', date = new Date(), inputWords = { names: {}, units: {} } } = {}) {
  const semicolon = style === 'semicolon';
  const sep = semicolon ? ';' : ',';
  const cell = (v) => {
    if (typeof v === 'number') return semicolon ? String(v).replace('.', ',') : String(v);
    const t = v === undefined || v === null ? '' : String(v);
    return /["\n;,]/.test(t) ? `"${t.replace(/"/g, '""')}"` : t;
  };
  const row = (...cells) => cells.map(cell).join(sep);
  const lines = ['# HobSharp results (hobsharp-case/1)', row('# date', date.toISOString().slice(0, 10))];
  if (caseObject) {
    lines.push('', '# inputs', row('input', 'value', 'unit', 'case field'));
    for (const [k, v] of inputRows(caseObject)) {
      lines.push(row(inputWords.names[k] || k, Array.isArray(v) ? v.join(' ') : v, inputWords.units[k] || '', k));
    }
  }
  const c = r.correction;
  if (c) {
    lines.push('', '# correction', row('verdict', c.verdict), row('method', c.method), row('status', c.status));
    // After the pass: the identified machine's figures (the face re-simulated with the identified
    // error, plus the measurement's residual, noise and all); what the pass leaves is at most the
    // bound, a row of its own (correction.predictedRmsHigh, without this measurement's noise, so it
    // can be below the rms after). No bound where there is no pass: a stop, a run kept, a proposal
    // not to be used.
    lines.push('', '# figures (normal deviation)', row('figure', 'unit', 'measured', 'after the pass on the identified machine (the measurement\'s noise and all)'));
    for (const q of FACE_FIGURES) {
      const before = `correction.${q}Before`;
      lines.push(row(fieldLabel(before), fieldUnit(before), c[`${q}Before`], c[`${q}After`]));
    }
    const bound = passBound(c);
    if (bound !== null) lines.push(row('rms the pass leaves at most (the bound without this measurement\'s noise)', fieldUnit('correction.predictedRmsHigh'), '', bound));
  } else {
    const t = r.topography;
    lines.push('', '# figures (normal deviation, simulated for the axes run)', row('figure', 'unit', 'value'));
    for (const q of FACE_FIGURES) lines.push(row(fieldLabel(`topography.${q}`), fieldUnit(`topography.${q}`), t[q]));
  }
  // The effect on the gear (docs/gear-effect.md): its figures per flank, or why there are none.
  const g = r.gearEffect;
  if (hasGearEffect(g)) {
    lines.push('', `# effect on the gear, from the ${g.source === 'simulated' ? 'simulated' : 'measured'} rake face`,
      row('figure', 'unit', ...FLANKS.map(([, label]) => label)));
    for (const [label, unit, left, right] of gearEffectRows(g)) lines.push(row(label, unit, left, right));
  } else if (g) {
    lines.push('', '# effect on the gear', row('no figures', g.reason));
  }
  // The wheel's dressing proposed (correction.wheel): the record holds what the figures after the
  // pass take dressed, at its spline points and along the dresser path (the path may reach past the
  // points), with the shares the axes and the wheel remove (an independent review found the record
  // without it).
  const w = c && c.wheelProfileOffset;
  if (w && Array.isArray(w.R) && Array.isArray(w.offset) && w.R.length === w.offset.length) {
    const R = 'correction.wheelProfileOffset.R', off = 'correction.wheelProfileOffset.offset';
    lines.push('', `# wheel dressing proposed: ${fieldMeaning(off)}`, row(fieldLabel(R), fieldUnit(R), fieldLabel(off), fieldUnit(off)));
    w.R.forEach((radius, i) => lines.push(row(radius, fieldUnit(R), w.offset[i], fieldUnit(off))));
    for (const q of ['axesShare', 'wheelShare']) {
      const path = `correction.${q}`;
      if (typeof c[q] === 'number') lines.push(row(fieldLabel(path), 'share, 0..1', c[q]));
    }
    const d = c.dresserPath;
    if (d && Array.isArray(d.R) && Array.isArray(d.Z) && Array.isArray(d.offset)) {
      const pr = 'correction.dresserPath.R', pz = 'correction.dresserPath.Z', po = 'correction.dresserPath.offset';
      lines.push('', `# dresser path: ${fieldMeaning(pr)}`,
        row(`${fieldLabel(pr)} (${fieldUnit(pr)})`, `${fieldLabel(pz)} (${fieldUnit(pz)})`, `${fieldLabel(po)} (${fieldUnit(po)})`));
      d.R.forEach((radius, i) => lines.push(row(radius, d.Z[i], d.offset[i])));
    }
  }
  lines.push('', '# axis polynomials; change = corrected - run: what the correction changes',
    row('coefficient', 'unit', 'nominal', 'run', 'corrected', 'change'));
  const per = motionUnit(r);
  const run = (caseObject && caseObject.axes) || r.axes;
  for (const a of AXES) {
    r.axes[a].forEach((v, k) => {
      const ran = run[a] ? run[a][k] : v;
      const corrected = c ? c.axes[a][k] : '';
      lines.push(row(`${a} a${k}`, coefficientUnit(a, k, per), v, ran, corrected, c ? corrected - ran : ''));
    });
  }
  const grid = (title, z) => {
    lines.push('', `# ${title}; rows r (${unitText('topography.r')}) root to tip, columns x (${unitText('topography.x')}) along the gash`);
    lines.push(row('r \\ x', ...r.topography.x));
    z.forEach((values, i) => lines.push(row(r.topography.r[i], ...values)));
  };
  // The measured grid is the case's: an input, in the case format's µm (docs/case-format.md).
  if (caseObject && caseObject.measured) grid('measured normal deviation (µm)', caseObject.measured);
  // Axes run that alone grind no face the wheel envelops (correction.linearisedAtNominal): the
  // module's topography is then the nominal axes' face, which the correction was linearised at, not
  // a face of the axes run: no grid, and no thickness, is written for them.
  const unsimulated = Boolean(c) && c.linearisedAtNominal === true;
  if (unsimulated) lines.push('', `# no simulated face for the axes run: ${fieldMeaning('correction.linearisedAtNominal')}`);
  else {
    grid(`simulated normal deviation (${unitText('topography.normal')}) for the axes run`, r.topography.normal);
    grid(`simulated circular deviation (${unitText('topography.circular')} at the mean radius)`, r.topography.circular);
  }
  if (c) grid(`predicted normal deviation after correction, on the identified machine (${unitText('correction.residual')})`, c.residual);
  // At the measuring machine's points (docs/measured-points.md): each block reads back as a
  // points CSV (wasm/lib/points-csv.js), its title line a comment; its header is that format's.
  const points = (title, list) => {
    lines.push('', `# ${title}`, POINTS_HEADER.split(',').join(sep));
    for (const p of list) lines.push(row(...p));
  };
  if (c && c.pointMeasured) {
    points('measured points', c.pointMeasured);
    points('predicted at the measured points after correction, on the identified machine', c.pointResidual);
  }
  if (!unsimulated) lines.push('', row(`# ${fieldMeaning('topography.thickness')} (${unitText('topography.thickness')})`, r.topography.thickness));
  return BOM + lines.join('\n') + '\n';
}

// The conjugate wheel's profile (it grinds the nominal face), and where the case gives the wheel a
// profile offset or a measured profile, that wheel's beside it (wheelProfile.dressedR, dressedZ):
// read back (wasm/lib/wheel-csv.js), R and Z are the conjugate wheel's, the dressed columns left out.
export function profileCsv(r) {
  const p = r.wheelProfile;
  const dressed = Array.isArray(p.dressedR) && Array.isArray(p.dressedZ) && p.dressedR.length === p.r.length && p.dressedZ.length === p.r.length;
  const rows = dressed
    ? ['# wheel axial profile (mm): tooth-face radius r; the conjugate wheel, which grinds the nominal face: wheel radius R, axial position Z; '
      + 'the case\'s dressed (or measured) wheel: R_dressed, Z_dressed', 'r_mm,R_mm,Z_mm,R_dressed_mm,Z_dressed_mm']
    : ['# wheel axial profile of the conjugate wheel, which grinds the nominal face: tooth-face radius r, wheel radius R, axial position Z (mm)', 'r_mm,R_mm,Z_mm'];
  p.r.forEach((radius, i) => rows.push(dressed ? `${radius},${p.R[i]},${p.Z[i]},${p.dressedR[i]},${p.dressedZ[i]}` : `${radius},${p.R[i]},${p.Z[i]}`));
  return rows.join('\n') + '\n';
}

// The dresser path: the wheel's axial profile after the proposed offset (correction.dresserPath),
// in the frame of the profile points; read back by wasm/lib/wheel-csv.js as a measured wheel.
export function dresserCsv(r) {
  const d = r.correction.dresserPath;
  const rows = ['# dresser path: the wheel axial profile with the proposed offset dressed (HobSharp correction.dresserPath)',
    '# R wheel radius, Z along the wheel axis (mm), in the frame of the wheel profile points', 'R_mm,Z_mm'];
  d.R.forEach((radius, i) => rows.push(`${radius},${d.Z[i]}`));
  return rows.join('\n') + '\n';
}
