// How deeply a value read from a link or a file nests. A case nests 3 deep (measured, a row, a
// value); one nested thousands deep cannot even be copied to the worker or written back as text
// (the stack runs out), so the page refuses it before the calculator sees it.
export const MAX_CASE_DEPTH = 32;

// The depth of nested lists and objects in `value`, counted up to limit + 1 and no further.
export function nestingDepth(value, limit = MAX_CASE_DEPTH) {
  let deepest = 0;
  const stack = [[value, 0]];
  while (stack.length) {
    const [v, depth] = stack.pop();
    if (v === null || typeof v !== 'object') continue;
    if (depth + 1 > deepest) deepest = depth + 1;
    if (deepest > limit) return deepest;
    for (const child of Object.values(v)) stack.push([child, depth + 1]);
  }
  return deepest;
}
