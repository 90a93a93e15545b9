// The calculator client: starts the worker that runs the WebAssembly module and sends it cases.
// A request that gets no answer within the watchdog's time ends the worker; a fresh one starts.

// From worker.js when served; opened from disk (where a page may not start a worker from a file
// URL), from a blob of the module's factory and hobsharpWorkerMain, loaded into the page for it.
export function loadScript(src) {
  return new Promise((resolve, reject) => {
    const el = document.createElement('script');
    el.src = src;
    el.onload = resolve;
    el.onerror = () => reject(new Error(`${src} did not load`));
    document.head.append(el);
  });
}

let blobSource = null;
async function startWorker() {
  if (location.protocol !== 'file:') return new Worker('worker.js');
  if (!blobSource) {
    await loadScript('hobsharp.js');
    await loadScript('worker-main.js');
    blobSource = URL.createObjectURL(new Blob([`var _scriptDir;\nvar HobSharpModule = ${self.HobSharpModule.toString()};\n` +
      `(${self.hobsharpWorkerMain.toString()})(self, HobSharpModule, ${JSON.stringify(self.HOBSHARP_PAPER_CASE || null)});\n`], { type: 'text/javascript' }));
  }
  return new Worker(blobSource);
}

function failure(message, fields = {}) {
  return Object.assign(new Error(message), fields);
}

// The page's Error for what the worker posts: a refusal keeps its code and field, and its message
// is put in the page's words by words({field, message}) (the field named as on screen, never its
// path: views/field-names.js), the calculator's own kept as .calculatorMessage; anything else is
// a fault of the calculator (code 'Internal', no field).
export function workerError({ message, code, field }, words = null) {
  const refusal = code === 'InvalidInput' || code === 'Unsolvable';
  if (!refusal) return failure(message, { code: 'Internal' });
  const worded = words ? words({ field: field || '', message }) : message;
  return failure(worded, { code, field: field || '', calculatorMessage: message });
}

// A value as JSON with its objects' keys sorted: the same case gives the same text, whatever order
// its members were set in.
export function canonicalJson(value) {
  return JSON.stringify(value, (_, v) => (v !== null && typeof v === 'object' && !Array.isArray(v)
    ? Object.fromEntries(Object.keys(v).sort().map((k) => [k, v[k]])) : v));
}

// evaluate(case) resolves to {result, ms}; limits() to the module's limits(), fields() to its
// resultFields() (the result's fields with their units and meanings). Each rejects with
// an Error whose .code is the module's ('InvalidInput' or 'Unsolvable', a refusal, with its
// .field; 'Internal', a fault: the worker took a fresh module), 'Timeout' when the watchdog
// ended the worker, or 'Cancelled' when cancel() did.
// A case is evaluated once: the last case computed is kept with its result, and asked again (a
// loaded case, checked and then shown) it is answered from there. evaluations counts the cases
// the worker was given; onBusy(busy) says when the first evaluation starts and the last ends.
export function createCalculator({ watchdogMs = 20000, onRestart = () => {}, words = null } = {}) {
  const pending = new Map();
  let nextId = 1;
  let started;
  let last = null;  // {key, result, ms}: the last case computed
  let running = 0;  // evaluations under way

  const rejectAll = (error) => {
    for (const p of pending.values()) { clearTimeout(p.timer); p.reject(error); }
    pending.clear();
  };
  const start = () => {
    started = startWorker();
    started.then((w) => {
      w.onmessage = (event) => {
        const { id, ok, result, error, ms } = event.data;
        const p = pending.get(id);
        if (!p) return;
        pending.delete(id);
        clearTimeout(p.timer);
        if (ok) p.resolve({ result, ms });
        else p.reject(workerError(error, words));
      };
      w.onerror = (event) => rejectAll(failure(`The calculator stopped: ${event.message || 'the worker failed to start'}`, { code: 'Internal' }));
    }, (e) => rejectAll(failure(`The calculator did not start: ${e.message}`, { code: 'Internal' })));
  };
  // Ends the worker, whatever it computes, rejecting every request with `error`; a fresh one starts.
  const replace = (error) => {
    started.then((w) => w.terminate(), () => {});
    rejectAll(error);
    start();
  };
  const restart = () => {
    const seconds = (client.watchdogMs / 1000).toFixed(client.watchdogMs < 10000 ? 1 : 0);
    replace(failure(`The calculator did not answer within ${seconds} s and was restarted.`, { code: 'Timeout' }));
    onRestart();
  };
  const evaluate = (caseObject) => {
    const key = canonicalJson(caseObject);
    if (last && last.key === key) return Promise.resolve({ result: last.result, ms: last.ms });
    client.evaluations += 1;
    if (running++ === 0) client.onBusy(true);
    const done = () => { if (--running === 0) client.onBusy(false); };
    return send({ caseObject }).then((answer) => {
      done();
      last = { key, result: answer.result, ms: answer.ms };
      return answer;
    }, (error) => { done(); throw error; });
  };
  const send = (message) => {
    const id = nextId++;
    return new Promise((resolve, reject) => {
      const timer = setTimeout(restart, client.watchdogMs);
      pending.set(id, { resolve, reject, timer });
      started.then((w) => w.postMessage({ id, ...message })).catch((e) => {
        pending.delete(id);
        clearTimeout(timer);
        reject(failure(`The case cannot be sent to the calculator: ${e.message}`, { code: 'Internal' }));
      });
    });
  };

  start();
  const client = {
    watchdogMs,
    evaluations: 0,
    onBusy: () => {},
    busy: () => running > 0,  // an evaluation is under way (the tests' hobsharpTest.settled())
    evaluate,
    // Ends the computation under way: the worker is ended and a fresh one started; every request
    // waiting rejects with code 'Cancelled'.
    cancel: () => replace(failure('The computation was cancelled.', { code: 'Cancelled' })),
    limits: () => send({ limits: true }).then(({ result }) => result),
    // The result's fields with their units and meanings (the module's resultFields()).
    fields: () => send({ fields: true }).then(({ result }) => result),
    // For the tests: the worker stops answering (it spins) until the watchdog ends it.
    stall: () => send({ stall: true }),
  };
  return client;
}
