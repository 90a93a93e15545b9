// The run axes of a second pass (a loaded case's "axes"): shown while they are in use, with a
// button that clears them, so that the face is ground with the nominal axes again.
import { AXES, AXIS_UNIT } from '../limits.js';
import { escapeHtml, motionSymbol, polynomialText } from '../format.js';

const $ = (selector) => document.querySelector(selector);

export function mountRunAxes(store) {
  const box = $('#run-axes');
  const render = (state) => {
    box.hidden = !state.axes;
    if (!state.axes) return;
    const symbol = motionSymbol(state.result);
    $('#run-axes-list').innerHTML = AXES.map((a) =>
      `<li data-run-axis="${a}">${a} (${AXIS_UNIT[a]}) = ${escapeHtml(polynomialText(state.axes[a] || [], symbol))}</li>`).join('');
  };
  for (const event of ['inputs', 'restore', 'result']) store.on(event, (_, state) => render(state));
  $('#clear-run-axes').addEventListener('click', () => {
    store.setInputs({ axes: null }, { source: 'axes' });
    store.emit('commit');
  });
}
