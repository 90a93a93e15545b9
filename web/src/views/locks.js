// The locks, in the correction's options: a switch per axis that keeps all its coefficients out
// of the correction (state.lockedAxes), and, folded under them, a box per coefficient
// (state.locked: "X a0", ...), as the case format keeps them. A loaded case's locks show here;
// each change is an undo step.
import { AXES, coefficientUnit } from '../limits.js';
import { motionUnit } from '../format.js';

const $ = (selector) => document.querySelector(selector);
const toggled = (list, item, on) => (on ? [...new Set([...list, item])] : list.filter((x) => x !== item));

function render(r, state) {
  $('#lock-axes').innerHTML = AXES.map((a) => `<label class="lock-switch" title="Keep every coefficient of ${a} out of the correction">` +
    `<input type="checkbox" data-lock-axis="${a}" ${state.lockedAxes.includes(a) ? 'checked' : ''}
      aria-label="Lock every coefficient of ${a}"> ${a}</label>`).join('');
  const degree = r.axes.X.length - 1, per = motionUnit(r);
  $('#lock-coefficient-boxes').innerHTML = AXES.map((a) => `<p class="lock-row"><span>${a}</span>${Array.from({ length: degree + 1 }, (_, k) => {
    const name = `${a} a${k}`, unit = coefficientUnit(a, k, per);
    return `<label title="${name}, ${unit}"><input type="checkbox" data-lock="${name}" ${state.locked.includes(name) ? 'checked' : ''}
      aria-label="Lock ${name} (${unit})"> a${k}</label>`;
  }).join('')}</p>`).join('');
}

export function mountLocks(store) {
  // Drawn again only when what it shows changed, so that a tick keeps the keyboard's place.
  let drawn = '';
  const show = (force) => {
    const s = store.state;
    if (!s.result) return;
    const key = JSON.stringify([s.result.axes.X.length, motionUnit(s.result), s.locked, s.lockedAxes]);
    if (force || key !== drawn) { render(s.result, s); drawn = key; }
  };
  store.on('result', () => show(false));
  store.on('restore', () => show(true));
  store.on('inputs', () => show(false));
  $('#locks').addEventListener('change', (e) => {
    const t = e.target, s = store.state;
    if (t.dataset.lock) store.setInputs({ locked: toggled(s.locked, t.dataset.lock, t.checked) }, { source: 'locks' });
    else if (t.dataset.lockAxis) store.setInputs({ lockedAxes: toggled(s.lockedAxes, t.dataset.lockAxis, t.checked) }, { source: 'locks' });
    else return;
    store.emit('commit');
  });
}
