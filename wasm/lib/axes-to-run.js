// The axes a sharpening machine runs, in the units its control takes (pure, with Node tests):
// X, Y, Z in mm and A, B in degrees, each a polynomial of the hob rotation in degrees (helical
// gash) or of the travel in mm (straight gash); which axes to run; and their NC program. Shared by
// the page (web/src/machine-axes.js, views/machine-axes.js) and the CLI (wasm/cli.mjs --nc).
// The calculator's polynomials are of phi in rad with A and B in rad (docs/conventions.md).
import { AXES, isRotary } from './limits.js';
import { ncProgram } from './nc-program.js';
import { changesNothing, keepsAxesRun } from './pass-bound.js';

const DEG = 180 / Math.PI;

// Coefficient a_k of an axis, converted: value factor (deg per rad for A and B) times
// (rad per deg)^k for the motion in degrees (helical); a straight gash's motion stays in mm.
export function machineCoefficients(axes, helical) {
  const out = {};
  for (const a of AXES) {
    const value = isRotary(a) ? DEG : 1;
    out[a] = axes[a].map((c, k) => c * value * (helical ? DEG ** -k : 1));
  }
  return out;
}

// The axes shown under "Axes to run" and written to the NC program, chosen alike by the page and
// the CLI: with a correction its proposal as the program carries it (correction.roundedAxes);
// when the correction says stop (the face measured is within the probe noise), or proposes no change,
// the axes run stay;
// else the case's axes (the axes run) or the nominal ones. caseAxes: the case's `axes`, if any.
export function axesToRun(result, caseAxes) {
  const c = result.correction;
  if (c && c.stop === true) {
    return { axes: result.runAxes || caseAxes || result.axes, kind: 'run',
      words: 'the axes run: keep them; the face measured is within the probe noise' };
  }
  // No change proposed (a run kept, or nothing above the noise): the axes run stay too.
  if (c && changesNothing(c)) {
    return { axes: result.runAxes || caseAxes || result.axes, kind: 'run', words: 'the axes run: keep them; no change proposed' };
  }
  if (c && c.roundedAxes) return { axes: c.roundedAxes, kind: 'corrected', words: 'the corrected proposal, as the NC program carries it' };
  if (caseAxes) return { axes: caseAxes, kind: 'run', words: 'the axes run; no correction' };
  return { axes: result.axes, kind: 'nominal', words: 'nominal; no correction' };
}

// The hob as the program's header names it, from the case: module, outer diameter, gash.
export function hobWords(hob = {}) {
  const parts = [];
  if (Number.isFinite(hob.normalModule)) parts.push(`module ${hob.normalModule} mm`);
  if (Number.isFinite(hob.outerDiameter)) parts.push(`outer diameter ${hob.outerDiameter} mm`);
  const gash = hob.gash || 'helical';
  parts.push(gash === 'straight' ? 'straight gash' : `helical gash, ${hob.hand || 'right'} hand${Number.isFinite(hob.gashLead) ? `, lead ${hob.gashLead} mm` : ''}`);
  if (Number.isFinite(hob.gashes)) parts.push(`${hob.gashes} gashes`);
  return parts.join(', ');
}

// The NC program for the axes to run (nc-program.js), for a result and the case it came
// from: the same axes, header and digits on the page and from the CLI.
export function programFor(result, caseObject, dialect, { date = new Date(), digits } = {}) {
  const helical = result.setup.motionUnit === 'rad';
  const { axes, words } = axesToRun(result, caseObject && caseObject.axes);
  const c = result.correction;
  const toProgram = (x) => (helical ? x * DEG : x);
  return ncProgram({
    axes: machineCoefficients(axes, helical),
    helical,
    motion: { min: toProgram(result.motion.min), max: toProgram(result.motion.max) },
    dialect,
    digits,
    header: {
      job: caseObject && caseObject.job,
      hob: hobWords(caseObject && caseObject.hob),
      module: caseObject && caseObject.hob && caseObject.hob.normalModule,
      axesWords: words,
      date: date.toISOString().slice(0, 10),
      rounding: c && c.roundedAxes && !keepsAxesRun(c) ? { rmsRounded: c.rmsRounded, resolutionFloor: c.resolutionFloor } : null,
    },
  });
}
