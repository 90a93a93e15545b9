// Keyboard and screen readers: each file button (data-opens) opens its hidden file input, so
// that Tab and Enter or Space reach it; and the status line is the one polite live region. The
// form's derived values are <output>s, whose implicit status role would announce each of them on
// every recompute: they are read where they stand, not announced.
export function mountAccess() {
  for (const button of document.querySelectorAll('button[data-opens]')) {
    button.addEventListener('click', () => document.getElementById(button.dataset.opens).click());
  }
  for (const output of document.querySelectorAll('output')) output.setAttribute('aria-live', 'off');
}
