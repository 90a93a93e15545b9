// The case in the page's address (#case=...), so that a link reopens the same job: the saved case
// (io/case-state.js), with the what-if offsets and the locks.
import { savedCase } from './case-state.js';

// A measured grid larger than this many values is left out of the link (it would make it long).
export const MAX_LINK_VALUES = 2500;

export function caseToHash(caseObject) {
  const c = { ...caseObject };
  if (Array.isArray(c.measured) && c.measured.length * (c.measured[0] || []).length > MAX_LINK_VALUES) {
    delete c.measured;
    delete c.correction;  // the locks go with the grid they were set for
  }
  return `#case=${encodeURIComponent(JSON.stringify(c))}`;
}

// {case} from a #case= address, {error} when it holds no readable case, null without one.
export function caseFromHash(hash) {
  const m = /^#case=(.*)$/s.exec(hash || '');
  if (!m) return null;
  try {
    return { case: JSON.parse(decodeURIComponent(m[1])) };
  } catch (e) {
    return { error: `The link holds no readable case (${e.message}).` };
  }
}

// Keeps the address in step with the last good result (a refused input never gets into a link);
// the entry's state (the undo step, views/undo.js) stays.
export function mountLink(store) {
  store.on('result', () => history.replaceState(history.state, '', caseToHash(savedCase(store.state))));
}
