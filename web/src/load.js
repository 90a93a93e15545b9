// A case from a link or a file passes the calculator's checks, the same as the form's, before
// it reaches the form and the state. A refused case shows why, in a notice that stays; a link's
// case is replaced by the paper example, a file leaves the page as it was. A measured grid (or
// its locks) that alone is refused is set aside: the rest loads, its text goes into the CSV box.
import { CASE_FORMAT } from './limits.js';
import { measuredText } from './io/csv.js';
import { MAX_CASE_DEPTH, nestingDepth } from './io/nesting.js';

const isPlainObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

export function createLoader({ store, calculator, form, measuredView, paperCase }) {
  // Puts a checked case into the form and the state; the recompute follows from 'inputs'.
  function apply(c, { setAside = null } = {}) {
    const formCase = form.write(c);
    const measured = setAside ? null : (c.measured || null);
    measuredView.setText(setAside ? measuredText(setAside) : measured ? measuredText(measured) : '');
    const correction = (measured && c.correction) || {};
    store.setInputs({
      form: formCase, measured,
      locked: [...(correction.locked || [])], lockedAxes: [...(correction.lockedAxes || [])],
    }, { source: 'load', force: true });
  }

  function refused(where, message, fallback) {
    store.setNotice(`${where}: ${message} ${fallback === 'paper' ? 'The paper example is loaded instead.' : 'Nothing was changed.'}`);
    store.setStatus(`${where} was not loaded.`, 'error');
    if (fallback === 'paper') apply(structuredClone(paperCase));
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
    store.setStatus(`Checking ${where === 'The link' ? 'the link' : where}…`, 'busy');
    // A refused measured grid or correction is taken out and the rest checked again.
    let candidate = c, aside = null;
    const notes = [], refusals = [];
    for (;;) {
      try {
        await calculator.evaluate(candidate);
        break;
      } catch (error) {
        const part = /^measured/.test(error.field || '') ? 'measured' : /^correction/.test(error.field || '') ? 'correction' : null;
        if (error.code !== 'InvalidInput' || !part || !(part in candidate)) {  // a fault, a timeout: not the part
          refused(where, error.message, fallback);
          return;
        }
        candidate = { ...candidate };
        delete candidate.correction;
        if (part === 'measured') {
          aside = c.measured;
          delete candidate.measured;
          notes.push(`the measured grid is set aside, not used: ${error.message} Its text is in the box under ` +
            '"Measured topography and correction": correct it there and press "Use this grid".');
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
    paper: () => apply(structuredClone(paperCase)),
    link: (c) => load(c, 'The link', 'paper'),
    file: (c, name) => load(c, name, 'keep'),
    refused,
  };
}
