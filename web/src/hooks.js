// For the browser tests, the benchmark and anyone curious, from the store's events only:
// window.hobsharpTimings says when the page showed its first result and drew its plots (ms after
// navigation), how many results, refusals and plot passes it has had, and how long each change
// of an input took to show its numbers, how many cases the worker evaluated and how many were
// cancelled. window.hobsharpTest lets the tests stall the worker and wait until the page has
// settled: nothing computing or waiting to be computed, no plot pass under way, for two frames.

export function installHooks(store, calculator) {
  const t = {
    opened: performance.now(), firstResult: undefined, plotted: undefined,
    results: 0, errors: 0, draws: 0,
    inputToNumbers: [],  // ms from a user's input event to its numbers in the page
    cancelled: 0,
  };
  // How many cases the worker was given to evaluate (a case is evaluated once: client.js).
  Object.defineProperty(t, 'evaluations', { get: () => calculator.evaluations, enumerable: true });
  store.on('cancelled', () => { t.cancelled += 1; });
  let inputAt = null;
  store.on('inputs', ({ at }) => { if (typeof at === 'number') inputAt = at; });
  store.on('result', () => {
    const now = performance.now();
    if (t.firstResult === undefined) t.firstResult = now;
    if (inputAt !== null) t.inputToNumbers.push(now - inputAt);
    inputAt = null;
    t.results += 1;
  });
  store.on('refusal', () => { t.errors += 1; });
  store.on('plots', ({ at }) => {
    if (t.plotted === undefined) t.plotted = at;
    t.draws += 1;
  });
  window.hobsharpTimings = t;
  const busy = [];  // () => boolean, one per part of the page that works after an input (watch())
  window.hobsharpTest = {
    settled: () => new Promise((resolve) => {
      let quiet = 0;
      const look = () => {
        quiet = busy.some((b) => b()) ? 0 : quiet + 1;
        if (quiet >= 2) resolve(); else requestAnimationFrame(look);
      };
      requestAnimationFrame(look);
    }),
    stallWorker(watchdogMs) {
      calculator.watchdogMs = watchdogMs;
      calculator.stall().catch(() => {});
    },
    // The measurement in use as the record keeps it (web/src/measurement.js): {name, what, meta} or null.
    measuredSource: () => {
      const s = store.state.measuredSource;
      return s && structuredClone({ name: s.name, what: s.what, meta: s.meta });
    },
  };
  return { watch: (isBusy) => { busy.push(isBusy); } };
}
