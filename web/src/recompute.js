// Every change of the inputs is sent at once; while a calculation runs, only the newest change
// waits (older ones are dropped), and a result is shown only if no newer input is waiting. A
// calculation cancelled (views/cancel.js) shows nothing new: the 'cancelled' event says so.
import { caseOf } from './store.js';
import { isMeasuredField } from './measurement.js';
import { GRID } from './limits.js';

// The calculator refused the measured grid or its locks: an input error (code InvalidInput)
// that names them. A fault (Internal) or a timeout says nothing about the grid, and neither does
// a refused option of the correction (its view shows it at its input; the grid stays in use).
const refusesMeasured = (error) => error.code === 'InvalidInput' && isMeasuredField(error.field);

// The grid lines a case asks for, radial x axial (the module's default where it gives none).
const linesOf = (c) => `${(c.grid && c.grid.radial) ?? GRID.radial}x${(c.grid && c.grid.axial) ?? GRID.axial}`;
const shapeOf = (grid) => `${grid.length}x${(grid[0] || []).length}`;
// Changes after which a grid set aside is not put back: another measurement, a loaded case, an undo
// step, a pass kept.
const DROPS_ASIDE = new Set(['measured', 'load', 'restore', 'passes']);

export function startRecompute(store, calculator) {
  let running = false;
  let waiting = null;
  // A grid in use set aside because it no longer fits the grid lines (the calculator names the whole
  // grid: its shape), with what it was and the lines it did not fit: {measured, source, lines}.
  let aside = null;

  const refused = (error, caseObject) => {
    store.refuse(error, caseObject);
    // A grid just given that the calculator refuses is replaced by the measurement in use before
    // (web/src/measurement.js, on the refusal). A grid in use that it now refuses (say, it no longer
    // fits the grid) is set aside, so that it is not sent again with every edit; the user's text
    // stays in the CSV box.
    if (caseObject.measured && refusesMeasured(error) && store.state.measured === caseObject.measured) {
      store.state.measured = null;
      aside = error.field === 'measured' && shapeOf(caseObject.measured) !== linesOf(caseObject)
        ? { measured: caseObject.measured, source: store.state.measuredSource, lines: linesOf(caseObject) } : null;
      store.emit('aside', { error, untilFits: Boolean(aside) });
      request();
    }
  };

  // Other grid lines than those the grid set aside did not fit: it is sent again. Back to its shape,
  // it is in use again and its refusal goes with the result; on other lines the calculator's refusal
  // names them, never the lines before. Any other measurement, a loaded case, an undo step or a pass
  // kept drops it.
  const putBack = ({ source }) => {
    if (!aside) return;
    if (DROPS_ASIDE.has(source) || store.state.measured) { aside = null; return; }
    if (linesOf(caseOf(store.state)) === aside.lines) return;
    store.state.measured = aside.measured;
    store.setMeasurement({ measuredSource: aside.source });
    aside = null;
  };

  async function next() {
    const caseObject = waiting;
    waiting = null;
    running = true;
    store.setStatus('Computing…', 'busy');
    store.emit('computing', { caseObject });
    try {
      const { result, ms } = await calculator.evaluate(caseObject);
      if (!waiting) store.accept(result, caseObject, ms);
    } catch (error) {
      // Cancelled (views/cancel.js): the results on screen stay, and say they are the last computed.
      // A cancel ends the inputs waiting too: the next change computes.
      if (error.code === 'Cancelled') { waiting = null; store.emit('cancelled', { caseObject }); }
      else if (!waiting) refused(error, caseObject);
    }
    running = false;
    if (waiting) next();
  }

  function request() {
    waiting = caseOf(store.state);
    if (!running) next();
  }

  store.on('inputs', (detail) => { putBack(detail); request(); });
  // busy(): a case is being computed or waits to be (the tests' hobsharpTest.settled()).
  return { request, busy: () => running || waiting !== null };
}
