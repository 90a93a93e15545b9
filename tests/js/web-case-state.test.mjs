// A case saved and loaded (web/src/io/case-state.js): everything the user gave comes back, the
// page's own member is stripped before the calculator sees the case, and a malformed one is
// refused naming it.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { calculatorCase, inputsFromCase, offsetsToSave, savedCase, userData } from '../../web/src/io/case-state.js';
import { caseOf, initialState } from '../../web/src/store.js';
import { setModuleLimits } from '../../web/src/limits.js';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';

setModuleLimits((await loadHobSharp()).limits());  // the axes, as the page has them once its calculator is ready

const paper = JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
const axes = { X: [22.4, 139.5, 0, 0, 0], Y: [39.3, 0, 0, 0, 0], Z: [-116.4, 0, 0, 0, 0], A: [0, 1, 0, 0, 0], B: [0.22, 0, 0, 0, 0] };

function stateWith(patch) {
  return Object.assign(initialState(), { form: structuredClone(paper) }, patch);
}

test('save then load gives back the form, the run axes, the offsets, the measured grid, the locks and the thresholds', () => {
  const offsets = { Z: [-0.01], B: [0, 0, 0.001] };
  const state = stateWith({
    measured: [[1, 2], [3, 4]], locked: ['B a2'], lockedAxes: ['A'], tuning: { truncation: 1e-5 }, axes, offsets,
  });
  const saved = JSON.parse(JSON.stringify(savedCase(state)));
  assert.deepEqual(saved.page, { whatIf: offsets });
  assert.deepEqual(saved.correction, { truncation: 1e-5, lockedAxes: ['A'], locked: ['B a2'] });
  const back = inputsFromCase(saved);
  assert.deepEqual(back.formCase, paper);
  assert.deepEqual(back.axes, axes);
  assert.deepEqual(back.offsets, offsets);
  assert.deepEqual(back.measured, [[1, 2], [3, 4]]);
  assert.deepEqual([back.locked, back.lockedAxes, back.tuning], [['B a2'], ['A'], { truncation: 1e-5 }]);
  // Loaded again into a state, it saves the same.
  const again = stateWith({ form: back.formCase, measured: back.measured, locked: back.locked, lockedAxes: back.lockedAxes,
    tuning: back.tuning, axes: back.axes, offsets: back.offsets });
  assert.deepEqual(JSON.parse(JSON.stringify(savedCase(again))), saved);
});

test('the calculator gets the run axes and the thresholds, never the page member', () => {
  const state = stateWith({ axes, offsets: { Y: [0.01] }, measured: [[1]], tuning: { amplification: 2 } });
  const c = caseOf(state);
  assert.deepEqual(c.axes, axes);
  assert.deepEqual(c.correction, { amplification: 2, lockedAxes: [], locked: [] });
  assert.equal('page' in c, false);
  const saved = savedCase(state);
  assert.ok('page' in saved);
  const sent = calculatorCase(saved);
  assert.equal('page' in sent, false);
  assert.deepEqual(sent, c);
  assert.equal(calculatorCase(paper), paper, 'a case without a page member goes as it is');
});

test('locks and thresholds without a measured grid are saved, not sent', () => {
  const state = stateWith({ locked: ['X a1'] });
  assert.equal(caseOf(state).correction, undefined);
  assert.deepEqual(savedCase(state).correction, { lockedAxes: [], locked: ['X a1'] });
  assert.equal(savedCase(stateWith({})).correction, undefined);
  assert.equal(savedCase(stateWith({})).page, undefined, 'no offsets, no page member');
});

test('offsets are saved as plain lists: holes are zeros, trailing zeros and empty axes left out', () => {
  const sparse = [];
  sparse[2] = 0.5;
  assert.deepEqual(offsetsToSave({ X: sparse, Y: [0, 0], Z: [NaN, 1, 0] }), { X: [0, 0, 0.5], Z: [0, 1] });
});

test('a malformed page member is refused, naming it', () => {
  const bad = (page) => () => inputsFromCase({ ...paper, page });
  assert.throws(bad(3), /^Error: page: must be an object/);
  assert.throws(bad({ whatIf: [] }), /^Error: page\.whatIf: must be an object/);
  assert.throws(bad({ whatIf: { W: [1] } }), /^Error: page\.whatIf\.W: unknown axis/);
  assert.throws(bad({ whatIf: { X: [1, 'a'] } }), /^Error: page\.whatIf\.X: must be a list of at most 7 finite numbers/);
  assert.throws(bad({ whatIf: { X: new Array(8).fill(0) } }), /page\.whatIf\.X/);
  assert.throws(bad({ notes: 'x' }), /^Error: page\.notes: unknown field \(expected: whatIf, view, surfaces\)/);
  assert.throws(bad({ view: 'tangential' }), /^Error: page\.view: must be "normal" or "circular"/);
  assert.throws(bad({ surfaces: 'yes' }), /^Error: page\.surfaces: must be true or false/);
  assert.deepEqual(inputsFromCase({ ...paper, page: {} }).offsets, {});
});

test('how the page shows the topography (circular deviation, 3D surfaces) is saved only when not the default', () => {
  assert.deepEqual(savedCase(stateWith({ view: 'circular', surfaces: true })).page, { view: 'circular', surfaces: true });
  assert.deepEqual(savedCase(stateWith({ surfaces: true, offsets: { Y: [0.01] } })).page, { whatIf: { Y: [0.01] }, surfaces: true });
  assert.equal(savedCase(stateWith({ view: 'normal', surfaces: false })).page, undefined);
  assert.deepEqual(inputsFromCase({ ...paper, page: { view: 'circular', surfaces: true } }).pageView, { view: 'circular', surfaces: true });
  assert.deepEqual(inputsFromCase(paper).pageView, { view: 'normal', surfaces: false }, 'without a page member: the defaults');
  assert.equal('page' in calculatorCase(savedCase(stateWith({ view: 'circular' }))), false, 'never sent to the calculator');
});

test('what loading another case would replace, in words', () => {
  assert.deepEqual(userData(stateWith({})), []);
  assert.deepEqual(userData(stateWith({ measured: [[1, 2, 3], [4, 5, 6]], axes, offsets: { Y: [0.01, 0.02] }, locked: ['X a0'] })),
    ['the measured grid (2 × 3 values)', 'the run axes', '2 what-if offsets', '1 lock']);
  assert.deepEqual(userData(stateWith({ offsets: { Y: [0] } })), [], 'zero offsets are nothing');
});

// The grinding passes (docs/case-format.md, "passes"): saved, loaded, read by the calculator.
const grid = (v) => Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (_, j) => v + i - j / 8));
const history = [{ axes, measured: grid(1.25) },
  { axes: { ...axes, Y: [39.31, 0, 0, 0, 1e-6] }, measured: grid(-0.5), correction: { probeNoise: 1, resolution: { A: 0.001 }, lockedAxes: ['B'], locked: [] } },
  { axes, measuredPoints: [[19.5, -60, 1.25], [30, 0, -0.5], [38, 60.5, 2]] }];  // measured at the measuring machine's points

test('the grinding passes are saved and loaded with the case, and the calculator reads them', async () => {
  const state = stateWith({ passes: structuredClone(history), axes, measured: grid(0.1) });
  const saved = JSON.parse(JSON.stringify(savedCase(state)));
  assert.deepEqual(saved.passes, history);
  assert.deepEqual(caseOf(state).passes, history, 'the correction identifies the machine from the history too');
  const back = inputsFromCase(saved);
  assert.deepEqual(back.passes, history);
  assert.deepEqual(back.formCase, paper, 'the history is not taken for a field of the form');
  assert.equal(savedCase(stateWith({})).passes, undefined, 'no history, no member');
  assert.deepEqual(inputsFromCase(paper).passes, []);
  assert.deepEqual(userData(stateWith({ passes: history })), ['the history of 3 grinding passes']);
  assert.equal('measured' in back.passes[2], false, 'a pass of points has no grid');
  // The C++ case reader (in the module) takes the saved case and reads the history. These faces
  // are made up, not ground by one machine error: the history is not joined, the verdict says so,
  // and the axes are those from the face alone.
  const hobsharp = await loadHobSharp();
  const withHistory = hobsharp.evaluate(calculatorCase(saved));
  const without = hobsharp.evaluate({ ...caseOf(state), passes: undefined });
  assert.equal(withHistory.correction.passesJoined, 0);
  assert.match(withHistory.correction.verdict, /No one machine error explains this face and the 2 earlier passes' faces/);
  assert.deepEqual(withHistory.correction.axes, without.correction.axes);
});

test('a history that does not fit its grid is refused by the calculator, naming the pass', async () => {
  const hobsharp = await loadHobSharp();
  const bad = structuredClone(history);
  bad[1].measured.pop();
  assert.throws(() => hobsharp.evaluate({ ...paper, passes: bad }),
    (e) => e.field === 'passes[1].measured' && /^Pass 2, measured grid: needs 5 rows \(the radial grid lines\) of 9 values \(the axial grid lines\); got 4 x 9\.$/.test(e.message));
  bad[1].measured = grid(0);
  bad[0].axes = { ...axes, B: [0.22] };
  assert.throws(() => hobsharp.evaluate({ ...paper, passes: bad }), (e) => e.field === 'passes[0].axes.B');
  bad[0].axes = axes;
  bad[2].measuredPoints[1] = [45, 0, 1];
  assert.throws(() => hobsharp.evaluate({ ...paper, passes: bad }),
    (e) => e.field === 'passes[2].measuredPoints[1]' && /off the rake face/.test(e.message));
  bad[2].measuredPoints = history[2].measuredPoints;
  bad[1].correction.probeNoise = -1;
  assert.throws(() => hobsharp.evaluate({ ...paper, passes: bad }),
    (e) => e.field === 'passes[1].correction.probeNoise' && /must be positive/.test(e.message));
});

test('what the form has no inputs for (inspection, dressed wheel) is kept from the loaded case, sent and saved', async () => {
  const loaded = { ...paper, wheel: { ...paper.wheel, profileOffset: { R: [30, 40, 49.9], offset: [1, -1, 0.5] } },
    inspection: { gashDeviations: [0, 1.5, -2, 0.5, 3, 0, -1, 0.25, 0, 2, -0.5, 1], uncertainty: 1.5 } };
  const inputs = inputsFromCase(loaded);
  assert.deepEqual(inputs.extra, { wheel: { profileOffset: loaded.wheel.profileOffset }, inspection: loaded.inspection });
  // The form keeps only its own fields; the state's extra puts the rest back.
  const form = structuredClone(paper);
  const state = stateWith({ form, extra: inputs.extra });
  const sent = caseOf(state);
  assert.deepEqual(sent.wheel, loaded.wheel);
  assert.deepEqual(sent.inspection, loaded.inspection);
  assert.deepEqual(JSON.parse(JSON.stringify(savedCase(state))).inspection, loaded.inspection);
  inputs.extra.inspection.gashDeviations[0] = 99;
  assert.equal(loaded.inspection.gashDeviations[0], 0, 'kept as a copy');
  const hobsharp = await loadHobSharp();
  const r = hobsharp.evaluate(sent);
  assert.ok(r.inspection.cumulativeSpacing > 0, 'the calculator gets the gash deviations');
  assert.equal(r.inspection.uncertainty, 1.5, 'and the measurement\'s uncertainty');
  assert.ok(r.wheelOffset, 'and the dressed wheel');
});

// The job's record (issue 22): kept in the form's case, saved, put in the link and loaded back,
// and the calculator (the module's case reader) takes it and refuses a text too long, naming it.
test('the job travels with the case: saved, in the link, loaded back; the calculator takes it and names a bad one', async () => {
  const { caseFromHash, caseToHash } = await import('../../web/src/io/url.js');
  const job = { number: 'A-2026-117', customer: 'Zahnradwerk Süd GmbH', hobSerial: 'H 4711', operator: 'K. Weber', notes: 'Second pass.\nWheel dressed.' };
  const state = stateWith({ form: { ...structuredClone(paper), job } });
  const saved = JSON.parse(JSON.stringify(savedCase(state)));
  assert.deepEqual(saved.job, job);
  const linked = caseFromHash(caseToHash(saved)).case;
  const back = inputsFromCase(linked);
  assert.deepEqual(back.formCase.job, job);
  assert.deepEqual(JSON.parse(JSON.stringify(savedCase(stateWith({ form: back.formCase })))), saved);
  const hobsharp = await loadHobSharp();
  const withJob = hobsharp.evaluate(calculatorCase(saved));
  const without = hobsharp.evaluate(paper);
  assert.deepEqual(withJob.axes, without.axes, 'the job changes nothing computed');
  assert.throws(() => hobsharp.evaluate({ ...paper, job: { number: '7'.repeat(61) } }),
    (e) => e.field === 'job.number' && /^job\.number: must be at most 60 characters; got 61\.$/.test(e.message));
  assert.throws(() => hobsharp.evaluate({ ...paper, job: { serial: 'H 4711' } }), (e) => e.field === 'job.serial' && /unknown field/.test(e.message));
  assert.throws(() => hobsharp.evaluate({ ...paper, job: { operator: 'K.\nWeber' } }), (e) => e.field === 'job.operator' && /one line of text/.test(e.message));
});
