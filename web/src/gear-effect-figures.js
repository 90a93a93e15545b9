// The effect on the gear as figures (docs/gear-effect.md), as the page's table
// (views/gear-effect.js), the results CSV and the printed report give them.
import { fieldLabel, unitText } from './result-fields.js';

// The two flanks, as the result names them and in words.
export const FLANKS = [['left', 'left flank (faces −x₁)'], ['right', 'right flank (faces +x₁)']];

// Whether the result has the figures: gearEffect.reason is "" when it has, otherwise why not.
export const hasGearEffect = (g) => Boolean(g && !g.reason);

// The figures per flank, as the result names them (gearEffect.left.<name>, gearEffect.right.<name>).
const FIGURES = ['profileSlope', 'pressureAngleError', 'profileForm', 'slopeScatter'];

// The figures' rows: [label, unit, left flank, right flank], from the result's gearEffect; the
// labels and units are the module's (result-fields.js), the same for both flanks.
export function gearEffectRows(g) {
  return FIGURES.map((q) => [fieldLabel(`gearEffect.left.${q}`), unitText(`gearEffect.left.${q}`), g.left[q], g.right[q]]);
}
