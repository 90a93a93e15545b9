// The paper example loads the setting angle and the centre distance as derived (their fields
// empty), so that they follow the hob, the wheel and the hand. This note says that the derived
// values equal the paper's (Tab. 1: 12.626°, 69.446 mm), for as long as they do.
import { fixed } from '../format.js';

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
      `${fixed(s.settingAngle, 4)}° and ${fixed(s.centerDistance, 4)} mm, equal to the paper's ` +
      `${fixed(p.settingAngle, 3)}° and ${fixed(p.centerDistance, 3)} mm to its three decimals. ` +
      'Type a value to fix one; clear the field to derive it again.';
  });
}
