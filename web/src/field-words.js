// A refusal in the words on screen: the calculator names fields by their path in the case
// ("hob.pitchDiameter: must be smaller than hob.outerDiameter (80 mm); got 90 mm."); the page
// shows the labels instead ("Pitch diameter d_p must be smaller than the outer diameter d_a
// (80 mm); got 90 mm."). Pure: the names come from the caller (views/field-names.js reads
// them from the form's labels), each as {text, html}.
import { escapeHtml } from './format.js';

// A reason that starts with a verb follows the name directly; any other after a colon.
const VERB = /^(must|is|are|has|holds|needs|lies|should)\b/;

// The name for a path: its own, or that of the nearest enclosing one ("axes.X" for "axes.X[2]").
function nameOf(path, names) {
  for (let p = path; p; p = p.replace(/(\.[^.[\]]*|\[\d+\])$/, '')) {
    if (names[p]) return { name: names[p], rest: path.slice(p.length) };
    if (!/[.[]/.test(p)) break;
  }
  return null;
}

const lowerFirst = (s) => s.replace(/^([A-Z])(?=[a-z])/, (c) => c.toLowerCase());

// [{text} | {name, article}] for a reason, each known path in it replaced by its name.
function tokens(reason, names) {
  const paths = Object.keys(names).filter((p) => p.includes('.')).sort((a, b) => b.length - a.length);
  if (!paths.length) return [{ text: reason }];
  const pattern = new RegExp(`\\b(${paths.map((p) => p.replace(/[.[\]]/g, '\\$&')).join('|')})\\b(?!\\.?\\w)`, 'g');
  const out = [];
  let last = 0;
  for (const m of reason.matchAll(pattern)) {
    out.push({ text: reason.slice(last, m.index) });
    const before = reason.slice(0, m.index);
    out.push({ name: names[m[1]], article: !/\b(the|a|an)\s$/i.test(before) && !reason.startsWith(' =', m.index + m[1].length) });
    last = m.index + m[1].length;
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

// {text, html} for an error {field, message}; null when its field has no name on screen (the
// message is then shown as the calculator gave it).
export function wordedError(error, names) {
  const field = error.field || '';
  const message = String(error.message || '');
  const prefix = `${field}: `;
  const found = field && message.startsWith(prefix) ? nameOf(field, names) : null;
  if (!found) return null;
  const reason = message.slice(prefix.length);
  const parts = [{ name: found.name, lead: true }];
  if (found.rest) parts.push({ text: ` ${found.rest}` });
  parts.push({ text: VERB.test(reason) ? ' ' : ': ' }, ...tokens(reason, names));
  return { text: render(parts, 'text'), html: render(parts, 'html') };
}
