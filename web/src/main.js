// HobSharp's page: a store, the views that show it, and the io that fills it. Nothing here
// computes geometry; every number shown comes from the module's evaluate(case), in a worker.
import { createStore } from './store.js';
import { createCalculator } from './client.js';
import { inputWords, worded } from './views/field-names.js';
import { startRecompute } from './recompute.js';
import { loadPlotly, mountPlots } from './plots/passes.js';
import { mountForm } from './form.js';
import { installHooks } from './hooks.js';
import { mountStatus } from './views/status.js';
import { mountDerived } from './views/derived.js';
import { mountAxes } from './views/axes.js';
import { mountMachineAxes } from './views/machine-axes.js';
import { mountReport } from './views/report.js';
import { mountInspection } from './views/inspection.js';
import { mountToleranceTable } from './views/tolerance-table.js';
import { mountPerGash } from './views/per-gash.js';
import { mountGearEffect } from './views/gear-effect.js';
import { mountWheel } from './views/wheel.js';
import { mountWheelInput } from './views/wheel-input.js';
import { mountWheelSplit } from './views/wheel-split.js';
import { mountTopography } from './views/topography.js';
import { mountSensitivities } from './views/sensitivities.js';
import { mountMeasured } from './views/measured.js';
import { mountWhatIf } from './views/what-if.js';
import { mountLocks } from './views/locks.js';
import { mountSummary } from './views/summary.js';
import { mountWheelEdge } from './views/wheel-edge.js';
import { mountOnDemand } from './views/on-demand.js';
import { mountFieldErrors } from './views/field-errors.js';
import { mountStale } from './views/stale.js';
import { mountPaperNote } from './views/paper-note.js';
import { mountRunAxes } from './views/run-axes.js';
import { mountPin } from './views/pin.js';
import { mountPassHistory } from './views/pass-history.js';
import { mountIdentification } from './views/identification.js';
import { mountCorrectionOptions } from './views/correction-options.js';
import { mountUndo } from './views/undo.js';
import { mountAccess } from './views/access.js';
import { mountCancel } from './views/cancel.js';
import { mountCaseFiles } from './io/case-files.js';
import { caseFromHash, mountLink } from './io/url.js';
import { createLoader } from './load.js';
import { setModuleLimits } from './limits.js';
import { setResultFields } from './result-fields.js';

const store = createStore();
const calculator = createCalculator({ words: (error) => worded(error).text });
loadPlotly().catch(() => {});  // in parallel with the calculator; a failure is reported when drawing

const hooks = installHooks(store, calculator);
hooks.watch(calculator.busy);
mountAccess();
mountStatus(store);
mountCancel(calculator);
const form = mountForm(store);
mountFieldErrors(store);
mountStale(store);
mountPin(store);
const plots = mountPlots(store);
hooks.watch(plots.busy);
mountDerived(store);
mountPaperNote(store);
mountAxes(store, plots);
mountMachineAxes(store);
mountReport(store);
mountInspection(store);
mountToleranceTable(store);
mountPerGash(store);
mountGearEffect(store, plots);
mountRunAxes(store);
mountWheel(store, plots);
mountWheelInput(store);
mountTopography(store, plots);
mountSensitivities(store, plots);
const measuredView = mountMeasured(store);
mountWhatIf(store, calculator, measuredView);
mountLocks(store);
mountSummary(store);
mountWheelEdge(store);
mountOnDemand(store);
mountCorrectionOptions(store);
mountIdentification(store);
mountWheelSplit(store, plots);
mountPassHistory(store, calculator, measuredView);
mountUndo(store);
const loader = createLoader({ store, calculator, form, measuredView, paperCase: self.HOBSHARP_PAPER_CASE });
mountCaseFiles(store, loader, mountLink(store), inputWords);
hooks.watch(startRecompute(store, calculator).busy);

// The module's limits first (the form's bounds, the axes, the case format) and the description of
// its results (the figures' units), then the case.
function openCase() {
  const fromLink = caseFromHash(location.hash);
  if (fromLink && fromLink.case !== undefined) loader.link(fromLink.case);
  else if (fromLink) loader.refused('The link', fromLink.error, 'paper');
  else loader.paper();
}
(function ready() {
  Promise.all([calculator.limits(), calculator.fields()]).then(([limits, fields]) => {
    setModuleLimits(limits);
    setResultFields(fields);
    store.emit('limits');
    openCase();
  }).catch((e) => {
    store.setStatus(e.message, 'error');
    if (e.code === 'Timeout') ready();  // a fresh worker was started: ask it
  });
})();
