// The calculator's worker: it owns one instance of the WebAssembly module and evaluates cases
// off the page's thread. The page builds the worker from this function's source and the module's
// factory, so it runs the same from a server or from a file opened on disk.
function hobsharpWorkerMain(scope, factory) {
  const ready = factory();
  scope.onmessage = async (event) => {
    const { id, caseObject } = event.data;
    const started = performance.now();
    try {
      const module = await ready;
      const result = module.evaluate(caseObject);
      scope.postMessage({ id, ok: true, result, ms: performance.now() - started });
    } catch (e) {
      scope.postMessage({ id, ok: false, error: { message: e.message || String(e), field: e.field || '' } });
    }
  };
}
