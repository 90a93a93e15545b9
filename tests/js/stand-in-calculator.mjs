// A stand-in for the page's calculator (web/src/client.js) whose answers the test releases: each
// evaluate() waits in `calls` ({caseObject, resolve, reject}) until the test answers it; settle()
// lets the page's promises run.
export function standIn() {
  const calls = [];
  return {
    calls,
    evaluate(caseObject) {
      return new Promise((resolve, reject) => calls.push({ caseObject, resolve, reject }));
    },
  };
}
export const settle = () => new Promise((resolve) => setImmediate(resolve));
