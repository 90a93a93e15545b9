// The XML reader for an X3P's main.xml (pure, with Node tests): well-formed XML 1.0 without a
// document type. Elements, attributes (skipped), text, the five predefined entities and character
// references, comments, CDATA sections and processing instructions; a <!DOCTYPE> (and so any
// entity declaration: no "billion laughs") is refused, as is anything not well formed, naming the
// line. The tree: an element holding only text is its text; one holding elements is an object
// from each child's local name (the namespace prefix dropped) to the child, or to a list of them
// when the name repeats (or is in `lists`).

const MAX_DEPTH = 64;
const NAME = /[A-Za-z_:][-A-Za-z0-9_:.\u00B7\u00C0-\uFFFF]*/y;
const PREDEFINED = { lt: '<', gt: '>', amp: '&', quot: '"', apos: "'" };

export function parseXml(xml, { lists = new Set(), file = 'the XML' } = {}) {
  let at = 0;
  // The name at k, or null.
  const nameAt = (k) => { NAME.lastIndex = k; const m = NAME.exec(xml); return m && m[0]; };
  const lineAt = (k) => {
    let n = 1;
    for (let i = xml.indexOf('\n'); i >= 0 && i < k; i = xml.indexOf('\n', i + 1)) n += 1;
    return n;
  };
  const fail = (text, k = at) => { throw new Error(`${file}, line ${lineAt(k)}: ${text}`); };
  const decode = (raw, start) => raw.replace(/&([^;&<]*);?/g, (whole, ref, offset) => {
    if (!whole.endsWith(';')) fail(`"&" not followed by an entity reference ending in ";".`, start + offset);
    if (ref in PREDEFINED) return PREDEFINED[ref];
    const code = /^#x[0-9a-fA-F]+$/.test(ref) ? parseInt(ref.slice(2), 16) : /^#\d+$/.test(ref) ? Number(ref.slice(1)) : NaN;
    if (!Number.isInteger(code) || code < 1 || code > 0x10FFFF) fail(`the entity "&${ref.slice(0, 20)};" is not one XML predefines, and the document declares none.`, start + offset);
    return String.fromCodePoint(code);
  });
  // Skips what may stand between elements: blanks, comments, processing instructions.
  const skipMisc = () => {
    for (;;) {
      while (at < xml.length && /\s/.test(xml[at])) at += 1;
      if (xml.startsWith('<!--', at)) {
        const end = xml.indexOf('-->', at + 4);
        if (end < 0) fail('a comment that does not end (the document is cut short?).');
        at = end + 3;
      } else if (xml.startsWith('<?', at)) {
        const end = xml.indexOf('?>', at + 2);
        if (end < 0) fail('a processing instruction that does not end (the document is cut short?).');
        at = end + 2;
      } else return;
    }
  };
  const localName = (name) => name.slice(name.indexOf(':') + 1);
  // The start tag at `at`: its name, and whether it closes itself.
  const startTag = () => {
    const name = nameAt(at + 1);
    if (!name) fail('a "<" that starts no element name.');
    at += 1 + name.length;
    for (;;) {
      while (/\s/.test(xml[at] || '')) at += 1;
      if (at >= xml.length) fail(`the start tag <${name}> does not end (the document is cut short?).`);
      if (xml.startsWith('/>', at)) { at += 2; return { name, empty: true }; }
      if (xml[at] === '>') { at += 1; return { name, empty: false }; }
      const a = nameAt(at);
      if (!a) fail(`<${name}> has something that is no attribute: "${xml.slice(at, at + 20)}".`);
      at += a.length;
      while (/\s/.test(xml[at] || '')) at += 1;
      if (xml[at] !== '=') fail(`<${name}>'s attribute ${a} has no "=".`);
      at += 1;
      while (/\s/.test(xml[at] || '')) at += 1;
      const quote = xml[at];
      if (quote !== '"' && quote !== "'") fail(`<${name}>'s attribute ${a} has no quoted value.`);
      const end = xml.indexOf(quote, at + 1);
      if (end < 0) fail(`<${name}>'s attribute ${a} does not end (the document is cut short?).`);
      if (xml.slice(at + 1, end).includes('<')) fail(`<${name}>'s attribute ${a} holds a "<".`);
      at = end + 1;
    }
  };
  const add = (children, name, value) => {
    if (!(name in children)) children[name] = lists.has(name) ? [value] : value;
    else if (Array.isArray(children[name])) children[name].push(value);
    else children[name] = [children[name], value];
  };
  // The element whose start tag is at `at`.
  const element = (depth) => {
    if (depth > MAX_DEPTH) fail(`elements nested more than ${MAX_DEPTH} deep.`);
    const opened = at;
    const { name, empty } = startTag();
    if (empty) return { name: localName(name), value: '' };
    let text = '';
    let children = null;
    for (;;) {
      const lt = xml.indexOf('<', at);
      if (lt < 0) fail(`<${name}> (opened on line ${lineAt(opened)}) is not closed: the document is cut short?`, xml.length);
      text += decode(xml.slice(at, lt), at);
      at = lt;
      if (xml.startsWith('</', at)) {
        const end = xml.indexOf('>', at);
        const closing = end < 0 ? '' : xml.slice(at + 2, end).trim();
        if (closing !== name) fail(end < 0 ? `<${name}> (opened on line ${lineAt(opened)}) is not closed: the document is cut short?` : `</${closing.slice(0, 40)}> closes <${name}> (opened on line ${lineAt(opened)}).`);
        at = end + 1;
        return { name: localName(name), value: children || text };
      }
      if (xml.startsWith('<!--', at) || xml.startsWith('<?', at)) { skipMisc(); continue; }
      if (xml.startsWith('<![CDATA[', at)) {
        const end = xml.indexOf(']]>', at);
        if (end < 0) fail('a CDATA section that does not end (the document is cut short?).');
        text += xml.slice(at + 9, end);
        at = end + 3;
        continue;
      }
      if (xml.startsWith('<!', at)) fail(`a "<!" declaration inside <${name}>.`);
      const child = element(depth + 1);
      children = children || {};
      add(children, child.name, child.value);
    }
  };

  if (xml.startsWith('\uFEFF')) at = 1;
  skipMisc();
  if (/^<!DOCTYPE/i.test(xml.slice(at, at + 9))) fail('a <!DOCTYPE> declaration; the document may declare no entities, and none are expanded.');
  if (xml[at] !== '<') fail(at >= xml.length ? 'no element: the document is empty.' : `text before the root element: "${xml.slice(at, at + 20)}".`);
  const root = element(1);
  skipMisc();
  if (at < xml.length) fail(`"${xml.slice(at, at + 20)}" after the root element </${root.name}>.`);
  return { [root.name]: root.value };
}
