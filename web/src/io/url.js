// The case in the page's address (#case=...), so that a link reopens the same job: the saved case
// (io/case-state.js), with the what-if offsets, the locks and the grinding passes.
import { savedCase } from './case-state.js';

// Measured values beyond this many are left out of the link (it would make it long): first the
// history of grinding passes (as a whole, so that the passes kept are numbered as they were), then
// the measured grid.
export const MAX_LINK_VALUES = 2500;
// The longest link the page hands out, characters after the '#': browsers keep far longer
// addresses (Chromium drops one over 2 MB, and opens the page without it), but a link is pasted
// into mails, chats and tickets, which cut long ones. 64 kB holds the case with a measured grid
// of MAX_LINK_VALUES values; what does not fit is left out, part by part, and said.
export const MAX_LINK_CHARS = 64 * 1024;

// A grid's values, or a list of points' (three numbers each).
const valuesOf = (grid) => (Array.isArray(grid) ? grid.length * (grid[0] || []).length : 0);
const isObject = (v) => v !== null && typeof v === 'object' && !Array.isArray(v);

// The parts a link may leave out, each with the words that say so: value(c) is the part in the
// case c (undefined without it), drop(c) takes it out of the copy c.
const without = (c, group, key) => {
  const rest = { ...c[group] };
  delete rest[key];
  if (Object.keys(rest).length) c[group] = rest; else delete c[group];
};
const member = (c, group, key) => (isObject(c[group]) ? c[group][key] : undefined);
const PARTS = [
  { words: 'the history of grinding passes (a correction from the link uses the face measured now alone)', value: (c) => c.passes, drop: (c) => { delete c.passes; } },
  { words: 'the measured grid (with its locks)', value: (c) => c.measured,
    drop: (c) => { delete c.measured; if (c.measuredPoints === undefined) delete c.correction; } },
  { words: 'the per-gash topographies', value: (c) => member(c, 'inspection', 'gashTopographies'),
    drop: (c) => without(c, 'inspection', 'gashTopographies') },
  { words: "the measuring machine's points (with their locks)", value: (c) => c.measuredPoints,
    drop: (c) => { delete c.measuredPoints; if (c.measured === undefined) delete c.correction; } },
  { words: "the wheel's points (as dressed or measured)", value: (c) => member(c, 'wheel', 'profileOffset') || member(c, 'wheel', 'measuredProfile'),
    drop: (c) => { without(c, 'wheel', 'profileOffset'); if (c.wheel) without(c, 'wheel', 'measuredProfile'); } },
  { words: 'the tolerance table', value: (c) => member(c, 'inspection', 'tolerances'), drop: (c) => without(c, 'inspection', 'tolerances') },
];
const sizeOf = (v) => (v === undefined ? 0 : JSON.stringify(v).length);

const hashOf = (c) => `#case=${encodeURIComponent(JSON.stringify(c))}`;

// The link of a case: {hash, leftOut: [words of each part left out], chars: its length}; hash is
// null when the case does not fit in MAX_LINK_CHARS even without every part that may be left out.
export function caseLink(caseObject) {
  const c = { ...caseObject };
  const leftOut = [];
  const drop = (part) => { part.drop(c); leftOut.push(part.words); };
  const history = (c.passes || []).reduce((n, p) => n + valuesOf(p.measured || p.measuredPoints), 0);
  if (history && valuesOf(c.measured) + history > MAX_LINK_VALUES) drop(PARTS[0]);
  if (valuesOf(c.measured) > MAX_LINK_VALUES) drop(PARTS[1]);
  // Then, while the link is too long, the largest part left: the link keeps as much as fits.
  let hash = hashOf(c);
  while (hash.length - 1 > MAX_LINK_CHARS) {
    const largest = PARTS.reduce((a, b) => (sizeOf(b.value(c)) > sizeOf(a.value(c)) ? b : a));
    if (largest.value(c) === undefined) break;
    drop(largest);
    hash = hashOf(c);
  }
  return { hash: hash.length - 1 <= MAX_LINK_CHARS ? hash : null, leftOut, chars: hash.length - 1 };
}

// The case's address, as it fits (a case that does not fit gives an address without one).
export const caseToHash = (caseObject) => caseLink(caseObject).hash || '';

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

// What the link of the last good result leaves out, in words ('' when nothing), or why there is
// no link.
export function leftOutText({ hash, leftOut, chars }) {
  if (hash === null) {
    return `This job is too large for a link: ${Math.ceil(chars / 1024)} kB${leftOut.length ? ` even without ${leftOut.join(', ')}` : ''}; ` +
      `a link holds at most ${MAX_LINK_CHARS / 1024} kB. Save the case (a file) to hand it on.`;
  }
  return leftOut.length ? `The link leaves out ${leftOut.join(', ')}: save the case (a file) to keep ${leftOut.length > 1 ? 'them' : 'it'}.` : '';
}

// Keeps the address in step with the last good result (a refused input never gets into a link);
// the entry's state (the undo step, views/undo.js) stays. Returns link(): the link written last,
// {hash, leftOut}, for "Copy link".
export function mountLink(store) {
  let last = { hash: '', leftOut: [], chars: 0 };
  const write = () => {
    last = caseLink(savedCase(store.state));
    history.replaceState(history.state, '', last.hash || `${location.pathname}${location.search}`);
  };
  store.on('result', write);
  for (const event of ['view', 'surfaces']) store.on(event, () => { if (store.state.result) write(); });  // as shown
  return { link: () => last };
}
