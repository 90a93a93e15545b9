// The paper example loads the setting angle and the centre distance as derived (their fields
// empty), so that they follow the hob, the wheel and the hand. This note says that the derived
// values equal the paper's (Tab. 1: 12.626°, 69.446 mm), for as long as they do.
import { fixed, withUnit } from '../format.js';
import { unitText } from '../result-fields.js';

// The paper's values in the units of the result's (setup.settingAngle, setup.centerDistance).
const angle = (text) => withUnit(text, unitText('setup.settingAngle'));
const distance = (text) => withUnit(text, unitText('setup.centerDistance'));

const close = (derived, paper) => typeof paper === 'number' && Math.abs(derived - paper) < 5e-4;

export function mountPaperNote(store) {
  const note = document.querySelector('#paper-note');
  store.on('result', ({ result }, state) => {
    const p = state.paper, s = result.setup;
    const same = !!p && s.settingAngleDerived && s.centerDistanceDerived &&
      close(s.settingAngle, p.settingAngle) && close(s.centerDistance, p.centerDistance);
    note.hidden = !same;
    if (!same) return;
    note.innerHTML = `Paper example: <i>γ<sub>m</sub></i> and <i>E<sub>t</sub></i> are derived (their fields are empty): ` +
      `${angle(fixed(s.settingAngle, 4))} and ${distance(fixed(s.centerDistance, 4))}, equal to the paper's ` +
      `${angle(fixed(p.settingAngle, 3))} and ${distance(fixed(p.centerDistance, 3))} to its three decimals. ` +
      'Type a value to fix one; clear the field to derive it again.';
  });
}
