// The message beside the measured data's box: why a measurement, a file or a pasted text was
// refused, and what is in use (state.measuredMessage, web/src/measurement.js), or nothing.
const $ = (selector) => document.querySelector(selector);

export function mountMeasuredMessage(store) {
  const message = $('#measured-error');
  store.on('measurement', (_, state) => {
    if (state.measuredMessage === null) { message.hidden = true; return; }
    message.textContent = state.measuredMessage;
    message.hidden = false;
  });
}
