// The page's sentences about a result, in the words of the engineer at the machine (pure, with
// Node tests): the status after a calculation, the setting angle the calculator derived, and the
// correction's verdict.
import { fixed, fmt, signed } from './format.js';

// The status line once the newest inputs are computed.
export function updatedText(ms) {
  return `Updated — ${ms < 1 ? 'under 1' : Math.round(ms)} ms`;
}

// What the setting angle γm beside its field says: the value used, or the derived one and where
// it comes from (the gash helix angle, signed by the hand; a straight gash has none: 0°).
export function settingAngleNote(setup) {
  if (!setup.settingAngleDerived) return `used: ${fmt(setup.settingAngle)}°`;
  if (setup.gash === 'straight') return `auto: ${fixed(setup.settingAngle, 4)}° (straight gash: no helix to follow)`;
  return `auto: ${fixed(setup.settingAngle, 4)}° (the gash helix angle, ${setup.hand === 'left' ? 'left' : 'right'} hand)`;
}

const plural = (n, one, many) => `${n} ${n === 1 ? one : many}`;

// The correction's verdict with its figures. rank: independent coefficient combinations the
// correction moves; amplifyingDropped: combinations it leaves alone because a visible change of
// the face would need axis moves far larger than the deviation they remove (README "How the core
// computes" > Correction).
export function verdictText(c) {
  const dropped = c.amplifyingDropped
    ? `; ${plural(c.amplifyingDropped, 'combination is', 'combinations are')} left unchanged, because ` +
      `${c.amplifyingDropped === 1 ? 'it' : 'they'} would need large axis moves for little gain`
    : '';
  // Led by the rms, which compares between grids; the paper's sum of squares after it.
  const squares = `sum of squares ${fmt(c.sseBefore, 6)} → ${fmt(c.sseAfter, 4)} µm²`;
  const lead = Number.isFinite(c.rmsBefore) ? `RMS ${fixed(c.rmsBefore, 3)} → ${fixed(c.rmsAfter, 3)} µm; ${squares}`
    : `S${squares.slice(1)}`;
  return `${c.verdict} ${lead}; ` +
    `thickness ${signed(c.thicknessBefore, 3)} → ${signed(c.thicknessAfter, 3)} µm. ` +
    `The correction changes ${plural(c.rank, 'independent combination', 'independent combinations')} of the coefficients${dropped}.`;
}
