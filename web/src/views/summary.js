// The summary at the top of the results (issue 23): what to do first, then the answer: the verdict
// and what the pass will leave (views/measured.js writes them), the rake face's class with its
// conformity (views/inspection.js), the face's rms before and after, the axes to run with their
// Copy and NC program buttons (views/machine-axes.js) and "Use as next run", and the warning when
// part of the face lies past the edge of the wheel's envelope (views/wheel-edge.js). This view
// writes the line on what to do and the rms; the others write their own elements, which stand here.
import { LEAST_RMS, rmsFixed } from '../format.js';
import { fieldUnit } from '../result-fields.js';
import { floorNote } from '../words.js';
import { changesNothing } from '../../../wasm/lib/pass-bound.js';

const $ = (selector) => document.querySelector(selector);

// What to do next, by where the job is: no measured face yet, the axes of a pass to grind (run
// axes given, as "Use as next run" gives them), or a correction to run.
export function firstStepText(result, caseObject = null) {
  if (result && !result.correction && caseObject && (caseObject.axes || (caseObject.passes || []).length)) {
    return 'Grind with the axes to run below (the run axes in use), measure the face and load the new measurement in step 2; ' +
      'the verdict, the class and the next axes to run show here.';
  }
  if (!result || !result.correction) {
    return 'First type the hob\'s data at the left (or load a case); then load the measured face in step 2 below, ' +
      'and the verdict, the class and the axes to run show here.';
  }
  if (result.correction.stop === true) return 'The face is within the probe noise: there is no pass to run.';
  if (changesNothing(result.correction)) return 'No change is proposed: there is no pass to run (the verdict says why).';
  if (result.correction.signReversed === true) {
    return 'Do not run the axes below yet: the faces measured moved against the change of the axes (the verdict says by ' +
      'how much). If the measuring machine signs deviations the other way round, load every face again with "change sign" ' +
      '(the earlier passes\' too): the axes below were computed from faces of the wrong sign.';
  }
  return 'Run the axes below, measure the face and load it in step 2; "Use as next run" keeps this pass in the history first.';
}

// The face's rms before (measured, or simulated for the axes run) and after the pass, with the
// module's units: "Face rms: 3.214 µm measured → at most 0.052 µm after the pass." After the pass
// is the prediction's bound (correction.predictedRmsHigh), what the pass leaves; the identified
// machine's figure (correction.rmsAfter) only with that condition, where there is no bound; after a
// stop, nothing.
export function rmsText(result, unitOf = fieldUnit) {
  if (!result) return '';
  const c = result.correction;
  if (c) {
    const [before, after, high] = [unitOf('correction.rmsBefore'), unitOf('correction.rmsAfter'), unitOf('correction.predictedRmsHigh')];
    if (!before || !after) return '';
    const measured = `Face rms: ${rmsFixed(c.rmsBefore)} ${before} measured`;
    // A stop proposes no pass: nothing after it.
    if (c.stop === true) return `${measured}: within the probe noise, the axes run stay.`;
    // A proposal that is not to be run: nothing after it either.
    if (c.usable === false) return `${measured}.`;
    // No change proposed (the correction found would leave more, or nothing stands above the
    // noise): the axes run stay.
    if (changesNothing(c)) return `${measured}: no change proposed, the axes run stay.`;
    // Faces that moved against the change of the axes (correction.signReversed): nothing after.
    if (c.signReversed === true) return `${measured}; nothing is predicted after the pass until the measuring machine's sign is checked.`;
    if (high && Number.isFinite(c.predictedRmsHigh))
      // A bound below the least rms written reads "at most 0.001", not 0.000.
      return `${measured} → at most ${rmsFixed(Math.max(c.predictedRmsHigh, LEAST_RMS))} ${high} after the pass${floorNote(c, unitOf)}.`;
    return `${measured} → ${rmsFixed(c.rmsAfter)} ${after} after the pass if the identified error is all of the machine's.`;
  }
  const unit = unitOf('topography.rms');
  return unit ? `Face rms: ${rmsFixed(result.topography.rms)} ${unit} simulated for the axes run; no measured face yet.` : '';
}

export function mountSummary(store) {
  store.on('result', ({ result, caseObject }) => {
    $('#first-step').textContent = firstStepText(result, caseObject);
    $('#summary-rms').textContent = rmsText(result);
    $('#summary-class').hidden = !result.inspection;
  });
}
