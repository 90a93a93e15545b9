// A refusal in the words on screen: the calculator names fields by their path in the case
// ("hob.pitchDiameter: must be smaller than hob.outerDiameter (80 mm); got 90 mm."); the page
// shows the labels instead ("Pitch diameter d_p must be smaller than the outer diameter d_a
// (80 mm); got 90 mm."). Pure: the names come from the caller (views/field-names.js reads
// them from the form's labels), each as {text, html}.
import { escapeHtml } from './format.js';

// A reason that starts with a verb follows the name directly; any other after a colon.
const VERB = /^(must|is|are|has|holds|needs|lies|should)\b/;

// The case's members: a path starts with one of these (a word that does not is no path).
const ROOTS = ['format', 'hob', 'wheel', 'setup', 'machine', 'degree', 'grid', 'axes', 'measured', 'measuredPoints',
  'correction', 'passes', 'inspection', 'job', 'page'];
const PATH = new RegExp(`\\b(?:${ROOTS.join('|')})(?:\\.[A-Za-z]\\w*|\\[\\d+\\])+|\\b(?:${ROOTS.join('|')})\\b`, 'g');

// A member's own words where splitting its name would not do.
const MEMBER_WORDS = {
  format: 'case format', axes: 'run axes', measured: 'measured grid', measuredPoints: 'measured points',
  passes: 'grinding passes', correction: 'correction options', tolerances: 'tolerance table',
  probeNoise: 'probe noise σ', hobSerial: 'hob serial number', gashDeviations: 'gash deviations',
  gashTopographies: 'gash topographies', measuredProfile: 'wheel file', profileOffset: 'profile offsets',
  uncertainty: 'measuring uncertainty U95',
};
// What one element of a list is called, by the list's member.
const ELEMENT = {
  passes: (i) => `pass ${i}`, measuredPoints: (i) => `measured point ${i}`, measuredProfile: (i) => `wheel file, point ${i}`,
  gashDeviations: (i) => `gash ${i}'s deviation`, gashTopographies: (i) => `gash ${i}'s topography`,
};
// A member's name in words: "gashDeviations" is "gash deviations" (result-fields.js says result paths so).
export const splitName = (name) => name.replace(/([a-z])([A-Z])/g, '$1 $2').toLowerCase();

// Words for a path that has no name on screen, in the words of the case's members, counted from
// 1: "passes[0].axes.X[2]" is "Pass 1, run axis X, coefficient a2"; "inspection.gashDeviations[3]"
// is "Inspection, gash 4's deviation". No path reaches the page as it is.
export function pathWords(path) {
  const parts = [];
  let list = null, rows = 0, axis = false, checks = false;
  for (const [, key, index] of path.matchAll(/\.?([A-Za-z]\w*)|\[(\d+)\]/g)) {
    if (index !== undefined) {
      const n = Number(index) + 1;
      const element = ELEMENT[list];
      if (axis) parts.push(`coefficient a${index}`);
      else if (element) parts[parts.length - 1] = element(n);
      else if (list === 'measured' || list === 'gashTopographies' || list === 'measuredRow') {
        parts.push(rows++ === 0 ? `row ${n}` : `value ${n}`);
      } else parts.push(`number ${n}`);
      if (list === 'gashTopographies') list = 'measuredRow';
      continue;
    }
    if (list === 'axes' && /^[XYZAB]$/.test(key)) { parts[parts.length - 1] = `run axis ${key}`; axis = true; list = key; continue; }
    if (checks && /^[A-D]{1,2}$/.test(key)) { parts.push(`class ${key}`); continue; }
    if (key === 'checks') { checks = true; continue; }
    parts.push(MEMBER_WORDS[key] || (/^[A-Z]\w?\d*$/.test(key) ? key : splitName(key)));
    list = key;
    axis = false;
  }
  const text = parts.join(', ');
  return text.charAt(0).toUpperCase() + text.slice(1);
}

const asName = (text) => ({ text, html: escapeHtml(text) });

// The name for a path: its own, or that of the nearest enclosing one ("axes.X" for "axes.X[2]"),
// or, with neither on screen, the path in words (pathWords).
function nameOf(path, names) {
  for (let p = path; p; p = p.replace(/(\.[^.[\]]*|\[\d+\])$/, '')) {
    if (names[p]) return p === path ? { name: names[p], rest: '' } : { name: asName(pathWords(path)) };
    if (!/[.[]/.test(p)) break;
  }
  return { name: asName(pathWords(path)) };
}

const lowerFirst = (s) => s.replace(/^([A-Z])(?=[a-z])/, (c) => c.toLowerCase());

// [{text} | {name, article}] for a reason, each path in it (one with a dot or an index) replaced
// by its name.
function tokens(reason, names) {
  const out = [];
  let last = 0;
  for (const m of reason.matchAll(PATH)) {
    if (!/[.[]/.test(m[0])) continue;  // a word such as "grid" or "wheel" in a sentence
    if (/^\.\w/.test(reason.slice(m.index + m[0].length))) continue;  // part of a longer name
    out.push({ text: reason.slice(last, m.index) });
    const before = reason.slice(0, m.index);
    out.push({ name: nameOf(m[0], names).name, article: !/\b(the|a|an)\s$/i.test(before) && !reason.startsWith(' =', m.index + m[0].length) });
    last = m.index + m[0].length;
  }
  out.push({ text: reason.slice(last) });
  return out;
}

function render(parts, key) {
  return parts.map((t) => {
    if (t.text !== undefined) return key === 'html' ? escapeHtml(t.text) : t.text;
    const name = t.lead ? t.name[key] : lowerFirst(t.name[key]);
    return (t.article ? 'the ' : '') + name;
  }).join('');
}

// {text, html} for an error {field, message}: its field by its name on screen, or in words; null
// when the message does not start with its field (it is then the calculator's own sentence).
export function wordedError(error, names) {
  const field = error.field || '';
  const message = String(error.message || '');
  const prefix = `${field}: `;
  const found = field && message.startsWith(prefix) ? nameOf(field, names) : null;
  if (!found) return null;
  const reason = message.slice(prefix.length);
  const parts = [{ name: found.name, lead: true }];
  parts.push({ text: VERB.test(reason) ? ' ' : ': ' }, ...tokens(reason, names));
  return { text: render(parts, 'text'), html: render(parts, 'html') };
}
