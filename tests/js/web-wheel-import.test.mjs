// A wheel's points as files come (wasm/lib/wheel-csv.js), the dresser path the page writes
// (io/results-csv.js dresserCsv), and the offsets Fig. 4 shows on its µm scale (wheel-offsets.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readWheelCsv, wheelSource, withWheelPoints } from '../../wasm/lib/wheel-csv.js';
import { dresserCsv, profileCsv } from '../../web/src/io/results-csv.js';
import { offsetRange, wheelOffsetCurves } from '../../web/src/wheel-offsets.js';

test('a dressed wheel\'s offset, with its units in the header in any of the usual spellings', () => {
  for (const header of ['R (mm),offset (µm)', 'R_mm,offset_um', 'R [mm], offset [µm]', 'R mm,offset μm']) {
    const w = readWheelCsv(`${header}\n30,1.5\n40,-2\n50,0.25\n`);
    assert.equal(w.kind, 'profileOffset', header);
    assert.deepEqual(w.points, { R: [30, 40, 50], offset: [1.5, -2, 0.25] }, header);
  }
  const mm = readWheelCsv('R (mm),offset (mm)\n30,0.0015\n50,-0.002\n');
  assert.deepEqual(mm.points.offset.map((v) => Math.round(v * 1e6) / 1e6), [1.5, -2]);
  assert.ok(mm.notes.some((n) => /×1000/.test(n)));
});

test('a spreadsheet\'s semicolons and decimal commas, a BOM, comments and points in falling R', () => {
  const w = readWheelCsv('\uFEFF# measured on the dresser\nR (mm);Z (mm)\n50,5;1,25\n40;−0,5\n30,25;-2\n');
  assert.equal(w.kind, 'measuredProfile');
  assert.deepEqual(w.points, { R: [30.25, 40, 50.5], Z: [-2, -0.5, 1.25] });
  assert.ok(w.notes.includes('semicolons with decimal commas'));
  assert.ok(w.notes.some((n) => /falling R/.test(n)));
});

test('the page\'s own profile and dresser exports read back as a measured wheel, r left out', () => {
  const r = { wheelProfile: { r: [19, 25, 40], R: [29.5, 35, 50], Z: [3, 1.5, -2] },
    correction: { dresserPath: { R: [29.5, 35, 50], Z: [3.001, 1.5, -2.0004] } } };
  const profile = readWheelCsv(profileCsv(r));
  assert.deepEqual(profile.points, { R: r.wheelProfile.R, Z: r.wheelProfile.Z });
  assert.ok(profile.notes.some((n) => /column r left out/.test(n)));
  assert.deepEqual(readWheelCsv(dresserCsv(r)).points, r.correction.dresserPath);
});

test('what cannot be read is refused, naming the line and column', () => {
  const refused = (text, pattern) => assert.throws(() => readWheelCsv(text), pattern, text.slice(0, 40));
  refused('', /empty/);
  refused('30,1\n40,2\n', /Line 1: no header/);
  refused('R,offset\n30,1\n40,2\n', /Line 1, column 1: "R" has no unit; write R \(mm\)/);
  refused('R (mm),offset\n30,1\n40,2\n', /Line 1, column 2: "offset" has no unit; write offset \(µm\)/);
  refused('R (µm),Z (mm)\n30,1\n40,2\n', /Line 1, column 1: R in "µm"; it must be in mm/);
  refused('radius (mm),depth (mm)\n30,1\n', /needs "R \(mm\)" and either "offset \(µm\)"/);
  refused('R (mm),offset (µm),Z (mm)\n30,1,2\n', /both "offset" and "Z"/);
  refused('R (mm),offset (µm)\n30,1\n40,x\n', /Line 3, column 2: "x" is not a number \(µm\)/);
  refused('R (mm),offset (µm)\n30,1\n40\n', /Line 3, column 2: "" is not a number/);
  refused('R (mm),offset (µm)\n30,1\n', /1 point; it needs at least 2/);
  refused('R (mm),offset (µm)\n30,1\n40,2\n35,1\n', /Line 4: R = 35 mm does not follow the line before \(R = 40 mm\)/);
  refused('R (mm),offset (µm)\n' + '1,'.repeat(1200000), /MB.*right file/);
});

test('the case keeps one wheel: a new file replaces the old kind, the conjugate wheel removes both', () => {
  const extra = { inspection: { gashDeviations: [1, 2] }, wheel: { measuredProfile: { R: [30, 50], Z: [1, 2] } } };
  const dressed = withWheelPoints(extra, { kind: 'profileOffset', points: { R: [30, 50], offset: [1, 2] } });
  assert.deepEqual(dressed, { inspection: { gashDeviations: [1, 2] }, wheel: { profileOffset: { R: [30, 50], offset: [1, 2] } } });
  assert.deepEqual(extra.wheel.measuredProfile.R, [30, 50], 'not changed in place');
  assert.deepEqual(withWheelPoints(dressed, null), { inspection: { gashDeviations: [1, 2] } });
  assert.match(wheelSource(dressed).text, /offset at 2 points, R 30 to 50 mm, 1 to 2 µm/);
  assert.equal(wheelSource({}), null);
  assert.match(wheelSource({ wheel: { profileOffset: { R: 'x' } } }).text, /cannot read/);
});

test('Fig. 4\'s offsets: as dressed, the proposed spline at the profile points with its knots, and their sum', () => {
  const p = { r: [19, 30, 40], R: [29.5, 40, 50], Z: [0, 0, 0] };
  assert.deepEqual(wheelOffsetCurves({ wheelProfile: p }), [], 'the conjugate wheel: no offset scale');
  const dressed = { ...p, offset: [1, 2, 3] };
  const proposed = { R: [29.5, 50], offset: [-1, 4] };
  const dresserPath = { R: [29.6, 40.1, 50.1], Z: [0, 0, 0], offset: [0, 2.5, 7] };
  const curves = wheelOffsetCurves({ wheelProfile: dressed, correction: { wheelProfileOffset: proposed, dresserPath } });
  assert.deepEqual(curves.map((c) => c.name), ['offset as dressed', 'proposed in addition', 'dressed after the correction']);
  assert.deepEqual(curves[1].R, p.R, 'the proposal drawn at the profile points, not through its knots');
  assert.deepEqual(curves[1].offset, [-1, 0.5, 4]);
  assert.deepEqual(curves[1].knots, proposed);
  assert.deepEqual(curves[2].offset, [0, 2.5, 7]);
  const conjugate = wheelOffsetCurves({ wheelProfile: p, correction: { wheelProfileOffset: proposed, dresserPath } });
  assert.deepEqual(conjugate.map((c) => c.name), ['proposed in addition'], 'the conjugate wheel: the proposal is the sum');
  assert.deepEqual(conjugate[0].offset, [0, 2.5, 7]);
  assert.deepEqual(offsetRange(curves).map((v) => Math.round(v * 100) / 100), [-8.05, 8.05]);
  assert.deepEqual(offsetRange([{ offset: [0, 0] }]), [-1.15, 1.15], 'a zero offset is a line at 0, not blown up');
});
