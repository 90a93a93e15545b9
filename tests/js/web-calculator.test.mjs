// The page and the module's error codes and limits: the limits the page uses are the module's
// (web/src/limits.js), the worker tells a refusal from a fault by the error's code
// (web/worker-main.js, web/src/client.js), and the recompute and the loader choose by code.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';
import * as limits from '../../web/src/limits.js';
import { workerError } from '../../web/src/client.js';
import { createStore } from '../../web/src/store.js';
import { startRecompute } from '../../web/src/recompute.js';
import { createLoader } from '../../web/src/load.js';

const hobsharp = await loadHobSharp();
const paper = () => JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));
const settle = () => new Promise((resolve) => setImmediate(resolve));

test('the page has no limits of its own until the module gives them, then exactly the module\'s', () => {
  const fresh = hobsharp.limits();
  fresh.maxGridLines = 150;
  fresh.degree = { min: 2, max: 5, default: 3 };
  fresh.axes = fresh.axes.slice(0, 4).concat([{ name: 'C', kind: 'rotary', unit: 'rad' }]);
  limits.setModuleLimits(fresh);
  assert.deepEqual(limits.GRID, { min: 2, max: 150, radial: 5, axial: 9 });
  assert.deepEqual(limits.DEGREE, { min: 2, max: 5, default: 3 });
  assert.deepEqual(limits.AXES, ['X', 'Y', 'Z', 'A', 'C']);
  assert.equal(limits.isRotary('C'), true);
  assert.equal(limits.isRotary('B'), false);
  assert.equal(limits.AXIS_NAMES.C, 'C', 'an axis the page has no words for shows its name');

  const own = hobsharp.limits();
  limits.setModuleLimits(own);
  assert.equal(limits.CASE_FORMAT, own.format);
  assert.deepEqual(limits.GRID, { min: 2, max: own.maxGridLines, radial: own.defaultGrid.radial, axial: own.defaultGrid.axial });
  assert.deepEqual(limits.DEGREE, own.degree);
  assert.deepEqual(limits.AXES, own.axes.map((a) => a.name));
  assert.deepEqual(limits.AXIS_UNIT, Object.fromEntries(own.axes.map((a) => [a.name, a.unit])));
  assert.equal(limits.AXIS_UNIT.C, undefined);
  for (const a of own.axes) assert.equal(limits.isRotary(a.name), a.kind === 'rotary');
  assert.equal(limits.coefficientUnit('A', 2, own.motionUnits.helical), 'rad/rad²');
  assert.equal(limits.coefficientUnit('X', 12, 'mm'), 'mm/mm¹²');
  assert.throws(() => limits.setModuleLimits({ format: 'hobsharp-case/1' }), /no limits the page can use/);
});

// The worker's function (a classic script) run with a stand-in scope and a counting factory.
function worker(evaluate) {
  const source = readFileSync(new URL('../../web/worker-main.js', import.meta.url), 'utf8');
  const main = new Function(`${source}\nreturn hobsharpWorkerMain;`)();
  const posted = [];
  let instances = 0;
  const scope = { postMessage: (m) => posted.push(m) };
  main(scope, async () => {
    instances += 1;
    const module = await loadHobSharp();
    if (evaluate) module.evaluate = evaluate(module);
    return module;
  });
  const ask = async (data) => { await scope.onmessage({ data }); return posted[posted.length - 1]; };
  return { ask, instances: () => instances };
}

test('the worker keeps its module after a refusal and takes a fresh one after a fault', async () => {
  const w = worker();
  const answer = await w.ask({ id: 1, limits: true });
  assert.deepEqual(answer.result, hobsharp.limits());
  // The description of the result's fields (the figures' units), as the page asks for it.
  const fields = await w.ask({ id: 9, fields: true });
  assert.deepEqual(fields.result, hobsharp.resultFields());
  const rf = await import('../../web/src/result-fields.js');
  rf.setResultFields(fields.result);
  assert.equal(rf.fieldUnit('correction.resolutionFloor'), 'µm');
  assert.equal(rf.fieldUnit('correction.sseRounded'), 'µm²');
  const c = paper();
  c.setup.tilt = 'steep';
  const refusal = await w.ask({ id: 2, caseObject: c });
  assert.deepEqual([refusal.ok, refusal.error.code, refusal.error.field], [false, 'InvalidInput', 'setup.tilt']);
  assert.equal(w.instances(), 1, 'a refusal keeps the instance');

  // An Internal error, even one that names a field, and anything that is not a HobSharpError.
  const faults = [(m) => () => { throw Object.assign(new m.HobSharpError('boom', 'Internal'), { field: 'measured' }); },
    () => () => { throw new RangeError('memory access out of bounds'); }, () => () => { throw 7; }];
  for (const fault of faults) {
    const f = worker(fault);
    const posted = await f.ask({ id: 1, caseObject: paper() });
    assert.equal(posted.error.code, 'Internal');
    assert.equal(posted.error.field, '');
    assert.equal(f.instances(), 2, 'a fault gets a fresh instance');
  }
});

test('the page\'s error keeps a refusal\'s code and field; a fault has code Internal and no field', () => {
  const refused = workerError({ message: 'grid: no contact', code: 'Unsolvable', field: 'grid' });
  assert.deepEqual([refused.message, refused.code, refused.field], ['grid: no contact', 'Unsolvable', 'grid']);
  // In the page's words, with the calculator's own message kept.
  const words = ({ field, message }) => message.replace(`${field}: `, 'The grid: ');
  const worded = workerError({ message: 'grid: no contact', code: 'Unsolvable', field: 'grid' }, words);
  assert.deepEqual([worded.message, worded.calculatorMessage, worded.field], ['The grid: no contact', 'grid: no contact', 'grid']);
  for (const code of ['Internal', '', undefined, 'Something']) {
    const fault = workerError({ message: 'trap', code, field: 'measured' });
    assert.equal(fault.code, 'Internal');
    assert.equal('field' in fault, false);
  }
});

function standIn() {
  const calls = [];
  return { calls, evaluate: (caseObject) => new Promise((resolve, reject) => calls.push({ caseObject, resolve, reject })) };
}
const err = (message, fields) => Object.assign(new Error(message), fields);

test('the recompute sets a measured grid aside only when the module refuses it as input', async () => {
  for (const [error, asideExpected] of [
    [err('measured: must have 5 rows', { code: 'InvalidInput', field: 'measured' }), true],
    [err('The calculation failed inside the module', { code: 'Internal', field: 'measured[0][0]' }), false],
    [err('The calculator did not answer within 20 s', { code: 'Timeout' }), false],
  ]) {
    const store = createStore();
    const calc = standIn();
    startRecompute(store, calc);
    store.setInputs({ form: { format: 'hobsharp-case/1' }, measured: [[1, 2]] });
    calc.calls[0].reject(error);
    await settle();
    assert.equal(store.state.measured === null, asideExpected, error.message);
  }
});

test('a loaded case loses its measured grid only when the module refuses the grid as input', async () => {
  limits.setModuleLimits(hobsharp.limits());
  for (const [error, expected] of [
    [err('measured[0][0]: must be a number', { code: 'InvalidInput', field: 'measured[0][0]' }), 'aside'],
    [err('The calculation failed inside the module', { code: 'Internal', field: 'measured' }), 'refused'],
    [err('The calculator did not answer', { code: 'Timeout', field: 'measured' }), 'refused'],
  ]) {
    const store = createStore();
    const calc = standIn();
    const written = [];
    const loader = createLoader({
      store, calculator: calc, paperCase: paper(),
      form: { write: (c) => { written.push(c); return c; } }, measuredView: { setText() {} },
    });
    const c = { ...paper(), measured: [[1]] };
    const loading = loader.file(c, 'case.json');
    calc.calls[0].reject(error);
    await settle();
    if (calc.calls[1]) calc.calls[1].resolve({ result: {}, ms: 1 });
    await loading;
    const outcome = written.length === 0 ? 'refused' : written[0].measured === undefined ? 'aside' : 'kept';
    assert.equal(outcome, expected, error.message);
  }
});

test('the page takes a result\'s units from the module\'s field list, and nothing from its own text', async () => {
  const rf = await import('../../web/src/result-fields.js');
  rf.setResultFields([]);
  assert.equal(rf.fieldUnit('correction.identifiedAlone.A'), null, 'no units until the module gives its fields');
  rf.setResultFields(hobsharp.resultFields());
  assert.equal(rf.fieldUnit('correction.identifiedAlone.A'), 'µrad');
  assert.equal(rf.fieldUnit('correction.identifiedAlone.Y'), 'µm');
  assert.equal(rf.fieldUnit('correction.precision.changePerNoise.B'), 'µrad per µm');
  assert.ok(rf.fieldMeaning('correction.identifiedCombinations').length > 0);
  assert.throws(() => rf.setResultFields(undefined), /no description of its results/);
});
