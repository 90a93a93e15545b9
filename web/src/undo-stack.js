// The undo history of the inputs: one step per committed change, numbered as the page's entries
// in the browser's session history are (step 0 is the page as opened). Pure: the caller keeps
// the browser in step (views/undo.js).

export function createUndoStack() {
  let steps = [];  // [{inputs, key}], step i at index i
  let at = -1;
  const keyOf = (inputs) => JSON.stringify(inputs);

  return {
    get step() { return at; },
    get inputs() { return at < 0 ? null : steps[at].inputs; },
    // Undo goes back to the step before (the browser's entry holds its inputs, even from before
    // a reload); redo only to a step this stack made.
    canUndo: () => at > 0,
    canRedo: () => at >= 0 && at < steps.length - 1,

    // A committed change: a new step after the current one (the steps after it are dropped, as
    // the browser drops its forward entries). Returns the step's number, or null if the inputs
    // are those of the current step.
    commit(inputs) {
      const key = keyOf(inputs);
      if (at >= 0 && steps[at].key === key) return null;
      steps = steps.slice(0, at + 1);
      steps.push({ inputs, key });
      at = steps.length - 1;
      return at;
    },

    // The page as opened, or opened again: step `step` holds these inputs, and is the current one.
    // Steps before it that the stack does not hold (from before a reload) cannot be undone here,
    // but the browser's Back button still brings them (moveTo).
    start(inputs, step = 0) {
      steps = [];
      steps[step] = { inputs, key: keyOf(inputs) };
      at = step;
    },

    // The browser went to an entry: step `step` with these inputs is the current one. An entry the
    // stack holds other inputs for (it did not make it) starts the history again from there.
    moveTo(step, inputs) {
      const key = keyOf(inputs);
      if (steps[step] && steps[step].key === key) { at = step; return; }
      steps = steps.slice(0, step);
      steps[step] = { inputs, key };
      at = step;
    },
  };
}
