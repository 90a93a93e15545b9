// The correction's options at the measured grid: the method (identify, then compensate; or the
// paper's linear step), the probe noise sigma and the machine's resolution per axis, with the
// calculator's defaults as placeholders (web/src/correction-options.js). A refused option is shown
// at its input; the measured grid is kept.
import { CORRECTION } from '../limits.js';
import { OPTION_FIELD, optionTexts, withOption } from '../correction-options.js';
import { fmt } from '../format.js';

const $ = (selector) => document.querySelector(selector);
const $$ = (selector) => Array.from(document.querySelectorAll(selector));

function applyDefaults() {
  if (!CORRECTION.probeNoise) return;
  $('#probe-noise').placeholder = fmt(CORRECTION.probeNoise.default, 3);
  $('#probe-noise').max = CORRECTION.probeNoise.max;
  for (const el of $$('[data-resolution]')) {
    const r = CORRECTION.resolution[el.dataset.resolution];
    Object.assign(el, { placeholder: String(r.default), min: r.min, max: r.max });
    el.nextElementSibling.textContent = r.unit;
  }
}

function clearError() {
  for (const el of $$('#correction-options .invalid')) { el.classList.remove('invalid'); el.removeAttribute('aria-invalid'); }
  $('#correction-options-error').hidden = true;
}

export function mountCorrectionOptions(store) {
  const box = $('#correction-options');
  const show = (state) => {
    const t = optionTexts(state.tuning, CORRECTION.defaultMethod || 'nonlinear');
    $('#correction-method').value = t.method;
    $('#correct-wheel').checked = t.wheel;
    const noise = $('#probe-noise');
    if (document.activeElement !== noise) noise.value = t.probeNoise;
    $('#probe-noise-note').textContent = t.simulated
      ? 'The grid is a simulated what-if: declared noise-free by the page. Type a value to override.'
      : t.method === 'linear' ? 'The probe\'s standard deviation; the linear step uses it only for the standard uncertainties.'
        : 'The probe\'s standard deviation; the correction moves nothing the noise could have made.';
    for (const el of $$('[data-resolution]')) {
      if (document.activeElement !== el) el.value = t.resolution[el.dataset.resolution] || '';
    }
  };
  const changed = (event) => {
    const el = event.target;
    const key = el.id === 'correction-method' ? 'method' : el.id === 'correct-wheel' ? 'wheel' : el.id === 'probe-noise' ? 'probeNoise'
      : el.dataset.resolution ? `resolution.${el.dataset.resolution}` : null;
    if (!key) return;
    const tuning = withOption(store.state.tuning, key, el.type === 'checkbox' ? el.checked : el.value, CORRECTION.defaultMethod || 'nonlinear');
    store.setInputs({ tuning }, { source: 'correction-options', at: event.timeStamp });
    show(store.state);  // also when no measured grid is in use, and so nothing is recomputed
    if (event.type === 'change') store.emit('commit');
  };
  box.addEventListener('input', changed);
  box.addEventListener('change', changed);
  store.on('limits', applyDefaults);
  for (const event of ['restore', 'inputs']) store.on(event, (_, state) => show(state || store.state));
  store.on('result', clearError);
  store.on('refusal', ({ error }) => {
    if (!OPTION_FIELD.test(error.field || '')) return;
    clearError();
    const [, , , axis] = /^correction\.(\w+)(\.([XYZAB]))?$/.exec(error.field) || [];
    const input = axis ? $(`[data-resolution="${axis}"]`)
      : error.field === 'correction.probeNoise' ? $('#probe-noise') : error.field === 'correction.method' ? $('#correction-method')
        : error.field === 'correction.wheel' ? $('#correct-wheel') : null;
    if (input) { input.classList.add('invalid'); input.setAttribute('aria-invalid', 'true'); }
    const note = $('#correction-options-error');
    note.textContent = error.message;
    note.hidden = false;
  });
}
