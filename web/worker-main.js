// The calculator's worker: it owns one instance of the WebAssembly module and evaluates cases
// off the page's thread. worker.js calls it when the page is served; a page opened from disk
// builds its worker from this function's source and the module's factory.
function hobsharpWorkerMain(scope, factory) {
  let ready = factory();
  scope.onmessage = async (event) => {
    const { id, caseObject, stall } = event.data;
    // The tests' stand-in for a calculation that never ends: the page's watchdog must end it.
    if (stall) for (;;) { /* spin */ }
    const started = performance.now();
    try {
      const module = await ready;
      const result = module.evaluate(caseObject);
      scope.postMessage({ id, ok: true, result, ms: performance.now() - started });
    } catch (e) {
      // A refusal of the input leaves the module as it was; anything else (a trap) may not, so
      // the next case gets a fresh instance.
      if (!(e && typeof e === 'object' && 'field' in e)) ready = factory();
      scope.postMessage({ id, ok: false, error: { message: e.message || String(e), field: e.field || '', code: e.code || '' } });
    }
  };
}
