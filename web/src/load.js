// A case from a link or a file passes the calculator's checks, the same as the form's, before
// it reaches the form and the state. A refused case shows why, in a notice that stays; a link's
// case is replaced by the paper example, a file leaves the page as it was. A measured grid (or
// its locks) that alone is refused is set aside: the rest loads, its text goes into the CSV box.
// Everything else the case holds is kept (io/case-state.js): the run axes, the correction's
// thresholds, the grinding passes, the what-if offsets of its page member. A pass history that
// alone is refused (it no longer fits the grid, say) is left out the same way.
import { CASE_FORMAT } from './limits.js';
import { measuredText } from '../../wasm/lib/csv.js';
import { MAX_CASE_DEPTH, nestingDepth } from '../../wasm/lib/nesting.js';
import { calculatorCase, inputsFromCase, readPage } from './io/case-state.js';
import { caseOf } from './store.js';
import { canonicalJson } from './client.js';

const isPlainObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

// The case checked for c: the case the page sends once c is loaded (store.caseOf of its inputs)
// when it is c as given but for the empty locks caseOf adds to a measurement. Then the check is
// the computation itself, and the calculator (client.js) answers the same case again from its
// last result: a loaded case is evaluated once. Otherwise (locks that are not lists, a correction
// without a measurement) c as given, so that the calculator names what is wrong in it.
function checkedCase(c) {
  const given = calculatorCase(c);
  let sent;
  try {
    const { formCase, measured, locked, lockedAxes, tuning, axes, passes, extra } = inputsFromCase(c);
    sent = caseOf({ form: formCase, measured, locked, lockedAxes, tuning, axes, passes, extra });
  } catch {
    return given;  // (members the page cannot take in: the calculator names them)
  }
  const measuring = given.measured !== undefined || given.measuredPoints !== undefined;
  const expected = measuring ? { ...given, correction: { lockedAxes: [], locked: [], ...given.correction } } : { ...given };
  if (Array.isArray(expected.passes) && !expected.passes.length) delete expected.passes;  // no history, as caseOf sends it
  return canonicalJson(expected) === canonicalJson(sent) ? sent : given;
}

// The paper's example with the setting angle and the centre distance derived, as the paper
// derives them (tests/data/tab1.json fixes them at the paper's rounded values, for the native
// tests); paper: those values, for the note that the derived ones equal them.
export function paperInputs(paperCase) {
  const c = structuredClone(paperCase);
  const paper = { settingAngle: c.setup.settingAngle, centerDistance: c.setup.centerDistance };
  delete c.setup.settingAngle;
  delete c.setup.centerDistance;
  return { c, paper };
}

export function createLoader({ store, calculator, form, measuredView, paperCase }) {
  // Puts a checked case into the form and the state; the recompute follows from 'inputs'. The
  // load is an undo step.
  function apply(c, { setAside = null, paper = null } = {}) {
    const inputs = inputsFromCase(c);
    const formCase = form.write(inputs.formCase);
    const measured = setAside ? null : inputs.measured;
    measuredView.setText(setAside ? measuredText(setAside) : measured ? measuredText(measured) : '');
    const { locked, lockedAxes, tuning, axes, offsets, passes, extra, pageView } = inputs;
    store.setInputs({ form: formCase, measured, locked, lockedAxes, tuning, axes, offsets, passes, paper, extra },
      { source: 'load', force: true });
    // How the case's page showed the topography (the page member; the defaults without one).
    if (pageView.view !== store.state.view) store.setView(pageView.view);
    if (pageView.surfaces !== store.state.surfaces) store.setSurfaces(pageView.surfaces);
    store.emit('commit');
  }

  function refused(where, message, fallback) {
    store.setNotice(`${where}: ${message} ${fallback === 'paper' ? 'The paper example is loaded instead.' : 'Nothing was changed.'}`);
    store.setStatus(`${where} was not loaded.`, 'error');
    if (fallback === 'paper') loadPaper();
  }

  function loadPaper() {
    const { c, paper } = paperInputs(paperCase);
    apply(c, { paper });
  }

  // where: "The link" or the file's name; fallback: 'paper' (a link on opening) or 'keep'.
  async function load(c, where, fallback) {
    if (!isPlainObject(c) || c.format !== CASE_FORMAT) {
      refused(where, `this is not a case: its "format" must be "${CASE_FORMAT}".`, fallback);
      return;
    }
    if (nestingDepth(c) > MAX_CASE_DEPTH) {
      refused(where, `the case holds lists or objects nested more than ${MAX_CASE_DEPTH} deep; a case nests at most 3 deep (measured, a row, a value).`, fallback);
      return;
    }
    try {
      readPage(c.page);  // the page's own member; the rest is the calculator's to check
    } catch (error) {
      refused(where, error.message, fallback);
      return;
    }
    store.setStatus(`Checking ${where === 'The link' ? 'the link' : where}…`, 'busy');
    // A refused measured grid or correction is taken out and the rest checked again.
    let candidate = c, aside = null;
    const notes = [], refusals = [];
    for (;;) {
      try {
        await calculator.evaluate(checkedCase(candidate));
        break;
      } catch (error) {
        const part = (/^(measured|correction|passes)\b/.exec(error.field || '') || [])[1];
        if (error.code !== 'InvalidInput' || !part || !(part in candidate)) {  // a fault, a timeout: not the part
          refused(where, error.message, fallback);
          return;
        }
        candidate = { ...candidate };
        if (part === 'passes') {
          delete candidate.passes;
          notes.push(`its history of grinding passes is left out: ${error.message}`);
          refusals.push(error);
          continue;
        }
        delete candidate.correction;
        if (part === 'measured') {
          aside = c.measured;
          delete candidate.measured;
          notes.push(`the measured grid is set aside, not used: ${error.message} Its text is in the box under ` +
            '"The measured face": correct it there and press "Use this grid".');
        } else {
          notes.push(`its correction settings are left out: ${error.message}`);
        }
        refusals.push(error);
      }
    }
    apply(candidate, { setAside: aside });
    for (const error of refusals) store.refuse(error, null);
    store.setNotice(notes.length ? `${where}: ${notes.join(' Also, ')}` : null);  // an older notice ends
  }

  return {
    paper: loadPaper,
    link: (c) => load(c, 'The link', 'paper'),
    file: (c, name) => load(c, name, 'keep'),
    refused,
  };
}
