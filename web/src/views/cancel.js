// Cancel: while the calculator has computed for longer than a moment, a button beside the status
// ends the computation (client.js cancel(): the worker is ended and a fresh one started). The
// results on screen stay; the status and a notice say that nothing was computed for the inputs
// now in the form (views/status.js, 'cancelled'), and the next change computes.
const $ = (selector) => document.querySelector(selector);
// A computation shorter than this shows no button (it would only flicker).
const SHOW_AFTER_MS = 400;

export function mountCancel(calculator) {
  const button = $('#cancel-computation');
  let timer = null;
  calculator.onBusy = (busy) => {
    clearTimeout(timer);
    if (busy) timer = setTimeout(() => { button.hidden = false; }, SHOW_AFTER_MS);
    else button.hidden = true;
  };
  button.addEventListener('click', () => {
    button.hidden = true;
    calculator.cancel();
  });
}
