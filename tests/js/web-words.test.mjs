// The page's words and figures (web/src/words.js, web/src/figures.js, web/src/format.js): what an
// engineer trying the page tripped on, said in the engineer's words.
import { test } from 'node:test';
import assert from 'node:assert/strict';
import { readFileSync } from 'node:fs';
import { fixed, signed } from '../../web/src/format.js';
import { gridFigures } from '../../web/src/figures.js';
import { floorNote, predictionText, settingAngleNote, updatedText, verdictText } from '../../web/src/words.js';
import { fieldMeaning, fieldUnit, setResultFields } from '../../web/src/result-fields.js';
import { loadHobSharp } from '../../wasm/hobsharp.mjs';

const hobsharp = await loadHobSharp();
setResultFields(hobsharp.resultFields());  // the units, as the page has them once the calculator is ready
const paper = () => JSON.parse(readFileSync(new URL('../data/tab1.json', import.meta.url), 'utf8'));

test('a value that rounds to zero has no sign: 0.000 µm, never −0.000 µm', () => {
  for (const v of [-0.0004, -1e-12, -0, 0, 0.0004]) {
    assert.equal(fixed(v, 3), '0.000', String(v));
    assert.equal(signed(v, 3), '0.000', String(v));
  }
  assert.equal(fixed(-0.0005001, 3), '-0.001');
  assert.equal(signed(-0.0005001, 3), '-0.001');
  assert.equal(signed(0.0005001, 3), '+0.001');
});

test('the status after a calculation says that the numbers are updated and how long it took', () => {
  assert.equal(updatedText(3.14), 'Updated — 3 ms');
  assert.equal(updatedText(40.6), 'Updated — 41 ms');
  assert.equal(updatedText(0.3), 'Updated — under 1 ms');
  assert.doesNotMatch(updatedText(3.14), /WebAssembly|worker|Computed/);
});

test('the derived setting angle names the hand of a helical gash, and no hand for a straight one', () => {
  const c = paper();
  delete c.setup.settingAngle;
  const right = hobsharp.evaluate(c).setup;
  assert.equal(right.settingAngleDerived, true);
  assert.match(settingAngleNote(right), /^auto: 12\.62\d\d° \(the gash helix angle, right hand\)$/);
  c.hob.hand = 'left';
  assert.match(settingAngleNote(hobsharp.evaluate(c).setup), /^auto: -12\.62\d\d° \(the gash helix angle, left hand\)$/);
  c.hob.gash = 'straight';
  delete c.hob.gashLead;
  delete c.hob.hand;
  delete c.setup.centerDistance;
  const straight = hobsharp.evaluate(c).setup;
  assert.equal(straight.settingAngleDerived, true);
  assert.equal(settingAngleNote(straight), 'auto: 0.0000° (straight gash: no helix to follow)');
  assert.doesNotMatch(settingAngleNote(straight), /hand/);
  assert.equal(settingAngleNote({ settingAngle: 12.5, settingAngleDerived: false }), 'used: 12.5°');
});

test('the verdict says what the left-out combinations are, not "left out as amplifying"', () => {
  const c = {
    verdict: 'Partly uncorrectable: 40 % of the sum of squares is a shape no axis polynomial produces.',
    sseBefore: 1234.5, sseAfter: 456.2, thicknessBefore: -0.0001, thicknessAfter: 2.5, rank: 10, amplifyingDropped: 10,
  };
  const text = verdictText(c);
  assert.doesNotMatch(text, /amplif/);
  assert.match(text, /^Partly uncorrectable: .* Sum of squares 1234\.5 → 456\.2 µm²; thickness 0\.000 → \+2\.500 µm\. /);
  assert.match(text, /The correction changes 10 independent combinations of the coefficients; 10 combinations are left unchanged, because they would need large axis moves for little gain\.$/);
  assert.match(verdictText({ ...c, rank: 1, amplifyingDropped: 1 }), /changes 1 independent combination of the coefficients; 1 combination is left unchanged, because it would need/);
  assert.match(verdictText({ ...c, amplifyingDropped: 0 }), /combinations of the coefficients\.$/);
  assert.match(verdictText({ ...c, rmsBefore: 5.2376, rmsAfter: 0.01 }), /^Partly uncorrectable: .* On the identified machine, with this measurement's misfit \(noise and all\) kept: RMS 5\.238 → 0\.010 µm; sum of squares 1234\.5 → 456\.2 µm²; thickness/);
});

test('a grid\'s figures: the sum of squares and the largest deviation, NaN (a dash) if any value is not', () => {
  assert.deepEqual(gridFigures([[1, -2], [0.5, 0]]), { sse: 5.25, max: 2, rms: Math.sqrt(5.25 / 4), peakToValley: 3 });
  assert.deepEqual(gridFigures([[1, NaN]]), { sse: NaN, max: NaN, rms: NaN, peakToValley: NaN });
  // The module's own figures of the normal deviation are those of its grid.
  const t = hobsharp.evaluate(paper()).topography;
  const f = gridFigures(t.normal);
  assert.ok(Math.abs(f.sse - t.sse) <= 1e-9 * t.sse);
  assert.equal(f.max, t.max);
  // The circular grid differs from the normal one, so do its figures.
  const circular = gridFigures(t.circular);
  assert.ok(Math.abs(circular.sse - t.sse) > 1e-3 * t.sse);
});

// A measured grid of the paper's 5 x 9 points: a shape the axes make (10 µm), or noise of 0.2 µm rms
// (the correction's default sigma is 0.5 µm: within it).
const shaped = () => Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (__, j) => (i - 2) * (j - 4) * 0.5 + 0.3 * (j - 4)));
const noisy = () => Array.from({ length: 5 }, (_, i) => Array.from({ length: 9 }, (__, j) => 0.3 * Math.sin(7 * i + 3 * j + 9 * i * j)));

test('the prediction: what the pass will leave and its bound, µm rms at the probe points, units from the module', () => {
  setResultFields(hobsharp.resultFields());
  assert.equal(fieldUnit('correction.predictedRms'), 'µm');
  assert.match(fieldMeaning('correction.predictedRmsHigh'), /^at most this rms/);
  assert.equal(fieldUnit('no.such.field'), null);
  const c = hobsharp.evaluate({ ...paper(), measured: shaped() }).correction;
  assert.equal(c.stop, false);
  const text = predictionText(c, fieldUnit);
  // The bound first; the model's figure only with its condition, never as what the pass leaves.
  assert.match(text, /^Predicted after the pass: at most [\d.e+-]+ µm rms at the probe points \(if the identified error is all of the machine's: ([\d.e+-]+ µm rms|within the probe noise)\)(; that is with the exact axes, and the machine's position resolution sets a floor of about [\d.]+ µm rms)?\.$/);
  // The pass's floor follows a bound below it (the module's verdict says the same), and only then.
  const low = { ...c, predictedRmsHigh: 0.00575, resolutionFloor: 0.0329 };
  assert.match(predictionText(low, fieldUnit), /\); that is with the exact axes, and the machine's position resolution sets a floor of about 0\.0329 µm rms\.$/);
  assert.equal(floorNote({ ...low, predictedRmsHigh: 0.5 }, fieldUnit), '');
  assert.equal(floorNote(low, () => null), '', 'no unit, no figure');
  // A prediction of no shape beyond the noise is said in words, not as a certain-looking 0.
  assert.match(predictionText({ ...c, predictedRms: 0 }, fieldUnit), /\(if the identified error is all of the machine's: within the probe noise\)/);
  assert.match(predictionText({ ...c, predictedRms: 0.2 }, fieldUnit), /\(if the identified error is all of the machine's: 0\.2 µm rms\)/);
  assert.doesNotMatch(predictionText({ ...c, predictedRms: 0.2 }, fieldUnit), /pass: 0\.2/);
  assert.ok(text.includes(`at most ${Number(c.predictedRmsHigh.toPrecision(3))} µm rms`), text);
  // Units are the module's: another unit is shown as given; none given, no line.
  assert.match(predictionText({ ...c, predictedRms: 0.2 }, (p) => (p.endsWith('High') ? 'mm' : 'µm')), /at most [\d.e+-]+ mm rms at the probe points \(if the identified error is all of the machine's: 0\.2 µm rms\)/);
  assert.equal(predictionText(c, () => null), null);
  // Nothing that is not a number, nothing for a proposal that is not to be run.
  assert.equal(predictionText({ ...c, predictedRmsHigh: NaN }, fieldUnit), null);
  assert.equal(predictionText({ ...c, predictedRms: undefined }, fieldUnit), null);
  assert.equal(predictionText({ ...c, usable: false }, fieldUnit), null);
  assert.equal(predictionText({ ...c, stop: true }, fieldUnit), null);
  assert.equal(predictionText({ ...c, runKept: true }, fieldUnit), null, 'no change proposed, no pass to predict');
  assert.throws(() => setResultFields({}), /no description of its results/);
});

test('stop: a face measured within the probe noise says so first, with the figures measured and nothing predicted', () => {
  const c = hobsharp.evaluate({ ...paper(), measured: noisy() }).correction;
  assert.equal(c.stop, true);
  const text = verdictText(c);
  assert.match(text, /^Stop: the measured face \([\d.]+ µm rms\) is within the probe noise \(sigma 0\.5 µm\); another pass would only move noise\. Keep the axes run\. /);
  assert.match(text, /Measured: RMS [\d.]+ µm; sum of squares [\d.e+-]+ µm²; thickness [+-]?[\d.]+ µm\.$/);
  assert.doesNotMatch(text, /→|predicted|NaN|undefined/);
  assert.equal(predictionText(c, fieldUnit), null);
  assert.doesNotMatch(text, /another unit/, 'a probe sigma of 0.5 µm is a probe\'s');
  // A sigma typed in another unit (500 for 0.5 µm): the stop says what it rests on.
  const slipped = hobsharp.evaluate({ ...paper(), measured: noisy(), correction: { probeNoise: 500 } }).correction;
  assert.equal(slipped.stop, true);
  assert.match(verdictText(slipped), /The probe noise declared, sigma 500 µm, is more than ten times a measuring machine's \(about 1 µm, U95 about 2 µm\): if it was entered in another unit, this stop rests on that\./);
});
