// The case in the page's address (#case=...), so that a link reopens the same job: the saved case
// (io/case-state.js), with the what-if offsets, the locks and the grinding passes.
import { savedCase } from './case-state.js';

// Measured values beyond this many are left out of the link (it would make it long): first the
// history of grinding passes (as a whole, so that the passes kept are numbered as they were), then
// the measured grid.
export const MAX_LINK_VALUES = 2500;

// A grid's values, or a list of points' (three numbers each).
const valuesOf = (grid) => (Array.isArray(grid) ? grid.length * (grid[0] || []).length : 0);

export function caseToHash(caseObject) {
  const c = { ...caseObject };
  const history = (c.passes || []).reduce((n, p) => n + valuesOf(p.measured || p.measuredPoints), 0);
  if (history && valuesOf(c.measured) + history > MAX_LINK_VALUES) delete c.passes;
  if (valuesOf(c.measured) > MAX_LINK_VALUES) {
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
  const write = () => history.replaceState(history.state, '', caseToHash(savedCase(store.state)));
  store.on('result', write);
  for (const event of ['view', 'surfaces']) store.on(event, () => { if (store.state.result) write(); });  // as shown
}
