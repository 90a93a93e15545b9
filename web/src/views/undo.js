// Undo and redo of the inputs: the buttons, Ctrl+Z and Ctrl+Shift+Z (or Ctrl+Y) outside text
// fields, and the browser's Back and Forward buttons. Every committed change of the inputs is an
// entry in the browser's session history (history.pushState) holding the inputs; going to an
// entry (popstate) puts its inputs back. Undo and redo go through the browser (history.back and
// history.forward), so that its Back button and the page's Undo are one history.
import { inputsOf } from '../store.js';
import { createUndoStack } from '../undo-stack.js';

const $ = (selector) => document.querySelector(selector);
const isTextField = (el) => !!el && !!el.matches &&
  el.matches('input:not([type=checkbox]):not([type=radio]):not([type=button]):not([type=file]), textarea, select, [contenteditable]');

export function mountUndo(store) {
  const stack = createUndoStack();
  const show = () => {
    $('#undo').disabled = !stack.canUndo();
    $('#redo').disabled = !stack.canRedo();
  };
  const entry = () => ({ ...(history.state || {}), hobsharp: { step: stack.step, inputs: stack.inputs } });

  store.on('commit', () => {
    const inputs = inputsOf(store.state);
    if (stack.step < 0) {
      // The page as opened (or reloaded: then the browser's entry keeps its step number).
      const prior = history.state && history.state.hobsharp;
      stack.start(inputs, prior ? prior.step : 0);
      history.replaceState(entry(), '', location.href);
    } else if (stack.commit(inputs) !== null) {
      history.pushState(entry(), '', location.href);
    }
    show();
  });

  window.addEventListener('popstate', (event) => {
    const h = event.state && event.state.hobsharp;
    if (!h || !h.inputs) return;
    stack.moveTo(h.step, h.inputs);
    store.restore(h.inputs);
    show();
  });

  const undo = () => { if (stack.canUndo()) history.back(); };
  const redo = () => { if (stack.canRedo()) history.forward(); };
  $('#undo').addEventListener('click', undo);
  $('#redo').addEventListener('click', redo);
  document.addEventListener('keydown', (e) => {
    if (!(e.ctrlKey || e.metaKey) || e.altKey || isTextField(e.target)) return;
    const key = e.key.toLowerCase();
    if (key !== 'z' && key !== 'y') return;
    e.preventDefault();
    if (key === 'y' || e.shiftKey) redo(); else undo();
  });
}
