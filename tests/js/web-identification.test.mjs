// What the engineer reads of the machine error's identification (web/src/identification.js).
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { combinationSentences, errorRows, precisionTable, roundedFigures, statusText } from '../../web/src/identification.js';

const AXES = ['X', 'Y', 'Z', 'A', 'B'];
// The units as the module's resultFields() gives them (a stand-in: the page reads its own list).
const UNITS = {
  'correction.identifiedAlone': { X: 'µm', Y: 'µm', Z: 'µm', A: 'µrad', B: 'µrad' },
  'correction.axisChange': { X: 'µm', Y: 'µm', Z: 'µm', A: 'µrad', B: 'µrad' },
  'correction.precision.facePerError': { X: 'µm per µm', A: 'µm per µrad' },
  'correction.precision.changePerNoise': { X: 'µm per µm', A: 'µrad per µm' },
};
const unitOf = (path) => {
  const dot = path.lastIndexOf('.');
  return (UNITS[path.slice(0, dot)] || {})[path.slice(dot + 1)] || '';
};

test('per axis: the error read on its own only where the face tells it apart, units from the field list', () => {
  const c = {
    identifiedAxes: { X: 'together', Y: 'together', Z: 'alone', A: 'unseen', B: 'alone' },
    identifiedAlone: { X: 0, Y: 0, Z: -3.01, A: 0, B: NaN },
    identifiedAloneUncertainty: { X: 0, Y: 0, Z: 0.06, A: 0, B: 4 },
    identifiedAloneSecondOrder: { X: 0, Y: 0, Z: 0.4, A: 0, B: NaN },
    identifiedError: { X: 1.5, Y: -2, Z: -3.2, A: 12, B: 3 },
    axisChange: { X: -1.5, Y: 2, Z: 3.2, A: -12, B: -3 },
  };
  // The labels as the module gives them (a stand-in: the page reads its own list).
  const labelOf = (path) => (path.startsWith('correction.identifiedAloneSecondOrder.') ? 'second order up to' : '');
  const rows = errorRows(c, AXES, unitOf, labelOf);
  assert.deepEqual(rows[2], { axis: 'Z', reading: 'alone', error: -3.01, errorUnit: 'µm', uncertainty: 0.06, secondOrder: 0.4,
    secondOrderLabel: 'second order up to', change: 3.2, changeUnit: 'µm', changeOverFace: null });
  assert.equal(rows[0].secondOrder, null, 'no second-order figure where no value is read on its own');
  assert.equal(rows[4].secondOrder, null, 'NaN never reaches the table');
  assert.equal(rows[0].error, null, 'X is not read on its own: its share of a combination is not shown as its error');
  assert.equal(rows[0].uncertainty, null);
  assert.equal(rows[0].change, -1.5, 'the change proposed is shown for every axis');
  assert.equal(rows[3].reading, 'unseen');
  assert.equal(rows[4].error, null, 'NaN never reaches the table');
  assert.equal(rows[4].errorUnit, 'µrad');
  assert.deepEqual(errorRows({ sseAfter: 1 }, AXES, unitOf), [], 'no rows without the fields');
  assert.deepEqual(errorRows({ identifiedError: { X: 1 }, axisChange: { X: 1 } }, ['X'], unitOf)[0].error, null,
    'a result without identifiedAxes reads no axis on its own');
});

test('the change over the whole face where measured points span less: given where it says more, not where it agrees', () => {
  const c = {
    identifiedAxes: { X: 'together', A: 'together', B: 'alone' },
    axisChange: { X: 5.749, A: -244.3, B: 50.24, Y: 3, Z: 1 },
    axisChangeOverFace: { X: 16.5, A: -244.30001, B: NaN, Y: -5, Z: 0.9 },
  };
  const rows = errorRows(c, ['X', 'A', 'B', 'Y', 'Z'], unitOf);
  assert.equal(rows[0].changeOverFace, 16.5, 'the program changes X by more beyond the points');
  assert.equal(rows[1].changeOverFace, null, 'the same figure is not said twice');
  assert.equal(rows[2].changeOverFace, null, 'NaN never reaches the table');
  assert.equal(rows[3].changeOverFace, -5, 'larger with the other sign');
  assert.equal(rows[4].changeOverFace, null, 'never a smaller figure as "over the whole face"');
  assert.equal(errorRows({ axisChange: { X: 1 } }, ['X'], unitOf)[0].changeOverFace, null, 'an older result without it');
});

test('the combinations in words: the sentences as given, nothing else', () => {
  const c = { identifiedCombinations: ['Y, Z and B together: +1 µm on Y grinds nearly the face of ...', '', 3] };
  assert.deepEqual(combinationSentences(c), ['Y, Z and B together: +1 µm on Y grinds nearly the face of ...']);
  assert.deepEqual(combinationSentences({}), []);
});

test('the precision demand: the two known quantities per axis, with words and the fields\' units', () => {
  const precision = {
    facePerError: Object.fromEntries(AXES.map((a, i) => [a, i + 1])),
    changePerNoise: { X: 10, Y: 20, Z: 30, A: 40, B: Infinity },
  };
  const t = precisionTable(precision, AXES, unitOf);
  assert.deepEqual(t.columns.map((q) => q.key), ['facePerError', 'changePerNoise']);
  assert.deepEqual(t.columns.map((q) => q.unit('X')), ['µm per µm', 'µm per µm']);
  assert.deepEqual(t.columns.map((q) => q.unit('A')), ['µm per µrad', 'µrad per µm']);
  assert.deepEqual(t.rows[3], { axis: 'A', values: [4, 40] });
  assert.deepEqual(t.rows[4].values, [5, null]);
  // The columns' labels are the fields' own (labelOf: result-fields.js's fieldLabel on the page).
  const labelled = precisionTable(precision, AXES, unitOf, (path) => `label of ${path}`);
  assert.deepEqual(labelled.columns.map((q) => q.label), ['label of correction.precision.facePerError.X', 'label of correction.precision.changePerNoise.X']);
  assert.equal(precisionTable(undefined, AXES, unitOf), null);
  assert.equal(precisionTable({}, AXES, unitOf), null);
  assert.equal(precisionTable({ sensitivity: { X: 1 } }, AXES, unitOf), null, 'no guessing at unknown keys');
});

test('the status, its reason, the iterations and the method in words', () => {
  assert.equal(statusText({ status: 'converged', iterations: 4, method: 'nonlinear', statusReason: 'the step fell below its tolerance', usable: true }),
    'Solver (nonlinear identification): converged, 4 iterations. The step fell below its tolerance.');
  assert.equal(statusText({ status: 'notConverged', iterations: 1, method: 'linear' }),
    'Solver (one linear step (Eq. 17)): not converged (the iterations ran out), 1 iteration.');
  assert.equal(statusText({ status: { code: 'stalled', reason: 'no lower sum of squares' }, iterations: NaN }),
    'Solver: stalled. No lower sum of squares.');
  assert.match(statusText({ status: 'failed', usable: false }), /failed\. The proposal is not usable: do not run it\.$/);
  assert.equal(statusText({}), '');
});

test('the rounded axes: their predicted face beside the exact proposal\'s, nothing that is not finite', () => {
  const c = { roundedAxes: { X: [1] }, sseRounded: 0.02, maxRounded: 0.1, thicknessRounded: NaN, sseAfter: 1e-5, maxAfter: 0.002, thicknessAfter: 0 };
  assert.deepEqual(roundedFigures(c), { rounded: { sse: 0.02, max: 0.1, thickness: null }, exact: { sse: 1e-5, max: 0.002, thickness: 0 } });
  assert.equal(roundedFigures({ sseRounded: 1 }), null);
});
