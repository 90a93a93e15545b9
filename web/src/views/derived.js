// The derived values beside the form's fields: what the calculator used where a field was left
// empty, and the lead or helix angle that goes with the other.
import { fixed, fmt } from '../format.js';
import { settingAngleNote } from '../words.js';

const $ = (selector) => document.querySelector(selector);

export function mountDerived(store) {
  store.on('result', ({ result }) => {
    const s = result.setup;
    const out = (name, text) => { $(`[data-derived="${name}"]`).textContent = text; };
    out('rakeAngle', `rake angle γc = ${fixed(s.rakeAngle, 4)}°`);
    out('gashHelixAngle', s.gashHelixAngle !== undefined ? `helix angle βc = ${fixed(s.gashHelixAngle, 4)}°` : '');
    out('gashLead', s.gashLead !== undefined ? `lead Lc = ${fixed(s.gashLead, 3)} mm` : '');
    out('settingAngle', settingAngleNote(s));
    out('centerDistance', s.centerDistanceDerived ? `auto: ${fixed(s.centerDistance, 6)} mm (wheel rim at the gash root)` : `used: ${fmt(s.centerDistance)} mm`);
    out('screwParameter', s.motionUnit === 'mm' ? 's (mm): straight gash, the hob travels along its axis'
      : `${fixed(s.screwParameter, 4)} φ₁ mm (P_t = L_c / 2π = ${fixed(s.screwParameter, 4)} mm/rad)`);
    $('.motion-symbol').textContent = s.motionUnit === 'mm' ? 's in mm (straight gash)' : 'φ₁ in rad';
  });
}
