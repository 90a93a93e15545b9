// The page's sentences about a result, in the words of the engineer at the machine (pure, with
// Node tests): the status after a calculation, the setting angle the calculator derived, and the
// correction's verdict.
import { fixed, fmt, signed, withUnit } from './format.js';
import { fieldUnit, unitText } from './result-fields.js';
import { floorAboveBound, keepsAxesRun, passBound } from '../../wasm/lib/pass-bound.js';


// The status line once the newest inputs are computed.
export function updatedText(ms) {
  return `Updated — ${ms < 1 ? 'under 1' : Math.round(ms)} ms`;
}

// What the setting angle γm beside its field says: the value used, or the derived one and where
// it comes from (the gash helix angle, signed by the hand; a straight gash has none: 0°). Its unit
// is the module's (setup.settingAngle).
export function settingAngleNote(setup, unitOf = unitText) {
  const angle = (text) => withUnit(text, unitOf('setup.settingAngle'));
  if (!setup.settingAngleDerived) return `used: ${angle(fmt(setup.settingAngle))}`;
  if (setup.gash === 'straight') return `auto: ${angle(fixed(setup.settingAngle, 4))} (straight gash: no helix to follow)`;
  return `auto: ${angle(fixed(setup.settingAngle, 4))} (the gash helix angle, ${setup.hand === 'left' ? 'left' : 'right'} hand)`;
}

const plural = (n, one, many) => `${n} ${n === 1 ? one : many}`;

// The correction's verdict with its figures, in the units the module gives them (unitOf, as
// result-fields.js's fieldUnit). rank: independent coefficient combinations the
// correction moves; amplifyingDropped: combinations it leaves alone because a visible change of
// the face would need axis moves far larger than the deviation they remove (docs/method.md,
// "Correction").
export function verdictText(c, unitOf = unitText) {
  const u = (q) => unitOf(`correction.${q}Before`);
  // Stop (correction.stop): the measured face is within the probe noise; or no change proposed.
  // Its figures as measured, and nothing predicted: another pass would only move noise, or grind
  // the same face.
  if (keepsAxesRun(c)) {
    const rms = Number.isFinite(c.rmsBefore) ? `RMS ${withUnit(fixed(c.rmsBefore, 3), u('rms'))}; ` : '';
    return `${c.verdict} Measured: ${rms}sum of squares ${withUnit(fmt(c.sseBefore, 6), u('sse'))}; ` +
      `thickness ${withUnit(signed(c.thicknessBefore, 3), u('thickness'))}.`;
  }
  const dropped = c.amplifyingDropped
    ? `; ${plural(c.amplifyingDropped, 'combination is', 'combinations are')} left unchanged, because ` +
      `${c.amplifyingDropped === 1 ? 'it' : 'they'} would need large axis moves for little gain`
    : '';
  // Led by the rms, which compares between grids; the paper's sum of squares after it. The figures
  // after are the identified machine's (the face re-simulated with the identified error) with the
  // measurement's misfit kept, noise and all, said so: what the pass leaves is the bound the verdict
  // quotes, which leaves this measurement's noise out and so can lie below them.
  const squares = `sum of squares ${fmt(c.sseBefore, 6)} → ${withUnit(fmt(c.sseAfter, 4), u('sse'))}`;
  const lead = Number.isFinite(c.rmsBefore) ? `RMS ${fixed(c.rmsBefore, 3)} → ${withUnit(fixed(c.rmsAfter, 3), u('rms'))}; ${squares}`
    : `S${squares.slice(1)}`;
  return `${c.verdict} On the identified machine, with this measurement's misfit (noise and all) kept: ${lead}; ` +
    `thickness ${signed(c.thicknessBefore, 3)} → ${withUnit(signed(c.thicknessAfter, 3), u('thickness'))}. ` +
    `The correction changes ${plural(c.rank, 'independent combination', 'independent combinations')} of the coefficients${dropped}.`;
}

// A figure of µm rms for a sentence: 3 significant digits, 0 as 0.
const rmsFigure = (v) => fmt(v, 3);

// What the pass will leave: its bound (correction.predictedRmsHigh, on the probe grid) first, and
// the model's figure (correction.predictedRms) said for what it is, the face left if the identified
// error is all of the machine's, never as what the pass leaves (the pass can leave more, up to the
// bound); with the units the module gives its fields (unitOf: a path to its unit, null for a field
// it does not describe): "Predicted after the pass: at most 0.446 µm rms at the probe points (if
// the identified error is all of the machine's: 0.012 µm rms)." (the condition first: after
// a bound far above it, "at most 118 µm rms (within the probe noise if ...)" read as a contradiction,
// an independent review). Null when there is nothing to run
// (correction.stop, a run kept, or a proposal that is not usable), when a figure is not a finite number, or
// when the module gives no unit.
// After a bound below the pass's floor (floorAboveBound), the floor in words, with the module's unit:
// "; that is with the exact axes, and the machine's position resolution sets a floor of about
// 0.0329 µm rms";
// '' where the bound is above it (or there is none).
export function floorNote(c, unitOf) {
  const floor = floorAboveBound(c);
  const unit = unitOf('correction.resolutionFloor');
  if (floor === null || !unit) return '';
  return `; that is with the exact axes, and the machine's position resolution sets a floor of about ${rmsFigure(floor)} ${unit} rms`;
}

export function predictionText(c, unitOf) {
  const high = passBound(c);
  if (high === null || !Number.isFinite(c.predictedRms)) return null;
  const rms = c.predictedRms;
  const unit = unitOf('correction.predictedRms'), highUnit = unitOf('correction.predictedRmsHigh');
  if (!unit || !highUnit) return null;
  // No shape left beyond the probe's noise: say so rather than print a certain-looking 0.
  const model = rms === 0 ? 'within the probe noise' : `${rmsFigure(rms)} ${unit} rms`;
  return `Predicted after the pass: at most ${rmsFigure(high)} ${highUnit} rms at the probe points (if the identified error is all of the machine's: ${model})${floorNote(c, unitOf)}.`;
}
