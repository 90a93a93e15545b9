// The module's names, units and limits as the page uses them: the bindings the page and the CLI
// share (wasm/lib/limits.js, filled from the module's limits()) and the page's own words, the
// axes' descriptions.
import { setModuleLimits as setSharedLimits } from '../../wasm/lib/limits.js';

export * from '../../wasm/lib/limits.js';

// The page's descriptions of the module's axes (Eq. 9); an axis without one shows its name.
const AXIS_WORDS = {
  X: 'C<sub>x</sub> horizontal stroke', Y: 'C<sub>y</sub> radial infeed', Z: 'C<sub>z</sub> wheel axial',
  A: 'ψ<sub>a</sub> hob rotation', B: 'ψ<sub>b</sub> wheel swivel',
};
export const AXIS_NAMES = {};

// limits: what Module.limits() returns (docs/api.md): the shared bindings (refusing a shape they
// cannot use), then the axes' descriptions.
export function setModuleLimits(limits) {
  setSharedLimits(limits);
  for (const a of limits.axes) AXIS_NAMES[a.name] = AXIS_WORDS[a.name] || a.name;
}
