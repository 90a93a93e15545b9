// The status line (what the calculator is doing) and the notice, a message that stays on screen
// until the user changes an input or closes it (a refused link, a grid set aside, a restart).
// Both stay in view while scrolling (a sticky bar).
import { worded } from './field-names.js';
import { updatedText } from '../words.js';

const $ = (selector) => document.querySelector(selector);

export function mountStatus(store) {
  const status = $('#status');
  const notice = $('#notice');
  store.on('status', (_, state) => {
    status.textContent = state.status.text;
    status.className = state.status.kind;
  });
  store.on('notice', (_, state) => {
    notice.hidden = !state.notice;
    $('#notice-text').textContent = state.notice ? state.notice.text : '';
  });
  $('#notice-close').addEventListener('click', () => store.setNotice(null));

  const kept = () => (store.state.result ? ' The results below are from the last good input.' : '');
  store.on('result', ({ ms }) => store.setStatus(updatedText(ms), 'ok'));
  store.on('refusal', ({ error, caseObject }) => {
    const what = caseObject ? 'Not computed' : 'Measurement not used';
    store.setStatus(`${what}: ${worded(error).text}${kept()}`, 'error');
    if (error.code === 'Timeout') store.setNotice(`${error.message}${kept()} Change an input to compute again.`);
  });
  store.on('cancelled', () => {
    store.setStatus(`Cancelled: nothing was computed for the inputs now in the form.${kept()}`, 'error');
    store.setNotice(`The computation was cancelled.${kept()} Change an input to compute again.`);
  });
  // A grid that does not fit the grid lines is used again once they are back to its shape (recompute.js).
  store.on('aside', ({ error, untilFits }) => store.setNotice(`The measured grid is set aside, not used: ${error.message} ` +
    `Its text stays in the box under "The measured face": ${untilFits ? 'set the grid lines back to its shape and it is used again, or correct it there and press "Use this grid".'
      : 'correct it there, or the grid, and press "Use this grid".'}`));
  // A user's change ends the notice; loading a case does not.
  store.on('inputs', ({ source }) => { if (store.state.notice && source !== 'load') store.setNotice(null); });
}
