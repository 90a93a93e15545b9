// The derived values beside the form's fields: what the calculator used where a field was left
// empty, and the lead or helix angle that goes with the other.
import { fixed, fmt, withUnit } from '../format.js';
import { fieldLabel, fieldPresent, unitText } from '../result-fields.js';
import { settingAngleNote } from '../words.js';

const $ = (selector) => document.querySelector(selector);
const unit = (name) => unitText(`setup.${name}`);

export function mountDerived(store) {
  store.on('result', ({ result }) => {
    const s = result.setup;
    const out = (name, text) => { $(`[data-derived="${name}"]`).textContent = text; };
    // "label = value unit", as the module labels and units the field (setup.<name>).
    const figure = (name, digits) => (fieldPresent(result, `setup.${name}`)
      ? `${fieldLabel(`setup.${name}`)} = ${withUnit(fixed(s[name], digits), unit(name))}` : '');
    out('rakeAngle', figure('rakeAngle', 4));
    out('gashHelixAngle', figure('gashHelixAngle', 4));
    out('gashLead', figure('gashLead', 3));
    out('settingAngle', settingAngleNote(s));
    out('centerDistance', s.centerDistanceDerived ? `auto: ${withUnit(fixed(s.centerDistance, 6), unit('centerDistance'))} (wheel rim at the gash root)`
      : `used: ${withUnit(fmt(s.centerDistance), unit('centerDistance'))}`);
    // The motion parameter's unit is the result's value setup.motionUnit; P_t φ₁ is a travel, in
    // the unit of P_t's numerator (mm/rad).
    const travel = unit('screwParameter').split('/')[0];
    out('screwParameter', s.gash === 'straight' ? `s (${s.motionUnit}): straight gash, the hob travels along its axis`
      : `${withUnit(`${fixed(s.screwParameter, 4)} φ₁`, travel)} (P_t = L_c / 2π = ${withUnit(fixed(s.screwParameter, 4), unit('screwParameter'))})`);
    $('.motion-symbol').textContent = s.gash === 'straight' ? `s in ${s.motionUnit} (straight gash)` : `φ₁ in ${s.motionUnit}`;
  });
}
