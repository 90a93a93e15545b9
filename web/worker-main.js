// The calculator's worker: it owns one instance of the WebAssembly module and evaluates cases
// off the page's thread. worker.js calls it when the page is served; a page opened from disk
// builds its worker from this function's source and the module's factory.
function hobsharpWorkerMain(scope, factory) {
  let ready = factory();
  scope.onmessage = async (event) => {
    const { id, caseObject, limits, stall } = event.data;
    // The tests' stand-in for a calculation that never ends: the page's watchdog must end it.
    if (stall) for (;;) { /* spin */ }
    const started = performance.now();
    try {
      const module = await ready;
      const result = limits ? module.limits() : module.evaluate(caseObject);
      scope.postMessage({ id, ok: true, result, ms: performance.now() - started });
    } catch (e) {
      // A refusal (a HobSharpError of code InvalidInput or Unsolvable) leaves the module as it
      // was; anything else (code Internal, a trap, a module that did not start) may not, so the
      // next request gets a fresh instance.
      const refusal = e instanceof Error && e.name === 'HobSharpError' && e.code !== 'Internal';
      if (!refusal) ready = factory();
      scope.postMessage({ id, ok: false, error: {
        message: (e && e.message) || String(e), code: refusal ? e.code : 'Internal', field: refusal ? e.field || '' : '',
      } });
    }
  };
}
