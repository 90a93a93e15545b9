// The table of result fields in docs/api.md (it was the README's), made from the module's own
// field list (resultFields(), core/io/result_model.cpp). tests/js/readme.test.mjs checks that
// docs/api.md holds it.
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

// The table in docs/api.md's text, between the markers (null without them).
export function readmeTable(text) {
  const begin = text.indexOf(BEGIN), end = text.indexOf(END);
  if (begin < 0 || end < begin) return null;
  return text.slice(begin + BEGIN.length, end).trim();
}

if (process.argv[1] === fileURLToPath(import.meta.url)) {
  const { loadHobSharp } = await import('../../wasm/hobsharp.mjs');
  const table = fieldTable((await loadHobSharp()).resultFields());
  if (process.argv[2] === '--write') {
    const text = readFileSync(readmePath, 'utf8');
    if (readmeTable(text) === null) throw new Error(`docs/api.md has no markers ${BEGIN} ... ${END}`);
    const begin = text.indexOf(BEGIN) + BEGIN.length, end = text.indexOf(END);
    writeFileSync(readmePath, `${text.slice(0, begin)}\n${table}\n${text.slice(end)}`);
    console.log('docs/api.md: the result table rewritten');
  } else {
    console.log(table);
  }
}
