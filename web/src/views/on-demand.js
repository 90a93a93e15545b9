// The parts of the page kept on demand, each in a <details> closed by default (the machine
// constants and grid, the what-if, the correction options, the solver's details, the wheel, Tab. 2,
// the sensitivities): a refused input opens the part that holds it, so that its message is seen;
// and print opens those the report prints (class print-open), closing them again after. The
// header's menu also closes on Escape.
// (Their plots are drawn, or laid out again, when they open: plots/passes.js.)

const $$ = (selector) => Array.from(document.querySelectorAll(selector));

// The <details> around what a refusal names: its form field, else the correction's options for
// the correction's own fields (its method, noise, resolution, locks).
function holderOf(field) {
  const input = document.querySelector(`[data-field="${CSS.escape(field)}"]`);
  if (input) return input.closest('details');
  if (/^correction\.(method|wheel|probeNoise|resolution|locked)/.test(field)) return document.querySelector('#correction-options-details');
  return null;
}

export function mountOnDemand(store) {
  store.on('refusal', ({ error }) => {
    for (let d = error && error.field ? holderOf(error.field) : null; d; d = d.parentElement && d.parentElement.closest('details')) d.open = true;
  });
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
