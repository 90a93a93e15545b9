// The table of result fields in docs/api.md (it was the README's), made from the module's own
// field list (resultFields(), core/io/result_model.cpp), and the table of limits() entries
// (limitFields(), core/io/limits_model.cpp). tests/js/readme.test.mjs checks that docs/api.md
// holds them.
//   node tests/js/readme-table.mjs           prints the table
//   node tests/js/readme-table.mjs --write   rewrites it in docs/api.md, between the two markers
import { readFileSync, writeFileSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

export const readmePath = path.join(path.dirname(fileURLToPath(import.meta.url)), '..', '..', 'docs', 'api.md');
export const BEGIN = '<!-- result-fields: made by `node tests/js/readme-table.mjs --write` from resultFields() -->';
export const END = '<!-- /result-fields -->';

const KINDS = {
  number: 'number', integer: 'integer', boolean: 'boolean', string: 'string', strings: 'list of strings',
  numbers: 'list of numbers', matrix: 'rows of numbers', matrices: 'list of (rows of numbers)',
  axes: '`{X, Y, Z, A, B}`: lists a0..an',
};

const cell = (s) => s.replace(/\|/g, '\\|');

export function fieldTable(fields) {
  const rows = fields.map((f) => {
    const kind = KINDS[f.kind];
    if (!kind) throw new Error(`${f.path}: unknown kind ${f.kind}`);
    const meaning = f.when ? `${f.meaning}; ${f.when}` : f.meaning;
    return `| \`${f.path}\` | ${kind} | ${cell(f.unit)} | ${cell(f.label || '')} | ${cell(meaning)} |`;
  });
  return ['| field | holds | unit | label | meaning |', '|---|---|---|---|---|', ...rows].join('\n');
}

// The table of limits() entries (limitFields(), core/io/limits_model.cpp).
export const LIMITS_BEGIN = '<!-- limit-fields: made by `node tests/js/readme-table.mjs --write` from limitFields() -->';
export const LIMITS_END = '<!-- /limit-fields -->';
const LIMIT_KINDS = {
  string: 'string', strings: 'list of strings', integer: 'integer', number: 'number',
  range: '`{default, min, max, unit}` (min, max and unit where given)', document: 'a JSON document',
};
export function limitTable(entries) {
  const rows = entries.map((e) => {
    const kind = LIMIT_KINDS[e.kind];
    if (!kind) throw new Error(`${e.path}: unknown kind ${e.kind}`);
    return `| \`${e.path}\` | ${kind} | ${cell(e.unit)} | ${cell(e.words)} |`;
  });
  return ['| entry | holds | unit | what |', '|---|---|---|---|', ...rows].join('\n');
}

// The table in docs/api.md's text, between the markers (null without them).
export function readmeTable(text, begin = BEGIN, end = END) {
  const from = text.indexOf(begin), to = text.indexOf(end);
  if (from < 0 || to < from) return null;
  return text.slice(from + begin.length, to).trim();
}

// The text with `table` between the markers.
function withTable(text, table, begin, end) {
  if (readmeTable(text, begin, end) === null) throw new Error(`docs/api.md has no markers ${begin} ... ${end}`);
  return `${text.slice(0, text.indexOf(begin) + begin.length)}\n${table}\n${text.slice(text.indexOf(end))}`;
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const { loadHobSharp } = await import('../../wasm/hobsharp.mjs');
  const hobsharp = await loadHobSharp();
  const table = fieldTable(hobsharp.resultFields()), limits = limitTable(hobsharp.limitFields());
  if (process.argv[2] === '--write') {
    const text = withTable(withTable(readFileSync(readmePath, 'utf8'), table, BEGIN, END), limits, LIMITS_BEGIN, LIMITS_END);
    writeFileSync(readmePath, text);
    console.log('docs/api.md: the result table and the limits table rewritten');
  } else {
    console.log(`${table}\n\n${limits}`);
  }
}
