// A pinned result to compare with. "Pin this result" keeps the result on screen; while one is
// pinned, the views show the difference to it (now minus pinned), labelled "difference to
// pinned", and this bar says which inputs changed since; "Unpin" ends it. The views call the
// helpers below, one hook each; the differences themselves are pin-diff.js.
import { escapeHtml, fixed, motionSymbol, polynomialText } from '../format.js';
import { figureTexts } from '../figures.js';
import { axesDifference, changedInputs, gridDifference, profileDifference } from '../pin-diff.js';
import { fieldNames } from './field-names.js';
import { pathWords } from '../field-words.js';
import { unitText } from '../result-fields.js';

const $ = (selector) => document.querySelector(selector);
export const PINNED = 'difference to pinned';

// Tab. 2: the line under an axis's polynomial (set: 'nominal' or 'corrected').
export function pinnedPolynomial(state, set, axis) {
  const p = state.pinned;
  if (!p) return '';
  const pick = (r) => (set === 'corrected' ? r.correction && r.correction.axes : r.axes);
  if (!pick(state.result) && !pick(p.result)) return '';
  const d = axesDifference(pick(state.result), pick(p.result), state.result, p.result);
  const text = d ? polynomialText(d[axis], motionSymbol(state.result)) : 'not comparable (another degree or gash, or no correction)';
  return `<span class="pin-diff">${PINNED}: ${escapeHtml(text)}</span>`;
}

// The coefficients table: the nominal coefficients' differences, or null when nothing is pinned.
export function pinnedCoefficients(state) {
  const p = state.pinned;
  return p ? { axes: axesDifference(state.result.axes, p.result.axes, state.result, p.result) } : null;
}

// A difference as shown: signed, with a typographic minus; ±0 when it rounds to nothing.
function change(v, digits) {
  const d = Number(v.toFixed(digits));
  return d === 0 ? '±0' : `${d > 0 ? '+' : '−'}${Math.abs(d).toFixed(digits)}`;
}

function figuresLine(now, then, comparable) {
  if (!comparable || !now || !then) return `${PINNED}: not comparable (another grid)`;
  const digits = { sse: 4, max: 3, thickness: 3 };
  return `${PINNED}: ${figureTexts(['sse', 'max', 'thickness'], (q) => `topography.${q}`, (q) => change(now[q] - then[q], digits[q])).join(', ')}`;
}

// The topography: each side's grid as its difference to the pinned one, and its figures with
// theirs. viewsOf(result, caseObject, view) is the topography view's own reading of a result.
export function comparedToPinned(v, state, viewsOf) {
  const p = state.pinned;
  if (!p) return v;
  const w = viewsOf(p.result, p.caseObject, state.view);
  const out = { ...v };
  for (const side of ['before', 'after']) {
    if (!v[side]) continue;
    const d = w[side] ? gridDifference(v[side], w[side], state.result, p.result) : null;
    if (d) Object.assign(out, { [side]: d, [`${side}Name`]: `${v[`${side}Name`]}, ${PINNED}` });
    out[`${side}Figures`] = `${v[`${side}Figures`]} · ${figuresLine(v[`${side}Numbers`], w[`${side}Numbers`], !!d)}`;
  }
  return out;
}

// The wheel profile: the pinned profile as a dotted trace, and the differences in words.
export function pinnedProfile(state) {
  const p = state.pinned;
  if (!p) return null;
  const q = p.result.wheelProfile;
  const d = profileDifference(state.result.wheelProfile, q);
  const r = unitText('wheelProfile.r');  // the tooth-face radius as the module states it; ΔR, ΔZ the page's µm of a change
  const text = d ? `Wheel profile, ${PINNED} at the same tooth-face radius: largest |ΔR| ${fixed(Math.abs(d.maxR.value), 3)} µm ` +
    `(r = ${fixed(d.maxR.r, 2)} ${r}), largest |ΔZ| ${fixed(Math.abs(d.maxZ.value), 3)} µm (r = ${fixed(d.maxZ.r, 2)} ${r}).`
    : `Wheel profile, ${PINNED}: not comparable (the radii do not overlap).`;
  return { text, trace: { x: q.Z, y: q.R, mode: 'lines', name: 'pinned', line: { dash: 'dot', color: '#8a4b00' } } };
}

function changedText(now, pinned) {
  const names = fieldNames();
  const value = (v) => (v === undefined ? 'empty' : typeof v === 'object' ? 'given' : String(v));
  const changes = changedInputs(now, pinned).map(({ path, from, to }) => {
    const name = names[path] ? names[path].text : { measured: 'measured grid', axes: 'run axes', correction: 'locks' }[path] || pathWords(path);
    return /^(measured|axes|correction)$/.test(path) ? `${name} changed` : `${name} ${value(from)} → ${value(to)}`;
  });
  return changes.length ? `Changed since pinning: ${changes.join('; ')}.` : 'No input changed since pinning.';
}

export function mountPin(store) {
  const render = (_, state) => {
    const p = state.pinned;
    $('#results').classList.toggle('pinned', !!p);
    $('#unpin').hidden = !p;
    $('#pin').disabled = !state.result;
    $('#pin').textContent = p ? 'Pin this result instead' : 'Pin this result';
    $('#pin-note').textContent = p && state.result
      ? `Pinned: the views show the ${PINNED} (now − pinned). ${changedText(state.resultCase, p.caseObject)}` : '';
  };
  store.on('result', render);
  store.on('view', render);
  $('#pin').addEventListener('click', () => {
    const s = store.state;
    if (s.result) store.pin({ result: s.result, caseObject: s.resultCase });
  });
  $('#unpin').addEventListener('click', () => store.pin(null));
  render(null, store.state);
}
