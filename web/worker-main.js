// The calculator's worker: it owns one instance of the WebAssembly module and evaluates cases
// off the page's thread. worker.js calls it when the page is served; a page opened from disk
// builds its worker from this function's source and the module's factory.
//
// warmUpCase (the paper example), when given, is evaluated once as soon as a module is there, and
// its result dropped: the browser compiles the module's functions on their first call, which makes
// a first evaluation about ten times slower than the next. Done here, while the page is still
// loading its plotting library, the user's first case is computed at full speed. A warm-up that
// fails changes nothing: the user's own case then meets the same failure and reports it.
function hobsharpWorkerMain(scope, factory, warmUpCase) {
  const start = () => factory().then((module) => {
    if (warmUpCase) {
      try { module.evaluate(warmUpCase); } catch (e) { /* reported by the user's own case */ }
    }
    return module;
  });
  let ready = start();
  scope.onmessage = async (event) => {
    const { id, caseObject, limits, fields, stall } = event.data;
    // The tests' stand-in for a calculation that never ends: the page's watchdog must end it.
    if (stall) for (;;) { /* spin */ }
    const started = performance.now();
    try {
      const module = await ready;
      const result = limits ? module.limits() : fields ? module.resultFields() : module.evaluate(caseObject);
      scope.postMessage({ id, ok: true, result, ms: performance.now() - started });
    } catch (e) {
      // A refusal (a HobSharpError of code InvalidInput or Unsolvable) leaves the module as it
      // was; anything else (code Internal, a trap, a module that did not start) may not, so the
      // next request gets a fresh instance.
      const refusal = e instanceof Error && e.name === 'HobSharpError' && e.code !== 'Internal';
      if (!refusal) ready = start();
      scope.postMessage({ id, ok: false, error: {
        message: (e && e.message) || String(e), code: refusal ? e.code : 'Internal', field: refusal ? e.field || '' : '',
      } });
    }
  };
}
