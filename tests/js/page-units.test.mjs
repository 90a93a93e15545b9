// The page spells no unit the result schema states (issue 23, item 3): a figure's unit and label
// come from the module's resultFields() (web/src/result-fields.js), not from words of the page.
//
// The check reads the page's code (web/src and wasm/lib, comments left out) line by line: a line
// that names a result field that has a unit (by its key: `rmsBefore`, `profileSlope`, or its label:
// "sum of squares") and that also holds a unit the schema states ('µm', 'µm²', 'arc-min', 'deg'
// or its sign °, ...) inside a string spells that unit by hand. Keys of one letter (r, x, R, Z)
// and the keys every object has (value, min, max, offset, ...) are too common to be read so; a
// few lines are allowed, each with why. A second test renders the page's figures with a schema
// whose units are tokens of their own, and finds each figure's token beside it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync, readdirSync, statSync } from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';

const root = path.join(path.dirname(fileURLToPath(import.meta.url)), '..', '..');
const hobsharp = await loadHobSharp();
const fields = hobsharp.resultFields();

// Where a key is not the field's own name: an axis, a flank, a check's name, a list's index.
const NOT_KEYS = new Set(['X', 'Y', 'Z', 'A', 'B', 'left', 'right']);
// Keys that every kind of object has, too common to tell a result field by.
const COMMON = new Set(['value', 'min', 'max', 'offset', 'height', 'normal', 'circular', 'thickness', 'uncertainty',
  'tolerances', 'change', 'axes', 'beta', 'source', 'deviation', 'profile']);

// The result's units as the page could write them: each unit, each part of a composite one
// ("mm, mm, µm", "µm per 100 mm"), and the sign the page writes for deg.
export function schemaUnits(list) {
  const units = new Set();
  for (const f of list) {
    if (!f.unit) continue;
    for (const part of f.unit.split(/,\s*|\s+(?:per|or)\s+|\//)) {
      if (/^(µm²?|µrad|mm|rad|deg|arc-min)$/.test(part)) units.add(part);
    }
  }
  if (units.has('deg')) units.add('°');
  return units;
}

// The words that name a field with a unit: its key (the last name of its path that is a name of
// its own) and its label.
export function fieldNamesWithUnits(list) {
  const names = new Map();
  for (const f of list) {
    if (!f.unit) continue;
    const key = f.path.split('.').filter((k) => !NOT_KEYS.has(k) && !/^\d+$/.test(k)).at(-1);
    if (key.length > 1 && !COMMON.has(key)) names.set(key, f.path);
    if (f.label) names.set(f.label, f.path);
  }
  return names;
}

const escape = (s) => s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');

// The text of a line's strings and templates ('...', "...", `...` with ${...} left in).
function stringsOf(line) {
  const out = [];
  const re = /'((?:[^'\\]|\\.)*)'|"((?:[^"\\]|\\.)*)"|`((?:[^`\\]|\\.)*)`/g;
  for (let m; (m = re.exec(line));) out.push(m[1] ?? m[2] ?? m[3]);
  return out.join('\n');
}

// A line's code without a trailing // comment (not inside a string: good enough for this code).
const codeOf = (line) => (/^\s*(\/\/|\*|\/\*)/.test(line) ? '' : line.replace(/\s\/\/\s.*$/, ''));

// [{file, line, text, name, unit}] for each line that spells a unit beside a field's name.
export function handTypedUnits(files, names, units) {
  const unitRe = new RegExp(`(?:^|[^\\wµ])(${[...units].sort((a, b) => b.length - a.length).map(escape).join('|')})(?![\\w²])`);
  const nameRes = [...names.keys()].map((n) => [n, new RegExp(`(?<![\\w-])${escape(n)}(?![\\w-])`)]);
  const found = [];
  for (const file of files) {
    readFileSync(path.join(root, file), 'utf8').split('\n').forEach((raw, i) => {
      const code = codeOf(raw);
      const strings = stringsOf(code);
      const unit = unitRe.exec(strings);
      if (!unit) return;
      // A name in the code (a key) or in the strings (a label); Math.max and the like are not keys.
      const named = nameRes.find(([, re]) => re.test(code.replace(/Math\.\w+/g, '')));
      if (named) found.push({ file, line: i + 1, text: raw.trim(), name: named[0], unit: unit[1] });
    });
  }
  return found;
}

function sources(dir) {
  return readdirSync(path.join(root, dir)).flatMap((name) => {
    const rel = path.join(dir, name);
    return statSync(path.join(root, rel)).isDirectory() ? sources(rel) : /\.m?js$/.test(name) ? [rel] : [];
  });
}

// Lines allowed to spell a unit beside a field's name, each with why: [file, text in the line, why].
const ALLOWED = [
  // An input's words: the deviation of a points file (µm or mm by its header), not the result's.
  ['wasm/lib/points-csv.js', 'The largest |deviation| is', 'the points file reader\'s warning on the file\'s deviation column, an input'],
];

test('the page spells no unit of a result field by hand', () => {
  const names = fieldNamesWithUnits(fields);
  const units = schemaUnits(fields);
  assert.ok(names.has('rmsBefore') && names.has('profileSlope') && units.has('µm²') && units.has('arc-min'), 'the schema is read');
  const all = handTypedUnits([...sources('web/src'), ...sources('wasm/lib')], names, units);
  const allowed = (f, [file, text]) => f.file === file && f.text.includes(text);
  const found = all.filter((f) => !ALLOWED.some((a) => allowed(f, a)));
  assert.deepEqual(found.map((f) => `${f.file}:${f.line}: '${f.unit}' beside ${f.name} (${names.get(f.name)}): ${f.text}`), []);
  // Each allowed line is still there and still found: the list holds nothing stale.
  for (const a of ALLOWED) assert.ok(all.some((f) => allowed(f, a)), `allowed but not found: ${a[0]}: ${a[1]}`);
});

test('the check finds a unit typed beside a field, and not one the schema gives', () => {
  const names = fieldNamesWithUnits(fields);
  const units = schemaUnits(fields);
  const file = 'tests/js/page-units.fixture.js';
  const found = handTypedUnits([file], names, units).map((f) => f.line);
  const lines = readFileSync(path.join(root, file), 'utf8').split('\n');
  const expected = lines.flatMap((l, i) => (/\/\/ hand-typed$/.test(l) ? [i + 1] : []));
  assert.ok(expected.length >= 3);
  assert.deepEqual(found, expected);
});

// The page's figures drawn with a schema whose units and labels are tokens of their own: each
// figure shows its field's token, and no unit the page could have typed is left.
test('the results CSV, the gear effect, the verdict and the setting angle take their units and labels from the schema', async () => {
  const { setResultFields } = await import('../../web/src/result-fields.js');
  const { setModuleLimits } = await import('../../web/src/limits.js');
  const { resultsCsv } = await import('../../web/src/io/results-csv.js');
  const { gearEffectRows } = await import('../../web/src/gear-effect-figures.js');
  const { settingAngleNote, verdictText } = await import('../../web/src/words.js');
  const { FACE_FIGURES } = await import('../../web/src/figures.js');
  const U = (p) => `U[${p}]`, L = (p) => `L[${p}]`;
  setModuleLimits(hobsharp.limits());
  setResultFields(fields.map((f) => ({ ...f, unit: f.unit && U(f.path), label: f.label && L(f.path) })));
  try {
    const paper = JSON.parse(readFileSync(path.join(root, 'tests', 'data', 'tab1.json'), 'utf8'));
    const measured = Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (__, j) => 0.5 * (i - 2) + 0.1 * (j - 4)));
    const r = hobsharp.evaluate({ ...paper, hob: { ...paper.hob, gashes: 12, relief: 4.5 }, measured });
    const lines = resultsCsv(r).split('\n');
    for (const q of FACE_FIGURES) {
      const p = `correction.${q}Before`;
      assert.ok(lines.some((l) => l.startsWith(`${L(p)},${U(p)},${r.correction[`${q}Before`]},`)), p);
    }
    for (const q of ['profileSlope', 'pressureAngleError', 'profileForm', 'slopeScatter']) {
      const p = `gearEffect.left.${q}`;
      assert.ok(lines.some((l) => l.startsWith(`${L(p)},${U(p)},`)), p);
    }
    // No unit of the result typed by the page; mm only in the axes' coefficients (limits().axes),
    // and the verdict is the module's sentence.
    const typed = lines.filter((l) => !l.startsWith('verdict,') &&
      (/µm|µrad|°|arc-min|\bdeg\b/.test(l) || (/\bmm\b/.test(l) && !/^[XYZAB] a\d,/.test(l))));
    assert.deepEqual(typed, []);
    assert.deepEqual(gearEffectRows(r.gearEffect).map(([label, unit]) => [label, unit]),
      ['profileSlope', 'pressureAngleError', 'profileForm', 'slopeScatter'].map((q) => [L(`gearEffect.left.${q}`), U(`gearEffect.left.${q}`)]));
    const verdict = verdictText(r.correction);
    for (const q of ['rms', 'sse', 'thickness']) assert.ok(verdict.includes(U(`correction.${q}Before`)), `${q}: ${verdict}`);
    assert.doesNotMatch(verdict.slice(r.correction.verdict.length), /µm/, 'after the module\'s own sentence');
    assert.match(settingAngleNote(r.setup), /U\[setup\.settingAngle\]/);
  } finally {
    setResultFields(fields);
  }
});

test('a meaning the page shows (a tooltip) names no result path: each is said by its label or in words', async () => {
  const { setResultFields, fieldMeaning } = await import('../../web/src/result-fields.js');
  const fields = hobsharp.resultFields();
  setResultFields(fields);
  const PATH = /\b(nominal|correction|inspection|gearEffect|face|wheel|setup|machine|measured|passes|job|hob|grid)(\.[A-Za-z]\w*|\[\d+\])+/;
  const withPaths = fields.filter((f) => PATH.test(f.meaning));
  assert.ok(withPaths.length > 10, 'the module\'s meanings name paths (for docs/api.md): the check has something to do');
  for (const f of fields) assert.doesNotMatch(fieldMeaning(f.path), PATH, f.path);
  assert.match(fieldMeaning('correction.residual'), /re-simulated with the correction's axes and the identified error/);
});

// The maps, the surfaces, their colour bar, the wheel plot and the gallery: no grid unit typed in
// their code (comments aside), and, drawn with a schema of tokens, the tokens in their titles.
test('the plots of a grid and of the wheel take their units from the schema', async () => {
  const plotFiles = ['web/src/plots/maps.js', 'web/src/plots/surface.js', 'web/src/plots/colours.js',
    'web/src/plots/gallery.js', 'web/src/views/wheel.js'];
  for (const file of plotFiles) {
    const code = readFileSync(path.join(root, file), 'utf8').split('\n').map((l) => l.replace(/\/\/.*$/, '')).join('\n');
    assert.doesNotMatch(code, /['`"(,\s](µm|mm)\b/, `${file} types a unit`);
  }
  const { setResultFields } = await import('../../web/src/result-fields.js');
  const { gridAxisTitles, gridHover } = await import('../../web/src/plots/grid-units.js');
  const { deviationColourBar } = await import('../../web/src/plots/colours.js');
  setResultFields(fields.map((f) => ({ ...f, unit: f.unit && `U[${f.path}]` })));
  try {
    assert.deepEqual(gridAxisTitles(), {
      x: 'x along the gash (U[topography.x])', y: 'r root to tip (U[topography.r])', z: 'deviation (U[topography.normal])',
    });
    assert.match(gridHover(), /^r = %\{y:\.2f\} U\[topography\.r\]<br>x = %\{x:\.2f\} U\[topography\.x\]<br>deviation %\{z:\.3f\} U\[topography\.normal\]/);
    assert.match(deviationColourBar().title.text, /^U\[topography\.normal\]<br>/);
  } finally {
    setResultFields(fields);
  }
});
