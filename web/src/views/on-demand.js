// The parts of the page kept on demand, each in a <details> closed by default (the machine
// constants and grid, the what-if, the correction options, the solver's details, the wheel, Tab. 2,
// the sensitivities): a refused input opens the part that holds it, so that its message is seen;
// and print opens those the report prints (class print-open), closing them again after. The
// header's menu also closes on Escape.
// (Their plots are drawn, or laid out again, when they open: plots/passes.js.)

import { isWheelField } from './wheel-input.js';

const $$ = (selector) => Array.from(document.querySelectorAll(selector));

// The parts that hold the messages of the fields the form has no input for: the correction's own
// options (its method, noise, resolution, locks), the inspection's (uncertainty, tolerances, gash
// deviations) and the wheel's files.
const HOLDERS = [[(f) => /^correction\.(method|wheel|probeNoise|resolution|locked)/.test(f), '#correction-options-details'],
  [(f) => /^inspection\./.test(f), '#inspection-details'], [isWheelField, '#wheel-details']];

// The <details> around what a refusal names: its form field's, else the part that shows its message.
function holderOf(field) {
  const input = document.querySelector(`[data-field="${CSS.escape(field)}"]`);
  if (input) return input.closest('details');
  const [, part] = HOLDERS.find(([holds]) => holds(field)) || [];
  return part ? document.querySelector(part) : null;
}

export function mountOnDemand(store) {
  store.on('refusal', ({ error }) => {
    for (let d = error && error.field ? holderOf(error.field) : null; d; d = d.parentElement && d.parentElement.closest('details')) d.open = true;
  });
  // A part opened by a view (the tolerance table, to show its message) opens the parts around it.
  document.addEventListener('toggle', (e) => {
    for (let d = e.target.open && e.target.parentElement ? e.target.parentElement.closest('details:not([open])') : null; d;
      d = d.parentElement && d.parentElement.closest('details:not([open])')) d.open = true;
  }, true);
  // The header's menu ("Report and files…") closes on its summary, as a <details> does, or Escape.
  const menus = $$('details.menu');
  document.addEventListener('keydown', (e) => {
    if (e.key !== 'Escape') return;
    for (const m of menus.filter((x) => x.open)) { m.open = false; m.querySelector('summary').focus(); }
  });
}

// Called as print starts (printing true) and ends: the parts the report prints opened for it, and
// those print opened closed again.
export function openForPrint(printing) {
  if (printing) {
    for (const d of $$('details.print-open:not([open])')) { d.open = true; d.dataset.printOpened = 'true'; }
  } else {
    for (const d of $$('details[data-print-opened]')) { d.open = false; delete d.dataset.printOpened; }
  }
}
