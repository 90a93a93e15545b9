// While the calculator refuses the inputs, the results on screen are those of the last valid
// input: they are greyed, and a banner says so, until the next result.
const $ = (selector) => document.querySelector(selector);

export function mountStale(store) {
  const results = $('#results');
  const banner = $('#stale-banner');
  const mark = (stale) => {
    results.classList.toggle('stale', stale);
    banner.hidden = !stale;
  };
  store.on('result', () => mark(false));
  // A refusal by the page itself (a CSV that does not parse) leaves the results current.
  store.on('refusal', ({ caseObject }) => { if (caseObject && store.state.result) mark(true); });
}
