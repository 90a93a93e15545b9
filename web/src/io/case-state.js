// A case as saved in a file or a link, and the page's inputs it holds. Nothing the user gave is
// dropped: the form's case, the measured grid, the locks and the correction's thresholds (kept
// even without a measured grid), the run axes of the pass under way, the grinding passes kept
// ("passes", docs/case-format.md), and the what-if offsets.
//
// The offsets are the page's own: they travel in a "page" member, {"page": {"whatIf": {"Y":
// [0.01, 0, ...]}}}, with how the page shows the topography when it is not the default
// ("view": "circular", "surfaces": true for the 3D surfaces). The C++ case reader refuses unknown
// top-level members (onlyKnown in core/case_json.cpp), so calculatorCase() strips it before a
// case goes to the calculator.
import { AXES } from '../limits.js';
import { caseOf } from '../store.js';

const isPlainObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

// The offsets as plain lists (no holes, no trailing zeros); axes without an offset left out.
export function offsetsToSave(offsets) {
  const out = {};
  for (const a of AXES) {
    const list = Array.from(offsets[a] || [], (v) => (typeof v === 'number' && Number.isFinite(v) ? v : 0));
    while (list.length && list[list.length - 1] === 0) list.pop();
    if (list.length) out[a] = list;
  }
  return out;
}

export function savedCase(state) {
  const c = caseOf(state);
  const correction = { ...state.tuning, lockedAxes: [...state.lockedAxes], locked: [...state.locked] };
  if (!c.correction && (state.locked.length || state.lockedAxes.length || Object.keys(state.tuning).length)) {
    c.correction = correction;
  }
  const whatIf = offsetsToSave(state.offsets);
  const page = {
    ...(Object.keys(whatIf).length ? { whatIf } : {}),
    ...(state.view === 'circular' ? { view: 'circular' } : {}),
    ...(state.surfaces ? { surfaces: true } : {}),
  };
  if (Object.keys(page).length) c.page = page;
  return c;
}

// The members of a case the form has no inputs for (the inspection's gash deviations and
// tolerance table, the measuring machine's points, a dressed or measured wheel): kept as they came
// and put back into every case the page sends and saves (store.caseOf), so nothing is lost.
const EXTRA = [['inspection'], ['measuredPoints'], ['wheel', 'profileOffset'], ['wheel', 'measuredProfile']];
export function extraOf(c) {
  const out = {};
  for (const [group, key] of EXTRA) {
    const v = key ? c[group] && c[group][key] : c[group];
    if (v === undefined) continue;
    if (key) out[group] = { ...(out[group] || {}), [key]: structuredClone(v) };
    else out[group] = structuredClone(v);
  }
  return out;
}

// How the page member says to show the topography: {view: 'normal' | 'circular', surfaces: boolean}.
export function readPageView(page = {}) {
  const { view = 'normal', surfaces = false } = page;
  if (!['normal', 'circular'].includes(view)) throw new Error('page.view: must be "normal" or "circular" (the deviation shown).');
  if (typeof surfaces !== 'boolean') throw new Error('page.surfaces: must be true or false (the 3D surfaces shown).');
  return { view, surfaces };
}

export function calculatorCase(c) {
  if (!isPlainObject(c) || !('page' in c)) return c;
  const { page, ...rest } = c;
  return rest;
}

// The what-if offsets of a page member (readPageView gives how it shows the topography).
export function readPage(page) {
  if (page === undefined) return {};
  if (!isPlainObject(page)) throw new Error('page: must be an object such as {"whatIf": {"Y": [0.01]}}.');
  for (const key of Object.keys(page)) {
    if (!['whatIf', 'view', 'surfaces'].includes(key)) throw new Error(`page.${key}: unknown field (expected: whatIf, view, surfaces).`);
  }
  readPageView(page);
  const whatIf = page.whatIf === undefined ? {} : page.whatIf;
  if (!isPlainObject(whatIf)) throw new Error('page.whatIf: must be an object of axis offsets such as {"Y": [0.01]}.');
  const offsets = {};
  for (const [axis, list] of Object.entries(whatIf)) {
    if (!AXES.includes(axis)) throw new Error(`page.whatIf.${axis}: unknown axis (expected one of: ${AXES.join(', ')}).`);
    if (!Array.isArray(list) || list.length > 7 || !list.every((v) => typeof v === 'number' && Number.isFinite(v))) {
      throw new Error(`page.whatIf.${axis}: must be a list of at most 7 finite numbers (the offsets of a0, a1, ...).`);
    }
    offsets[axis] = [...list];
  }
  return offsets;
}

// The page's inputs from a case the calculator accepted (without its page member); throws an
// Error naming the member when the page member is malformed.
export function inputsFromCase(c) {
  const offsets = readPage(c.page);
  const { measured, correction = {}, axes, passes = [], page, ...formCase } = c;
  const { locked = [], lockedAxes = [], ...tuning } = correction;
  return {
    formCase, measured: measured === undefined ? null : measured, extra: extraOf(formCase),
    locked: [...locked], lockedAxes: [...lockedAxes], tuning: { ...tuning },
    axes: axes === undefined ? null : structuredClone(axes), offsets, pageView: readPageView(page),
    passes: passes.map(({ axes: a, measured: m, measuredPoints: p, correction: o }) => ({ axes: structuredClone(a),
      ...(p === undefined ? { measured: structuredClone(m) } : { measuredPoints: structuredClone(p) }),
      ...(o === undefined ? {} : { correction: structuredClone(o) }) })),
  };
}

// What loading another case would replace that the user gave beyond the form, in words; empty
// when nothing (then no need to ask).
export function userData(state) {
  const out = [];
  if (state.measured) out.push(`the measured grid (${state.measured.length} × ${(state.measured[0] || []).length} values)`);
  if (state.axes) out.push('the run axes');
  if (state.passes.length) out.push(`the history of ${state.passes.length} grinding pass${state.passes.length > 1 ? 'es' : ''}`);
  const offsets = Object.values(offsetsToSave(state.offsets)).flat().filter((v) => v !== 0).length;
  if (offsets) out.push(`${offsets} what-if offset${offsets > 1 ? 's' : ''}`);
  const locks = state.locked.length + state.lockedAxes.length;
  if (locks) out.push(`${locks} lock${locks > 1 ? 's' : ''}`);
  return out;
}
