// The effect on the gear as figures (docs/gear-effect.md), as the page's table
// (views/gear-effect.js), the results CSV and the printed report give them.

// The two flanks, as the result names them and in words.
export const FLANKS = [['left', 'left flank (faces −x₁)'], ['right', 'right flank (faces +x₁)']];

// Whether the result has the figures: gearEffect.reason is "" when it has, otherwise why not.
export const hasGearEffect = (g) => Boolean(g && !g.reason);

// The figures' rows: [label, unit, left flank, right flank], from the result's gearEffect.
export function gearEffectRows(g) {
  return [
    ['profile slope deviation fHα (largest over the teeth)', 'µm', g.left.profileSlope, g.right.profileSlope],
    ['pressure-angle error of that tooth', 'arc-min', g.left.pressureAngleError, g.right.pressureAngleError],
    ['profile form deviation ffα (largest)', 'µm', g.left.profileForm, g.right.profileForm],
    ['scatter of fHα along the hob', 'µm', g.left.slopeScatter, g.right.slopeScatter],
  ];
}
