// Runs inside the module factory (--pre-js). The module's JS API, the same in the browser and in
// Node (docs/api.md):
//   Module.evaluate(case[, {typedArrays: true}])  the result of a hobsharp-case/1 object
//   Module.evaluateToJson(case)                   the C++ JSON writer's text for it (the CLI's output)
//   Module.resultFields(), Module.limits()        the result's fields, the case's limits and defaults
//   Module.limitFields()                          the limits' entries: [{path, kind, unit, words}]
//   Module.HobSharpError                          what evaluate and evaluateToJson throw
// The results, the fields and the limits come from C++ in their final shape (wasm/bindings.cpp);
// this file only checks what JSON cannot carry (NaN, Infinity) and throws the failures.

// A failure of the calculation. .code says which kind: 'InvalidInput' (change the field named),
// 'Unsolvable' (valid input whose equations have no solution, e.g. a grid point the wheel never
// grinds) or 'Internal' (a fault of the calculator; the instance may have to be replaced).
// .field is the input field's path ('' when the error names none, e.g. text that is not JSON);
// an Internal error has no .field.
class HobSharpError extends Error {
  constructor(message, code, field) {
    super(message);
    this.name = 'HobSharpError';
    this.code = code;
    if (code !== 'Internal') this.field = field;
  }

  // Each module instance makes its own class; an error from any of them is a HobSharpError.
  static [Symbol.hasInstance](x) {
    return x instanceof Error && x.name === 'HobSharpError';
  }
}

// Nesting deeper than this is not searched for NaN (no case field is deeper than 3).
const HOBSHARP_SCAN_DEPTH = 64;

// The first number of the case that JSON would write as null (NaN, Infinity, -Infinity), with its
// path written as the C++ reader writes paths ("hob.outerDiameter", "measured[2][3]", "axes.B[1]"),
// and whether the case holds a typed array (JSON would write it as an object). Iterative, bounded in
// depth, each object once: user data is never walked recursively.
function hobsharpScan(root) {
  const isList = (v) => Array.isArray(v) || ArrayBuffer.isView(v);
  const frame = (node, path) => ({ node, path, keys: isList(node) ? null : Object.keys(node), i: 0 });
  const seen = new Set([root]);
  const stack = [frame(root, '')];
  let typed = false;
  while (stack.length > 0) {
    const top = stack[stack.length - 1];
    const n = top.keys ? top.keys.length : top.node.length;
    if (top.i >= n) {
      stack.pop();
      continue;
    }
    const key = top.keys ? top.keys[top.i] : top.i;
    top.i += 1;
    const v = top.node[key];
    if (typeof v === 'number') {
      if (!Number.isFinite(v)) return { nonFinite: v, path: hobsharpPath(top, key), typed };
    } else if (v !== null && typeof v === 'object' && !seen.has(v) && stack.length < HOBSHARP_SCAN_DEPTH) {
      seen.add(v);
      if (ArrayBuffer.isView(v)) typed = true;
      stack.push(frame(v, hobsharpPath(top, key)));
    }
  }
  return { nonFinite: null, path: '', typed };
}

function hobsharpPath(frame, key) {
  if (!frame.keys) return `${frame.path}[${key}]`;
  return frame.path ? `${frame.path}.${key}` : key;
}

// The case as the JSON text the C++ reader takes.
function hobsharpCaseText(caseObject, call) {
  if (caseObject === null || typeof caseObject !== 'object' || Array.isArray(caseObject)) {
    throw new TypeError(`${call}(case): the case must be a hobsharp-case/1 object`);
  }
  const scan = hobsharpScan(caseObject);
  if (scan.nonFinite !== null) {
    throw new HobSharpError(`${scan.path}: must be a finite number; got ${scan.nonFinite}.`, 'InvalidInput', scan.path);
  }
  try {
    return JSON.stringify(caseObject, scan.typed ? (k, v) => (ArrayBuffer.isView(v) ? Array.from(v) : v) : undefined);
  } catch (e) {
    // Nested too deeply for JSON.stringify, a cycle, a BigInt: no case file can hold these.
    throw new HobSharpError(`The case cannot be written as JSON: ${e.message}.`, 'InvalidInput', '');
  }
}

// Calls a binding; {ok: false} and anything thrown (a trap) become HobSharpErrors.
function hobsharpCall(binding, ...args) {
  let r;
  try {
    r = Module[binding](...args);
  } catch (e) {
    throw new HobSharpError(`The calculation failed inside the module: ${e && e.message ? e.message : String(e)}`, 'Internal');
  }
  if (!r.ok) throw new HobSharpError(r.message, r.code, r.field);
  return r.value;
}

Module['HobSharpError'] = HobSharpError;

// The result, as docs/api.md's table lists it. Numeric lists are Arrays, or with typedArrays
// Float64Arrays (cheaper to post between threads); matrices are lists of rows either way.
Module['evaluate'] = function (caseObject, options) {
  const text = hobsharpCaseText(caseObject, 'evaluate');
  return hobsharpCall(options && options.typedArrays ? 'evaluateJsonTyped' : 'evaluateJson', text);
};

// The same result as JSON text, written by the C++ writer. Takes the case as an object or as the
// text of a case file.
Module['evaluateToJson'] = function (caseObject) {
  const text = typeof caseObject === 'string' ? caseObject : hobsharpCaseText(caseObject, 'evaluateToJson');
  return hobsharpCall('evaluateJsonText', text);
};
